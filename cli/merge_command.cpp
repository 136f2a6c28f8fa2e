#include "cli/merge_command.hpp"

#include "cli/report.hpp"  // write_report
#include "conform/merge.hpp"
#include "formats/output_file.hpp"

#include <nlohmann/json.hpp>

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
    const std::string merged = conform::merge_reports(texts, reports);
    write_report(out, "report", merged);
    const nlohmann::json m = nlohmann::json::parse(merged);
    const std::string verdict = m["verdict"];
    said << "circles report merge: " << out << ": " << m["candidate"].get<std::string>() << " " << verdict << ": "
         << m["cases"].get<std::uint64_t>() << (m["cases"] == 1 ? " case" : " cases") << " of seed "
         << m["seed"].get<std::uint64_t>() << " in " << reports.size() << (reports.size() == 1 ? " report" : " reports");
    if (m["counterexample"].is_object() && m["counterexample"].contains("replay"))
      said << "; replay: " << m["counterexample"]["replay"].get<std::string>();
    if (m["error"].is_string()) said << "; " << m["error"].get<std::string>();
    said << "\n";
    return verdict == "conforms" ? 0 : verdict == "does not conform" ? 1 : 2;
  } catch (const conform::ReportError& e) {
    err << "circles report merge: " << e.what() << "\n";
  } catch (const formats::OutputError& e) {
    err << "circles report merge: " << e.what() << "\n";
  }
  return 2;
}

}  // namespace circles::cli
