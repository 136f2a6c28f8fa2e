#include "cli/merge_command.hpp"

#include "cli/counted.hpp"
#include "cli/report.hpp"  // write_report
#include "conform/merge.hpp"
#include "formats/output_file.hpp"

#include <fstream>
#include <sstream>

namespace circles::cli {

CLI::App* add_report_command(CLI::App& app, MergeCommandOptions& options) {
  CLI::App* report = app.add_subcommand("report", "Work with the JSON reports of circles conform --report");
  report->require_subcommand(1, 1);
  CLI::App* merge = report->add_subcommand(
      "merge", "Combine the reports of the shards of one run into OUT; exits 0, 1 or 2 as the merged verdict");
  merge->add_option("out", options.out, "The merged report (written whole or not at all)")->required();
  merge->add_option("reports", options.reports, "The shards' reports")->required()->check(CLI::ExistingFile);
  return merge;
}

int merge_command(const std::string& out, const std::vector<std::string>& reports, std::ostream& said,
                  std::ostream& err) {
  std::vector<std::string> texts;
  for (const std::string& file : reports) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) {
      err << "circles report merge: " << file << ": cannot read it\n";
      return 2;
    }
    texts.push_back(text.str());
  }
  try {
    const conform::Report merged = conform::merged_report(texts, reports);
    write_report(out, "report", conform::json_report(merged.verdict, merged.text));
    const conform::Verdict& v = merged.verdict;
    said << "circles report merge: " << out << ": " << v.candidate << " " << name(v.outcome) << ": "
         << counted(v.cases, "case") << " of seed " << v.options.seed << " in " << counted(reports.size(), "report");
    if (v.counterexample && !v.counterexample->replay.empty()) said << "; replay: " << v.counterexample->replay;
    if (!v.error.empty()) said << "; " << v.error;
    said << "\n";
    switch (v.outcome) {
      case conform::Outcome::conforms: return 0;
      case conform::Outcome::does_not_conform: return 1;
      case conform::Outcome::cannot_check: break;
    }
  } catch (const conform::ReportError& e) {
    err << "circles report merge: " << e.what() << "\n";
  } catch (const formats::OutputError& e) {
    err << "circles report merge: " << e.what() << "\n";
  }
  return 2;
}

}  // namespace circles::cli
