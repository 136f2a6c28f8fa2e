#include "cli/conform_command.hpp"

#include "cli/options.hpp"
#include "cli/conform_report.hpp"
#include "cli/report.hpp"
#include "conform/candidate.hpp"
#include "conform/conform.hpp"
#include "engines/registry.hpp"
#include "conform/expect.hpp"
#include "formats/output_file.hpp"
#include "pictures/progress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <stdexcept>
#include <tuple>

namespace circles::cli {
namespace {

using conform::Outcome;
using conform::Verdict;

// The options of conform::check from the strings given. Throws std::invalid_argument naming the option.
conform::Options check_options(const ConformCommandOptions& given) {
  conform::Options options;
  options.cases = given.cases;
  options.seed = given.seed;
  options.steps = given.steps;
  options.keep_going = given.keep_going;
  options.max_circles = given.max_circles;
  options.level = properties::parse_level(given.level);
  options.profile = properties::parse_profile(given.profile);
  std::tie(options.shard, options.shards) = conform::parse_shard(given.shard);
  if (given.families_given) {
    const auto only = conform::parse_families("--families", given.families, options.profile);
    for (const properties::Family f : properties::families(options.profile))
      if (std::find(only.begin(), only.end(), f) == only.end()) options.skip.push_back(f);
  }
  if (given.skip_families_given)
    options.skip = conform::parse_families("--skip-families", given.skip_families, options.profile);
  return options;
}

// The verdict on the candidate the options name: an engine, or the program of --exec (one that cannot start is
// a verdict too, for the reports). Throws ConformError and UnknownEngine.
Verdict verdict_of(const ConformCommandOptions& given, const conform::Options& options) {
  try {
    std::unique_ptr<conform::Candidate> candidate;
    if (given.exec.empty())
      candidate = std::make_unique<conform::EngineCandidate>(engines::engine(given.engine), given.threads);
    else
      candidate = std::make_unique<conform::ProcessCandidate>(
          given.exec, std::chrono::milliseconds(static_cast<long long>(std::ceil(given.timeout * 1000))));
    return conform::check(*candidate, options);
  } catch (const conform::BrokenCandidate& e) {
    return conform::unchecked("the program `" + given.exec + "`", options, e.what());
  }
}

// The cases a run checks: --case's one, or the cases of its shard's rounds in the families not skipped.
std::uint64_t cases_to_check(const conform::Options& o) {
  if (o.only_case) return 1;
  const std::span<const properties::Family> families = properties::families(o.profile);
  const std::uint64_t F = families.size();
  const auto checked = [&](std::uint64_t first) {  // of the first `first` families of a round
    std::uint64_t n = 0;
    for (std::uint64_t f = 0; f < first; ++f)
      n += std::find(o.skip.begin(), o.skip.end(), families[f]) == o.skip.end();
    return n;
  };
  const std::uint64_t rounds = o.cases / F, rest = o.cases % F;  // whole rounds, and the cases of a last one
  const std::uint64_t mine = rounds > o.shard ? (rounds - o.shard - 1) / o.shards + 1 : 0;
  return mine * checked(F) + (rest > 0 && rounds % o.shards == o.shard ? checked(rest) : 0);
}

// The progress line of a run on a terminal, once it has taken 2 s: "[####......]  20%  case 200 of 1000  2
// families failing  8.0 s left".
class ConformProgress {
 public:
  ConformProgress(std::ostream* out, conform::Options& options)
      : progress_(out, cases_to_check(options), 1, pictures::Progress::Clock::now(), {kAfter, kAfter, kAfter},
                  [this](unsigned, std::uint64_t done, double left) { return line(done, left); }),
        total_(cases_to_check(options)) {
    if (out)
      options.progress = [this](const Verdict& v) {
        failing_ = static_cast<std::uint64_t>(std::count_if(v.families.begin(), v.families.end(), [](const auto& f) {
          return f.status == conform::FamilyStatus::failed;
        }));
        progress_.update(0, v.cases, pictures::Progress::Clock::now());
      };
  }
  // Erases the line, before the verdict is printed.
  void finish() { progress_.finish(); }

 private:
  static constexpr std::chrono::milliseconds kAfter{2000};
  std::string line(std::uint64_t done, double left) const {
    const std::string note = failing_ == 0 ? "" : "  " + std::to_string(failing_) + (failing_ == 1 ? " family" : " families") + " failing";
    return pictures::progress_line(0, 1, done, total_, left, "case", note);
  }
  pictures::Progress progress_;
  std::uint64_t total_;
  std::uint64_t failing_ = 0;
};

}  // namespace

CLI::App* add_conform_command(CLI::App& app, ConformCommandOptions& options) {
  options.seed = std::random_device{}();
  CLI::App* conform = app.add_subcommand(
      "conform",
      "Check an engine (--engine) or any program speaking the step protocol (--exec) against the oracle; exits 0 "
      "(conforms), 1 (a counterexample) or 2 (cannot check) (see conform.md in the docs)");
  add_engine_options(conform, options.engine, options.threads);
  takes(conform->add_option("--exec", options.exec,
                            "Check this program instead, run as /bin/sh -c COMMAND (see protocol.md in the docs)"),
        "COMMAND", "a shell command");
  takes(conform
            ->add_option("--level", options.level,
                         "exact (the nearest double), faithful (1 ulp) or ulps:K; decisions always exact")
            ->capture_default_str(),
        "LEVEL", "exact, faithful or ulps:K");
  // --cases and --case up to 2^63 - 1, as the counts of run and vectors.
  constexpr std::uint64_t kMaxCases = std::numeric_limits<std::int64_t>::max();
  takes_whole_number(conform->add_option("--cases", options.cases, "Worlds to check")->capture_default_str(), "N", 0,
                     kMaxCases);
  takes_whole_number(conform->add_option("--seed", options.seed, "Seed of the worlds (default: a random one, printed)"),
                     "N", 0, std::numeric_limits<std::uint64_t>::max());
  takes_whole_number(
      conform->add_option("--steps", options.steps, "Steps chained per world, the candidate fed its own answers")
          ->capture_default_str(),
      "N", 1, 1000000);
  takes_one_of(conform
                   ->add_option("--profile", options.profile,
                                "resolved, or literal (only worlds where the seed's step is defined, checked against it)")
                   ->capture_default_str(),
               "NAME", {"resolved", "literal"});
  takes(conform
            ->add_option("--shard", options.shard,
                         "Check only the rounds q (of one case per family) with q mod n == i, for parallel jobs")
            ->capture_default_str(),
        "I/N", "a shard i/n with 0 <= i < n");
  takes_directory(conform->add_option("--save", options.save,
                                      "Replay every counterexample stored in DIR first, and store a new one there "
                                      "(with its picture)"),
                  "a directory of counterexamples");
  takes_output_file(conform->add_option(
      "--svg", options.svg, "Draw a counterexample's picture in FILE (default: beside it in --save DIR, else none)"));
  takes_number(conform
                   ->add_option("--timeout", options.timeout,
                                "Seconds to wait for each answer, up to 512 circles; (n/512)^2 times as long for n "
                                "circles above")
                   ->capture_default_str(),
               "SECONDS", "a number from 0.001 to 3600", [](double x) { return x >= 0.001 && x <= 3600; });
  takes_whole_number(conform
                         ->add_option("--max-circles", options.max_circles,
                                      "The most circles of a big world (conform.md in the docs, Big worlds): 4097 "
                                      "crosses every power of two up to 4096; fast programs go to 100000 or more")
                         ->capture_default_str(),
                     "N", circles::properties::kMinMaxCircles, std::size_t{1} << 31);
  takes_whole_number(conform->add_option("--case", options.only_case, "Check only this case (to replay a counterexample)"),
                     "N", 0, kMaxCases);
  takes_output_file(conform->add_option(
      "--report", options.report, "Also write the verdict as JSON to FILE (conform.md in the docs, Reports for CI)"));
  takes_output_file(
      conform->add_option("--junit", options.junit, "Also write the verdict as JUnit XML to FILE, a test case per family"));
  conform->add_flag("--keep-going", options.keep_going,
                    "Check every family, shrink a counterexample per failing family, and print a row per family");
  // --families with nothing after it lists the families (as `circles families` does) instead of checking.
  CLI::Option* families_option =
      takes(conform
                ->add_option("--families", options.families,
                             "Check only these families, A,B,...; with no list, list the families (conform.md in the "
                             "docs)")
                ->expected(0, 1),
            "LIST", "families A,B,...");
  takes(conform->add_option("--skip-families", options.skip_families, "Check every family but these, A,B,...")
            ->excludes(families_option),
        "LIST", "families A,B,...");
  takes_input_file(conform->add_option("--expect", options.expect,
                                       "Known failures, FAMILY fail REASON a line: failing them passes, passing them "
                                       "fails (implies --keep-going)"));
  takes_output_file(conform->add_option(
      "--write-expect", options.write_expect,
      "Write this run's failing families to FILE as an expectation file (implies --keep-going)"));
  return conform;
}

void note_given(const CLI::App& conform, ConformCommandOptions& options) {
  options.engine_given = conform.count("--engine") > 0;
  options.threads_given = conform.count("--threads") > 0;
  options.case_given = conform.count("--case") > 0;
  options.families_given = conform.count("--families") > 0;
  options.skip_families_given = conform.count("--skip-families") > 0;
}

int conform_command(const ConformCommandOptions& given, std::ostream& out, std::ostream& err) {
  conform::Options options;
  try {
    options = check_options(given);
  } catch (const std::invalid_argument& e) {
    err << "circles conform: " << e.what() << "\n";
    return 2;
  }
  if (!given.exec.empty() && given.engine_given) {
    err << "circles conform: --engine and --exec exclude each other: check one candidate at a time\n";
    return 2;
  }
  if (!given.exec.empty() && given.threads_given) {
    err << "circles conform: --threads sets the threads of an --engine; a program given with --exec runs its own\n";
    return 2;
  }
  if (given.case_given) options.only_case = given.only_case;
  std::optional<conform::Expectations> expectations;
  try {
    if (!given.expect.empty()) expectations = conform::read_expectations(given.expect, options.profile);
  } catch (const conform::ExpectError& e) {
    err << "circles conform: --expect: " << e.what() << "\n";
    return 2;
  }
  if (expectations || !given.write_expect.empty()) options.keep_going = true;
  options.save = given.save;
  // A --svg file that cannot be written is a usage error, found before any case runs.
  if (const std::filesystem::path svg = given.svg; !svg.empty()) {
    const std::filesystem::path parent = svg.parent_path().empty() ? "." : svg.parent_path();
    if (!std::filesystem::is_directory(parent)) {
      err << "circles conform: --svg: cannot write " << svg.string() << ": the directory " << parent.string()
          << " does not exist\n";
      return 2;
    }
  }
  Verdict verdict;
  ConformProgress progress(given.progress, options);
  try {
    verdict = verdict_of(given, options);
    progress.finish();
  } catch (const conform::ConformError& e) {
    progress.finish();
    err << "circles conform: " << e.what() << "\n";
    return 2;
  } catch (const engines::UnknownEngine& e) {  // the program's --engine refuses it while parsing
    progress.finish();
    err << "circles conform: " << e.what() << "\n";
    return 2;
  }
  if (expectations) conform::apply(verdict, *expectations);
  // The ^C a terminal echoed after the progress line goes before the verdict.
  if (verdict.outcome == Outcome::interrupted && given.progress) err << "\r\x1b[K";
  const int status = print_verdict(verdict, given.svg, out, err);
  if (expectations && conform::judged(verdict.outcome))
    for (const std::string& line : conform::unexpected_passes(verdict, *expectations)) out << line << "\n";
  // The reports for CI, for every verdict; a report that cannot be written makes the run's status 2.
  const std::string text = counterexample_text(verdict);
  try {
    if (!given.report.empty()) write_report(given.report, "--report", json_report(verdict, text));
    if (!given.junit.empty()) write_report(given.junit, "--junit", junit_report(verdict, text));
    // The expectation file of a run that judged the candidate, whole or not at all.
    if (!given.write_expect.empty() && conform::judged(verdict.outcome)) {
      write_report(given.write_expect, "--write-expect", conform::expectations_text(verdict));
      out << "expectations: " << given.write_expect << "\n";
    }
  } catch (const formats::OutputError& e) {
    err << "circles conform: " << e.what() << "\n";
    return 2;
  }
  return status;
}

}  // namespace circles::cli
