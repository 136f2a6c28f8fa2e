# Read by cpack before it packages (CPACK_PROJECT_CONFIG_FILE, cmake/package.cmake): a build that CIRCLES_ARCH=auto
# made for the building machine's own instruction set is not packaged, since a package runs on other machines.
if(CPACK_CIRCLES_ARCH STREQUAL "auto" AND CPACK_CIRCLES_ARCH_LEVEL)
  message(FATAL_ERROR "circles: this build is for ${CPACK_CIRCLES_ARCH_LEVEL} CPUs only (CIRCLES_ARCH=auto chose the "
                      "level of the machine that built it), and would stop with SIGILL on an older one. Configure "
                      "the build to package with -DCIRCLES_ARCH=portable (or name a level with -DCIRCLES_ARCH=LEVEL).")
endif()
