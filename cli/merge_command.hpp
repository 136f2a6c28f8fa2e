// `circles report merge OUT IN... [--junit FILE]`: the JSON reports of the shards of one run
// (conform/report.hpp) combined into one (conform/merge.hpp), written as OUT and in every other format given a
// file (conform/report_formats.hpp).
#pragma once

#include "conform/report_formats.hpp"

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace circles::cli {

struct MergeCommandOptions {
  std::string out;                   // OUT: the merged JSON report
  std::vector<std::string> reports;  // IN...
  conform::ReportFiles formats;      // --junit FILE, ...: the merged verdict in the other formats, by option
};

// Declares `circles report` and its one subcommand `merge` on `app`; returns `merge`.
CLI::App* add_report_command(CLI::App& app, MergeCommandOptions& options);

// `circles report merge OUT IN...`: merges the reports IN into OUT (and each other format given a file) and says
// the merged verdict in one line on `said` (on `err` when an output is stdout): "circles report merge: OUT:
// CANDIDATE conforms: 1700 cases of seed 5 in 4 reports" (with the counterexample's replay line, or the reason it
// cannot check). Returns the exit status of the merged verdict (0 conforms, 1 does not conform, 2 cannot check,
// or was interrupted), or 2 with the reason on `err` for a report that cannot be read or merged, two outputs on
// stdout, or an output that cannot be written (left as it was).
int merge_command(const MergeCommandOptions& options, std::ostream& said, std::ostream& err);

}  // namespace circles::cli
