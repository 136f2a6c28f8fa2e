#!/bin/sh
# End-to-end checks of where the outputs of `circles` go and where its inputs come from (docs/protocol.md,
# "Commands and exit codes"; tests/CMakeLists.txt runs one case per test):
#   files_end_to_end.sh PATH/TO/circles SOURCE_DIR CASE
# Every output (a trace, an exact trace, frames, a video, conform's reports, picture and expectation file, a
# merged report, vectors) renames over only a regular file or a path that does not exist yet, writes what a
# symbolic link leads to in that file's own directory and keeps the link, and writes a FIFO or a device in place;
# `-` is stdout for every output and stdin for every input. Each case exits 0 when the program behaves so, and
# names what differs otherwise.
set -eu
circles=$1
source_dir=$2
case_name=$3
. "$(dirname "$0")/end_to_end_lib.sh"

# The outputs, each written by a short command of its own.
outputs="trace exact-trace report junit svg write-expect merge vectors"
if command -v ffmpeg >/dev/null; then outputs="$outputs video"; fi

# write OUTPUT PATH: runs the command that writes OUTPUT to PATH, its stdout in $dir/said and its stderr in
# $dir/err; it must exit 0, or 1 for a verdict against the program (conform --exec cat answers each world with
# itself, and fails).
write() {
  set +e
  case $1 in
  trace) "$circles" run --steps 2 --threads 1 --trace "$2" ;;
  exact-trace) "$circles" run --steps 2 --threads 1 --engine exact --exact-trace "$2" ;;
  video) "$circles" run --steps 2 --video "$2" ;;
  report) "$circles" conform --engine double --cases 26 --seed 1 --report "$2" ;;
  junit) "$circles" conform --engine double --cases 26 --seed 1 --junit "$2" ;;
  svg) "$circles" conform --exec cat --cases 26 --seed 1 --svg "$2" ;;
  write-expect) "$circles" conform --exec cat --cases 26 --seed 1 --write-expect "$2" ;;
  merge) "$circles" report merge "$2" "$dir/shard.json" ;;
  vectors) "$circles" vectors --out "$2" --cases 5 --scenes "$source_dir/scenes" --scene-steps 1 ;;
  esac >"$dir/said" 2>"$dir/err"
  status=$?
  set -e
  [ "$status" -le 1 ] || fail "$1 to $2 exited $status: $(cat "$dir/err")"
}

# What OUTPUT's file starts with: a few bytes that only it would.
opening() {
  case $1 in
  trace | exact-trace | vectors) printf '{' ;;
  report | merge) printf '{' ;;
  junit | svg) printf '<?xml' ;;
  write-expect) printf '# circles conform expectations' ;;
  video) printf '\000\000\000' ;;
  esac
}

# starts_with FILE OUTPUT: FILE is not empty and opens as OUTPUT's do.
starts_with() {
  want=$(opening "$2" | od -An -c)
  [ -s "$1" ] && [ "$(head -c "$(opening "$2" | wc -c)" "$1" | od -An -c)" = "$want" ] ||
    fail "$2: $1 does not hold it: $(head -c 100 "$1" | od -An -c | head -n 2)"
}

shard() { "$circles" conform --engine double --cases 26 --seed 1 --report "$dir/shard.json" >/dev/null; }

case $case_name in
every_output_renames_over_a_file_and_writes_through_a_link_in_its_targets_directory)
  shard
  for output in $outputs; do
    rm -rf "$dir/at" && mkdir -p "$dir/at/links" "$dir/at/files"
    if [ "$output" = vectors ]; then
      # --out names a directory: a link to one leads to the directory, and vectors.jsonl is written in it.
      ln -s ../files "$dir/at/links/out"
      write vectors "$dir/at/links/out"
      [ -L "$dir/at/links/out" ] || fail "vectors: the link to the directory was replaced"
      starts_with "$dir/at/files/vectors.jsonl" vectors
      [ "$(ls -A "$dir/at/files")" = vectors.jsonl ] || fail "vectors: files left: $(ls -A "$dir/at/files")"
      continue
    fi
    # A regular file: replaced, its permissions kept.
    printf 'before' >"$dir/at/files/old.mp4" && chmod 600 "$dir/at/files/old.mp4"
    write "$output" "$dir/at/files/old.mp4"
    starts_with "$dir/at/files/old.mp4" "$output"
    [ "$(stat -c %a "$dir/at/files/old.mp4")" = 600 ] || fail "$output: the file's mode is now $(stat -c %a "$dir/at/files/old.mp4")"
    # A link in another directory, relative, to a file: the file is replaced and the link stays.
    printf 'before' >"$dir/at/files/target.mp4"
    ln -s ../files/target.mp4 "$dir/at/links/link.mp4"
    write "$output" "$dir/at/links/link.mp4"
    [ -L "$dir/at/links/link.mp4" ] || fail "$output: the link was replaced by a file"
    starts_with "$dir/at/files/target.mp4" "$output"
    # A dangling link: the file it names is made.
    ln -s ../files/new.mp4 "$dir/at/links/dangling.mp4"
    write "$output" "$dir/at/links/dangling.mp4"
    [ -L "$dir/at/links/dangling.mp4" ] || fail "$output: the dangling link was replaced by a file"
    starts_with "$dir/at/files/new.mp4" "$output"
    [ "$(ls -A "$dir/at/links" | tr '\n' ' ')" = "dangling.mp4 link.mp4 " ] && \
      [ "$(ls -A "$dir/at/files" | tr '\n' ' ')" = "new.mp4 old.mp4 target.mp4 " ] ||
      fail "$output: files left: $(ls -A "$dir/at/links" "$dir/at/files")"
  done
  ;;
every_output_writes_a_fifo_and_a_device_in_place)
  shard
  mkfifo "$dir/fifo"
  # A device: /dev/null itself, and a copy of it in the scratch directory where the tests run as root.
  devices=/dev/null
  if [ "$(id -u)" -eq 0 ]; then mknod "$dir/null" c 1 3 && devices="$devices $dir/null"; fi
  for output in $outputs; do
    [ "$output" = vectors ] && continue # --out names a directory, which no FIFO is; - is the next case
    # The reader gives up after a minute: a FIFO replaced by a file is never opened for writing.
    timeout 60 cat "$dir/fifo" >"$dir/read" &
    reader=$!
    write "$output" "$dir/fifo"
    [ -p "$dir/fifo" ] || fail "$output: the FIFO was replaced by a file"
    wait "$reader" || fail "$output: nothing was written to the FIFO"
    starts_with "$dir/read" "$output"
    for device in $devices; do
      write "$output" "$device"
      [ -c "$device" ] || fail "$output: $device is no longer a device"
    done
  done
  [ "$(ls -A "$dir" | tr '\n' ' ')" = "$(ls -A "$dir" | grep -v partial | tr '\n' ' ')" ] ||
    fail "temporary files left: $(ls -A "$dir")"
  ;;
dash_is_stdout_for_every_output_and_stdin_for_every_input)
  shard
  cd "$dir"
  for output in $outputs; do
    write "$output" -
    starts_with "$dir/said" "$output"
    # The summary or verdict goes to stderr, so that stdout holds the output alone.
    grep -q '^circles ' "$dir/err" || fail "$output: no summary on stderr: $(cat "$dir/err")"
    ! grep -q '^circles ' "$dir/said" || fail "$output: a summary on stdout"
  done
  [ ! -e "$dir/-" ] || fail "a file named - was made"
  # Two outputs on stdout would interleave: refused before any work.
  expect_exit 2 sh -c '"$1" run --trace - --video /dev/stdout >"$2" 2>"$3"' sh "$circles" "$dir/out" "$dir/err"
  [ "$(cat "$dir/err")" = "circles run: --trace and --video both go to stdout; give - to one of them" ] && [ ! -s "$dir/out" ] ||
    fail "two outputs on stdout: $(cat "$dir/err")"
  expect_exit 2 sh -c '"$1" conform --report - --junit - >"$2" 2>"$3"' sh "$circles" "$dir/out" "$dir/err"
  [ "$(cat "$dir/err")" = "circles conform: --report and --junit both go to stdout; give - to one of them" ] ||
    fail "two reports on stdout: $(cat "$dir/err")"
  "$circles" run --steps 2 --trace - 2>/dev/null >"$dir/trace.jsonl"
  [ "$(wc -l <"$dir/trace.jsonl")" -eq 3 ] || fail "run --trace -: $(cat "$dir/trace.jsonl")"
  # The frames one PNG after another (the signature, 8 bytes, three times).
  "$circles" run --steps 2 --render - 2>/dev/null >"$dir/frames"
  [ "$(grep -c 'IEND' "$dir/frames")" -eq 3 ] || fail "run --render - did not write 3 PNGs"
  # Inputs: a scene, a trace, an expectation file and a report from stdin.
  "$circles" run - --steps 3 --trace "$dir/from-stdin.jsonl" <"$source_dir/scenes/default.json" >"$dir/out"
  grep -q '^circles run: <stdin>: 3 steps of 10 circles' "$dir/out" || fail "run -: $(cat "$dir/out")"
  "$circles" oracle - --steps 3 <"$source_dir/scenes/default.json" >"$dir/out"
  grep -q '^circles: the exact oracle on <stdin> (10 circles, 3 steps' "$dir/out" || fail "oracle -: $(cat "$dir/out")"
  "$circles" check-trace - <"$dir/trace.jsonl" >"$dir/out"
  grep -q '^circles check-trace: <stdin>: agrees with the correctly rounded step at each of its 2 steps' "$dir/out" ||
    fail "check-trace -: $(cat "$dir/out")"
  cat "$dir/trace.jsonl" | "$circles" check-trace - >"$dir/out" || fail "check-trace - from a pipe: $(cat "$dir/out")"
  printf 'tangency fail a reason\n' | "$circles" conform --engine double --cases 26 --seed 1 --expect - >"$dir/out" ||
    [ $? -eq 1 ]
  grep -q '^tangency: unexpected pass (1 case checked): delete its line, <stdin>:1$' "$dir/out" ||
    fail "conform --expect -: $(cat "$dir/out")"
  "$circles" report merge "$dir/merged.json" - <"$dir/shard.json" >"$dir/out"
  grep -q "^circles report merge: $dir/merged.json: the double engine .*conforms: 26 cases of seed 1 in 1 report$" "$dir/out" ||
    fail "report merge -: $(cat "$dir/out")"
  ;;
a_name_of_stdout_is_written_through_stdout)
  # /dev/fd/1 (like /dev/stdout) with stdout a file: the trace is written through it, the file stays the one
  # stdout writes to, and the summary goes to stderr.
  "$circles" run --steps 2 --trace /dev/fd/1 >"$dir/out" 2>"$dir/err"
  [ "$(wc -l <"$dir/out")" -eq 3 ] && [ "$(head -c 10 "$dir/out")" = '{"step":0,' ] || fail "trace: $(cat "$dir/out")"
  grep -q '^trace: /dev/fd/1 (w_0 to w_2, 3 lines)$' "$dir/err" || fail "summary: $(cat "$dir/err")"
  # and with stdout a pipe.
  [ "$("$circles" run --steps 2 --trace /dev/fd/1 2>/dev/null | wc -l)" -eq 3 ] || fail "/dev/fd/1 on a pipe"
  # /dev/stdout itself, stays the link it is.
  [ "$("$circles" run --steps 2 --trace /dev/stdout 2>/dev/null | wc -l)" -eq 3 ] || fail "/dev/stdout on a pipe"
  [ -L /dev/stdout ] || fail "/dev/stdout is no longer a link"
  # A shell's process substitution, a pipe named /dev/fd/N.
  if command -v bash >/dev/null; then
    bash -c '"$1" run --steps 2 --trace >(gzip >"$2") >/dev/null; wait' sh "$circles" "$dir/t.gz"
    sleep 0.5
    [ "$(gzip -dc "$dir/t.gz" | wc -l)" -eq 3 ] || fail ">(gzip > t.gz) holds no trace"
  fi
  ;;
*)
  fail "no case $case_name"
  ;;
esac
