# circles::sanitize: the compiler's run-time checkers, chosen with -DCIRCLES_SANITIZE=LIST (e.g.
# address,undefined), for the hardening build of docs/hardening.md. Empty (the default) adds nothing.
#
# It reaches every target of ours through circles::warnings, the one interface library that all of them link
# (spec, impl and its variants, cli, properties, tests, benchmarks), so no global flag is edited and no
# subdirectory has to name it. Libraries from Debian (GoogleTest, RapidCheck, GMP, libgomp) are not
# instrumented: AddressSanitizer still checks every access our code makes, and intercepts malloc everywhere.
#   -fno-sanitize-recover=all  an undefined-behaviour finding aborts, so the test that triggers it fails
#                              (UBSan's default is to print and continue, and the test would pass)
#   -fno-omit-frame-pointer    whole stack traces in reports at no cost to the checks
set(CIRCLES_SANITIZE "" CACHE STRING "Sanitizers for every circles target, e.g. address,undefined; empty: none")

add_library(circles_sanitize INTERFACE)
add_library(circles::sanitize ALIAS circles_sanitize)
if(CIRCLES_SANITIZE)
  target_compile_options(circles_sanitize INTERFACE -fsanitize=${CIRCLES_SANITIZE} -fno-sanitize-recover=all
                                                    -fno-omit-frame-pointer)
  target_link_options(circles_sanitize INTERFACE -fsanitize=${CIRCLES_SANITIZE})
  # GCC's manual (-fsanitize=address): "sanitizers tend to increase the rate of false positive warnings,
  # most notably those around -Wmaybe-uninitialized". GCC 12 gives them inside libstdc++'s <regex>
  # (tests/docs_test.cpp), so that one warning is off here; the ordinary build still checks it.
  target_compile_options(circles_sanitize INTERFACE $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
  target_link_libraries(circles_warnings INTERFACE circles::sanitize)
  # Libraries instrumented for libFuzzer report their filters' margins to its value profile (impl/detail/steer.hpp).
  if(CIRCLES_SANITIZE MATCHES "fuzzer")
    target_compile_definitions(circles_sanitize INTERFACE CIRCLES_FUZZ_STEERING)
  endif()
  message(STATUS "circles: sanitizers ${CIRCLES_SANITIZE} on every circles target")
endif()
