# One status line per optional part that a README command promises, "built" or the reason it is not,
# each starting "vibroimpact part" so that scripts/configure-build can show them, and the file
# parts.txt that the test Build.EveryInstalledPartIsBuilt compares with the installed packages.
set(vi_parts "")
function(vi_part name state why)
  if(state)
    message(STATUS "vibroimpact part ${name}: built")
    set(line "${name}=ON")
  else()
    message(STATUS "vibroimpact part ${name}: NOT built: ${why}")
    set(line "${name}=OFF")
  endif()
  set(vi_parts "${vi_parts}${line}\n" PARENT_SCOPE)
endfunction()

vi_part(python ${VI_PYTHON_BUILT} "${VI_PYTHON_WHY}")
vi_part(mpi ${VI_HAVE_MPI} "MPI not found (Debian: openmpi-bin libopenmpi-dev; bash scripts/install-deps mpi)")
vi_part(tests ${VI_BUILD_TESTS} "VI_BUILD_TESTS is OFF")
vi_part(bench ${VI_BUILD_BENCH} "VI_BUILD_BENCH is OFF")
message(STATUS "vibroimpact compile: ${VI_CCACHE_STATUS}; unity ${VI_UNITY} (batch ${VI_UNITY_BATCH})")
file(WRITE ${PROJECT_BINARY_DIR}/parts.txt "${vi_parts}")
