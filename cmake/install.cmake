# `cmake --install`: the vibroimpact command, the static library with its headers, and a CMake
# package so that another project can `find_package(vibroimpact)` (docs/install.md).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(VI_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/vibroimpact)

# The library keeps its target name in the build; consumers see vibroimpact::vibroimpact (and
# vibroimpact::mpi when built with MPI), the same names as the aliases below.
set_target_properties(vibroimpact_lib PROPERTIES EXPORT_NAME vibroimpact)
add_library(vibroimpact::vibroimpact ALIAS vibroimpact_lib)
set(VI_INSTALL_TARGETS vibroimpact_lib)
if(VI_HAVE_MPI)
  set_target_properties(vibroimpact_mpi PROPERTIES EXPORT_NAME mpi)
  add_library(vibroimpact::mpi ALIAS vibroimpact_mpi)
  list(APPEND VI_INSTALL_TARGETS vibroimpact_mpi)
endif()
# A library compiled with the sanitizers needs them in whatever uses it: their run-time libraries at
# link time, and the same compile flags, since Eigen allocates differently under AddressSanitizer
# (__SANITIZE_ADDRESS__), so a matrix made in the library and freed in the consumer would not match.
if(VI_SANITIZE)
  target_compile_options(vibroimpact_lib INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
  target_link_options(vibroimpact_lib INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
endif()

install(TARGETS vibroimpact RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${VI_INSTALL_TARGETS} EXPORT vibroimpactTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# Headers keep their layer folders under include/vibroimpact/ (src/model/case.hpp ->
# include/vibroimpact/model/case.hpp); src/CMakeLists.txt puts include/ and include/vibroimpact/ on
# the consumers' include path, the second because the headers include each other as "model/case.hpp".
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vibroimpact
  FILES_MATCHING PATTERN "*.hpp")
install(EXPORT vibroimpactTargets NAMESPACE vibroimpact:: DESTINATION ${VI_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/vibroimpactConfig.cmake.in
  ${PROJECT_BINARY_DIR}/vibroimpactConfig.cmake INSTALL_DESTINATION ${VI_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vibroimpactConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vibroimpactConfig.cmake ${PROJECT_BINARY_DIR}/vibroimpactConfigVersion.cmake
  DESTINATION ${VI_INSTALL_CMAKEDIR})
