# Per-target flag sets. Nothing here edits the global flags: a target opts in by linking these.

# circles::warnings: -Wall -Wextra everywhere we compile our own code; -Werror when CIRCLES_WERROR is on (CI).
add_library(circles_warnings INTERFACE)
target_compile_options(circles_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
                                                  $<$<BOOL:${CIRCLES_WERROR}>:-Werror>)
# GCC 12 reports "__builtin_memcpy accessing 9223372036854775810 or more bytes ... may overlap" [-Wrestrict]
# inside libstdc++'s operator+(const char*, std::string&&), on ordinary code such as "#" + std::to_string(j),
# wherever its optimizer inlines that operator: a known false positive of that release (GCC bugzilla 105329 and
# its duplicates). Our code appends to a std::string instead where it would, so that the Release build (the
# README's, CI's and a newcomer's) prints no warning, and in CI fails on the next one. In the other build types
# GCC 12 inlines elsewhere, so there it stays a warning, and -DCIRCLES_WERROR=ON builds in every build type.
target_compile_options(circles_warnings INTERFACE
  $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>,$<NOT:$<CONFIG:Release>>>:-Wno-error=restrict>)
add_library(circles::warnings ALIAS circles_warnings)

# circles::numeric: for every target whose floating-point results matter.
#   -ffp-contract=off  GCC contracts a+b*c into one FMA by default (-ffp-contract=fast), which rounds once
#                      instead of twice and so changes results; we want the roundings the source says.
#   -fno-fast-math     is the default; stated so that a user's CXXFLAGS=-ffast-math cannot reach our numerics.
# -fexcess-precision and x87 are not a concern: x86-64 uses SSE2 for double.
add_library(circles_numeric INTERFACE)
target_compile_options(circles_numeric INTERFACE -ffp-contract=off -fno-fast-math)
add_library(circles::numeric ALIAS circles_numeric)
