// The `circles` program. With no subcommand it runs the main job on the embedded default scene.
#include "cli/oracle_report.hpp"
#include "cli/scene.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every usage error exits 2, like every other bad input.
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    const bool from_file = !scene_path.empty();
    const auto scene = from_file ? circles::cli::load_scene(scene_path) : circles::cli::default_scene();
    circles::cli::report_oracle(scene, from_file ? scene_path : "the embedded default scene", steps, std::cout);
  } catch (const circles::cli::SceneError& e) {
    std::cerr << "circles: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
