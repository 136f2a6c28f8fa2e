#!/bin/sh
# End-to-end checks of `circles conform`: the example candidates in Python and JavaScript, the gallery of wrong
# implementations, profiles, the corpus and pictures (tests/CMakeLists.txt runs one case per test):
#   conform_end_to_end.sh PATH/TO/circles SOURCE_DIR CASE [ARGS...]
# Each case exits 0 when the program behaves as docs/conform.md says, and names what differs otherwise. The
# gallery's cases take the path of tests/gallery_candidate.cpp's program, and an entry's name, as ARGS.
set -eu
circles=$1
source_dir=$2
case_name=$3
shift 3
. "$(dirname "$0")/end_to_end_lib.sh"

# run_conform WANT ARGS...: runs `circles conform ARGS`, stdout to $dir/out, stderr to $dir/err; it must exit
# with WANT.
run_conform() {
  want=$1
  shift
  set +e
  "$circles" conform "$@" >"$dir/out" 2>"$dir/err"
  got=$?
  set -e
  [ "$got" -eq "$want" ] || fail "conform $* exited $got, expected $want: $(cat "$dir/out" "$dir/err")"
}

naive="python3 $source_dir/examples/python/step_naive.py"

case $case_name in
refuses_the_naive_python_example_with_exit_1)
  run_conform 1 --cases 500 --seed 1 --exec "$naive"
  ;;
refuses_the_float32_python_example_with_exit_1_on_every_seed)
  # Positions stored in float32, written by Python's json (Infinity and NaN where float32 overflows): a wrong
  # value, so exit 1 with a counterexample on every seed, never exit 2 for a malformed line or a mismatched id.
  for seed in 1 2 3 4 5 6; do
    run_conform 1 --seed "$seed" --exec "python3 $source_dir/examples/python/step_float32.py"
  done
  ;;
refuses_the_naive_node_example_with_exit_1)
  run_conform 1 --seed 3 --exec "node $source_dir/examples/node/step_naive.js"
  ;;
exits_2_for_a_program_that_hangs)
  run_conform 2 --cases 5 --timeout 0.2 --exec 'sleep 30'
  ;;
rejects_a_gallery_entry_with_exit_1)
  # ARGS: GALLERY_CANDIDATE ENTRY [OPTIONS...]. Default options (a random seed, printed in the report) but OPTIONS.
  gallery=$1
  entry=$2
  shift 2
  run_conform 1 --exec "$gallery $entry" "$@"
  ;;
rejects_a_wrong_number_reader_with_exit_1)
  # ARGS: KIND. tests/wrong_reader_candidate.py KIND, the exact step behind a reader that reads some spellings of
  # docs/protocol.md wrong: default options (a random seed, printed), and the counterexample is the wire family's,
  # whose requests alone hold an E or a number that underflows. A reader that cuts digits to 17 may be caught
  # earlier: our shortest form of an integer above 10^17 (110680464442257309696.0) has more than 17 digits too.
  run_conform 1 --exec "python3 $source_dir/tests/wrong_reader_candidate.py $1"
  [ "$1" = truncate-17 ] || grep -q "(family wire)" "$dir/out" || fail "not caught by the wire family: $(cat "$dir/out")"
  ;;
gallery_candidate_exits_2_listing_the_entries_for_an_unknown_name)
  # ARGS: GALLERY_CANDIDATE.
  expect_exit 2 sh -c '"$1" no-such-mistake </dev/null >"$2" 2>&1' sh "$1" "$dir/out"
  grep -qx 'gallery_candidate: no gallery entry is called "no-such-mistake"; the entries are: none, strict-intersect, .*, flush-subnormals; optimized, contact-slots, .*, kept-pairs' \
    "$dir/out" || fail "wrong message: $(cat "$dir/out")"
  ;;
literal_profile_accepts_the_exact_python_example)
  run_conform 0 --profile literal --cases 300 --seed 1 --exec "python3 $source_dir/examples/python/step.py"
  grep -q "conforms: 300 cases" "$dir/out" || fail "no verdict: $(cat "$dir/out")"
  grep -q "literal profile" "$dir/out" || fail "the profile is not named: $(cat "$dir/out")"
  ;;
sends_several_requests_before_reading_an_answer)
  # `circles serve` behind a shell that holds the first request back until it has read the second: conform,
  # asking one request at a time, would wait past --timeout for the first answer and exit 2.
  run_conform 0 --cases 170 --seed 1 --timeout 2 \
    --exec "{ read -r a; read -r b; printf '%s\n%s\n' \"\$a\" \"\$b\"; exec cat; } | '$circles' serve --engine double"
  grep -q "conforms: 170 cases" "$dir/out" || fail "no verdict: $(cat "$dir/out")"
  ;;
exits_2_naming_an_unknown_profile)
  run_conform 2 --profile sideways
  [ "$(cat "$dir/err")" = 'circles conform: --profile: "sideways" is not resolved or literal' ] ||
    fail "unexpected message: $(cat "$dir/err")"
  ;;
exits_2_when_too_few_cases_reach_every_family)
  run_conform 2 --cases 5 --seed 1
  [ "$(cat "$dir/err")" = "circles conform: no case of the family tie-p was checked: each round of 26 cases \
draws every family of the resolved profile once, and this run checked 5; raise --cases to at least 26 (seed 1)" ] ||
    fail "unexpected message: $(cat "$dir/err")"
  ;;
saves_a_counterexample_and_replays_it_first)
  run_conform 1 --seed 3 --save "$dir/corpus" --exec "$naive"
  [ "$(ls "$dir/corpus"/*.json | wc -l)" -eq 1 ] || fail "not one counterexample saved: $(ls "$dir/corpus")"
  [ "$(ls "$dir/corpus"/*.svg | wc -l)" -eq 1 ] || fail "no picture beside it: $(ls "$dir/corpus")"
  saved=$(ls "$dir/corpus"/*.json)
  grep -q "^saved: $saved\$" "$dir/out" || fail "the report does not name $saved: $(cat "$dir/out")"
  run_conform 1 --seed 4 --cases 0 --save "$dir/corpus" --exec "$naive"
  grep -q "^counterexample: stored in $saved, replayed first" "$dir/out" || fail "not replayed: $(cat "$dir/out")"
  run_conform 0 --seed 4 --budget 20 --save "$dir/corpus" --exec "python3 $source_dir/examples/python/step.py"
  grep -q "corpus: 1 stored counterexample replayed from $dir/corpus" "$dir/out" || fail "$(cat "$dir/out")"
  ;;
draws_the_picture_where_svg_says)
  run_conform 1 --seed 3 --svg "$dir/picture.svg" --exec "$naive"
  grep -q "^picture: $dir/picture.svg\$" "$dir/out" || fail "the report does not name the picture: $(cat "$dir/out")"
  head -c 5 "$dir/picture.svg" | grep -q '<?xml' || fail "not an SVG document"
  grep -q '<svg ' "$dir/picture.svg" || fail "not an SVG document"
  run_conform 2 --seed 3 --svg "$dir/no/such/picture.svg" --exec "$naive"
  [ "$(cat "$dir/err")" = "circles conform: --svg: cannot write $dir/no/such/picture.svg: the directory $dir/no/such \
does not exist" ] || fail "unexpected message: $(cat "$dir/err")"
  ;;
draws_no_picture_unless_asked)
  # Without --svg or --save a failing run draws nothing, in the temporary directory or anywhere: CI loops stay clean.
  mkdir "$dir/tmp"
  export TMPDIR="$dir/tmp"
  run_conform 1 --seed 3 --exec "$naive"
  ! grep -q "^picture:" "$dir/out" || fail "a picture without --svg or --save: $(cat "$dir/out")"
  [ -z "$(ls -A "$dir/tmp")" ] || fail "files left in the temporary directory: $(ls -A "$dir/tmp")"
  ;;
writes_reports_for_ci_for_every_verdict)
  # --report and --junit for each verdict, read back by Python's json and xml.etree (expat); a report that
  # cannot be written is exit 2 and leaves nothing behind.
  check_reports() {
    python3 - "$dir/r.json" "$dir/r.xml" "$1" <<'PY' || fail "reports for verdict $1: $(cat "$dir/r.json" "$dir/r.xml")"
import json, sys, xml.etree.ElementTree as ET
report, junit, verdict = json.load(open(sys.argv[1])), ET.parse(sys.argv[2]).getroot(), sys.argv[3]
assert report["verdict"] == verdict, report["verdict"]
assert junit.tag == "testsuites" and len(junit.findall("testsuite/testcase")) == len(report["families"]) == 26
failures = junit.findall("testsuite/testcase/failure")
assert len(failures) == (verdict == "does not conform"), failures
assert (report["counterexample"] is None) == (verdict != "does not conform")
assert (report["error"] is None) == (verdict != "cannot check")
PY
  }
  run_conform 0 --engine double --cases 170 --seed 2 --report "$dir/r.json" --junit "$dir/r.xml"
  check_reports conforms
  run_conform 1 --seed 3 --exec "$naive" --report "$dir/r.json" --junit "$dir/r.xml"
  check_reports "does not conform"
  run_conform 2 --cases 5 --timeout 0.2 --exec 'sleep 30' --report "$dir/r.json" --junit "$dir/r.xml"
  check_reports "cannot check"
  run_conform 2 --engine double --cases 26 --report "$dir/no/such/r.json"
  grep -q "^circles conform: --report $dir/no/such/r.json: cannot create " "$dir/err" || fail "$(cat "$dir/err")"
  [ ! -e "$dir/no" ] || fail "something was written"
  ;;
judges_nan_infinity_and_signed_zeros_in_every_field_and_step)
  # tests/odd_token_candidate.py writes NaN, Infinity, -Infinity or 1e400 in each field of circle 0, in every
  # answer or only at the second step of --steps 2: a counterexample, exit 1, naming the field, the expected value
  # and the one received, in the printed report and in --report; and -0.0 for 0.0 in every field is right, exit 0.
  odd="python3 $source_dir/tests/odd_token_candidate.py"
  for when in every even; do
    steps=1
    [ $when = even ] && steps=2
    for field in px py vx vy r; do
      case $field in
      px | py) decision="none: the velocity is right, the position is not the nearest double" ;;
      vx | vy) decision="the intersect test (3) (docs/math.md#3-intersect--specintersect): circle 0 touches no circle, yet its velocity changed" ;;
      r) decision="none: the position and velocity are right, but the radius changed, which no step does" ;;
      esac
      tokens="NaN Infinity -Infinity 1e400"
      [ $when = even ] && tokens=NaN
      for token in $tokens; do
        received=$token
        [ "$token" = 1e400 ] && received=Infinity
        run_conform 1 --seed 1 --cases 26 --steps $steps --exec "$odd $field $token $when" --report "$dir/r.json"
        [ "$(sed -n 3,4p "$dir/out")" = "  step $steps of $steps, circle 0, field $field: expected 0.0 (0x0p+0), got $received
  which decision: $decision" ] || fail "$field $token $when: $(cat "$dir/out")"
        python3 -c "import json, sys; d = json.load(open(sys.argv[1]))['counterexample']['difference']
assert (d['field'], d['expected'], d['received']) == (sys.argv[2], 0.0, sys.argv[3]), d" "$dir/r.json" $field $received ||
          fail "$field $token $when: the report says otherwise"
      done
      run_conform 0 --seed 1 --cases 26 --steps $steps --exec "$odd $field -0.0 $when"
    done
  done
  # A NaN counterexample stored in the corpus and replayed keeps its NaN.
  run_conform 1 --seed 1 --cases 26 --save "$dir/corpus" --exec "$odd py NaN every"
  run_conform 1 --cases 0 --save "$dir/corpus" --exec "$odd py NaN every"
  grep -q "^  step 1 of 1, circle 0, field py: expected 0.0 (0x0p+0), got NaN$" "$dir/out" || fail "$(cat "$dir/out")"
  ;;
exits_2_for_a_count_beyond_2_63_or_threads_with_a_program)
  # CLI11 reads "-1" as 2^64 - 1: as --cases it would run for ever, as --case check nothing (I + 1 wraps) and
  # conform. And --threads is an engine's: a program given with --exec runs its own.
  run_conform 2 --cases -1 --engine double
  grep -q '^circles conform: --cases: "-1" is not a whole number from 0 to 9223372036854775807$' "$dir/err" || fail "$(cat "$dir/err")"
  run_conform 2 --case 18446744073709551615 --engine double
  grep -q '^circles conform: --case: "18446744073709551615" is not a whole number from 0 to 9223372036854775807$' "$dir/err" || fail "$(cat "$dir/err")"
  run_conform 2 --threads 2 --exec "python3 $source_dir/examples/python/step.py"
  [ "$(cat "$dir/err")" = "circles conform: --threads sets the threads of an --engine; a program given with --exec runs its own" ] ||
    fail "unexpected message: $(cat "$dir/err")"
  ;;
gives_a_slow_program_the_time_its_speed_needs_and_stops_one_that_hangs)
  # tests/slow_candidate.py answers right after 10 ms a circle: its worlds of 100 or more circles (index-bits has
  # 272 to 320) take longer than the 1 s floor, and the deadlines its earlier answers predict give them that time.
  # The same program hanging after 10 answers is stopped.
  slow="python3 $source_dir/tests/slow_candidate.py $circles 0.01"
  run_conform 0 --cases 26 --seed 1 --timeout 1 --jobs 1 --exec "$slow"
  run_conform 1 --cases 26 --seed 1 --timeout 1 --jobs 1 --exec "$slow 10"
  grep -q "^  step 1 of 1: no answer: the program hung$" "$dir/out" || fail "$(cat "$dir/out" "$dir/err")"
  grep -q "gave no answer to request 11 within " "$dir/out" || fail "$(cat "$dir/out" "$dir/err")"
  ;;
cuts_a_ladder_stage_that_runs_past_the_budget)
  # tests/slow_candidate.py, correct and fast below 2048 circles, hangs on every world of 2048 or more: the ladder
  # climbs to 2048 (1024 took little), and that stage is cut a tenth of the budget after its end, the program
  # stopped (none left running), the run judged on the cases before it: exit 0, within the budget and the cut.
  cliff="python3 $source_dir/tests/slow_candidate.py $circles 0 from:2048"
  start=$(date +%s)
  run_conform 0 --seed 1 --budget 8 --exec "$cliff"
  took=$(( $(date +%s) - start ))
  [ "$took" -le 12 ] || fail "took $took s for a budget of 8: $(cat "$dir/out")"
  grep -q "big worlds up to 1,024 circles, \([89]\|10\) s of 8 (a stage at 2,048 circles cut at the budget's end)$" "$dir/out" ||
    fail "$(cat "$dir/out" "$dir/err")"
  ! pgrep -f "slow_candidate.py $circles 0 from:2048" >/dev/null || fail "a program was left running"
  ;;
reports_a_crash_and_a_malformed_line_on_a_world_as_counterexamples_and_logs_every_line)
  # tests/faulty_candidate.cpp, right on worlds of up to 6 circles, breaks on one of 7 or more: a counterexample,
  # exit 1, shrunk to a world of 7 circles on which it breaks the same way, with its replay line, which
  # reproduces it; breaking on the first world asked, before any answer, it cannot be checked, exit 2. --log
  # holds every request sent and answer read, each line marked with its copy of the program.
  faulty=$1
  for mode in abort garble; do
    case $mode in
    abort) kind="crashed or exited" ;;
    garble) kind="wrote a malformed answer" ;;
    esac
    run_conform 1 --seed 2 --budget 5 --exec "$faulty $mode 7" --log "$dir/log" --save "$dir/corpus-$mode"
    grep -q "^  step 1 of 1: no answer: the program $kind$" "$dir/out" || fail "$mode: $(cat "$dir/out")"
    # Stored with its kind of fault, and asked first by the next run with the same --save.
    grep -q "^  \"fault\": \"$kind\",$" "$dir"/corpus-$mode/counterexample-*.json ||
      fail "$mode: not stored with its fault: $(cat "$dir"/corpus-$mode/* "$dir/out")"
    cp "$dir/out" "$dir/found"
    run_conform 1 --seed 2 --budget 5 --exec "$faulty $mode 7" --save "$dir/corpus-$mode"
    grep -q "^counterexample: stored in $dir/corpus-$mode/counterexample-[0-9a-f]*.json, replayed first (found as case [0-9]* of seed 2, family [a-z-]*)$" "$dir/out" &&
      grep -q "^  step 1 of 1: no answer: the program $kind$" "$dir/out" || fail "$mode: not replayed: $(cat "$dir/out")"
    cp "$dir/found" "$dir/out"
    [ "$(grep -c '^    #' "$dir/out")" -eq 14 ] || fail "$mode: not shrunk to 7 circles: $(cat "$dir/out")"
    grep -q "^counterexample: case [0-9]* of seed 2 (family [a-z-]*), shrunk from" "$dir/out" || fail "$(cat "$dir/out")"
    replay=$(sed -n 's/^replay: //p' "$dir/out")
    cp "$dir/out" "$dir/first"
    (PATH="$(dirname "$circles"):$PATH" && export PATH && eval "$replay" >"$dir/out" 2>"$dir/err") &&
      fail "$mode: the replay line conforms" || true
    [ "$(grep '^    #\|^  step' "$dir/out")" = "$(grep '^    #\|^  step' "$dir/first")" ] ||
      fail "$mode: the replay differs: $(cat "$dir/out")"
    grep -q '^1> {"id":1,"circles":' "$dir/log" && grep -q '^[0-9]< {"id":' "$dir/log" ||
      fail "$mode: the log: $(head -c 600 "$dir/log")"
  done
  run_conform 2 --seed 2 --budget 5 --exec "$faulty abort 0"
  grep -q "^circles conform: the program \`$faulty abort 0\` exited with status 134 before answering request 1 " "$dir/err" ||
    fail "$(cat "$dir/err")"
  ;;
keeps_going_and_gates_on_an_expectation_file)
  # The naive example's two mistakes (hypot distance, p + v*(1/60)) reach every family but tangent-after-step,
  # signed-zeros and long-rows in seed 1's 1000 cases: on their worlds there its answers are the nearest doubles.
  run_conform 1 --keep-going --cases 1000 --seed 1 --exec "$naive" --write-expect "$dir/naive.expect" --svg "$dir/first.svg"
  grep -q "^picture: $dir/first.svg$" "$dir/out" && [ -s "$dir/first.svg" ] || fail "no picture: $(cat "$dir/out")"
  for family in lattice random-doubles tangency ulp-nudge tie-px tie-p tie-p-vx tie-p-v duplicates incomparable \
      mutual-contacts square-overflow subnormals cancellation zero-radius wire sizes crowds cell-crowds radius-spread \
      index-bits order-borders big-chains; do
    grep -Eq "^  $family +[0-9]+ +failed at its [0-9]+(st|nd|rd|th) case; none asked after$" "$dir/out" ||
      fail "$family did not fail: $(cat "$dir/out")"
    grep -q "^$family fail TODO: why it fails$" "$dir/naive.expect" || fail "$family is not in the file: $(cat "$dir/naive.expect")"
  done
  for family in tangent-after-step signed-zeros long-rows; do
    grep -q "^  $family  *[0-9][0-9]*  *passed$" "$dir/out" || fail "$family did not pass: $(cat "$dir/out")"
  done
  grep -q "^  families: 23 failed, 3 passed$" "$dir/out" || fail "no summary: $(cat "$dir/out")"
  [ "$(grep -c "replay: circles conform --exec 'python3 $source_dir/examples/python/step_naive.py' --seed 1 --case" "$dir/out")" -eq 23 ] ||
    fail "not a replay line per failure: $(cat "$dir/out")"
  # With the file it wrote, the naive example passes the gate.
  run_conform 0 --cases 1000 --seed 1 --exec "$naive" --expect "$dir/naive.expect"
  grep -q "^  families: 23 expected failures, 3 passed$" "$dir/out" || fail "no expected failures: $(cat "$dir/out")"
  # A run that passes only through its expectation file says so, and never that the program conforms.
  grep -q "^circles conform: the program \`$naive\` passes with 23 expected failures, 3 families pass: [0-9]* cases, " "$dir/out" ||
    fail "the first line does not say what passed: $(head -n 1 "$dir/out")"
  ! grep -q "conforms" "$dir/out" || fail "a run with expected failures says it conforms: $(head -n 1 "$dir/out")"
  # The exact example, with the same file: an unexpected pass for each line.
  run_conform 1 --cases 1000 --seed 1 --exec "python3 $source_dir/examples/python/step.py" --expect "$dir/naive.expect"
  [ "$(grep -c ": unexpected pass (.* cases checked): delete its line, $dir/naive.expect:" "$dir/out")" -eq 23 ] ||
    fail "not 22 unexpected passes: $(cat "$dir/out")"
  # A wrong implementation whose failures the file does not list (float32 fails signed-zeros too).
  run_conform 1 --cases 1000 --seed 1 --exec "python3 $source_dir/examples/python/step_float32.py" \
    --expect "$dir/naive.expect"
  grep -q "^  signed-zeros  *[0-9][0-9]*  *failed at its " "$dir/out" || fail "signed-zeros did not fail: $(cat "$dir/out")"
  ;;
exits_2_for_unknown_families_and_bad_expectation_files)
  run_conform 2 --families lattice,sideways --exec true
  grep -q "^circles conform: --families: unknown family \"sideways\"; the families of the resolved profile are lattice, random-doubles, " "$dir/err" ||
    fail "unexpected message: $(cat "$dir/err")"
  run_conform 2 --skip-families "" --exec true
  grep -q "^circles conform: --skip-families: unknown family \"\"" "$dir/err" || fail "unexpected message: $(cat "$dir/err")"
  printf '# known failures\n\nfail rounding\n' >"$dir/bad.expect"
  run_conform 2 --expect "$dir/bad.expect" --exec true
  [ "$(cat "$dir/err")" = "circles conform: --expect: $dir/bad.expect:3: the entry names no family: expected FAMILY fail REASON" ] ||
    fail "unexpected message: $(cat "$dir/err")"
  # A run that cannot write its expectation file leaves nothing behind and exits 2.
  run_conform 2 --cases 100 --seed 1 --exec "$naive" --write-expect "$dir/missing/naive.expect"
  [ ! -e "$dir/missing" ] || fail "wrote $dir/missing"
  ;;
replay_lines_reproduce_their_counterexample_pasted_into_sh)
  # The replay line is a whole command: pasted into sh, with `circles` on PATH, it prints the same report. The
  # candidate's path holds a space and a quote, so the line must quote it for sh; the options that change the
  # case (--steps, --profile, --level, --skip-families) must be on it.
  mkdir "$dir/it's here"
  cp "$source_dir/examples/python/step_naive.py" "$dir/it's here/"
  quoted="python3 \"$dir/it's here/step_naive.py\""
  PATH="$(cd "$(dirname "$circles")" && pwd):$PATH"
  replayed() { # replayed LINE: runs the replay LINE in sh, stdout to $dir/again; it must exit 1.
    set +e
    sh -c "$1" >"$dir/again" 2>&1
    got=$?
    set -e
    [ "$got" -eq 1 ] || fail "the replay line exited $got: $1: $(cat "$dir/again")"
  }
  run_conform 1 --seed 3 --steps 2 --profile literal --level ulps:2 --skip-families lattice --exec "$quoted" \
    --report "$dir/r.json" --junit "$dir/r.xml"
  line=$(sed -n 's/^replay: //p' "$dir/out")
  case $line in
  "circles conform --exec 'python3 \"$dir/it'\\''s here/step_naive.py\"' --seed 3 --case "*" --level ulps:2 --steps 2 --profile literal --skip-families lattice") ;;
  *) fail "the replay line is not the whole command: $line" ;;
  esac
  replayed "$line"
  cmp "$dir/out" "$dir/again" || fail "the replay line printed another report: $(cat "$dir/again")"
  # The reports for CI carry the same line.
  python3 - "$dir/r.json" "$dir/r.xml" "$line" <<'PY' || fail "the reports' replay lines differ from the printed one"
import json, sys, xml.etree.ElementTree as ET
report, junit, line = json.load(open(sys.argv[1])), ET.parse(sys.argv[2]).getroot(), sys.argv[3]
assert report["counterexample"]["replay"] == line, report["counterexample"]["replay"]
assert [c["replay"] for c in report["counterexamples"]] == [line], report["counterexamples"]
assert ("replay: " + line + "\n") in junit.find("testsuite/testcase/failure").text
PY
  # Each --keep-going row's line replays its own family's counterexample; the row shows its world, and the
  # reports carry each row's counterexample, with which decision differs.
  run_conform 1 --seed 3 --keep-going --families ulp-nudge,tie-p-vx,cancellation --exec "$quoted" \
    --report "$dir/r.json" --junit "$dir/r.xml"
  [ "$(grep -c '^ *the world asked (w_0):$' "$dir/out")" -eq 3 ] || fail "not a world per row: $(cat "$dir/out")"
  python3 - "$dir/r.json" "$dir/r.xml" <<'PY' || fail "the reports do not hold each row's counterexample"
import json, sys, xml.etree.ElementTree as ET
report, junit = json.load(open(sys.argv[1])), ET.parse(sys.argv[2]).getroot()
assert [c["family"] for c in report["counterexamples"]] == ["ulp-nudge", "tie-p-vx", "cancellation"], report["counterexamples"]
failures = junit.findall("testsuite/testcase/failure")
assert len(failures) == 3 and all("which decision: " in f.text for f in failures), [f.text for f in failures]
PY
  [ "$(grep -c '^ *replay: circles conform ' "$dir/out")" -eq 3 ] || fail "not 3 replay lines: $(cat "$dir/out")"
  grep '^ *step 1 of 1, ' "$dir/out" | sed 's/^ *//; s/; which decision: .*//' >"$dir/rows"
  sed -n 's/^ *replay: //p' "$dir/out" | while IFS= read -r line; do
    replayed "$line"
    sed -n 3p "$dir/again" | sed 's/^ *//' >>"$dir/replayed"
  done
  cmp "$dir/rows" "$dir/replayed" || fail "the rows' replay lines found other counterexamples: $(cat "$dir/replayed")"
  # A counterexample replayed from the corpus: its line replays the corpus alone.
  run_conform 1 --seed 3 --save "$dir/corpus" --exec "$quoted"
  run_conform 1 --seed 4 --save "$dir/corpus" --exec "$quoted"
  line=$(sed -n 's/^replay: //p' "$dir/out")
  [ "$line" = "circles conform --exec 'python3 \"$dir/it'\\''s here/step_naive.py\"' --save $dir/corpus --cases 0 --level exact" ] ||
    fail "the corpus's replay line: $line"
  replayed "$line"
  cmp "$dir/out" "$dir/again" || fail "the corpus's replay line printed another report: $(cat "$dir/again")"
  ;;
replays_the_committed_corpus_with_each_engine)
  # A copy, so that a failure writes its picture there rather than into the source tree.
  cp -r "$source_dir/tests/corpus/conform" "$dir/corpus"
  for engine in double exact; do
    run_conform 0 --engine "$engine" --cases 0 --save "$dir/corpus"
    grep -Eq "corpus: [0-9]+ stored counterexamples replayed from" "$dir/out" || fail "$engine: $(cat "$dir/out")"
  done
  ;;
*)
  fail "no such case: $case_name"
  ;;
esac
