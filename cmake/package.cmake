# `cpack -G DEB` in a build folder: a Debian package of what `cmake --install` installs, under /usr
# (docs/install.md). Its Depends: the shared libraries the command links (dpkg-shlibdeps), and the
# -dev packages that the installed CMake package finds for the static library.
set(CPACK_PACKAGE_NAME vibroimpact)
set(CPACK_PACKAGE_VENDOR "The vibroimpact developers")
set(CPACK_PACKAGE_CONTACT "The vibroimpact developers <vibroimpact@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Finite-element simulation of vibro-impact dynamics in contact-type MEMS devices")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(VI_DEB_DEV_DEPENDS libeigen3-dev libspectra-dev libsundials-dev libtomlplusplus-dev nlohmann-json3-dev
  libnlopt-dev libceres-dev)
if(VI_HAVE_MPI)
  list(APPEND VI_DEB_DEV_DEPENDS libopenmpi-dev)
endif()
list(JOIN VI_DEB_DEV_DEPENDS ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
# The figures are drawn by gnuplot; everything else runs without it.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gnuplot-nox, fonts-dejavu-core")
include(CPack)
