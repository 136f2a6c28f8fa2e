// Reports of `circles conform` for CI: the verdict as JSON (--report FILE.json), as JUnit XML (--junit FILE.xml),
// which `circles report merge OUT.json IN.json...` combines for the shards of one run (conform/merge.hpp).
//
// The JSON report, one object (format "circles-conform-report/1"):
//   {"format": "circles-conform-report/1",
//    "verdict": "conforms" | "does not conform" | "cannot check",
//    "error": null | "why it cannot check",
//    "candidate": "the program `python3 step.py`",
//    "seed": 3, "shard": "0/1", "level": "exact", "profile": "resolved", "steps": 1,
//    "cases": 1000, "skipped": 0, "cut_short": 0, "replayed": 0,
//    "families": {"lattice": 59, ...},                  cases checked per family, in the profile's order
//    "family_status": {"lattice": "passed", ...},       "passed", "failed", "expected failure", "unexpected pass",
//                                                       "skipped" or "not reached" (conform::FamilyStatus)
//    "counterexample": null | {"family": "ulp-nudge", "case": 3 | null (a stored file), "stored": null | "F.json",
//        "step": 1, "steps": 1, "world": [[...]], "expected": [[...]], "received": [[...]],
//        "difference": {"circle": 0, "field": "px", "expected": 0.5, "received": "Infinity", "decision": "..."},
//        "shrink_path": [[[...]], ...], "replay": "circles conform --exec 'python3 step.py' --seed 3 --case 3 --level
//        exact", "text": "the printed report"},
//    "counterexamples": [{...}, ...],   every failing family's counterexample (with --keep-going, more than one),
//                                       in the order of the --keep-going table, each as "counterexample" is: the
//                                       run's with the printed report as "text", the others with their difference,
//                                       which decision and replay line
//    "elapsed_seconds": 0.43}
// Numbers follow formats/json_number.hpp; a received number that is not finite is the string "NaN", "Infinity"
// or "-Infinity". A merged report's "shard" lists the shards it merged, "0,1,2,3/4".
//
// The JUnit XML: one <testsuite> of one <testcase> per family, with a <failure> (its message the line that
// names the field, its text the printed counterexample) in each family that failed (with --keep-going, more
// than one) and in each unexpected pass, <skipped> in an expected failure, a skipped family and a family not
// reached, and an <error> in each family not checked when the run cannot check.
//
// Every file is written to a temporary name beside it and renamed (formats/output_file.hpp): whole or not at all.
#pragma once

#include "conform/conform.hpp"
#include "conform/merge.hpp"

#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::cli {

// `text`: the counterexample as `circles conform` prints it (cli/conform_report.hpp), kept in both reports.
std::string json_report(const conform::Verdict& verdict, const std::string& text);
std::string junit_report(const conform::Verdict& verdict, const std::string& text);

// Writes `text` to `path` whole or not at all. Throws formats::OutputError.
void write_report(const std::string& path, const std::string& what, const std::string& text);

}  // namespace circles::cli
