#!/bin/sh
# End-to-end checks of `circles run`'s pictures and figures (tests/CMakeLists.txt runs one case per test):
#   run_render_end_to_end.sh PATH/TO/circles CASE
# Each case exits 0 when the program behaves as docs/run.md says, and names what differs otherwise.
set -eu
circles=$1
case_name=$2
. "$(dirname "$0")/end_to_end_lib.sh"

case $case_name in
run_writes_every_kth_frame_and_says_so)
  "$circles" run --steps 10 --every 3 --render "$dir/frames" >"$dir/out"
  [ "$(ls "$dir/frames" | tr '\n' ' ')" = "frame-000000.png frame-000003.png frame-000006.png frame-000009.png " ] ||
    fail "wrong frames: $(ls "$dir/frames")"
  grep -qx "frames: $dir/frames/frame-000000.png to $dir/frames/frame-000009.png (4, every 3 steps)" "$dir/out" ||
    fail "wrong summary: $(cat "$dir/out")"
  # PNG's signature, then the IHDR chunk: width 1280 (0x500), height 720 (0x2d0).
  [ "$(od -An -tx1 -j16 -N8 "$dir/frames/frame-000003.png" | tr -d ' \n')" = "00000500000002d0" ] ||
    fail "frame-000003.png is not a 1280x720 PNG"
  ;;
run_prints_stats_one_figure_a_line)
  "$circles" run --steps 50 --threads 1 --render "$dir/frames" --every 10 --fit --trace "$dir/t.jsonl" --stats \
    >"$dir/out"
  sed 1,3d "$dir/out" | sed -E 's/[0-9][0-9.e+-]*/N/g' >"$dir/shape"
  printf '%s\n' 'steps: N' 'circles: N' 'engine: double' 'threads: N' 'stepping: N s' 'ns per circle-step: N' \
    'pair lists built: N (keys, re-sort and broad phase; one per N steps)' 'pairs tested: N (N per circle-step)' \
    'pairs in contact: N (N%)' 'steps with no pair to test: N (N%)' 'circle-steps with no contact test: N (N%)' \
    'fit pass: N s' 'frames: N' 'drawing: N s (N ms per frame)' 'png: N s (N ms per frame)' \
    'trace: N s (N bytes, N MB/s)' \
    'total: N s' >"$dir/want"
  cmp -s "$dir/shape" "$dir/want" || fail "wrong stats: $(cat "$dir/out")"
  grep -qx 'steps: 50' "$dir/out" && grep -qx 'circles: 10' "$dir/out" && grep -qx 'frames: 6' "$dir/out" &&
    grep -qx 'threads: 1' "$dir/out" || fail "wrong figures: $(cat "$dir/out")"
  # Each figure to 3 significant digits: 7 pair lists in 100 steps are one per 14.3 steps.
  "$circles" run --steps 100 --threads 1 --stats >"$dir/out"
  grep -qx 'pair lists built: 7 (keys, re-sort and broad phase; one per 14.3 steps)' "$dir/out" ||
    fail "not 3 significant digits: $(cat "$dir/out")"
  sed 1d "$dir/out" | grep -oE '[0-9][0-9.]*' | sed 's/\.//; s/^0*//; s/0*$//' | grep -E '.{4}' &&
    fail "a figure with more than 3 significant digits: $(cat "$dir/out")"
  # No step, no rate: no "one per 0 steps".
  "$circles" run --steps 0 --threads 1 --stats >"$dir/out"
  grep -qx 'pair lists built: 0 (keys, re-sort and broad phase)' "$dir/out" && grep -qx 'pairs tested: 0' "$dir/out" ||
    fail "a rate of no steps: $(cat "$dir/out")"
  ;;
run_without_ffmpeg_exits_2_before_stepping)
  mkdir "$dir/bin"
  expect_exit 2 env PATH="$dir/bin" "$circles" run --steps 10 --video "$dir/v.mp4" --trace "$dir/t.jsonl" \
    --render "$dir/frames" >"$dir/out" 2>"$dir/err"
  [ "$(cat "$dir/err")" = "circles: --video needs ffmpeg, which is not installed (apt-get install ffmpeg)" ] ||
    fail "wrong message: $(cat "$dir/err")"
  [ ! -s "$dir/out" ] || fail "it printed a summary: $(cat "$dir/out")"
  [ "$(ls "$dir")" = "bin
err
out" ] || fail "files left behind: $(ls "$dir")"
  ;;
run_exits_2_naming_a_render_directory_it_cannot_make)
  : >"$dir/file"
  expect_exit 2 "$circles" run --steps 10 --render "$dir/file/frames" --trace "$dir/t.jsonl" 2>"$dir/err"
  [ "$(cat "$dir/err")" = "circles: render directory $dir/file/frames: cannot create it: Not a directory" ] ||
    fail "wrong message: $(cat "$dir/err")"
  [ "$(ls "$dir")" = "err
file" ] || fail "files left behind: $(ls "$dir")"
  ;;
run_exits_2_for_fit_or_every_without_pictures)
  expect_exit 2 "$circles" run --steps 10 --fit 2>"$dir/err"
  [ "$(cat "$dir/err")" = "circles run: --fit and --every shape the frames of --render and --video, and neither is given" ] ||
    fail "wrong message: $(cat "$dir/err")"
  expect_exit 2 "$circles" run --steps 10 --every 2 2>/dev/null
  expect_exit 2 "$circles" run --steps 10 --every 0 --render "$dir/frames" 2>/dev/null
  [ ! -e "$dir/frames" ] || fail "--every 0 made the frames' directory"
  ;;
run_keeps_the_frames_before_an_overflow)
  # Circle 1 reaches DBL_MAX in w_3 and overflows at step 4 (tests/cli_end_to_end.sh, tests/step_worlds.hpp).
  printf '{"circles": [[0, 0, 0, 0, 1], [1.7555597020139802e+308, -5, 8.426686569667106e+307, 0, 1]]}' >"$dir/s.json"
  expect_exit 2 "$circles" run "$dir/s.json" --steps 10 --every 2 --render "$dir/frames" >/dev/null 2>"$dir/err"
  [ "$(cat "$dir/err")" = "circles run: step 4, circle 1, field px: the position p + v/60 overflows to infinity; stopped after 3 steps, and the frames in $dir/frames go to w_2" ] ||
    fail "wrong message: $(cat "$dir/err")"
  [ "$(ls "$dir/frames" | tr '\n' ' ')" = "frame-000000.png frame-000002.png " ] || fail "wrong frames: $(ls "$dir/frames")"
  ;;
*)
  fail "no case $case_name"
  ;;
esac
