#include "cli/merge_command.hpp"

#include "cli/options.hpp"
#include "conform/merge.hpp"
#include "conform/report_formats.hpp"
#include "formats/counted.hpp"
#include "formats/input_file.hpp"
#include "formats/output_file.hpp"

namespace circles::cli {

using formats::counted;

CLI::App* add_report_command(CLI::App& app, MergeCommandOptions& options) {
  CLI::App* report = app.add_subcommand("report", "Work with the JSON reports of circles conform --report");
  report->require_subcommand(1, 1);
  CLI::App* merge = report->add_subcommand(
      "merge", "Combine the reports of the shards of one run into OUT; exits 0, 1 or 2 as the merged verdict");
  takes(merge->add_option("out", options.out, "The merged report (written whole or not at all), or - for stdout")
            ->required(),
        "OUT", "a file to write, or - for stdout");
  takes(merge->add_option("reports", options.reports, "The shards' reports (- for stdin)")->required(), "REPORT",
        "report files to read");
  add_report_options(merge, options.formats, &conform::json_format());
  return merge;
}

int merge_command(const MergeCommandOptions& options, std::ostream& said, std::ostream& err) {
  std::vector<std::pair<std::string, std::string>> outputs{{"OUT", options.out}};
  for (const auto& [option, file] : options.formats) outputs.emplace_back(option, file);
  if (const std::string both = two_on_stdout(outputs); !both.empty()) {
    err << "circles report merge: " << both << "\n";
    return 2;
  }
  const std::vector<std::string>& reports = options.reports;
  std::vector<std::string> texts;
  for (const std::string& file : reports) {
    try {
      texts.push_back(formats::read_input(file));
    } catch (const formats::InputError& e) {
      err << "circles report merge: " << formats::input_name(file) << ": " << e.what() << "\n";
      return 2;
    }
  }
  std::vector<std::string> names;
  for (const std::string& file : reports) names.push_back(formats::input_name(file));
  try {
    const conform::Report merged = conform::merged_report(texts, names);
    conform::write_report(conform::json_format(), options.out, "report", merged.verdict, merged.text);
    conform::write_reports(options.formats, merged.verdict, merged.text);
    const conform::Verdict& v = merged.verdict;
    // With a report on stdout, the line goes to stderr, so that stdout holds the report alone.
    std::ostream& told = any_on_stdout(outputs) ? err : said;
    told << "circles report merge: " << options.out << ": " << v.candidate << " " << name(v.outcome) << ": "
         << counted(v.cases, "case") << " of seed " << v.options.seed << " in " << counted(reports.size(), "report");
    if (v.counterexample && !v.counterexample->replay.empty()) told << "; replay: " << v.counterexample->replay;
    if (!v.error.empty()) told << "; " << v.error;
    told << "\n";
    switch (v.outcome) {
      case conform::Outcome::conforms: return 0;
      case conform::Outcome::does_not_conform: return 1;
      case conform::Outcome::cannot_check:
      case conform::Outcome::interrupted: break;
    }
  } catch (const conform::ReportError& e) {
    err << "circles report merge: " << e.what() << "\n";
  } catch (const formats::OutputError& e) {
    err << "circles report merge: " << e.what() << "\n";
  }
  return 2;
}

}  // namespace circles::cli
