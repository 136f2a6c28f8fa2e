#!/usr/bin/env python3
"""scripts/benchmarks without running a benchmark: its engine section (the engine targets, judged at their
bounds, by the names of docs/benchmarks.md's Targets table), the configurations it asks for, the filter that
selects them, its check that each was measured, its plot, its exit without matplotlib and the coverage labels
of the names; and, given the benchmark programs, that every configuration it asks for is one they register.

    benchmarks_script_test.py REPOSITORY report
    benchmarks_script_test.py REPOSITORY names ENGINE_BENCH [BOX2D_BENCH]
"""
import argparse
import datetime
import re
import subprocess
import sys
from importlib.machinery import SourceFileLoader
from pathlib import Path


def load(repository):
    sys.dont_write_bytecode = True  # no scripts/__pycache__ in the repository
    return SourceFileLoader("benchmarks", str(Path(repository) / "scripts" / "benchmarks")).load_module()


def measured_table(b, value):
    """A figure for every configuration of a full run: value(family, n, coverage, threads) ns, three repetitions."""
    engine, box2d = b.configurations(b.SIZES)
    return {k: [value(*k)] * 3 for k in engine + box2d}


def render_args():
    args = argparse.Namespace(quick=False, repetitions=3, build_dir="build-benchmarks", argv=[])
    info = {k: "?" for k in ("cpu", "cores", "memory", "os", "kernel", "compiler", "flags", "benchmark", "box2d")}
    info["arch"], info["arch_setting"] = "x86-64-v3", "auto"
    started = datetime.datetime(2026, 12, 1, tzinfo=datetime.timezone.utc)
    return args, info, (0.1, 0.1, 0.1), started


def render(b, table, sizes=None):
    args, info, load, started = render_args()
    return b.render(table, args, info, load, started, True, sizes or b.SIZES)


def render_conform(b):
    """The conform section of a run that measured nothing: its targets table, every target not measured."""
    args, info, load, started = render_args()
    return b.render_conform({}, args, info, load, started)


def verdicts(section):
    """{target name: [verdicts of its rows]} from a section's targets table ("the growth target, dense" is a row
    of the growth target)."""
    found = {}
    for m in re.finditer(r"^\| (the [^|,]+ target)(?:, \w+)? \| [^|]* \| [^|]* \| ([^|]*) \|$", section, re.M):
        found.setdefault(m.group(1), []).append(m.group(2))
    return found


def targets_table(repository):
    """The target names of docs/benchmarks.md's section "## Targets", its table's first column."""
    lines = (Path(repository) / "docs" / "benchmarks.md").read_text().splitlines()
    assert "## Targets" in lines, "docs/benchmarks.md has no section ## Targets"
    names = set()
    for line in lines[lines.index("## Targets") + 1:]:
        if line.startswith("## "):
            break
        m = re.match(r"^\| (the [^|]+ targets?) \|", line)
        if m:
            names.add(m.group(1))
    return names


def meeting(family, n, coverage, threads):
    """Figures that meet every target, each by a margin: the double engine at 30 ns dense at every size (the
    plain grid 100) and 6 ns sparse (the floor 2.5), 1.9 times faster on two threads; Box2D 250 times slower;
    the exact engine 1.2 times the double engine."""
    base = {"double_engine": 30.0 if coverage >= 1 else 6.0, "uniform_grid": 100.0, "streaming_floor": 2.5,
            "box2d": 30.0 * 250}[family] if family != "exact_engine" else 1.2 * (30.0 if coverage >= 1 else 6.0)
    return base / (1.9 if threads == 2 else 1)


def check_report(b, repository):
    table = measured_table(b, meeting)
    section = render(b, table)
    assert verdicts(section) == {"the dense target": ["met"], "the sparse target": ["met"],
                                 "the Box2D target": ["met"], "the growth target": ["met", "met"],
                                 "the two-thread target": ["met"], "the exact-engine target": ["met"],
                                 "the sweeps target": ["met"]}, verdicts(section)
    assert "Every target is met." in section
    assert f"]({b.PLOT})" in section, "the section links the plot"

    # The targets the sections judge are those docs/benchmarks.md's Targets table names, which they link, so that
    # a regenerated section and the table above it speak of the same targets.
    assert section.startswith(f"{b.BEGIN}\n\n## The engines (`impl/`) against the engine targets\n"), section[:200]
    assert "([Targets](#targets) above)" in section, "the engine section does not link the Targets table"
    named = targets_table(repository)
    conform = render_conform(b)
    judged = set(verdicts(section)) | set(verdicts(conform))
    assert {"the conform throughput target", "the protocol overhead target"} <= judged, verdicts(conform)
    assert judged <= named, f"the sections judge targets docs/benchmarks.md's Targets table lacks: {judged - named}"

    # Each target turns at its bound: a figure just past it is not met, and names that target only.
    def past(key, factor, target):
        worse = dict(table)
        worse[key] = [v * factor for v in table[key]]
        got = verdicts(render(b, worse))
        failed = [t for t, vs in got.items() if any(v != "met" for v in vs)]
        assert failed == [target], f"{key} × {factor}: targets {failed} not met, expected only {target}"

    past(("double_engine", 10**6, 10, 1), 0.36 / 0.30, "the dense target")          # 0.36× the grid
    past(("streaming_floor", 10**6, 0.1, 1), 6.0 / 3.1 / 2.5, "the sparse target")  # the floor at 1.94: 3.1×
    past(("box2d", 10**5, 10, 1), 199 / 250, "the Box2D target")                    # 199×
    past(("exact_engine", 10**3, 10, 1), 1 / 1.51, "the growth target")             # the exact engine grows 1.51× dense
    past(("double_engine", 10**6, 10, 2), 1.9 / 1.79, "the two-thread target")      # two threads 1.79×
    past(("exact_engine", 10**6, 0.1, 1), 1.26 / 1.2, "the exact-engine target")    # 1.26× sparse
    # At the bound itself, the target holds.
    at_bound = dict(table)
    at_bound[("double_engine", 10**6, 10, 1)] = [35.0] * 3
    assert verdicts(render(b, at_bound))["the dense target"] == ["met"], "0.35× the grid meets the dense target"

    # A run without 10^6 circles (--quick) measures neither the targets at 10^6 nor the sweeps.
    engine, box2d = b.configurations(b.QUICK_SIZES)
    quick = render(b, {k: [meeting(*k)] for k in engine + box2d}, b.QUICK_SIZES)
    assert ("Not measured in this run: the dense target; the sparse target; the Box2D target; the growth target, "
            "dense; the growth target, sparse; the two-thread target; the exact-engine target; the sweeps target."
            in quick), quick

    # The plot: every family drawn, no date, and the same figures give the same file.
    svg = b.plot_svg(table, b.SIZES)
    assert svg == b.plot_svg(table, b.SIZES), "two plots of the same figures differ"
    assert "<dc:date>" not in svg
    assert not [line for line in svg.splitlines() if line.endswith(" ")], "lines of the plot end in spaces"
    for _, label in b.SERIES:
        assert label in svg, f"the plot has no line labelled {label!r}"

    # A configuration asked for and not measured fails the run, naming it.
    missing = dict(table)
    del missing[("uniform_grid", 10**6, 40, 1)]
    try:
        b.check_measured(missing, engine_keys(b), "bench/engine_bench")
    except b.Failure as e:
        assert str(e) == ("bench/engine_bench measured no benchmark named uniform_grid/coverage:40/threads:1/n:1000000 "
                          "(`bench/engine_bench --benchmark_list_tests` lists the ones it has)"), str(e)
    else:
        raise AssertionError("check_measured accepted a run without uniform_grid at 40%")

    # The filter selects exactly the configurations asked for, Google Benchmark's suffixes after them.
    keys = engine_keys(b)
    pattern = re.compile(b.bench_filter(keys))
    for k in keys:
        assert pattern.search(b.bench_name(*k) + "/iterations:30/real_time"), k
    for other in ("double_engine/coverage:10/threads:1/n:10000000/iterations:1/real_time",
                  "engine_naive/coverage:10/threads:1/n:1000000/iterations:30/real_time",
                  "uniform_grid/coverage:10/threads:2/n:1000000/iterations:30/real_time",
                  "exact_engine/coverage:40/threads:1/n:1000/iterations:3000/real_time"):
        assert not pattern.search(other), f"the filter selects {other}"


def check_without_matplotlib(b):
    """Without matplotlib the run stops before building anything, exit status 1, the document as it was."""
    import contextlib
    import io
    import tempfile
    with tempfile.TemporaryDirectory() as scratch:
        doc = Path(scratch) / "benchmarks.md"
        doc.write_text("# Benchmarks\n")
        stderr = io.StringIO()
        find_spec = b.importlib.util.find_spec
        b.importlib.util.find_spec = lambda name: None if name == "matplotlib" else find_spec(name)
        try:
            with contextlib.redirect_stderr(stderr):
                status = b.main(["--output", str(doc), "--build-dir", str(Path(scratch) / "build")])
        finally:
            b.importlib.util.find_spec = find_spec
        assert status == 1, status
        assert stderr.getvalue() == ("scripts/benchmarks: the engine section's plot needs matplotlib (apt-get install "
                                     f"python3-matplotlib; scripts/setup installs it); {doc} is unchanged\n"), \
            stderr.getvalue()
        assert doc.read_text() == "# Benchmarks\n"
        assert not (Path(scratch) / "build").exists(), "it configured a build before finding matplotlib missing"


def engine_keys(b):
    return b.configurations(b.SIZES)[0]


def check_coverage_labels(b):
    """The coverages in names as bench/harness.hpp's coverage_percent writes them (tests/bench_harness_test.cpp
    holds it to the same labels): a whole percent, or one decimal."""
    labels = {c: b.coverage_label(c) for c in (0.1, 1, 1.5, 10, 12.5, 40)}
    assert labels == {0.1: "0.1", 1: "1", 1.5: "1.5", 10: "10", 12.5: "12.5", 40: "40"}, labels


def check_names(b, engine_bench, box2d_bench):
    """Every configuration of a full run and of a quick one is registered (or the run would fail, naming it)."""
    full, quick = b.configurations(b.SIZES), b.configurations(b.QUICK_SIZES)
    for program, keys in ((engine_bench, full[0] + quick[0]), (box2d_bench, full[1] + quick[1])):
        if program is None:
            continue
        listed = subprocess.run([program, "--benchmark_list_tests"], capture_output=True, text=True, check=True)
        names = {line.split("/iterations:")[0] for line in listed.stdout.splitlines()}
        missing = [b.bench_name(*k) for k in keys if b.bench_name(*k) not in names]
        assert not missing, f"{program} registers no {missing}"


def main():
    repository, mode = sys.argv[1], sys.argv[2]
    b = load(repository)
    if mode == "report":
        check_report(b, repository)
        check_coverage_labels(b)
        check_without_matplotlib(b)
    elif mode == "names":
        check_names(b, sys.argv[3], sys.argv[4] if len(sys.argv) > 4 else None)
    else:
        sys.exit(f"benchmarks_script_test.py: unknown mode {mode!r}")
    print("ok")


if __name__ == "__main__":
    main()
