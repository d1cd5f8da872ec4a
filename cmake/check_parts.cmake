# Fails when an optional part whose Debian packages are installed is not in the build: the Python
# module with its test Python.pytest, and the MPI sweeps. Run by the test
# Build.EveryInstalledPartIsBuilt (tests/CMakeLists.txt):
#   cmake -DBUILD_DIR=build -DSANITIZE=OFF -P check_parts.cmake
# The packages are those of scripts/install-deps' jobs python and mpi. Without dpkg-query (not a
# Debian system) it checks only that parts.txt exists.
file(STRINGS ${BUILD_DIR}/parts.txt parts)
find_program(DPKG_QUERY dpkg-query)

function(installed out)
  set(all ON)
  foreach(p ${ARGN})
    execute_process(COMMAND ${DPKG_QUERY} -W -f=\${Status} ${p} OUTPUT_VARIABLE status ERROR_QUIET RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0 OR NOT status MATCHES "install ok installed")
      set(all OFF)
    endif()
  endforeach()
  set(${out} ${all} PARENT_SCOPE)
endfunction()

set(bad 0)
function(expect part packages why_not_expected)
  list(FIND parts "${part}=ON" built)
  if(NOT DPKG_QUERY OR why_not_expected)
    return()
  endif()
  installed(have ${packages})
  if(have AND built EQUAL -1)
    message(SEND_ERROR "part ${part} is not built although its packages (${packages}) are installed: "
      "configure ${BUILD_DIR} again (scripts/configure-build prints why a part is left out)")
  endif()
endfunction()

set(python_not_expected "")
if(SANITIZE)
  set(python_not_expected "a sanitizer build leaves the Python module out")
endif()
expect(python "pybind11-dev;python3-dev;python3-numpy" "${python_not_expected}")
expect(mpi "openmpi-bin;libopenmpi-dev" "")

list(FIND parts "python=ON" python_built)
if(NOT python_built EQUAL -1)
  file(GLOB module ${BUILD_DIR}/python/vibroimpact/_vibroimpact*.so)
  if(NOT module)
    message(SEND_ERROR "part python is configured but ${BUILD_DIR}/python/vibroimpact/_vibroimpact*.so is not built")
  endif()
  file(READ ${BUILD_DIR}/python/CTestTestfile.cmake python_tests)
  if(NOT python_tests MATCHES "Python.pytest")
    message(SEND_ERROR "part python is built but the test Python.pytest is not in the suite")
  endif()
endif()
message(STATUS "check_parts: ${parts}")
