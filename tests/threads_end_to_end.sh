#!/bin/sh
# `circles run`'s default thread count on a busy machine (impl/threads.hpp): with one spinning process for each
# online core, `--threads 0` steps a big world on one thread and says why, and its trace is the same bytes as
# the trace of two threads.
#   threads_end_to_end.sh PATH/TO/circles
set -eu
circles=$1
. "$(dirname "$0")/end_to_end_lib.sh"

busy=""
stop_busy() {
  for pid in $busy; do kill "$pid" 2>/dev/null || true; done
  rm -rf "$dir"
}
trap stop_busy EXIT
cores=$(getconf _NPROCESSORS_ONLN)
i=0
while [ "$i" -lt "$cores" ]; do
  sh -c 'while :; do :; done' &
  busy="$busy $!"
  i=$((i + 1))
done
sleep 0.1

"$circles" run --random 20000 --coverage 0.1 --steps 3 --stats --trace "$dir/default.jsonl" >"$dir/out" 2>&1
grep -q "with the double engine (1 thread, chosen from the load): " "$dir/out" ||
  fail "the summary does not say 1 thread chosen from the load: $(cat "$dir/out")"
line=$(grep '^threads: ' "$dir/out") || fail "no threads line: $(cat "$dir/out")"
others=$(printf '%s\n' "$line" | sed -n 's/^threads: 1 (chosen from the load: [0-9]* cores*, \([0-9]*\) tasks* of other programs running)$/\1/p')
[ -n "$others" ] || fail "unexpected threads line: $line"
[ "$others" -ge "$cores" ] || fail "$others tasks of other programs seen running, with $cores spinning: $line"

"$circles" run --random 20000 --coverage 0.1 --steps 3 --threads 2 --trace "$dir/two.jsonl" >/dev/null 2>&1
cmp "$dir/default.jsonl" "$dir/two.jsonl" || fail "the trace on one thread differs from the trace on two"
