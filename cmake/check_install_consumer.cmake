# Installs a build into a fresh prefix, builds the consumer project tests/consumer against it with
# find_package(vibroimpact), and checks that the consumer runs and agrees with the installed command.
# Run as a script (tests/CMakeLists.txt, test Install.ConsumerFindsPackageBuildsAndRuns):
#   cmake -DBUILD_DIR=build -DSOURCE_DIR=. -DWORK_DIR=dir -DCXX=c++ -DLAUNCHER=ccache
#         -DGENERATOR=... -DBUILD_TYPE=Release -P check_install_consumer.cmake
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer)
set(case_file ${SOURCE_DIR}/examples/paper/cantilever.toml)
file(REMOVE_RECURSE ${WORK_DIR})

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed bin/vibroimpact include/vibroimpact/model/case.hpp)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "cmake --install did not install ${installed}")
  endif()
endforeach()

set(configure_args -S ${SOURCE_DIR}/tests/consumer -B ${consumer_build} -G ${GENERATOR}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_CXX_COMPILER=${CXX})
if(LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run_step("configuring the consumer" ${CMAKE_COMMAND} ${configure_args})
# The package must come from the fresh prefix, not from some other installation.
string(FIND "${step_output}" "found in ${prefix}/" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the consumer did not find vibroimpact in ${prefix}:\n${step_output}")
endif()
run_step("building the consumer" ${CMAKE_COMMAND} --build ${consumer_build})

# The expected frequency: the installed command's own answer for the same case.
run_step("vibroimpact modes --json" ${prefix}/bin/vibroimpact modes ${case_file} --count 1 --json)
string(JSON expected GET "${step_output}" unsupported bending 0 frequency_hz)
run_step("the consumer" ${consumer_build}/first_frequency ${case_file} ${expected})
if(NOT step_output MATCHES "first bending frequency [0-9.e+]+ Hz")
  message(FATAL_ERROR "unexpected consumer output: ${step_output}")
endif()
message(STATUS "${step_output}(vibroimpact modes: ${expected} Hz)")
