// Options that several commands of `circles` declare alike: the engine and its threads (run, serve), and the
// scene a command runs on, a file or a random scene (oracle, run), with the one choice between them, and the files
// of the reports (conform, report merge).
#pragma once

#include "conform/report_formats.hpp"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace circles::cli {

// What an option takes, said once for the help and for the messages: its metavariable (`circles run --help`
// shows "--steps N") and, in words, the values it takes ("a whole number from 0 to 100"), the description of the
// option's one check. The check refuses any other value in the circles voice, "--steps: \"x\" is not a whole
// number from 0 to 100", before CLI11 would try to convert it; a value missing is said with the same words
// (cli/usage.hpp).
CLI::Option* takes_whole_number(CLI::Option* option, const std::string& metavariable, std::uint64_t least,
                                std::uint64_t most);
CLI::Option* takes_number(CLI::Option* option, const std::string& metavariable, const std::string& wants,
                          bool (*in_range)(double));
// Any text, or a file, or a directory: `wants` only says what it is ("a file to write, or - for stdout").
CLI::Option* takes(CLI::Option* option, const std::string& metavariable, const std::string& wants);
// DIR: a directory that `wants` describes; "-" is refused, since no stream holds a directory.
CLI::Option* takes_directory(CLI::Option* option, const std::string& wants);
CLI::Option* takes_output_file(CLI::Option* option);  // FILE: a file to write, or - for stdout
CLI::Option* takes_input_file(CLI::Option* option);   // FILE: a file to read, or - for stdin
// One of `names`, refused otherwise: "--engine: \"fast\" is not double or exact".
CLI::Option* takes_one_of(CLI::Option* option, const std::string& metavariable, const std::vector<std::string>& names);

// A FILE option per report format (conform/report_formats.hpp), "--junit FILE" into files["--junit"], but
// `except`'s.
void add_report_options(CLI::App* command, conform::ReportFiles& files, const conform::ReportFormat* except = nullptr);

// "--trace and --video both go to stdout; give - to one of them" when two of the outputs `given` (each an option
// and its path, "" for none) are stdout (formats::is_standard_output), whose bytes would interleave; else "".
std::string two_on_stdout(const std::vector<std::pair<std::string, std::string>>& given);
// Whether any of the outputs `given` (each an option and its path) is stdout: the command's summary then goes to
// stderr, so that stdout holds the output alone.
bool any_on_stdout(const std::vector<std::pair<std::string, std::string>>& given);

// The metavariable and the words of what `option` takes, as the functions above set them: {"N", "a whole
// number from 0 to 100"}; a flag's are empty.
struct Takes {
  std::string metavariable, wants;
};
Takes takes_of(const CLI::Option& option);

// --engine NAME, checked against the registry (its message lists the valid names), and --threads T.
void add_engine_options(CLI::App* command, std::string& engine_name, unsigned& threads);

// --random N --coverage C --seed S: the benchmarks' random scene (formats/random_scene.hpp) instead of a scene file.
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
  // How messages name it: "the embedded default scene", the file's path ("<stdin>" for -), or "a random scene of 1000 circles
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
// main.cpp shows for a scene with "steps".
template <class Count>
CLI::Option* add_scene_options(CLI::App* command, SceneOptions& scene, Count& steps, Count most) {
  CLI::Option* file = add_scene_file(command, scene);
  CLI::Option* steps_option = takes_whole_number(
      command->add_option("--steps", steps, "Number of steps; by default the scene's own \"steps\" where it has them")
          ->capture_default_str(),
      "N", 0, most);
  add_random_options(command, file, scene);
  return steps_option;
}

}  // namespace circles::cli
