// Reports of `circles conform` for CI: the verdict as JSON (--report FILE.json), as JUnit XML (--junit FILE.xml),
// and `circles report merge OUT.json IN.json...`, which combines the reports of the shards of one run.
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

#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::cli {

// A report that cannot be read or merged; what() names the file and why.
class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A JSON string: nlohmann escapes quotes and control characters; a byte that is not UTF-8 (a file name can hold
// one) becomes U+FFFD rather than an exception. The reports and `circles vectors` write names with it.
std::string json_string(const std::string& s);

// `text`: the counterexample as `circles conform` prints it (cli/conform_report.hpp), kept in both reports.
std::string json_report(const conform::Verdict& verdict, const std::string& text);
std::string junit_report(const conform::Verdict& verdict, const std::string& text);

// The reports of shards of one run (the same candidate, seed, level, profile, steps and shard count, each
// shard once), as one: cases, skipped and per-family counts add up; the verdict is "cannot check" if any is,
// else "does not conform" if any has a counterexample, the one of the lowest case index (a stored
// counterexample, replayed before any case, lowest of all), or if a family failed or passed unexpectedly; a
// family's status is the first of failed, expected failure, unexpected pass, passed, not reached, skipped that
// it has in any shard. Throws ReportError. `names` name the texts in messages.
std::string merge_reports(const std::vector<std::string>& texts, const std::vector<std::string>& names);

// `circles report merge OUT IN...`: merges the reports IN into OUT and says the merged verdict in one line on
// `said`: "circles report merge: OUT: CANDIDATE conforms: 1700 cases of seed 5 in 4 reports" (with the
// counterexample's replay line, or the reason it cannot check). Returns the exit status of the merged verdict (0
// conforms, 1 does not conform, 2 cannot check), or 2 with the reason on `err` for a report that cannot be read
// or merged, or an OUT that cannot be written (left as it was).
int merge_command(const std::string& out, const std::vector<std::string>& reports, std::ostream& said,
                  std::ostream& err);

// Writes `text` to `path` whole or not at all. Throws formats::OutputError.
void write_report(const std::string& path, const std::string& what, const std::string& text);

}  // namespace circles::cli
