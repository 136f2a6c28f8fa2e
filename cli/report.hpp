// Reports of `circles conform` for CI: the verdict as JSON (--report FILE.json; conform/report.hpp lists its keys),
// which `circles report merge OUT.json IN.json...` combines for the shards of one run (conform/merge.hpp), and as
// JUnit XML (--junit FILE.xml).
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
#include "conform/report.hpp"

#include <string>

namespace circles::cli {

// The JSON report (conform/report.hpp) and the JUnit XML. `text`: the counterexample as `circles conform` prints it
// (cli/conform_report.hpp), kept in both reports.
using conform::json_report;
std::string junit_report(const conform::Verdict& verdict, const std::string& text);

// Writes `text` to `path` whole or not at all. Throws formats::OutputError.
void write_report(const std::string& path, const std::string& what, const std::string& text);

}  // namespace circles::cli
