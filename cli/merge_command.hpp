// `circles report merge OUT IN...`: the reports of the shards of one run (cli/report.hpp) combined into one.
#pragma once

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace circles::cli {

struct MergeCommandOptions {
  std::string out;                   // OUT
  std::vector<std::string> reports;  // IN...
};

// Declares `circles report` and its one subcommand `merge` on `app`; returns `merge`.
CLI::App* add_report_command(CLI::App& app, MergeCommandOptions& options);

// `circles report merge OUT IN...`: merges the reports IN into OUT and says the merged verdict in one line on
// `said`: "circles report merge: OUT: CANDIDATE conforms: 1700 cases of seed 5 in 4 reports" (with the
// counterexample's replay line, or the reason it cannot check). Returns the exit status of the merged verdict (0
// conforms, 1 does not conform, 2 cannot check), or 2 with the reason on `err` for a report that cannot be read
// or merged, or an OUT that cannot be written (left as it was).
int merge_command(const std::string& out, const std::vector<std::string>& reports, std::ostream& said,
                  std::ostream& err);

}  // namespace circles::cli
