# A build folder configured while pybind11 cannot be found (as after scripts/run-example on a machine
# without the python job's packages) must build the Python module at the next configure once it can
# be found: the decision is not cached. Configures twice, builds nothing. Run by the test
# Build.PythonModuleComesBackWhenPybind11Appears:
#   cmake -DSOURCE_DIR=. -DWORK_DIR=dir -DGENERATOR=Ninja -P check_python_comes_back.cmake
# The test job installs pybind11 (scripts/install-deps test), so a machine without it fails here.
file(REMOVE_RECURSE ${WORK_DIR})
set(common -S ${SOURCE_DIR} -B ${WORK_DIR} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
  -DVI_BUILD_TESTS=OFF -DVI_BUILD_BENCH=OFF -DVI_CCACHE=OFF)

function(configure out)
  execute_process(COMMAND ${CMAKE_COMMAND} ${common} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "configure failed (${rc}):\n${text}\n${err}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

configure(first -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON)
if(NOT first MATCHES "vibroimpact part python: NOT built")
  message(FATAL_ERROR "without pybind11 the configure step did not say the module is not built:\n${first}")
endif()
configure(second -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=OFF)
if(second MATCHES "vibroimpact part python: built")
  message(STATUS "the Python module comes back once pybind11 is found")
else()
  message(FATAL_ERROR "with pybind11 found again the module stays out:\n${second}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
