# `cmake --install`: the property library as a CMake package, for a user's own GoogleTest (docs/properties.md).
#   include/circles/properties/*.hpp, include/circles/spec/*.hpp   the public headers and the oracle's, which
#                                                                  they include (not properties/detail/)
#   lib/libcircles_{properties,spec,impl}.a                        the library and the two it links
#   include/circles/step.h                                         the C ABI of a step (fuzz/step.h)
#   lib/libcircles_step_{fuzz,harness}.a                           the step fuzzer's harness around a user's step
#   lib/cmake/circles/                                             circlesConfig.cmake, the exported targets and
#                                                                  circles_add_step_fuzzer (circlesStepFuzzer.cmake)
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
set_target_properties(circles_step_fuzz PROPERTIES EXPORT_NAME step_fuzz)
set_target_properties(circles_step_harness PROPERTIES EXPORT_NAME step_harness)

install(TARGETS circles_properties circles_spec circles_impl circles_step_fuzz circles_step_harness EXPORT circlesTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/circles)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/properties ${PROJECT_SOURCE_DIR}/spec
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/circles
        FILES_MATCHING PATTERN "*.hpp" PATTERN "detail" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/fuzz/step.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/circles)
install(EXPORT circlesTargets NAMESPACE circles:: DESTINATION ${circles_install_cmakedir})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/circlesConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/circlesConfig.cmake INSTALL_DESTINATION ${circles_install_cmakedir})
# 0.x: a minor version may change the interface, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/circlesConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/circlesConfig.cmake ${PROJECT_BINARY_DIR}/circlesConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/circlesStepFuzzer.cmake
        DESTINATION ${circles_install_cmakedir})
