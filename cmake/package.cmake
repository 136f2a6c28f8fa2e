# `cpack -G DEB` in a build directory (docs/properties.md, Linking it): the Debian package
# circles_VERSION_ARCH.deb, which installs under /usr what `cmake --install` installs (cmake/install.cmake): the
# program, the static libraries, the headers, the CMake package and the licence.
#
# Depends lists the shared libraries the program runs with, as dpkg-shlibdeps reads them from the binary
# (dpkg-dev). Recommends lists what find_package(circles) needs to compile against the library (the -dev
# packages of the headers the public headers include, RapidCheck, GMP through pkg-config), so that the program
# alone installs without them.
#
# A package is for other machines: the build packaged must run on any x86-64 (-DCIRCLES_ARCH=portable, or a
# level named on purpose). cpack refuses a build for the building machine's own level (auto, which found
# x86-64-v3 there), whose program would stop with SIGILL on an older CPU (cmake/package_check.cmake).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME circles)
set(CPACK_PACKAGE_VENDOR "The circles authors")
set(CPACK_PACKAGE_CONTACT "The circles authors")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "conformance suite for the circles 2D physics spec")
# The extended description, under the summary, which cpack puts first.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "The circles program checks an implementation of the spec's step, in any\n"
    "language, over a line protocol (circles conform), and runs, traces and\n"
    "draws worlds with exact engines. The C++ property library (RapidCheck\n"
    "generators of the spec's boundary worlds and the conformance property)\n"
    "comes as the CMake package circles, for find_package(circles) in a\n"
    "project's own GoogleTest.")
string(JOIN "" CPACK_DEBIAN_PACKAGE_DESCRIPTION ${CPACK_DEBIAN_PACKAGE_DESCRIPTION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "cmake (>= 3.25), g++, pkg-config, libboost-dev, libeigen3-dev, libgmp-dev, librapidcheck-dev")
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_CURRENT_LIST_DIR}/package_check.cmake)
set(CPACK_CIRCLES_ARCH "${CIRCLES_ARCH}")
set(CPACK_CIRCLES_ARCH_LEVEL "${CIRCLES_ARCH_LEVEL}")
include(CPack)
