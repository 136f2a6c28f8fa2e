# Per-target flag sets. Nothing here edits the global flags: a target opts in by linking these.

# circles::warnings: -Wall -Wextra everywhere we compile our own code; -Werror when CIRCLES_WERROR is on (CI).
add_library(circles_warnings INTERFACE)
target_compile_options(circles_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
                                                  $<$<BOOL:${CIRCLES_WERROR}>:-Werror>)
add_library(circles::warnings ALIAS circles_warnings)

# circles::numeric: for every target whose floating-point results matter.
#   -ffp-contract=off  GCC contracts a+b*c into one FMA by default (-ffp-contract=fast), which rounds once
#                      instead of twice and so changes results; we want the roundings the source says.
#   -fno-fast-math     is the default; stated so that a user's CXXFLAGS=-ffast-math cannot reach our numerics.
# -fexcess-precision and x87 are not a concern: x86-64 uses SSE2 for double.
add_library(circles_numeric INTERFACE)
target_compile_options(circles_numeric INTERFACE -ffp-contract=off -fno-fast-math)
add_library(circles::numeric ALIAS circles_numeric)
