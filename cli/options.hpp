// Options that several commands of `circles` declare alike: the engine and its threads (run, serve), and the
// scene a command runs on, a file or a random scene (oracle, run), with the one choice between them.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace circles::cli {

// --engine NAME, checked against the registry (its message lists the valid names), and --threads T.
void add_engine_options(CLI::App* command, std::string& engine_name, unsigned& threads);

// --random N --coverage C --seed S: the benchmarks' random scene (impl/random_scene.hpp) instead of a scene file.
struct RandomOptions {
  std::size_t circles = 0;  // 0: no random scene
  double coverage = 0.1;    // the benchmarks' coverage of the dense target (docs/benchmarks.md, Targets)
  std::uint64_t seed = 1;   // the benchmarks' seed
};

// The scene of `circles oracle` and `circles run`: a scene file, a random scene, or else the embedded default.
struct SceneOptions {
  std::string path;  // the scene file, or empty
  RandomOptions random;

  enum class Source { embedded, file, random };
  // Which of the three the command line chose.
  Source source() const;
  // How messages name it: "the embedded default scene", the file's path, or "a random scene of 1000 circles
  // (coverage 0.1, seed 1)".
  std::string name() const;
};

// The positional scene file of `command`, and the random scene's options, which exclude `file`: the pieces of
// add_scene_options.
CLI::Option* add_scene_file(CLI::App* command, SceneOptions& scene);
void add_random_options(CLI::App* command, CLI::Option* file, SceneOptions& scene);

// The scene of a command that runs on one (oracle, run) and its steps, in the order --help lists them: the
// positional scene file, --steps N from 0 to `most` (default: the scene's "steps", else what `steps` holds), and
// the random scene's options. Returns --steps, whose count() says whether it was given, and whose default
// main.cpp shows for a scene with "steps". A `most` below 2^64 - 5 also refuses "-5", which CLI11 reads as
// 2^64 - 5 (strtoull).
template <class Count>
CLI::Option* add_scene_options(CLI::App* command, SceneOptions& scene, Count& steps, Count most) {
  CLI::Option* file = add_scene_file(command, scene);
  CLI::Option* steps_option =
      command->add_option("--steps", steps, "Number of steps (default: the scene's \"steps\", else 100)")
          ->capture_default_str()
          ->check(CLI::Range(Count{0}, most));
  add_random_options(command, file, scene);
  return steps_option;
}

}  // namespace circles::cli
