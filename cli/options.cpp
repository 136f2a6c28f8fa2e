#include "cli/options.hpp"

#include "engines/registry.hpp"
#include "formats/scene.hpp"

#include <limits>

namespace circles::cli {
namespace {

// "The engine, one of: double (the double engine ...); oracle (...)", from the registry.
std::string engine_help() {
  std::string help;
  for (const engines::EngineEntry& e : engines::engines())
    help += (help.empty() ? "The engine, one of: " : "; ") + std::string(e.name) + " (" + std::string(e.summary) + ")";
  return help;
}

}  // namespace

void add_engine_options(CLI::App* command, std::string& engine_name, unsigned& threads) {
  command
      ->add_option("--engine", engine_name, engine_help())
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& name) {
            return engines::find_engine(name) ? std::string() : std::string(engines::UnknownEngine(name).what());
          },
          "ENGINE"));
  // CLI11 reads unsigned values with strtoull, which wraps "-1" to 2^64 - 1, so the range refuses negatives too.
  command->add_option("--threads", threads, "Threads (0: one per core that other programs leave free)")
      ->capture_default_str()
      ->check(CLI::Range(0u, engines::max_threads()));
}

SceneOptions::Source SceneOptions::source() const {
  if (random.circles > 0) return Source::random;
  return path.empty() ? Source::embedded : Source::file;
}

std::string SceneOptions::name() const {
  switch (source()) {
    case Source::random: return formats::random_scene_name(random.circles, random.coverage, random.seed);
    case Source::file: return path;
    case Source::embedded: break;
  }
  return "the embedded default scene";
}

CLI::Option* add_scene_file(CLI::App* command, SceneOptions& scene) {
  // No CLI::ExistingFile on the scene: a missing file or a directory is reported by the scene loader, as every
  // other bad scene is (docs/scenes.md).
  return command->add_option("scene", scene.path, "Scene file (docs/scenes.md; default: the embedded default scene)");
}

void add_random_options(CLI::App* command, CLI::Option* file, SceneOptions& scene) {
  RandomOptions& random = scene.random;
  // Up to 2^63 - 1, which refuses "-5" (read as 2^64 - 5); a count beyond memory is refused with its bytes.
  CLI::Option* n = command
                       ->add_option("--random", random.circles,
                                    "Instead of a scene file, N random circles like the benchmarks' (r 2-6, |v| <= 100)")
                       ->check(CLI::Range(std::size_t{1}, std::size_t{std::numeric_limits<std::int64_t>::max()}))
                       ->excludes(file);
  command->add_option("--coverage", random.coverage, "With --random: the circles' area over their square's, in (0, 1]")
      ->capture_default_str()
      ->needs(n);
  command->add_option("--seed", random.seed, "With --random: the seed")->capture_default_str()->needs(n);
}

}  // namespace circles::cli
