#!/usr/bin/env python3
"""The CI examples under examples/ci/ parsed as YAML (python3-yaml): the GitHub Actions matrix workflow and the
Kubernetes Indexed Job each run `circles conform` as shards i/N of one run with one seed, and their shard
arithmetic covers every case once: conform's shard i/n checks the rounds q (cases qF ... qF + F - 1, F the
families of the profile) with q mod n = i (docs/conform.md, --shard).

    ci_examples_test.py REPOSITORY
"""
import re
import sys
from pathlib import Path

import yaml

FAMILIES = 17  # the resolved profile's (properties/boundaries.hpp)


def covered_once(shards, n, cases):
    """Each case 0 ... cases - 1 is checked by exactly one of `shards` (the i of --shard i/n)."""
    for c in range(cases):
        takers = [i for i in shards if (c // FAMILIES) % n == i]
        if len(takers) != 1:
            return f"case {c} is checked by shards {takers}"
    return None


def option(command, name):
    match = re.search(rf'--{name} (?:"([^"]*)"|(\S+))', command)
    assert match, f"no --{name} in {command!r}"
    return match.group(1) if match.group(1) is not None else match.group(2)


def github(path):
    workflow = yaml.safe_load(path.read_text())
    env = workflow["env"]
    n = int(env["SHARDS"])
    shards = workflow["jobs"]["shard"]["strategy"]["matrix"]["shard"]
    run = next(s["run"] for s in workflow["jobs"]["shard"]["steps"] if "conform" in s.get("run", ""))
    assert option(run, "shard") == "${{ matrix.shard }}/$SHARDS", run
    assert option(run, "seed") == "$SEED", "every shard must draw the same worlds"
    assert sorted(shards) == list(range(n)), f"matrix {shards} is not the shards 0 ... {n - 1}"
    merge = next(s["run"] for s in workflow["jobs"]["merge"]["steps"] if "run" in s and "merge" in s["run"])
    assert "report merge" in merge and "shard-*.json" in merge, merge
    return shards, n, int(env["CASES"])


def kubernetes(path):
    job = yaml.safe_load(path.read_text())
    assert job["kind"] == "Job" and job["spec"]["completionMode"] == "Indexed"
    n = job["spec"]["completions"]
    command = " ".join(job["spec"]["template"]["spec"]["containers"][0]["command"])
    shard = option(command, "shard")
    assert shard == f"$JOB_COMPLETION_INDEX/{n}", f"--shard {shard} with {n} completions"
    option(command, "seed")
    # Indexed: the pods get JOB_COMPLETION_INDEX = 0 ... completions - 1, each once.
    return list(range(n)), n, int(option(command, "cases"))


def main():
    root = Path(sys.argv[1])
    failures = []
    for name, read in (("github-actions.yml", github), ("kubernetes-job.yaml", kubernetes)):
        shards, n, cases = read(root / "examples" / "ci" / name)
        # The whole run's cases, and a run too short for a full round of every shard, both covered once.
        for total in (cases, n * FAMILIES + 5):
            problem = covered_once(shards, n, total)
            if problem:
                failures.append(f"{name}: {problem}")
        # A shard left out would leave its cases unchecked: the check can fail.
        assert covered_once(shards[1:], n, cases), f"{name}: the check cannot fail"
        print(f"{name}: shards {shards} of {n} cover each of {cases} cases once")
    if failures:
        print("\n".join(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
