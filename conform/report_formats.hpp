// The reports of a verdict for CI, one row per format: its name, the option that names its file, and its writer.
// `circles conform` offers every row's option, and `circles report merge` every row's but the JSON report's, which
// it reads back and writes to its OUT; both write every format given a file. A new format is its writer and a
// row of the table in report_formats.cpp.
//
// Every writer takes the verdict and its counterexample's text as `circles conform` prints it (counterexample_text,
// conform/verdict_text.hpp), which each report carries.
#pragma once

#include "conform/conform.hpp"

#include <map>
#include <span>
#include <string>

namespace circles::conform {

struct ReportFormat {
  const char* name;    // "JUnit XML": in the option's help, "Also write the verdict as JUnit XML to FILE"
  const char* option;  // "--junit": the option of `circles conform` and `circles report merge` that names its file
  const char* about;   // the rest of the option's help: ", a test case per family"
  std::string (*write)(const Verdict& verdict, const std::string& text);
};

// The table, in the order the options are declared and the files written: JSON (conform/report.hpp), then JUnit
// XML (conform/junit.hpp).
std::span<const ReportFormat> report_formats();

// The row of the JSON report, the one `circles report merge` reads.
const ReportFormat& json_format();

// Writes the verdict in `format` to `path`, whole or not at all (formats::write_file); a file that cannot be
// written throws formats::OutputError, its message opened by `what` and the path: "--junit r.xml: cannot create
// ...".
void write_report(const ReportFormat& format, const std::string& path, const std::string& what, const Verdict& verdict,
                  const std::string& text);

// The file of each format, by the format's option ("" or absent: not written).
using ReportFiles = std::map<std::string, std::string>;

// Writes the verdict in every format `files` gives a file for, in the table's order, each as write_report does,
// its messages opened by the format's option.
void write_reports(const ReportFiles& files, const Verdict& verdict, const std::string& text);

}  // namespace circles::conform
