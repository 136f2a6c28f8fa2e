#!/bin/sh
# The property library from outside the tree (docs/properties.md, Linking it): installs the build into a scratch
# prefix, checks that the exported targets carry none of our build flags, and builds and runs the worked example
# in tests/consumer/, a project that finds the package with find_package(circles):
#   package_end_to_end.sh BUILD_DIR SOURCE_DIR CXX_COMPILER [CXX_FLAGS]
# CXX_FLAGS are the consumer's own (the sanitizer build passes -fsanitize=..., which its libraries need to link).
set -eu
build=$1
source_dir=$2
cxx=$3
cxx_flags=${4-}
. "$(dirname "$0")/end_to_end_lib.sh"

# step NAME COMMAND...: runs COMMAND with its output in $dir/NAME.log, which a failure shows.
step() {
  name=$1
  shift
  "$@" >"$dir/$name.log" 2>&1 || fail "$name: $* exited $?: $(cat "$dir/$name.log")"
}

step install cmake --install "$build" --prefix "$dir/prefix"
targets=$(find "$dir/prefix" -path '*/cmake/circles/circlesTargets.cmake')
[ -n "$targets" ] || fail "no circlesTargets.cmake under $dir/prefix: $(cat "$dir/install.log")"
# Our flag sets (-Werror, -ffp-contract=off, -fsanitize) are for building our code, not the user's.
if grep -nE 'INTERFACE_(COMPILE|LINK)_OPTIONS|-Werror|-ffp-contract|-fsanitize|circles::(warnings|numeric|sanitize)' "$targets"; then
  fail "the exported targets carry build flags: $targets"
fi

# The user's package registry and system prefixes stay out: the package must be the one just installed.
step configure cmake -S "$source_dir/tests/consumer" -B "$dir/consumer" -DCMAKE_PREFIX_PATH="$dir/prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxx_flags"
grep -qx "circles_DIR:PATH=$dir/prefix/.*/cmake/circles" "$dir/consumer/CMakeCache.txt" ||
  fail "find_package(circles) did not find the installed package: $(grep circles_DIR "$dir/consumer/CMakeCache.txt")"
step build cmake --build "$dir/consumer"

# The example's assertions: the exact step conforms in both profiles, the naive one is caught.
step run "$dir/consumer/my_step_test"
for test in exact_step.steps_as_the_spec_says exact_step.steps_as_the_literal_spec_says_three_steps_in_a_row \
  naive_step.is_caught_with_a_counterexample properties_example.is_the_code_docs_properties_md_shows; do
  grep -q "^\[       OK \] $test " "$dir/run.log" || fail "$test did not pass: $(cat "$dir/run.log")"
done
