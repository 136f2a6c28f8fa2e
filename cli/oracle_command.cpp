#include "cli/oracle_command.hpp"

#include "cli/oracle_report.hpp"
#include "formats/scene.hpp"

namespace circles::cli {
namespace {

// The scene as exact circles: the oracle's report holds them as rationals.
formats::Scene exact_scene(const SceneOptions& scene) {
  const RandomOptions& r = scene.random;
  switch (scene.source()) {
    case SceneOptions::Source::random:
      return formats::random_scene(r.circles, r.coverage, r.seed, formats::kOracleBytesPerCircle);
    case SceneOptions::Source::file: return formats::load_scene(scene.path);
    case SceneOptions::Source::embedded: break;
  }
  return formats::default_scene();
}

}  // namespace

CLI::App* add_oracle_command(CLI::App& app, SceneOptions& scene, OracleCommandOptions& options) {
  CLI::App* oracle = app.add_subcommand(
      "oracle", "Run the exact oracle in both profiles on a scene and report what it did (the main job's first part)");
  options.steps_option = add_scene_options(oracle, scene, options.steps, kMaxOracleSteps);
  return oracle;
}

int oracle_command(const SceneOptions& scene, const OracleCommandOptions& options, std::ostream& out,
                   std::ostream& err) {
  const formats::Scene s = exact_scene(scene);
  std::size_t steps = options.steps;
  if (options.steps_option->count() == 0 && s.steps) {
    if (*s.steps > kMaxOracleSteps) {
      err << "circles oracle: " << scene.name() << ": \"steps\": " << *s.steps << " is more than the "
          << kMaxOracleSteps << " steps the oracle takes; give --steps\n";
      return 2;
    }
    steps = *s.steps;
  }
  report_oracle(s.circles, scene.name(), steps, out);
  return 0;
}

}  // namespace circles::cli
