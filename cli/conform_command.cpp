#include "cli/conform_command.hpp"

#include "cli/options.hpp"
#include "cli/conform_report.hpp"
#include "conform/candidate.hpp"
#include "conform/report_formats.hpp"
#include "conform/verdict_text.hpp"
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
#include <thread>
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
  // A fixed schedule (--cases, --shard, --case), or the time budget's.
  const bool fixed = given.cases_given || given.shard_given || given.case_given;
  if (given.budget_given && fixed)
    throw std::invalid_argument("--budget sets the time of a run without a fixed schedule; --cases, --shard and --case "
                                "fix the cases instead");
  if (!fixed) options.budget = given.budget;
  options.max_circles = given.max_circles_given ? given.max_circles
                        : fixed                 ? properties::kDefaultMaxCircles
                                                : conform::kBudgetMaxCircles;
  options.jobs = given.jobs > 0 ? given.jobs : std::max(1u, std::thread::hardware_concurrency());
  if (given.circles_given && !given.case_given)
    throw std::invalid_argument("--circles gives the size of the ladder's world that --case replays: give it with --case");
  if (given.circles_given) options.circles = given.circles;
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
    std::shared_ptr<conform::RequestLog> log;
    if (given.exec.empty()) {
      candidate = std::make_unique<conform::EngineCandidate>(engines::engine(given.engine), given.threads);
    } else {
      if (!given.log.empty()) log = std::make_shared<conform::RequestLog>(given.log);
      auto program = std::make_unique<conform::ProcessCandidate>(
          given.exec, std::chrono::milliseconds(static_cast<long long>(std::ceil(given.timeout * 1000))));
      program->log_to(log);
      candidate = std::move(program);
    }
    Verdict verdict = conform::check(*candidate, options);
    if (log) log->commit();
    return verdict;
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
// families failing  8.0 s left"; of a budget run, by its seconds: "[####......]  20%  second 12 of 60  3400
// cases, big worlds up to 8192 circles  48.0 s left".
class ConformProgress {
 public:
  ConformProgress(std::ostream* out, conform::Options& options)
      : total_(options.budget && !options.only_case ? static_cast<std::uint64_t>(std::ceil(*options.budget))
                                                    : cases_to_check(options)),
        budget_(options.budget && !options.only_case),
        progress_(out, total_, 1, pictures::Progress::Clock::now(), {kAfter, kAfter, kAfter},
                  [this](unsigned, std::uint64_t done, double left) { return line(done, left); }) {
    if (out)
      options.progress = [this](const Verdict& v) {
        failing_ = static_cast<std::uint64_t>(std::count_if(v.families.begin(), v.families.end(), [](const auto& f) {
          return f.status == conform::FamilyStatus::failed;
        }));
        cases_ = v.cases;
        largest_ = v.largest_world;
        const auto now = pictures::Progress::Clock::now();
        progress_.update(0, budget_ ? static_cast<std::uint64_t>(std::chrono::duration<double>(now - start_).count()) : v.cases,
                         now);
      };
  }
  // Erases the line, before the verdict is printed.
  void finish() { progress_.finish(); }

 private:
  static constexpr std::chrono::milliseconds kAfter{2000};
  std::string line(std::uint64_t done, double left) const {
    std::string note = failing_ == 0 ? "" : "  " + std::to_string(failing_) + (failing_ == 1 ? " family" : " families") + " failing";
    if (budget_) note = "  " + std::to_string(cases_) + " cases" +
                        (largest_ ? ", big worlds up to " + std::to_string(largest_) + " circles" : "") + note;
    return pictures::progress_line(0, 1, done, total_, left, budget_ ? "second" : "case", note);
  }
  std::uint64_t total_;
  bool budget_;
  pictures::Progress progress_;
  pictures::Progress::Clock::time_point start_ = pictures::Progress::Clock::now();
  std::uint64_t failing_ = 0, cases_ = 0;
  std::size_t largest_ = 0;
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
  takes_whole_number(conform->add_option("--cases", options.cases,
                                         "Worlds to check, a fixed schedule (default: as many as --budget allows)"),
                     "N", 0, kMaxCases);
  takes_number(conform
                   ->add_option("--budget", options.budget,
                                "Seconds to spend: the small families first, then big worlds of ever more circles as "
                                "far as the program's speed allows (conform.md in the docs, The time budget)")
                   ->capture_default_str(),
               "SECONDS", "a number from 0 to 10^6", [](double x) { return x >= 0 && x <= 1e6; });
  takes_whole_number(conform->add_option("--jobs", options.jobs,
                                         "Copies of the program run at once, each answering its own cases (default: "
                                         "one per core); the verdict is the same for every count"),
                     "N", 1, 1024);
  takes_whole_number(conform->add_option("--circles", options.circles,
                                         "With --case: replay a budget run's big world of this many circles"),
                     "N", circles::properties::kMinMaxCircles, std::size_t{1} << 31);
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
                                "The least seconds to wait for an answer; the deadline otherwise follows the "
                                "program's measured speed (conform.md in the docs, Deadlines)")
                   ->capture_default_str(),
               "SECONDS", "a number from 0.001 to 3600", [](double x) { return x >= 0.001 && x <= 3600; });
  takes_whole_number(conform
                         ->add_option("--max-circles", options.max_circles,
                                      "The most circles of a big world (conform.md in the docs, Big worlds): "
                                      "default 1000000 with --budget, 4097 with --cases, which crosses every power of "
                                      "two up to 4096"),
                     "N", circles::properties::kMinMaxCircles, std::size_t{1} << 31);
  takes_whole_number(conform->add_option("--case", options.only_case, "Check only this case (to replay a counterexample)"),
                     "N", 0, kMaxCases);
  add_report_options(conform, options.reports);
  takes_output_file(conform->add_option(
      "--log", options.log, "Write every request line sent to the program and every answer line read to FILE"));
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

std::vector<std::pair<std::string, std::string>> output_files(const ConformCommandOptions& options) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const conform::ReportFormat& format : conform::report_formats())
    if (const auto file = options.reports.find(format.option); file != options.reports.end())
      files.emplace_back(format.option, file->second);
  files.emplace_back("--svg", options.svg);
  files.emplace_back("--write-expect", options.write_expect);
  return files;
}

void note_given(const CLI::App& conform, ConformCommandOptions& options) {
  options.engine_given = conform.count("--engine") > 0;
  options.threads_given = conform.count("--threads") > 0;
  options.case_given = conform.count("--case") > 0;
  options.cases_given = conform.count("--cases") > 0;
  options.shard_given = conform.count("--shard") > 0;
  options.budget_given = conform.count("--budget") > 0;
  options.max_circles_given = conform.count("--max-circles") > 0;
  options.circles_given = conform.count("--circles") > 0;
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
  if (given.exec.empty() && !given.log.empty()) {
    err << "circles conform: --log writes the lines a program given with --exec reads and writes; an --engine "
           "runs in process\n";
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
  } catch (const formats::OutputError& e) {  // --log
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
  try {
    conform::write_reports(given.reports, verdict, conform::counterexample_text(verdict));
    // The expectation file of a run that judged the candidate, whole or not at all.
    if (!given.write_expect.empty() && conform::judged(verdict.outcome)) {
      formats::write_file(given.write_expect, "--write-expect " + given.write_expect, conform::expectations_text(verdict));
      out << "expectations: " << given.write_expect << "\n";
    }
  } catch (const formats::OutputError& e) {
    err << "circles conform: " << e.what() << "\n";
    return 2;
  }
  return status;
}

}  // namespace circles::cli
