// The `circles` program. With no subcommand it runs the main job on the embedded default scene: the oracle's
// report, then every engine checked against the correctly rounded oracle step by step.
#include "cli/check_trace_command.hpp"
#include "cli/conform_command.hpp"
#include "cli/oracle_report.hpp"
#include "cli/report.hpp"
#include "cli/run.hpp"
#include "cli/usage.hpp"
#include "cli/vectors.hpp"
#include "cli/version.hpp"
#include "conform/check_trace.hpp"
#include "conform/engines.hpp"
#include "conform/serve.hpp"
#include "formats/scene.hpp"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <random>

namespace {

using namespace circles::cli;
using namespace circles::conform;
using namespace circles::formats;

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

// --random N --coverage C --seed S: the benchmarks' random scene (impl/random_scene.hpp) instead of a scene file.
struct RandomOptions {
  std::size_t circles = 0;  // 0: no random scene
  double coverage = 0.1;    // the benchmarks' coverage of the targets
  std::uint64_t seed = 1;   // the benchmarks' seed
};

void add_random_options(CLI::App* command, CLI::Option* scene, RandomOptions& random) {
  // Up to 2^63 - 1, which refuses "-5" (read as 2^64 - 5); a count beyond memory is refused with its bytes.
  CLI::Option* n = command
                       ->add_option("--random", random.circles,
                                    "Instead of a scene file, N random circles like the benchmarks' (r 2-6, |v| <= 100)")
                       ->check(CLI::Range(std::size_t{1}, std::size_t{std::numeric_limits<std::int64_t>::max()}))
                       ->excludes(scene);
  command->add_option("--coverage", random.coverage, "With --random: the circles' area over their square's, in (0, 1]")
      ->capture_default_str()
      ->needs(n);
  command->add_option("--seed", random.seed, "With --random: the seed")->capture_default_str()->needs(n);
}

}  // namespace

int main(int argc, char** argv) {
  // A write beyond the file size limit (ulimit -f) fails with EFBIG instead of killing the program, so that
  // it ends like a full disk: a message naming the file, and no half-written output left.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"circles: a conformance suite for the circles physics spec.\nWith no command, plain `circles` runs the "
               "main job on the embedded default scene: the exact oracle's report (as `circles oracle`), then every "
               "engine checked against the oracle step by step; exit 0 when all agree"};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", "circles " CIRCLES_VERSION);

  std::string scene_path;
  std::size_t steps = 100;
  constexpr std::size_t kMaxOracleSteps = 1000000;
  RandomOptions random_options;
  CLI::App* oracle = app.add_subcommand(
      "oracle", "Run the exact oracle in both profiles on a scene and report what it did (the main job's first part)");
  // No CLI::ExistingFile on the scene of oracle or run: a missing file or a directory is reported by the scene
  // loader, as every other bad scene is (docs/scenes.md).
  CLI::Option* oracle_scene =
      oracle->add_option("scene", scene_path, "Scene file (docs/scenes.md; default: the embedded default scene)");
  CLI::Option* oracle_steps =
      oracle->add_option("--steps", steps, "Number of steps (default: the scene's \"steps\", else 100)")
          ->capture_default_str()
      ->check(CLI::Range(std::size_t{0}, kMaxOracleSteps));
  add_random_options(oracle, oracle_scene, random_options);

  std::string engine_name = "double";
  unsigned threads = 0;
  CLI::App* serve = app.add_subcommand(
      "serve", "Answer step-protocol requests on stdin, one JSON line each, on stdout (docs/protocol.md)");
  add_engine_options(serve, engine_name, threads);

  std::uint64_t run_steps = 100;
  std::string trace;
  CLI::App* run = app.add_subcommand(
      "run", "Run an engine on a scene, optionally writing a JSON Lines trace, PNG frames or a video (docs/run.md)");
  CLI::Option* run_scene =
      run->add_option("scene", scene_path, "Scene file (docs/scenes.md; default: the embedded default scene)");
  // Up to 2^63 - 1: CLI11 reads "-5" as 2^64 - 5 (strtoull), which this range refuses.
  CLI::Option* run_steps_option =
      run->add_option("--steps", run_steps, "Number of steps (default: the scene's \"steps\", else 100)")
          ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{0}, kMaxSceneSteps));
  add_random_options(run, run_scene, random_options);
  add_engine_options(run, engine_name, threads);
  run->add_option("--trace", trace,
                  "Write every world to this file, one JSON line {\"step\": t, \"circles\": [...]} each");
  std::string exact_trace;
  run->add_option("--exact-trace", exact_trace,
                  "With --engine exact: write every world's exact state to this file, the lines of --trace with "
                  "each number the rational \"n/d\"");
  std::string render_dir, video;
  std::uint64_t every = 1;
  bool fit = false, stats = false;
  run->add_option("--render", render_dir, "Draw frames as 1280x720 PNGs DIR/frame-000000.png, ... (DIR created if missing)");
  run->add_option("--every", every, "A frame every K steps: w_0, w_K, w_2K, ... (for --render and --video)")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{std::numeric_limits<std::int64_t>::max()}));
  run->add_option("--video", video, "Pipe the frames to ffmpeg for an H.264 video FILE.mp4 at 60 frames/s");
  run->add_flag("--fit", fit, "Scale and centre the frames to hold every circle of every frame (default: 1 unit = 1 pixel)");
  run->add_flag("--stats", stats, "Also print the run's figures: steps, circles, engine, threads, times, ns per circle-step");

  circles::cli::ConformCommandOptions conform_options;
  conform_options.seed = std::random_device{}();
  CLI::App* conform = app.add_subcommand(
      "conform",
      "Check an engine (--engine) or any program speaking the step protocol (--exec) against the oracle; exits 0 "
      "(conforms), 1 (a counterexample) or 2 (cannot check) (docs/conform.md)");
  add_engine_options(conform, conform_options.engine, conform_options.threads);
  conform->add_option("--exec", conform_options.exec,
                      "Check this program instead, run as /bin/sh -c COMMAND (docs/protocol.md)");
  conform
      ->add_option("--level", conform_options.level,
                   "exact (the nearest double), faithful (1 ulp) or ulps:K; decisions always exact")
      ->capture_default_str();
  // --cases and --case up to 2^63 - 1, as the counts of run and vectors: CLI11 reads "-1" as 2^64 - 1 (strtoull),
  // which as --cases would run for ever and as --case would check no case at all (I + 1 wraps to 0) and conform.
  constexpr std::uint64_t kMaxCases = std::numeric_limits<std::int64_t>::max();
  conform->add_option("--cases", conform_options.cases, "Worlds to check")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{0}, kMaxCases));
  conform->add_option("--seed", conform_options.seed, "Seed of the worlds (default: a random one, printed)");
  conform->add_option("--steps", conform_options.steps, "Steps chained per world, the candidate fed its own answers")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}));
  conform->add_option("--profile", conform_options.profile,
                       "resolved, or literal (only worlds where the seed's step is defined, checked against it)")
      ->capture_default_str();
  conform->add_option("--shard", conform_options.shard,
                      "Check only the rounds q (of one case per family) with q mod n == i, for parallel jobs")
      ->capture_default_str();
  conform->add_option("--save", conform_options.save,
                      "Replay every counterexample stored in DIR first, and store a new one there (with its picture)");
  conform->add_option("--svg", conform_options.svg,
                      "Draw a counterexample's picture in FILE (default: beside it in --save DIR, else none)");
  conform->add_option("--timeout", conform_options.timeout,
                      "Seconds to wait for each answer, up to 512 circles; (n/512)^2 times as long for n circles above")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 3600.0));
  conform->add_option("--max-circles", conform_options.max_circles,
                      "The most circles of a big world (docs/conform.md, Big worlds): 4097 crosses every power of two "
                      "up to 4096; fast programs go to 100000 or more")
      ->capture_default_str()
      ->check(CLI::Range(circles::properties::kMinMaxCircles, std::size_t{1} << 31));
  conform->add_option("--case", conform_options.only_case, "Check only this case (to replay a counterexample)")
      ->check(CLI::Range(std::uint64_t{0}, kMaxCases));
  conform->add_option("--report", conform_options.report,
                      "Also write the verdict as JSON to FILE (docs/conform.md, Reports for CI)");
  conform->add_option("--junit", conform_options.junit,
                      "Also write the verdict as JUnit XML to FILE, a test case per family");
  conform->add_flag("--keep-going", conform_options.keep_going,
                    "Check every family, shrink a counterexample per failing family, and print a row per family");
  CLI::Option* families_option = conform->add_option("--families", conform_options.families,
                                                     "Check only these families, A,B,... (docs/conform.md)");
  conform->add_option("--skip-families", conform_options.skip_families, "Check every family but these, A,B,...")
      ->excludes(families_option);
  conform->add_option("--expect", conform_options.expect,
                      "Known failures, FAMILY fail REASON a line: failing them passes, passing them fails (implies "
                      "--keep-going)");
  conform->add_option("--write-expect", conform_options.write_expect,
                      "Write this run's failing families to FILE as an expectation file (implies --keep-going)");

  CLI::App* report = app.add_subcommand("report", "Work with the JSON reports of circles conform --report");
  report->require_subcommand(1, 1);
  std::string merged_file;
  std::vector<std::string> shard_files;
  CLI::App* merge = report->add_subcommand(
      "merge", "Combine the reports of the shards of one run into OUT; exits 0, 1 or 2 as the merged verdict");
  merge->add_option("out", merged_file, "The merged report (written whole or not at all)")->required();
  merge->add_option("reports", shard_files, "The shards' reports")->required()->check(CLI::ExistingFile);

  circles::cli::VectorsOptions vectors_options;
  CLI::App* vectors = app.add_subcommand(
      "vectors", "Write golden test vectors for other languages to DIR/vectors.jsonl (docs/vectors.md)");
  vectors->add_option("--out", vectors_options.out, "The directory of vectors.jsonl (created if missing)")->required();
  // Ranges as for --steps: CLI11 reads "-5" as 2^64 - 5, which they refuse.
  vectors->add_option("--cases", vectors_options.cases, "Generated worlds: conform's cases 0 to N-1 of the seed")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{1000000}));
  vectors->add_option("--seed", vectors_options.seed, "Seed of the generated worlds")->capture_default_str();
  vectors->add_option("--scenes", vectors_options.scenes, "Directory of scenes (*.json) whose first worlds are cases")
      ->capture_default_str();
  vectors->add_option("--scene-steps", vectors_options.scene_steps, "Worlds w_0, w_1, ... taken from each scene")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{1000000}));

  std::string trace_file, trace_engine = "double";
  CLI::App* check_trace = app.add_subcommand(
      "check-trace",
      "Check a trace recorded by any implementation step by step against the spec; exits 0 (it agrees), 1 (a world "
      "differs) or 2 (not a trace) (docs/vectors.md)");
  // No CLI::ExistingFile: a missing file is reported by the trace reader, as every other bad trace is.
  check_trace->add_option("trace", trace_file, "The trace: JSON Lines, one {\"step\": t, \"circles\": [...]} per world")
      ->required();
  check_trace
      ->add_option("--engine", trace_engine,
                   "double: each world the correctly rounded step of the one before; exact: the oracle's exact "
                   "sequence from the first world, rounded")
      ->capture_default_str()
      ->check(CLI::IsMember({"double", "exact"}));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    // `circles run SCENE --help`: the default of --steps shown is that scene's "steps", when it has one.
    if (!scene_path.empty()) try {
        if (const std::optional<std::uint64_t> scene_steps = load_scene_world(scene_path).steps)
          for (CLI::Option* o : {oracle_steps, run_steps_option}) o->default_str(std::to_string(*scene_steps));
      } catch (const SceneError&) {
        // The help shows 100; the command run without --help names what is wrong with the scene.
      }
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Every usage error exits 2, like every other bad input.
    std::cerr << usage_error(app, e) << "\n";
    return 2;
  }

  try {
    if (*serve) {
      std::ios::sync_with_stdio(false);  // serve reads and writes only through the C++ streams
      return circles::conform::serve(engine(engine_name), threads, std::cin, std::cout, std::cerr);
    }
    if (*vectors) return circles::cli::vectors_command(vectors_options, std::cout, std::cerr);
    if (*merge) return circles::cli::merge_command(merged_file, shard_files, std::cout, std::cerr);
    if (*check_trace)
      return check_trace_command(trace_file, trace_reference(trace_engine), std::cout, std::cerr);
    if (*conform) {
      conform_options.engine_given = conform->count("--engine") > 0;
      conform_options.threads_given = conform->count("--threads") > 0;
      conform_options.case_given = conform->count("--case") > 0;
      conform_options.families_given = conform->count("--families") > 0;
      conform_options.skip_families_given = conform->count("--skip-families") > 0;
      // The progress line only on a terminal: output to a pipe, a file or CI stays free of it.
      if (isatty(STDOUT_FILENO)) conform_options.progress = &std::cout;
      return circles::cli::conform_command(conform_options, std::cout, std::cerr);
    }
    const bool from_file = !scene_path.empty(), random = random_options.circles > 0;
    const auto& [n, coverage, seed] = random_options;
    // A random world for `run` stays in doubles (random_world below): its exact circles would take ten times the
    // memory, and the engines step doubles.
    // A scene file for `run` is read into doubles alone (load_scene_world), for the same reason.
    const Scene scene = random ? (*run ? Scene{} : random_scene(n, coverage, seed, kOracleBytesPerCircle))
                        : from_file ? (*run ? Scene{} : load_scene(scene_path))
                                    : default_scene();
    SceneWorld file_world = *run && from_file ? load_scene_world(scene_path) : SceneWorld{};
    const std::string scene_name = random      ? random_scene_name(n, coverage, seed)
                                   : from_file ? scene_path
                                               : "the embedded default scene";

    if (*run) {
      if ((fit || run->count("--every") > 0) && render_dir.empty() && video.empty()) {
        std::cerr << "circles run: --fit and --every shape the frames of --render and --video, and neither is given\n";
        return 2;
      }
      RunOptions options{run_steps, &engine(engine_name), threads, trace};
      options.exact_trace = exact_trace;
      options.render = render_dir;
      options.every = every;
      options.video = video;
      options.fit = fit;
      // The progress bar only on a terminal: output to a pipe, a file or CI stays free of it.
      if (isatty(STDERR_FILENO)) options.progress = &std::cerr;
      const std::optional<std::uint64_t> scene_steps = from_file ? file_world.steps : scene.steps;
      if (run->count("--steps") == 0 && scene_steps) options.steps = *scene_steps;
      Circles world = random      ? random_world(n, coverage, seed, run_bytes_per_circle(engine_name))
                      : from_file ? std::move(file_world.circles)
                                  : doubles_of(scene);
      const std::size_t circle_count = world.size();
      RunResult result;
      try {
        result = circles::cli::run(std::move(world), options);
      } catch (const std::invalid_argument& e) {  // options run() refuses before any output, e.g. --exact-trace
        std::cerr << "circles run: " << e.what() << "\n";
        return 2;
      }
      std::cout << "circles run: " << scene_name << ": ";
      print_summary(result, circle_count, options, std::cout);
      if (stats) print_stats(result, circle_count, options, std::cout);
      if (!result.overflow) return 0;
      std::cerr << "circles run: " << result.overflow->what() << "; stopped after " << result.steps << " steps";
      if (!trace.empty()) std::cerr << ", and the trace " << trace << " holds w_0 to w_" << result.steps;
      if (!exact_trace.empty()) std::cerr << ", and the exact trace " << exact_trace << " w_0 to w_" << result.steps;
      if (!render_dir.empty() || !video.empty())
        std::cerr << (trace.empty() ? ", and " : "; ") << "the frames"
                  << (video.empty() ? "" : " of " + video) << (render_dir.empty() ? "" : " in " + render_dir)
                  << " go to w_" << result.steps / every * every;
      std::cerr << "\n";
      return 2;
    }

    if (*oracle && oracle->count("--steps") == 0 && scene.steps) {
      if (*scene.steps > kMaxOracleSteps) {
        std::cerr << "circles oracle: " << scene_name << ": \"steps\": " << *scene.steps << " is more than the "
                  << kMaxOracleSteps << " steps the oracle takes; give --steps\n";
        return 2;
      }
      steps = *scene.steps;
    }
    report_oracle(scene.circles, scene_name, steps, std::cout);
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
  } catch (const std::bad_alloc&) {
    // A world too large for memory that got past the checks (a huge scene file, or --random N near the limit).
    const std::size_t n = random_options.circles, per_circle = *oracle ? kOracleBytesPerCircle : run_bytes_per_circle(engine_name);
    if (n > 0 && n <= std::numeric_limits<std::size_t>::max() / per_circle)
      std::cerr << "circles: world too large for memory: " << n << " circles need about " << n * per_circle
                << " bytes, and an allocation failed\n";
    else
      std::cerr << "circles: out of memory: an allocation failed\n";
    return 2;
  }
}
