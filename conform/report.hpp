// The JSON report of a verdict (`circles conform --report FILE.json`, a row of conform/report_formats.hpp), written
// and read back, which `circles report merge OUT.json IN.json...` combines for the shards of one run
// (conform/merge.hpp).
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
//                                       run's with the printed report as "text", the others with their
//                                       counterexample_summary
//    "elapsed_seconds": 0.43}
// Numbers follow formats/json_number.hpp; a received number that is not finite is the string "NaN", "Infinity"
// or "-Infinity". A merged report's "shard" lists the shards it merged, "0,1,2,3/4".
#pragma once

#include "conform/conform.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

namespace circles::conform {

// The format of a report, its key "format".
inline constexpr const char* kReportFormat = "circles-conform-report/1";

// A report that cannot be read or merged; what() names the file and why.
class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The JSON report. `text`: the run's counterexample as `circles conform` prints it (counterexample_text,
// conform/verdict_text.hpp).
std::string json_report(const Verdict& verdict, const std::string& text);

// A report read back: the verdict as far as the report holds it, and the text of its counterexample.
struct Report {
  Verdict verdict;
  std::string text;
};

// Reads a report (`name` names it in messages): every key the verdict is made from is checked for the type
// json_report writes it with; a counterexample's keys may be left out (each then keeps its default), and the
// families must be the profile's. Throws ReportError: "b.json: \"cases\": expected an integer >= 0, found \"12\"".
Report read_report(std::string_view text, const std::string& name);

}  // namespace circles::conform
