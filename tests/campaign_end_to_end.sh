#!/bin/sh
# The campaign recipe (examples/ci/campaign): 4 local shards with GNU parallel, merged, against the unsharded run
# of the same seed and cases, for a conforming candidate (the same cases, per family too, and verdict) and a
# wrong one (the same verdict and counterexample: the lowest case's, shrunk the same).
#   campaign_end_to_end.sh PATH/TO/circles SOURCE_DIR
set -eu
circles=$1
source_dir=$2
. "$(dirname "$0")/end_to_end_lib.sh"

# same KEYS... : the merged report and the unsharded one agree on each key (a dotted path).
same() {
  python3 - "$dir/campaign/report.json" "$dir/whole.json" "$@" <<'PY' || fail "the merged report differs: $(cat "$dir/campaign/report.json")"
import json, sys
merged, whole = (json.load(open(p)) for p in sys.argv[1:3])
def at(r, path):
    for key in path.split("."):
        r = r[key]
    return r
bad = [k for k in sys.argv[3:] if at(merged, k) != at(whole, k)]
print("\n".join(f"{k}: merged {at(merged, k)!r}, unsharded {at(whole, k)!r}" for k in bad))
sys.exit(1 if bad else 0)
PY
}

set +e
"$source_dir/examples/ci/campaign" "$circles" 4 "$dir/campaign" --engine double --seed 5 --cases 1700 >"$dir/out" 2>&1
got=$?
"$circles" conform --engine double --seed 5 --cases 1700 --report "$dir/whole.json" >/dev/null 2>&1
set -e
[ "$got" -eq 0 ] || fail "the campaign exited $got: $(cat "$dir/out" "$dir/campaign/shards.log")"
[ "$(ls "$dir/campaign"/shard-*.json | wc -l)" -eq 4 ] || fail "not 4 shard reports: $(ls "$dir/campaign")"
same verdict cases families seed
# The campaign ends with the merged verdict in one line.
[ "$(cat "$dir/out")" = "circles report merge: $dir/campaign/report.json: the double engine conforms: 1700 cases of seed 5 in 4 reports" ] ||
  fail "no verdict line: $(cat "$dir/out")"
grep -q '"shard": "0,1,2,3/4"' "$dir/campaign/report.json" || fail "the shards merged are not named"

naive="python3 $source_dir/examples/python/step_naive.py"
set +e
"$source_dir/examples/ci/campaign" "$circles" 4 "$dir/campaign" --exec "$naive" --seed 3 --cases 700 >"$dir/out" 2>&1
got=$?
"$circles" conform --exec "$naive" --seed 3 --cases 700 --report "$dir/whole.json" >/dev/null 2>&1
set -e
[ "$got" -eq 1 ] || fail "the campaign of a wrong candidate exited $got: $(cat "$dir/out" "$dir/campaign/shards.log")"
same verdict counterexample.case counterexample.world counterexample.difference
grep -q "^circles report merge: $dir/campaign/report.json: the program \`$naive\` does not conform: [0-9]* cases of seed 3 in 4 reports; replay: circles conform --exec '$naive' --seed 3 --case [0-9]* --level exact$" "$dir/out" ||
  fail "no verdict line: $(cat "$dir/out")"
