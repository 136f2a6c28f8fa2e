# Run at build time (cli/CMakeLists.txt): writes OUT, the header that defines CIRCLES_VERSION, "VERSION" and, in a
# git checkout SOURCE, " (commit ABBREV)" with "-dirty" for uncommitted changes. OUT is rewritten only when its
# text changes, so that a build with nothing new compiles nothing.
execute_process(COMMAND git -C "${SOURCE}" describe --always --dirty --abbrev=12 --exclude=*
                OUTPUT_VARIABLE commit RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
set(version "${VERSION}")
if(NOT failed AND commit)
  string(APPEND version " (commit ${commit})")
endif()
set(text "// Written by cmake/version.cmake at build time.\n#pragma once\n#define CIRCLES_VERSION \"${version}\"\n")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
