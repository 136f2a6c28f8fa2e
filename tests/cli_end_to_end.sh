#!/bin/sh
# End-to-end checks of the `circles` program: its exit codes, `circles serve` and `circles run`
# (tests/CMakeLists.txt runs one case per test):
#   cli_end_to_end.sh PATH/TO/circles SOURCE_DIR CASE
# Each case exits 0 when the program behaves as docs/protocol.md and docs/run.md say, and names what differs
# otherwise.
set -eu
circles=$1
source_dir=$2
case_name=$3
. "$(dirname "$0")/end_to_end_lib.sh"

# Circle 1 moves by exactly 2^1017 per step from DBL_MAX - 3 * 2^1017 (0x1.f3fffffffffffp+1023) at
# v = 60 * 2^1017 (0x1.ep+1022): it reaches DBL_MAX in w_3, and step 4 overflows (tests/step_worlds.hpp derives
# it).
overflow_scene='{"circles": [[0, 0, 0, 0, 1], [1.7555597020139802e+308, -5, 8.426686569667106e+307, 0, 1]]}'

case $case_name in
exits_2_on_a_usage_error)
  expect_exit 2 sh -c '"$1" --no-such-option 2>/dev/null' sh "$circles"
  ;;
exits_2_naming_the_circle_and_field_of_a_bad_scene)
  printf '{"circles": [[0, 0, 0, 0, 1], [0, 0, 0, 0, -2]]}' >"$dir/scene.json"
  expect_exit 2 sh -c '"$1" oracle "$2" >/dev/null 2>"$3"' sh "$circles" "$dir/scene.json" "$dir/err"
  grep -qxF "circles: $dir/scene.json: circle 1, field r: radius -2 is negative (r >= 0, the resolved profile) (not an element of C)" \
    "$dir/err" || fail "wrong message: $(cat "$dir/err")"
  ;;
serve_answers_a_trace_with_its_next_worlds_identically_with_every_engine)
  # w_0 ... w_300 of the default scene as requests (a trace line with "id" for "step"): the responses are
  # w_1 ... w_301, the same bytes from the double engine (2 threads), the exact engine (2 threads; one step
  # from doubles, exact then rounded, is the correctly rounded step) and the oracle, under the same ids.
  "$circles" run --steps 300 --engine double --trace "$dir/trace.jsonl" >/dev/null
  sed 's/^{"step"/{"id"/' "$dir/trace.jsonl" >"$dir/requests.jsonl"
  "$circles" serve --engine oracle <"$dir/requests.jsonl" >"$dir/oracle.jsonl"
  "$circles" serve --engine double --threads 2 <"$dir/requests.jsonl" >"$dir/double.jsonl"
  [ "$(wc -l <"$dir/oracle.jsonl")" -eq 301 ] || fail "the oracle did not answer 301 requests"
  cmp "$dir/oracle.jsonl" "$dir/double.jsonl" || fail "the engines' responses differ"
  "$circles" serve --engine exact --threads 2 <"$dir/requests.jsonl" >"$dir/exact.jsonl"
  cmp "$dir/oracle.jsonl" "$dir/exact.jsonl" || fail "the exact engine's responses differ"
  cut -d, -f1 "$dir/requests.jsonl" >"$dir/request-ids"
  cut -d, -f1 "$dir/double.jsonl" >"$dir/response-ids"
  cmp "$dir/request-ids" "$dir/response-ids" || fail "a response has another id than its request"
  sed '1d; s/^{"step":[0-9]*,//' "$dir/trace.jsonl" >"$dir/next-worlds"
  sed '$d; s/^{"id":[0-9]*,//' "$dir/double.jsonl" >"$dir/responses"
  cmp "$dir/next-worlds" "$dir/responses" || fail "a response is not the trace's next world"
  ;;
serve_exits_0_at_the_end_of_an_empty_input)
  "$circles" serve </dev/null >"$dir/out"
  [ ! -s "$dir/out" ] || fail "serve wrote something for no request"
  ;;
serve_exits_2_naming_the_line_of_a_malformed_request)
  printf '{"id": 1, "circles": [[0, 0, 0, 0, 1]]}\n{"id": 2, "circles": [[0, 0, 0, 0, 1, 1]]}\n{"id": 3, "circles": []}\n' \
    >"$dir/requests"
  expect_exit 2 sh -c '"$1" serve <"$2" >"$3" 2>"$4"' sh "$circles" "$dir/requests" "$dir/out" "$dir/err"
  [ "$(cat "$dir/out")" = '{"id":1,"circles":[[0.0,0.0,0.0,0.0,1.0]]}' ] || fail "wrong responses: $(cat "$dir/out")"
  [ "$(cat "$dir/err")" = 'circles serve: malformed request, line 2: circle 0: expected 5 numbers [px, py, vx, vy, r], found more' ] ||
    fail "wrong message: $(cat "$dir/err")"
  ;;
serve_exits_2_naming_an_overflow)
  printf '{"id": 7, "circles": [[0, 0, 0, 0, 1], [1.7976931348623157e308, 0, 1e308, 0, 1]]}\n' >"$dir/requests"
  expect_exit 2 sh -c '"$1" serve --engine double <"$2" >"$3" 2>"$4"' sh "$circles" "$dir/requests" "$dir/out" "$dir/err"
  [ ! -s "$dir/out" ] || fail "serve answered an overflowing request"
  [ "$(cat "$dir/err")" = 'circles serve: line 1 (id 7): circle 1, field px: the position p + v/60 overflows to infinity; the step of this request has no finite image in doubles, so there is no response to write' ] ||
    fail "wrong message: $(cat "$dir/err")"
  ;;
run_writes_the_same_trace_with_the_double_engine_as_with_the_oracle)
  "$circles" run --steps 120 --engine double --threads 1 --trace "$dir/double.jsonl" >"$dir/summary"
  "$circles" run --steps 120 --engine oracle --trace "$dir/oracle.jsonl" >/dev/null
  [ "$(wc -l <"$dir/double.jsonl")" -eq 121 ] || fail "the trace does not hold w_0 to w_120"
  cmp "$dir/double.jsonl" "$dir/oracle.jsonl" || fail "the traces differ"
  grep -Eq '^circles run: the embedded default scene: 120 steps of 10 circles with the double engine \(1 thread\): [0-9.e+-]+ s stepping, [0-9.e+-]+ ns per circle-step$' "$dir/summary" ||
    fail "wrong summary: $(cat "$dir/summary")"
  [ "$(ls "$dir" | wc -l)" -eq 3 ] || fail "files left behind: $(ls "$dir")"
  ;;
run_with_the_exact_engine_writes_the_exact_sequence_rounded)
  # Circle 9 of the default scene moves by (1, -7)/60 per step, alone: exactly (1102, 86) at step 120, which
  # the double engine, rounding 120 times, misses in the last bits.
  "$circles" run --steps 120 --engine exact --threads 1 --trace "$dir/exact.jsonl" >"$dir/summary"
  [ "$(wc -l <"$dir/exact.jsonl")" -eq 121 ] || fail "the trace does not hold w_0 to w_120"
  tail -n 1 "$dir/exact.jsonl" | grep -qF '[1102.0,86.0,1.0,-7.0,5.0]' || fail "circle 9 is not at (1102, 86): $(tail -n 1 "$dir/exact.jsonl")"
  "$circles" run --steps 120 --engine double --threads 1 --trace "$dir/double.jsonl" >/dev/null
  ! tail -n 1 "$dir/double.jsonl" | grep -qF '[1102.0,86.0,' || fail "the double engine no longer rounds circle 9 away"
  grep -Eq 'with the exact engine \(1 thread\)' "$dir/summary" || fail "wrong summary: $(cat "$dir/summary")"
  ;;
run_exits_2_on_an_overflow_keeping_the_trace_before_it)
  printf '%s\n' "$overflow_scene" >"$dir/scene.json"
  expect_exit 2 sh -c '"$1" run "$2" --steps 10 --trace "$3" >/dev/null 2>"$4"' sh "$circles" "$dir/scene.json" "$dir/t.jsonl" "$dir/err"
  [ "$(wc -l <"$dir/t.jsonl")" -eq 4 ] || fail "the trace does not hold w_0 to w_3"
  grep -qF '{"step":3,"circles":[[0.0,0.0,0.0,0.0,1.0],[1.7976931348623157e+308,-5.0,8.426686569667106e+307,0.0,1.0]]}' "$dir/t.jsonl" ||
    fail "w_3 is not at DBL_MAX: $(tail -n 1 "$dir/t.jsonl")"
  [ "$(cat "$dir/err")" = "circles run: step 4, circle 1, field px: the position p + v/60 overflows to infinity; stopped after 3 steps, and the trace $dir/t.jsonl holds w_0 to w_3" ] ||
    fail "wrong message: $(cat "$dir/err")"
  [ "$(ls "$dir" | wc -l)" -eq 3 ] || fail "files left behind: $(ls "$dir")"
  ;;
run_exits_2_for_an_exact_trace_from_an_engine_that_keeps_only_doubles)
  mkdir "$dir/out"
  expect_exit 2 sh -c '"$1" run --steps 1 --exact-trace "$2" >/dev/null 2>"$3"' sh "$circles" "$dir/out/x.jsonl" "$dir/err"
  grep -qxF 'circles run: --exact-trace: the double engine keeps no exact state (only --engine exact does)' "$dir/err" ||
    fail "wrong message: $(cat "$dir/err")"
  [ -z "$(ls "$dir/out")" ] || fail "files left behind: $(ls "$dir/out")"
  ;;
run_takes_the_steps_of_the_scene_unless_steps_is_given)
  "$circles" run "$source_dir/scenes/cradle.json" --threads 1 >"$dir/out"
  grep -q ': 1200 steps of 12 circles' "$dir/out" || fail "without --steps: $(cat "$dir/out")"
  "$circles" run "$source_dir/scenes/cradle.json" --steps 7 --threads 1 >"$dir/out"
  grep -q ': 7 steps of 12 circles' "$dir/out" || fail "with --steps 7: $(cat "$dir/out")"
  ;;
run_random_makes_the_benchmarks_scene)
  # scenes/random.json is formats::random_scene(128, 0.4, 1), written by bench/accuracy_scenes.cpp.
  "$circles" run --random 128 --coverage 0.4 --seed 1 --steps 0 --trace "$dir/a.jsonl" >"$dir/out"
  "$circles" run "$source_dir/scenes/random.json" --steps 0 --trace "$dir/b.jsonl" >/dev/null
  grep -q '^circles run: a random scene of 128 circles (coverage 0.4, seed 1): 0 steps of 128 circles' "$dir/out" ||
    fail "wrong summary: $(cat "$dir/out")"
  cmp "$dir/a.jsonl" "$dir/b.jsonl" || fail "the random scene is not scenes/random.json"
  ;;
run_random_exits_2_for_a_world_too_large_for_memory)
  expect_exit 2 sh -c '"$1" run --random 100000000000 >/dev/null 2>"$2"' sh "$circles" "$dir/err"
  grep -q '^circles: world too large for memory: 100000000000 circles need 25600000000000 bytes, more than the [0-9]* bytes of memory of this machine$' \
    "$dir/err" || fail "wrong message: $(cat "$dir/err")"
  ;;
run_random_and_a_scene_file_exclude_each_other)
  expect_exit 2 sh -c '"$1" run "$2" --random 5 >/dev/null 2>&1' sh "$circles" "$source_dir/scenes/default.json"
  ;;
run_exits_2_when_an_allocation_fails)
  # 200 MB of address space, and a world estimated at about 1 GB (a 1-step run of 2·10^6 circles fits in
  # 200 MB): an allocation fails, and the program says so.
  expect_exit 2 sh -c 'ulimit -v 200000 && exec "$1" run --random 4000000 --steps 1 --threads 1 >/dev/null 2>"$2"' sh \
    "$circles" "$dir/err"
  grep -q '^circles: world too large for memory: 4000000 circles need about 1024000000 bytes, and an allocation failed$' \
    "$dir/err" || fail "wrong message: $(cat "$dir/err")"
  ;;
run_exits_2_leaving_no_file_when_the_trace_cannot_be_written)
  expect_exit 2 sh -c '"$1" run --steps 3 --trace "$2" >/dev/null 2>"$3"' sh "$circles" "$dir/missing/t.jsonl" "$dir/err"
  grep -q "^circles: trace $dir/missing/t.jsonl: cannot create $dir/missing/t.jsonl.partial-" "$dir/err" ||
    fail "wrong message: $(cat "$dir/err")"
  [ "$(ls "$dir")" = err ] || fail "files left behind: $(ls "$dir")"
  ;;
run_and_oracle_exit_2_naming_a_scene_file_that_is_missing_or_a_directory)
  # The scene loader's own messages (docs/scenes.md), as for every other bad scene, not the option parser's.
  for command in run oracle; do
    expect_exit 2 sh -c '"$1" "$2" "$3" >/dev/null 2>"$4"' sh "$circles" "$command" "$dir/none.json" "$dir/err"
    [ "$(cat "$dir/err")" = "circles: $dir/none.json: cannot open the file: No such file or directory" ] ||
      fail "$command, a missing file: $(cat "$dir/err")"
    mkdir -p "$dir/scenes"
    expect_exit 2 sh -c '"$1" "$2" "$3" >/dev/null 2>"$4"' sh "$circles" "$command" "$dir/scenes" "$dir/err"
    [ "$(cat "$dir/err")" = "circles: $dir/scenes: cannot read the file: it is a directory" ] ||
      fail "$command, a directory: $(cat "$dir/err")"
  done
  ;;
run_exits_2_leaving_no_file_when_writing_the_trace_fails_midway)
  # A file size limit of 1 MB or 2 MB (ulimit -f counts blocks of 512 or 1024 bytes, by shell): the first line of
  # 20000 circles is about 2 MB, so a write fails midway, as on a full disk.
  expect_exit 2 sh -c 'ulimit -f 2048; exec "$1" run --random 20000 --steps 2 --trace "$2" >/dev/null 2>"$3"' sh \
    "$circles" "$dir/t.jsonl" "$dir/err"
  grep -qx "circles: trace $dir/t.jsonl: cannot write to $dir/t.jsonl.partial-[A-Za-z0-9]*: File too large" \
    "$dir/err" || fail "wrong message: $(cat "$dir/err")"
  [ "$(ls "$dir")" = err ] || fail "files left behind: $(ls "$dir")"
  ;;
run_and_serve_exit_2_listing_the_engines_for_an_unknown_one)
  for command in run serve; do
    expect_exit 2 sh -c '"$1" "$2" --engine fast </dev/null >/dev/null 2>"$3"' sh "$circles" "$command" "$dir/err"
    grep -qF -- '--engine: unknown engine "fast" (the engines are: double, exact, oracle)' "$dir/err" ||
      fail "wrong message: $(cat "$dir/err")"
  done
  ;;
main_job_exits_0_with_every_engine_in_agreement)
  "$circles" >"$dir/out"
  grep -qx 'double engine: agrees with the correctly rounded oracle at each of the 100 steps' "$dir/out" ||
    fail "no agreement line: $(tail -n 3 "$dir/out")"
  # The nearest doubles in their shortest round-trip form: 88.33333333333333, not 17 digits (88.333333333333329).
  grep -qxF '    9  (3305/3, 265/3, 1, -7, 5)  ≈ (1101.6666666666667, 88.33333333333333, 1, -7, 5)' "$dir/out" ||
    fail "circle 9's doubles: $(grep '^    9 ' "$dir/out")"
  # One step, said in the singular, and times in plain decimals (no "5.6454e-05 s").
  "$circles" run --steps 1 --trace "$dir/t.jsonl" >"$dir/out"
  grep -Eqx 'circles run: the embedded default scene: 1 step of 10 circles with the double engine \(1 thread\): 0\.[0-9]+ s stepping, [0-9.]+ ns per circle-step' "$dir/out" ||
    fail "run's summary of one step: $(cat "$dir/out")"
  "$circles" check-trace "$dir/t.jsonl" >"$dir/out"
  grep -q "^circles check-trace: $dir/t.jsonl: agrees with the correctly rounded step at its one step (steps 0 to 1, 10 circles)" "$dir/out" ||
    fail "check-trace of one step: $(cat "$dir/out")"
  printf '{"step": 0, "circles": [[0, 0, 0, 0, 1]]}\n{"step": 1, "circles": [[0, 0, 0, 0, 1]]}\n' >"$dir/one.jsonl"
  "$circles" check-trace "$dir/one.jsonl" >"$dir/out"
  grep -q "^circles check-trace: $dir/one.jsonl: agrees with the correctly rounded step at its one step (steps 0 to 1, 1 circle)" "$dir/out" ||
    fail "check-trace of one circle: $(cat "$dir/out")"
  ;;
usage_errors_name_the_command_and_suggest_the_nearest_name)
  # usage LINE ARGS...: `circles ARGS` exits 2 with the one line LINE on stderr and nothing on stdout.
  usage() {
    message=$1
    shift
    expect_exit 2 "$circles" "$@" >"$dir/out" 2>"$dir/err"
    [ "$(cat "$dir/err")" = "$message" ] && [ ! -s "$dir/out" ] || fail "circles $*: $(cat "$dir/err" "$dir/out")"
  }
  usage 'circles: unknown command `rn`: did you mean `run`?' rn
  usage 'circles: unknown command `conforn`: did you mean `conform`?' conforn --exec x
  usage 'circles: unknown command `xyzzy`; `circles --help` lists the commands' xyzzy
  usage 'circles report: unknown command `merj`: did you mean `merge`?' report merj
  usage 'circles conform: unknown option `--step`: did you mean `--steps`?' conform --step 3
  usage 'circles conform: unknown option `--frobnicate`; `circles conform --help` lists the options' conform --frobnicate
  usage 'circles conform: unexpected argument `extra`; `circles conform --help` lists what it takes' conform extra
  # Every kind of error the parser raises, said in the circles voice: the command, the option or argument, and
  # what it takes (no CLI11 wording: "Could not convert", "required UINT missing", "is required", "not expected").
  usage 'circles run: --steps: "x" is not a whole number from 0 to 9223372036854775807' run --steps x
  usage 'circles conform: --seed: "abc" is not a whole number from 0 to 18446744073709551615' conform --seed abc
  usage 'circles conform: --seed needs a value: N, a whole number from 0 to 18446744073709551615' conform --seed
  usage 'circles conform: --timeout: "0" is not a number from 0.001 to 3600' conform --timeout 0
  usage 'circles run: --coverage: "2" is not a number in (0, 1]' run --random 5 --coverage 2
  usage 'circles check-trace: TRACE is missing: a trace file to read, or - for stdin' check-trace
  usage 'circles check-trace: --engine: "fast" is not double or exact' check-trace t.jsonl --engine fast
  usage 'circles vectors: --out is missing: DIR, a directory for vectors.jsonl, or - for stdout' vectors
  usage 'circles report: COMMAND is missing: merge' report
  usage 'circles report merge: REPORT is missing: report files to read' report merge out.json
  usage 'circles: unknown command `foo`; `circles --help` lists the commands' foo conform
  usage 'circles run: --coverage goes with --random, which is not given' run --coverage 0.5
  usage 'circles run: SCENE and --random exclude each other: give one' run scene.json --random 3
  usage 'circles conform: --families and --skip-families exclude each other: give one' conform --families a --skip-families b
  usage 'circles run: --fit takes no value: give it alone' run --fit=yes
  usage 'circles run: --steps is given 2 times: give it once' run --steps 1 --steps 2
  usage 'circles run: --trace needs a value: FILE, a file to write, or - for stdout' run --trace
  usage 'circles help: unknown command `rn`: did you mean `run`?' help rn
  usage 'circles help: `circles report` has no command `x`; `circles help report` lists its commands' help report x
  ;;
help_wraps_at_the_terminal_width_and_names_what_each_option_takes)
  # `circles help COMMAND` is `circles COMMAND --help`; -V is --version.
  for command in "" run conform "report merge" vectors check-trace oracle serve families; do
    # shellcheck disable=SC2086
    "$circles" $command --help >"$dir/flag"
    # shellcheck disable=SC2086
    "$circles" help $command >"$dir/help"
    cmp "$dir/flag" "$dir/help" || fail "circles help $command differs from circles $command --help"
    # shellcheck disable=SC2086
    COLUMNS=60 "$circles" $command --help >"$dir/narrow"
    # No line beyond the width (in characters: the help is ASCII), none of CLI11's type names, no path into the
    # repository for a doc, which an installed program's user does not have.
    [ -z "$(LC_ALL=C awk 'length > 60' "$dir/narrow")" ] || fail "circles $command --help beyond 60 columns: $(LC_ALL=C awk 'length > 60' "$dir/narrow")"
    ! LC_ALL=C grep -q '[^ -~]' "$dir/narrow" || fail "circles $command --help is not ASCII"
    ! grep -Eq 'TEXT|UINT|FLOAT|INT\b|docs/' "$dir/narrow" || fail "circles $command --help: $(grep -E 'TEXT|UINT|FLOAT|INT\b|docs/' "$dir/narrow")"
  done
  "$circles" run --help >"$dir/out"
  for option in "--steps N" "--trace FILE" "--exact-trace FILE" "--render DIR" "--video FILE" "--every N" "--seed N"; do
    grep -q "^  $option " "$dir/out" || fail "run --help has no $option: $(cat "$dir/out")"
  done
  grep -q '^  SCENE ' "$dir/out" && grep -q '^Usage: circles run \[OPTIONS\] \[SCENE\]$' "$dir/out" || fail "run --help: $(cat "$dir/out")"
  COLUMNS=200 "$circles" run --help >"$dir/wide"
  [ "$(wc -l <"$dir/wide")" -lt "$(wc -l <"$dir/out")" ] || fail "run --help is no shorter at 200 columns"
  [ "$("$circles" -V)" = "$("$circles" --version)" ] || fail "-V: $("$circles" -V)"
  ;;
families_lists_the_families_of_each_profile)
  "$circles" families >"$dir/resolved"
  "$circles" conform --families >"$dir/conform"
  cmp "$dir/resolved" "$dir/conform" || fail "conform --families lists other families: $(cat "$dir/conform")"
  [ "$(wc -l <"$dir/resolved")" -eq 26 ] && [ "$(head -n 1 "$dir/resolved")" = lattice ] &&
    [ "$(grep -c ' (big)$' "$dir/resolved")" -eq 8 ] && grep -qx 'sizes (big)' "$dir/resolved" ||
    fail "circles families: $(cat "$dir/resolved")"
  "$circles" families --profile literal >"$dir/literal"
  [ "$(wc -l <"$dir/literal")" -eq 16 ] && ! grep -q 'duplicates\|zero-radius\|(big)' "$dir/literal" ||
    fail "circles families --profile literal: $(cat "$dir/literal")"
  # Each name listed is one --families takes.
  "$circles" conform --engine double --cases 26 --families "$(tr '\n' , <"$dir/literal" | sed 's/,$//')" --profile literal \
    >/dev/null || fail "conform does not take the families listed"
  ;;
version_and_help_say_what_the_program_is)
  # --version: project()'s version, and the commit of a build from git.
  "$circles" --version >"$dir/out"
  grep -Eqx 'circles [0-9]+\.[0-9]+\.[0-9]+( \(commit [0-9a-f]{12}(-dirty)?\))?' "$dir/out" ||
    fail "--version: $(cat "$dir/out")"
  # --help says what plain `circles` does.
  "$circles" --help >"$dir/out"
  grep -q '^With no command, plain `circles` runs the main job' "$dir/out" ||
    fail "--help: $(cat "$dir/out")"
  # run --help shows the scene's own "steps" as the default of --steps: 1200 for the cradle, 100 for the
  # default scene, which has none.
  printf '{"steps": 1200, "circles": [[0, 0, 0, 0, 1]]}' >"$dir/scene.json"
  "$circles" run "$dir/scene.json" --help >"$dir/out"
  grep -q '(default: 1200)$' "$dir/out" || fail "run SCENE --help: $(cat "$dir/out")"
  "$circles" oracle "$dir/scene.json" --help >"$dir/out"
  grep -q '(default: 1200)$' "$dir/out" || fail "oracle SCENE --help: $(cat "$dir/out")"
  "$circles" run --help >"$dir/out"
  sed -n '/^  --steps N /,/^  --[a-z]/p' "$dir/out" | grep -q '(default: 100)$' || fail "run --help: $(cat "$dir/out")"
  ;;
*)
  fail "no case $case_name"
  ;;
esac
