# What tests/package_end_to_end.sh and tests/install_end_to_end.sh check of an installed prefix, read with
# `. "$(dirname "$0")/consumer_lib.sh"` after end_to_end_lib.sh, with $source_dir the repository.

# step NAME COMMAND...: runs COMMAND with its output in $dir/NAME.log, which a failure shows.
step() {
  name=$1
  shift
  "$@" >"$dir/$name.log" 2>&1 || fail "$name: $* exited $?: $(cat "$dir/$name.log")"
}

# check_program PREFIX: PREFIX/bin/circles runs and says its version; the licence is beside it.
check_program() {
  version=$("$1/bin/circles" --version) || fail "$1/bin/circles --version exited $?"
  case $version in
  "circles "[0-9]*) ;;
  *) fail "$1/bin/circles --version said: $version" ;;
  esac
  [ -f "$1/share/doc/circles/LICENSE" ] || fail "no $1/share/doc/circles/LICENSE"
  grep -qx 'License: MIT' "$1/share/doc/circles/copyright" || fail "$1/share/doc/circles/copyright names no licence"
}

# check_consumer PREFIX CXX [CXX_FLAGS]: tests/consumer/ configured against the package in PREFIX alone (the user's
# package registry left out), built (which runs the installed program through circles::circles) and run: the
# exact step conforms in both profiles, the naive one is caught.
check_consumer() {
  prefix=$1
  step configure cmake -S "$source_dir/tests/consumer" -B "$dir/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_CXX_COMPILER="$2" -DCMAKE_CXX_FLAGS="${3-}"
  grep -qx "circles_DIR:PATH=$prefix/.*/cmake/circles" "$dir/consumer/CMakeCache.txt" ||
    fail "find_package(circles) did not find the package in $prefix: $(grep circles_DIR "$dir/consumer/CMakeCache.txt")"
  step build cmake --build "$dir/consumer"
  grep -q "^circles [0-9]" "$dir/build.log" || fail "circles::circles --version did not run: $(cat "$dir/build.log")"
  step run "$dir/consumer/my_step_test"
  for test in exact_step.steps_as_the_spec_says exact_step.steps_as_the_literal_spec_says_three_steps_in_a_row \
    naive_step.is_caught_with_a_counterexample properties_example.is_the_code_docs_properties_md_shows; do
    grep -q "^\[       OK \] $test " "$dir/run.log" || fail "$test did not pass: $(cat "$dir/run.log")"
  done
}
