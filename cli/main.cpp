// The `circles` program. With no subcommand it runs the main job on the embedded default scene: the oracle's
// report, then every engine checked against the correctly rounded oracle step by step.
#include "cli/candidate.hpp"
#include "cli/conform.hpp"
#include "cli/engines.hpp"
#include "cli/oracle_report.hpp"
#include "cli/run.hpp"
#include "cli/scene.hpp"
#include "cli/serve.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <tuple>
#include <iostream>
#include <limits>
#include <memory>
#include <random>

namespace {

using namespace circles::cli;

// "The engine, one of: double (the double engine ...); oracle (...)", from the registry.
std::string engine_help() {
  std::string help;
  for (const EngineEntry& e : engines())
    help += (help.empty() ? "The engine, one of: " : "; ") + std::string(e.name) + " (" + std::string(e.summary) + ")";
  return help;
}

// --engine NAME, checked against the registry (its message lists the valid names), and --threads T.
void add_engine_options(CLI::App* command, std::string& engine_name, unsigned& threads) {
  command
      ->add_option("--engine", engine_name, engine_help())
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& name) { return find_engine(name) ? std::string() : std::string(UnknownEngine(name).what()); },
          "ENGINE"));
  // CLI11 reads unsigned values with strtoull, which wraps "-1" to 2^64 - 1, so the range refuses negatives too.
  command->add_option("--threads", threads, "Threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0u, max_threads()));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"circles: a conformance suite for the circles physics spec"};
  app.require_subcommand(0, 1);

  std::string scene_path;
  std::size_t steps = 100;
  CLI::App* oracle = app.add_subcommand(
      "oracle", "Run the exact oracle in both profiles on a scene and report what it did (the default)");
  oracle->add_option("scene", scene_path, "Scene file in compact form {\"circles\": [[px, py, vx, vy, r], ...]}")
      ->check(CLI::ExistingFile);
  oracle->add_option("--steps", steps, "Number of steps")->capture_default_str()->check(CLI::Range(0, 1000000));

  std::string engine_name = "double";
  unsigned threads = 0;
  CLI::App* serve = app.add_subcommand(
      "serve", "Answer step-protocol requests on stdin, one JSON line each, on stdout (docs/protocol.md)");
  add_engine_options(serve, engine_name, threads);

  std::uint64_t run_steps = 100;
  std::string trace;
  CLI::App* run = app.add_subcommand("run", "Run an engine on a scene, optionally writing a JSON Lines trace");
  run->add_option("scene", scene_path, "Scene file in compact form (default: the embedded default scene)")
      ->check(CLI::ExistingFile);
  // Up to 2^63 - 1: CLI11 reads "-5" as 2^64 - 5 (strtoull), which this range refuses.
  run->add_option("--steps", run_steps, "Number of steps")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{std::numeric_limits<std::int64_t>::max()}));
  add_engine_options(run, engine_name, threads);
  run->add_option("--trace", trace,
                  "Write every world to this file, one JSON line {\"step\": t, \"circles\": [...]} each");

  std::string exec, level = "exact", shard = "0/1";
  circles::cli::ConformOptions conform_options;
  conform_options.seed = std::random_device{}();
  double timeout = 10;
  std::uint64_t only_case = 0;
  CLI::App* conform = app.add_subcommand(
      "conform", "Check an engine (--engine) or any program speaking the step protocol (--exec) against the oracle");
  add_engine_options(conform, engine_name, threads);
  conform->add_option("--exec", exec, "Check this program instead, run as /bin/sh -c COMMAND (docs/protocol.md)");
  conform->add_option("--level", level, "exact (the nearest double), faithful (1 ulp) or ulps:K; decisions always exact")
      ->capture_default_str();
  conform->add_option("--cases", conform_options.cases, "Worlds to check")->capture_default_str();
  conform->add_option("--seed", conform_options.seed, "Seed of the worlds (default: a random one, printed)");
  conform->add_option("--steps", conform_options.steps, "Steps chained per world, the candidate fed its own answers")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}));
  conform->add_option("--shard", shard, "Check only the cases c with c mod n == i, for parallel jobs")
      ->capture_default_str();
  conform->add_option("--timeout", timeout, "Seconds to wait for each answer")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 3600.0));
  CLI::Option* case_option = conform->add_option("--case", only_case, "Check only this case (to replay a counterexample)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every usage error exits 2, like every other bad input.
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    if (*serve) {
      std::ios::sync_with_stdio(false);  // serve reads and writes only through the C++ streams
      return circles::cli::serve(engine(engine_name), threads, std::cin, std::cout, std::cerr);
    }
    if (*conform) {
      try {
        conform_options.level = circles::cli::parse_level(level);
        std::tie(conform_options.shard, conform_options.shards) = circles::cli::parse_shard(shard);
      } catch (const std::invalid_argument& e) {
        std::cerr << "circles conform: " << e.what() << "\n";
        return 2;
      }
      if (!exec.empty() && conform->count("--engine") > 0) {
        std::cerr << "circles conform: --engine and --exec exclude each other: check one candidate at a time\n";
        return 2;
      }
      if (*case_option) conform_options.only_case = only_case;
      try {
        std::unique_ptr<Candidate> candidate;
        if (exec.empty())
          candidate = std::make_unique<EngineCandidate>(engine(engine_name), threads);
        else
          candidate = std::make_unique<ProcessCandidate>(
              exec, std::chrono::milliseconds(static_cast<long long>(std::ceil(timeout * 1000))));
        return circles::cli::conform(*candidate, conform_options, std::cout);
      } catch (const BrokenCandidate& e) {
        std::cerr << "circles conform: " << e.what() << "\n";
        return 2;
      }
    }
    const bool from_file = !scene_path.empty();
    const auto scene = from_file ? load_scene(scene_path) : default_scene();
    const std::string scene_name = from_file ? scene_path : "the embedded default scene";

    if (*run) {
      const RunOptions options{run_steps, &engine(engine_name), threads, trace};
      const RunResult result = circles::cli::run(doubles_of(scene), options);
      std::cout << "circles run: " << scene_name << ": ";
      print_summary(result, scene.size(), options, std::cout);
      if (!result.overflow) return 0;
      std::cerr << "circles run: " << result.overflow->what() << "; stopped after " << result.steps << " steps";
      if (!trace.empty()) std::cerr << ", and the trace " << trace << " holds w_0 to w_" << result.steps;
      std::cerr << "\n";
      return 2;
    }

    report_oracle(scene, scene_name, steps, std::cout);
    if (*oracle) return 0;
    // The main job: every engine against the correctly rounded oracle, on the same scene and steps.
    std::cout << "\nthe engines, each stepped beside the oracle (a rounding engine against the correctly rounded step "
                 "from its own last world; the exact engine against the oracle's exact sequence)\n";
    bool all_agree = true;
    for (const EngineEntry& e : engines()) {
      if (e.name == "oracle") continue;
      const Comparison c = compare_with_oracle(e, doubles_of(scene), steps, 0);
      print_comparison(e, c, std::cout);
      all_agree = all_agree && !c.difference;
    }
    return all_agree ? 0 : 1;
  } catch (const SceneError& e) {
    std::cerr << "circles: " << e.what() << "\n";
    return 2;
  } catch (const TraceError& e) {
    std::cerr << "circles: " << e.what() << "\n";
    return 2;
  }
}
