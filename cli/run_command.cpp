#include "cli/run_command.hpp"

#include "formats/counted.hpp"
#include "cli/run.hpp"
#include "formats/scene.hpp"

#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace circles::cli {

using formats::any_is_standard_output;
using formats::counted;
using formats::default_scene;
using formats::doubles_of;
using formats::kMaxSceneSteps;
using formats::load_scene_world;
using formats::random_world;
using formats::Scene;
using formats::SceneWorld;

namespace {

// The world to step, in doubles, and the scene's "steps" if it has them. A scene file is read into doubles alone
// (load_scene_world), and a random world stays in doubles: its exact circles would take ten times the memory,
// and the engines step doubles.
SceneWorld world_of(const SceneOptions& scene, const engines::EngineEntry& engine) {
  const RandomOptions& r = scene.random;
  switch (scene.source()) {
    case SceneOptions::Source::random:
      return {.name = std::nullopt, .steps = std::nullopt,
              .circles = random_world(r.circles, r.coverage, r.seed, engine.bytes_per_circle)};
    case SceneOptions::Source::file: return load_scene_world(scene.path);
    case SceneOptions::Source::embedded: break;
  }
  const Scene s = default_scene();
  return {.name = std::nullopt, .steps = s.steps, .circles = doubles_of(s)};
}

// After an overflow: where it stopped, and what each output holds.
void print_overflow(const RunResult& result, const RunCommandOptions& given, std::ostream& err) {
  err << "circles run: " << result.overflow->what() << "; stopped after " << counted(result.steps, "step");
  if (!given.trace.empty()) err << ", and the trace " << given.trace << " holds w_0 to w_" << result.steps;
  if (!given.exact_trace.empty()) err << ", and the exact trace " << given.exact_trace << " w_0 to w_" << result.steps;
  if (!given.render.empty() || !given.video.empty())
    err << (given.trace.empty() ? ", and " : "; ") << "the frames" << (given.video.empty() ? "" : " of " + given.video)
        << (given.render.empty() ? "" : " in " + given.render) << " go to w_" << result.steps / given.every * given.every;
  err << "\n";
}

}  // namespace

CLI::App* add_run_command(CLI::App& app, SceneOptions& scene, RunCommandOptions& options) {
  CLI::App* run = app.add_subcommand(
      "run",
      "Run an engine on a scene, optionally writing a JSON Lines trace, PNG frames or a video (see run.md in the docs)");
  // Up to 2^63 - 1, as a scene's "steps".
  options.steps_option = add_scene_options(run, scene, options.steps, kMaxSceneSteps);
  add_engine_options(run, options.engine, options.threads);
  takes_output_file(run->add_option("--trace", options.trace,
                                    "Write every world to FILE, one JSON line {\"step\": t, \"circles\": [...]} each"));
  takes_output_file(run->add_option("--exact-trace", options.exact_trace,
                                    "With --engine exact: write every world's exact state to FILE, the lines of --trace "
                                    "with each number the rational \"n/d\""));
  takes(run->add_option("--render", options.render,
                        "Draw frames as 1280x720 PNGs DIR/frame-000000.png, ... (DIR created if missing; - for "
                        "stdout, one PNG after another)"),
        "DIR", "a directory for the frames, or - for stdout");
  options.every_option = takes_whole_number(
      run->add_option("--every", options.every, "A frame every N steps: w_0, w_N, w_2N, ... (for --render and --video)")
          ->capture_default_str(),
      "N", 1, std::numeric_limits<std::int64_t>::max());
  takes(run->add_option("--video", options.video,
                        "Pipe the frames to ffmpeg for an H.264 video FILE.mp4 at 60 frames/s (- for stdout, a "
                        "fragmented MP4)"),
        "FILE", "a file.mp4 to write, or - for stdout");
  run->add_flag("--fit", options.fit,
                "Scale and centre the frames to hold every circle of every frame (default: 1 unit = 1 pixel)");
  run->add_flag("--stats", options.stats,
                "Also print the run's figures: steps, circles, engine, threads, times, ns per circle-step");
  return run;
}

int run_command(const SceneOptions& scene, const RunCommandOptions& given, std::ostream& out, std::ostream& err) {
  const engines::EngineEntry& engine = engines::engine(given.engine);
  // A scene file is read first, so that a bad scene is named before any option that does not go with it; a random
  // world is made only for a run that will take place.
  const bool from_file = scene.source() == SceneOptions::Source::file;
  SceneWorld world = from_file ? world_of(scene, engine) : SceneWorld{};
  if ((given.fit || given.every_option->count() > 0) && given.render.empty() && given.video.empty()) {
    err << "circles run: --fit and --every shape the frames of --render and --video, and neither is given\n";
    return 2;
  }
  if (const std::string both = two_on_stdout({{"--trace", given.trace}, {"--exact-trace", given.exact_trace},
                                               {"--render", given.render}, {"--video", given.video}});
      !both.empty()) {
    err << "circles run: " << both << "\n";
    return 2;
  }
  if (!from_file) world = world_of(scene, engine);
  const RunOptions options{.steps = given.steps_option->count() == 0 && world.steps ? *world.steps : given.steps,
                           .engine = &engine,
                           .threads = given.threads,
                           .trace = given.trace,
                           .exact_trace = given.exact_trace,
                           .render = given.render,
                           .every = given.every,
                           .video = given.video,
                           .fit = given.fit,
                           .progress = given.progress};
  const std::size_t circle_count = world.circles.size();
  RunResult result;
  try {
    result = run(std::move(world.circles), options);
  } catch (const std::invalid_argument& e) {  // options run() refuses before any output, e.g. --exact-trace
    err << "circles run: " << e.what() << "\n";
    return 2;
  }
  // An output on stdout keeps stdout to itself: the summary goes to stderr.
  std::ostream& said = any_is_standard_output({given.trace, given.exact_trace, given.render, given.video}) ? err : out;
  said << "circles run: " << scene.name() << ": ";
  print_summary(result, circle_count, options, said);
  if (given.stats) print_stats(result, circle_count, options, said);
  if (!result.overflow) return 0;
  print_overflow(result, given, err);
  return 2;
}

}  // namespace circles::cli
