# Compile time (docs/architecture.md, "Continuous integration"): ccache when installed, unity builds
# of the targets with many files, and less optimisation for the command-line glue and the tests.
# Precompiled headers were measured and left out: with GCC 12 they made the cold build slower.

# ccache, when installed and no launcher is set. CCACHE_BASEDIR and CCACHE_NOHASHDIR let build folders
# of different checkouts of the project (git worktrees) share cached objects.
option(VI_CCACHE "Compile through ccache when it is installed" ON)
if(VI_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(VI_CCACHE_PROGRAM ccache)
  if(VI_CCACHE_PROGRAM)
    set(CMAKE_CXX_COMPILER_LAUNCHER env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=true ${VI_CCACHE_PROGRAM})
    set(VI_CCACHE_STATUS "ccache ${VI_CCACHE_PROGRAM}")
  else()
    set(VI_CCACHE_STATUS "no ccache (Debian: ccache)")
  endif()
elseif(CMAKE_CXX_COMPILER_LAUNCHER)
  set(VI_CCACHE_STATUS "launcher ${CMAKE_CXX_COMPILER_LAUNCHER}")
else()
  set(VI_CCACHE_STATUS "VI_CCACHE is OFF")
endif()

option(VI_UNITY "Unity builds: several source files of a target compiled as one" ON)
set(VI_UNITY_BATCH 8 CACHE STRING "Source files per unity translation unit")

# Compiles the target's files in batches of VI_UNITY_BATCH. A file that cannot share a translation
# unit (its anonymous-namespace names or macros clash with another's) is listed in the call to be
# compiled on its own.
function(vi_unity target)
  cmake_parse_arguments(U "" "" "ALONE" ${ARGN})
  if(VI_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${VI_UNITY_BATCH})
    if(U_ALONE)
      set_source_files_properties(${U_ALONE} TARGET_DIRECTORY ${target} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
  endif()
endfunction()

# The command-line glue and the tests compiled with less optimisation: their own code does little
# work (the solvers are in the library), and -O3 of CLI11's and GoogleTest's inline code is most of
# their compile time.
option(VI_LIGHT_GLUE "Compile the command and the tests at -O1 (the library keeps the build type's level)" ON)
function(vi_light_optimisation target)
  if(VI_LIGHT_GLUE)
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()
