#!/bin/sh
# End-to-end checks of `circles vectors` and `circles check-trace` (tests/CMakeLists.txt runs one case per test):
#   vectors_end_to_end.sh PATH/TO/circles SOURCE_DIR CASE
# Each case exits 0 when the program behaves as docs/vectors.md says, and names what differs otherwise.
set -eu
circles=$1
source_dir=$2
case_name=$3
. "$(dirname "$0")/end_to_end_lib.sh"

case $case_name in
python_example_checks_the_vectors_with_fractions)
  "$circles" vectors --out "$dir/v" --scenes "$source_dir/scenes" >"$dir/summary"
  [ "$(ls "$dir/v")" = vectors.jsonl ] || fail "the output directory holds $(ls "$dir/v")"
  python3 "$source_dir/examples/python/check_vectors.py" "$dir/v/vectors.jsonl"
  ;;
python_example_refuses_vectors_changed_in_one_place)
  # Line 5's next hash, its first exact fraction, then its first hex float: each change is caught.
  "$circles" vectors --out "$dir" --scenes "$source_dir/scenes" --cases 20 >/dev/null
  sed '5s/"next_hash":"\(.\)/"next_hash":"X\1/' "$dir/vectors.jsonl" >"$dir/hash.jsonl"
  sed '5s/"next_exact":\[\["/"next_exact":[["1/' "$dir/vectors.jsonl" >"$dir/exact.jsonl"
  sed '5s/"next_hex":\[\["/"next_hex":[["-/' "$dir/vectors.jsonl" >"$dir/hex.jsonl"
  for changed in hash exact hex; do
    cmp -s "$dir/vectors.jsonl" "$dir/$changed.jsonl" && fail "sed changed nothing in $changed.jsonl"
    expect_exit 1 python3 "$source_dir/examples/python/check_vectors.py" "$dir/$changed.jsonl" 2>"$dir/err"
    grep -q "^$dir/$changed.jsonl:5: case 4 " "$dir/err" || fail "no line 5 in: $(cat "$dir/err")"
  done
  ;;
check_trace_agrees_with_traces_of_circles_run)
  "$circles" run --steps 300 --engine double --trace "$dir/double.jsonl" >/dev/null
  "$circles" check-trace "$dir/double.jsonl" >"$dir/out"
  grep -q ": agrees with the correctly rounded step at each of its 300 steps (steps 0 to 300, 10 circles)" "$dir/out" ||
    fail "$(cat "$dir/out")"
  "$circles" run --steps 300 --engine exact --trace "$dir/exact.jsonl" >/dev/null
  "$circles" check-trace --engine exact "$dir/exact.jsonl" >/dev/null
  ;;
check_trace_exits_1_naming_a_field_changed_by_one_ulp)
  # Circle 3 of the default scene rests at px = 280 in w_20 (line 21); the next double up is 280 + 2^-44.
  "$circles" run --steps 50 --trace "$dir/t.jsonl" >/dev/null
  sed '21s/\],\[280\.0,/],[280.00000000000006,/' "$dir/t.jsonl" >"$dir/tampered.jsonl"
  [ "$(cmp "$dir/t.jsonl" "$dir/tampered.jsonl" | sed 's/.*line //')" = 21 ] || fail "sed did not change line 21"
  expect_exit 1 sh -c '"$1" check-trace "$2" >"$3"' sh "$circles" "$dir/tampered.jsonl" "$dir/out"
  head -n 1 "$dir/out" | grep -qxF "circles check-trace: $dir/tampered.jsonl:21: step 20 differs from the correctly rounded step of line 20: circle 3, field px: expected 280.0 (0x1.18p+8), actual 280.00000000000006 (0x1.1800000000001p+8)" ||
    fail "$(cat "$dir/out")"
  ;;
check_trace_exits_2_for_a_missing_file_and_a_malformed_line)
  expect_exit 2 sh -c '"$1" check-trace "$2" 2>"$3"' sh "$circles" "$dir/none.jsonl" "$dir/err"
  [ "$(cat "$dir/err")" = "circles check-trace: $dir/none.jsonl: cannot open the file: No such file or directory" ] ||
    fail "$(cat "$dir/err")"
  # Column 25 is the "}": 24 bytes of {"step": 1, "circles": [ before it.
  printf '{"step": 0, "circles": []}\n{"step": 1, "circles": [}\n' >"$dir/bad.jsonl"
  expect_exit 2 sh -c '"$1" check-trace "$2" 2>"$3"' sh "$circles" "$dir/bad.jsonl" "$dir/err"
  grep -q "^circles check-trace: $dir/bad.jsonl:2: malformed JSON at column 25: " "$dir/err" || fail "$(cat "$dir/err")"
  expect_exit 2 sh -c '"$1" check-trace --engine oracle "$2" 2>/dev/null' sh "$circles" "$dir/bad.jsonl"
  expect_exit 2 sh -c '"$1" vectors 2>/dev/null' sh "$circles"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
