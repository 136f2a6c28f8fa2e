// `circles run [SCENE]`: an engine stepping a scene, with a trace, PNG frames or a video if asked (docs/run.md);
// the loop itself and its printing are cli/run.hpp.
#pragma once

#include "cli/options.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <ostream>
#include <string>

namespace circles::cli {

// What the command line gave.
struct RunCommandOptions {
  std::uint64_t steps = 100;            // --steps, else the scene's "steps", else 100
  CLI::Option* steps_option = nullptr;  // whether --steps was given, and its default for --help
  std::string engine = "double";        // --engine NAME (engines/registry.hpp)
  unsigned threads = 0;                 // --threads T (0: chosen from the load, impl::choose_threads)
  std::string trace, exact_trace;       // --trace FILE, --exact-trace FILE ("" for none)
  std::string render, video;            // --render DIR, --video FILE.mp4 ("" for none)
  std::uint64_t every = 1;              // --every K
  CLI::Option* every_option = nullptr;  // whether --every was given
  bool fit = false, stats = false;      // --fit, --stats
  std::ostream* progress = nullptr;     // the progress bar's terminal, or none
};

// Declares the command and its options on `app`; the scene's options go to `scene`.
CLI::App* add_run_command(CLI::App& app, SceneOptions& scene, RunCommandOptions& options);

// The command: the run's summary (and with --stats its figures) on `out`, or on `err` when an output goes to
// stdout ("-", /dev/stdout), 0; or 2 with the reason on `err` for
// options that do not go together, or a run stopped by an overflow (what its outputs hold then). Throws
// SceneError for a scene that cannot be read, and OutputError or VideoError for an output that cannot be written.
int run_command(const SceneOptions& scene, const RunCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace circles::cli
