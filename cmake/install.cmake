# `cmake --install`: the property library as a CMake package, for a user's own GoogleTest (docs/properties.md).
#   include/circles/properties/*.hpp, include/circles/spec/*.hpp   the public headers and the oracle's, which
#                                                                  they include (not properties/detail/)
#   lib/libcircles_{properties,spec,impl}.a                        the library and the two it links
#   lib/cmake/circles/                                             circlesConfig.cmake and the exported targets
# A user's project then does find_package(circles) and links circles::properties, the same name as in this tree.
# The headers go under include/circles/ so that "spec/..." and "properties/..." do not land in the prefix's own
# include/. circles::impl is installed for the linker only: the property library uses it privately, and no
# public header includes impl/. The flag sets (circles::warnings, numeric, sanitize) are linked as
# $<BUILD_INTERFACE:...> by these three libraries, so the exported targets carry no compile or link options.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(circles_install_cmakedir ${CMAKE_INSTALL_LIBDIR}/cmake/circles)
set_target_properties(circles_properties PROPERTIES EXPORT_NAME properties)
set_target_properties(circles_spec PROPERTIES EXPORT_NAME spec)
set_target_properties(circles_impl PROPERTIES EXPORT_NAME impl)

install(TARGETS circles_properties circles_spec circles_impl EXPORT circlesTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/circles)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/properties ${PROJECT_SOURCE_DIR}/spec
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/circles
        FILES_MATCHING PATTERN "*.hpp" PATTERN "detail" EXCLUDE)
install(EXPORT circlesTargets NAMESPACE circles:: DESTINATION ${circles_install_cmakedir})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/circlesConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/circlesConfig.cmake INSTALL_DESTINATION ${circles_install_cmakedir})
# 0.x: a minor version may change the interface, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/circlesConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/circlesConfig.cmake ${PROJECT_BINARY_DIR}/circlesConfigVersion.cmake
        DESTINATION ${circles_install_cmakedir})
