// `circles conform`: the options as the command line gave them, and the command itself (docs/conform.md).
//
// add_conform_command declares the options (CLI11) and conform_command runs the command; everything after parsing
// is the latter, so that tests run the command in process: the checks of the options' values and of the options that exclude each
// other, the expectation file, the candidate (an engine or a program), conform::check, the expectations
// applied, the verdict printed (cli/conform_report.hpp) and the reports for CI written (conform/report_formats.hpp).
#pragma once

#include "conform/conform.hpp"
#include "conform/report_formats.hpp"
#include "properties/boundaries.hpp"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace circles::cli {

// What the command line gave, as given: the strings unparsed, and which options were given at all where that
// matters (an --engine given with --exec is refused, and the default engine is not).
struct ConformCommandOptions {
  std::string engine = "double";  // --engine NAME, one of engines/registry.hpp
  bool engine_given = false;
  unsigned threads = 0;           // --threads T of the engine (0: chosen from the load, impl::choose_threads)
  bool threads_given = false;
  std::string exec;               // --exec COMMAND: check this program instead of an engine ("" for none)
  double timeout = 10;            // --timeout: seconds to wait for each answer of the program
  // --max-circles: the most circles of a big world, when max_circles_given (else the fixed schedule's
  // properties::kDefaultMaxCircles, or a budget run's conform::kBudgetMaxCircles)
  std::size_t max_circles = properties::kDefaultMaxCircles;
  bool max_circles_given = false;
  double budget = conform::kDefaultBudget;             // --budget SECONDS of a run with no fixed schedule (no --cases, --shard or --case)
  bool budget_given = false;
  unsigned jobs = 0;              // --jobs N copies of the program at once (0: one per core)
  std::size_t circles = 0;        // --circles N: the ladder size of the case --case replays, when circles_given
  bool circles_given = false;
  std::string level = "exact";    // --level: exact, faithful or ulps:K (properties::parse_level)
  std::string profile = "resolved";  // --profile: resolved or literal
  std::string shard = "0/1";      // --shard i/n
  bool shard_given = false;
  std::uint64_t cases = 1000;     // --cases, when cases_given (else the budget decides)
  bool cases_given = false;
  std::uint64_t seed = 1;         // --seed (the program draws a random one when it is not given)
  std::uint64_t steps = 1;        // --steps chained per case
  std::uint64_t only_case = 0;    // --case I, when case_given
  bool case_given = false;
  std::string families;           // --families A,B,..., when families_given
  bool families_given = false;
  std::string skip_families;      // --skip-families A,B,..., when skip_families_given
  bool skip_families_given = false;
  bool keep_going = false;        // --keep-going
  std::string save;               // --save DIR ("" for none)
  std::string svg;                // --svg FILE ("" for none)
  // --report FILE.json, --junit FILE.xml, ...: the file of each report format (conform/report_formats.hpp), by
  // its option ("" or absent for none)
  conform::ReportFiles reports;
  std::string log;                // --log FILE: every request and answer line of the program ("" for none)
  std::string expect;             // --expect FILE ("" for none); implies keep_going
  std::string write_expect;       // --write-expect FILE ("" for none); implies keep_going
  std::ostream* progress = nullptr;  // where a run longer than 2 s draws its progress line (a terminal), or none
};

// Every file the options write to, each beside its option: the reports, --svg and --write-expect.
std::vector<std::pair<std::string, std::string>> output_files(const ConformCommandOptions& options);

// Declares the command and its options on `app`; the seed's default is a random one.
CLI::App* add_conform_command(CLI::App& app, ConformCommandOptions& options);
// After parsing: which of the options whose absence matters `conform` was given (the *_given fields).
void note_given(const CLI::App& conform, ConformCommandOptions& options);

// The command. Prints the verdict on `out` (or, when it cannot check, its reason on `err`), then the unexpected
// passes of --expect and "expectations: FILE" for --write-expect, and writes the reports, each whole or not at
// all. Returns the exit status: 0 (conforms), 1 (a counterexample, or a family against its expectation) or 2
// (cannot check). Options that cannot be used give 2 before any case runs, with "circles conform: reason" on
// `err`: a bad --level, --profile, --shard, --families or --skip-families, --engine or --threads with --exec, an
// unknown engine, an --expect file that cannot be read or parsed, an --svg file in a directory that does not
// exist, a --save directory that cannot be used. A report that cannot be written also makes the status 2.
int conform_command(const ConformCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace circles::cli
