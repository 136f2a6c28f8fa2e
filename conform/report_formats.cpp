#include "conform/report_formats.hpp"

#include "conform/junit.hpp"
#include "conform/report.hpp"
#include "formats/output_file.hpp"

namespace circles::conform {

namespace {

constexpr ReportFormat kReportFormats[] = {
    {"JSON", "--report", " (conform.md in the docs, Reports for CI)", json_report},
    {"JUnit XML", "--junit", ", a test case per family", junit_report},
};

}  // namespace

std::span<const ReportFormat> report_formats() { return kReportFormats; }

const ReportFormat& json_format() { return kReportFormats[0]; }

void write_report(const ReportFormat& format, const std::string& path, const std::string& what, const Verdict& verdict,
                  const std::string& text) {
  formats::write_file(path, what + " " + path, format.write(verdict, text));
}

void write_reports(const ReportFiles& files, const Verdict& verdict, const std::string& text) {
  for (const ReportFormat& format : report_formats())
    if (const auto file = files.find(format.option); file != files.end() && !file->second.empty())
      write_report(format, file->second, format.option, verdict, text);
}

}  // namespace circles::conform
