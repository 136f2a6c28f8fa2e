#!/bin/sh
# The property library from outside the tree (docs/properties.md, Linking it): installs the build into a scratch
# prefix, checks that the exported targets carry none of our build flags and that the program is installed,
# and builds and runs the worked example in tests/consumer/, a project that finds the package with
# find_package(circles):
#   package_end_to_end.sh BUILD_DIR SOURCE_DIR CXX_COMPILER [CXX_FLAGS]
# CXX_FLAGS are the consumer's own (the sanitizer build passes -fsanitize=..., which its libraries need to link).
# tests/install_end_to_end.sh does the same from the commands docs/properties.md shows, and from the Debian package.
set -eu
build=$1
source_dir=$2
cxx=$3
cxx_flags=${4-}
. "$(dirname "$0")/end_to_end_lib.sh"
. "$(dirname "$0")/consumer_lib.sh"

step install cmake --install "$build" --prefix "$dir/prefix"
targets=$(find "$dir/prefix" -path '*/cmake/circles/circlesTargets.cmake')
[ -n "$targets" ] || fail "no circlesTargets.cmake under $dir/prefix: $(cat "$dir/install.log")"
# Our flag sets (-Werror, -ffp-contract=off, -fsanitize) are for building our code, not the user's.
if grep -nE 'INTERFACE_(COMPILE|LINK)_OPTIONS|-Werror|-ffp-contract|-fsanitize|circles::(warnings|numeric|sanitize)' "$targets"; then
  fail "the exported targets carry build flags: $targets"
fi
check_program "$dir/prefix"
check_consumer "$dir/prefix" "$cxx" "$cxx_flags"
