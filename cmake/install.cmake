# `cmake --install`: the `circles` program, and the property library as a CMake package for a user's own
# GoogleTest (docs/properties.md, Linking it):
#   bin/circles                                                    the program
#   include/circles/properties/*.hpp, include/circles/spec/*.hpp   the public headers and the oracle's, which
#                                                                  they include (not properties/detail/)
#   lib/libcircles_{properties,spec,impl}.a                        the library and the two it links
#   include/circles/step.h                                         the C ABI of a step (fuzz/step.h)
#   lib/libcircles_step_{fuzz,harness}.a                           the step fuzzer's harness around a user's step
#   lib/cmake/circles/                                             circlesConfig.cmake, the exported targets and
#                                                                  circles_add_step_fuzzer (circlesStepFuzzer.cmake)
#   share/doc/circles/LICENSE, copyright                           the licence, and the same in Debian's format
# A user's project then does find_package(circles) and links circles::properties, the same name as in this tree;
# circles::circles is the program, for a test of theirs that runs `circles conform`.
# The headers go under include/circles/ so that "spec/..." and "properties/..." do not land in the prefix's own
# include/. circles::impl is installed for the linker only: the property library uses it privately, and no
# public header includes impl/. The flag sets (circles::warnings, numeric, sanitize) are linked as
# $<BUILD_INTERFACE:...> by these three libraries, so the exported targets carry no compile or link options.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(circles_install_cmakedir ${CMAKE_INSTALL_LIBDIR}/cmake/circles)
set(circles_installed_targets circles circles_properties circles_spec circles_impl circles_step_fuzz
                              circles_step_harness)
set_target_properties(circles_properties PROPERTIES EXPORT_NAME properties)
set_target_properties(circles_spec PROPERTIES EXPORT_NAME spec)
set_target_properties(circles_impl PROPERTIES EXPORT_NAME impl)
set_target_properties(circles_step_fuzz PROPERTIES EXPORT_NAME step_fuzz)
set_target_properties(circles_step_harness PROPERTIES EXPORT_NAME step_harness)

# Every file is checked before the first is copied: the install of a build that made only some of the targets
# (`cmake --build DIR --target circles_properties`) stops with this message instead of leaving half a prefix.
set(circles_built_files "")
foreach(target IN LISTS circles_installed_targets)
  list(APPEND circles_built_files "$<TARGET_FILE:${target}>")
endforeach()
install(CODE "set(circles_built_files \"${circles_built_files}\")")
install(CODE [[
  foreach(file IN LISTS circles_built_files)
    if(NOT EXISTS "${file}")
      message(FATAL_ERROR "circles: nothing installed: ${file} is not built. Build every target first "
                          "(cmake --build DIR, with no --target), then install.")
    endif()
  endforeach()
]])
# A build for this machine's instruction set (cmake/arch.cmake: auto found x86-64-v3 here) runs only on CPUs of
# that level; elsewhere its first AVX2 instruction stops it with SIGILL. Said where it is installed.
if(CIRCLES_ARCH STREQUAL "auto" AND CIRCLES_ARCH_LEVEL)
  install(CODE "message(WARNING \"circles: this build is for ${CIRCLES_ARCH_LEVEL} CPUs (CIRCLES_ARCH=auto chose the level \"
                                \"of the machine that built it): the program and libraries installed stop with \"
                                \"SIGILL on an older CPU. For an install that runs on any x86-64, configure with \"
                                \"-DCIRCLES_ARCH=portable (docs/properties.md).\")")
endif()

install(TARGETS ${circles_installed_targets} EXPORT circlesTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
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

# The licence, as it is and as Debian's machine-readable copyright file (the text after its title, each line
# indented by one space and an empty one written " ."), which is where a Debian package declares its licence.
file(READ ${PROJECT_SOURCE_DIR}/LICENSE circles_license)
string(REGEX MATCH "Copyright \\(c\\) ([^\n]*)" circles_copyright_line "${circles_license}")
set(circles_copyright_holder "${CMAKE_MATCH_1}")  # "2026 The circles authors"
string(REGEX REPLACE "^MIT License\n\nCopyright [^\n]*\n\n" "" circles_license "${circles_license}")
string(REGEX REPLACE "\n$" "" circles_license "${circles_license}")
string(REPLACE "\n" ";" circles_license_lines "${circles_license}")
set(circles_copyright "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n"
                      "Upstream-Name: circles\n\nFiles: *\nCopyright: ${circles_copyright_holder}\nLicense: MIT\n\nLicense: MIT\n")
foreach(line IN LISTS circles_license_lines)
  if(line STREQUAL "")
    list(APPEND circles_copyright " .\n")
  else()
    list(APPEND circles_copyright " ${line}\n")
  endif()
endforeach()
string(JOIN "" circles_copyright ${circles_copyright})
file(WRITE ${PROJECT_BINARY_DIR}/copyright "${circles_copyright}")
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_BINARY_DIR}/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})
