# Installs a build into a fresh prefix, builds the example consumer examples/cpp against it with
# find_package(vibroimpact) and the entry header <vibroimpact/vibroimpact.hpp>, runs it with a value
# set by path with a unit, and checks every number it prints against the installed command on a
# case file that holds the same value.
# Run as a script (tests/CMakeLists.txt, test Install.ConsumerFindsPackageBuildsAndRuns):
#   cmake -DBUILD_DIR=build -DSOURCE_DIR=. -DWORK_DIR=dir -DCXX=c++ -DLAUNCHER=ccache
#         -DGENERATOR=... -DBUILD_TYPE=Release -DPYTHON=python3 -P check_install_consumer.cmake
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer)
set(case_file ${SOURCE_DIR}/examples/switch/cantilever_switch.toml)
file(REMOVE_RECURSE ${WORK_DIR})

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# The number after `label` in the consumer's output, as it printed it.
function(printed out label)
  string(REGEX MATCH "${label} ([-+0-9.e]+)" m "${consumer_output}")
  if(NOT m)
    message(FATAL_ERROR "the consumer printed no '${label} <number>':\n${consumer_output}")
  endif()
  set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

# Fails unless `actual` (printed with 12 digits) agrees with `expected` to 1e-9 relative.
function(expect_close what actual expected)
  execute_process(COMMAND ${PYTHON} -c
    "import math, sys; sys.exit(0 if math.isclose(float(sys.argv[1]), float(sys.argv[2]), rel_tol=1e-9) else 1)"
    ${actual} ${expected} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: the consumer printed ${actual}, the command gives ${expected}")
  endif()
endfunction()

run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed bin/vibroimpact include/vibroimpact/vibroimpact.hpp include/vibroimpact/model/case.hpp)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "cmake --install did not install ${installed}")
  endif()
endforeach()

set(configure_args -S ${SOURCE_DIR}/examples/cpp -B ${consumer_build} -G ${GENERATOR}
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

# The consumer sets the voltage by path with a unit; the command reads the same value from a file.
file(READ ${case_file} case_text)
string(REPLACE "voltage = \"70 V\"" "voltage = \"75 V\"" case_75 "${case_text}")
if(case_75 STREQUAL case_text)
  message(FATAL_ERROR "${case_file} no longer holds voltage = \"70 V\"")
endif()
file(WRITE ${WORK_DIR}/switch_75V.toml "${case_75}")
run_step("the consumer" ${consumer_build}/switch_study ${case_file} "electrodes[0].voltage=75 V")
set(consumer_output "${step_output}")
message(STATUS "switch_study ${case_file} \"electrodes[0].voltage=75 V\":\n${consumer_output}")

set(cli ${prefix}/bin/vibroimpact)
run_step("vibroimpact modes --json" ${cli} modes ${WORK_DIR}/switch_75V.toml --count 1 --json)
string(JSON expected GET "${step_output}" unsupported bending 0 frequency_hz)
printed(actual "first frequency")
expect_close("first bending frequency [Hz]" ${actual} ${expected})

run_step("vibroimpact pullin --json" ${cli} pullin ${WORK_DIR}/switch_75V.toml --json)
string(JSON expected GET "${step_output}" pullin voltage_V)
printed(actual "pull-in:")
expect_close("pull-in voltage [V]" ${actual} ${expected})

run_step("vibroimpact simulate --json" ${cli} simulate ${WORK_DIR}/switch_75V.toml --json)
string(JSON impacts LENGTH "${step_output}" impacts)
string(JSON expected GET "${step_output}" T_s)
if(NOT consumer_output MATCHES "simulate: ${impacts} impacts, T ")
  message(FATAL_ERROR "the command counts ${impacts} impacts at 75 V; the consumer printed:\n${consumer_output}")
endif()
printed(actual "impacts, T")
expect_close("period T [s]" ${actual} ${expected})

# The sweep's middle point is the case itself: its T is the simulation's.
if(NOT consumer_output MATCHES "sweep supports\\[0\\].stiffness: [^\n]* -> T [^\n]* -> T ([-+0-9.e]+) s;[^\n]* -> T [^\n]*")
  message(FATAL_ERROR "the consumer's sweep did not give three points:\n${consumer_output}")
endif()
expect_close("period T of the sweep's middle point [s]" ${CMAKE_MATCH_1} ${expected})
