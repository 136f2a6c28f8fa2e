// The `circles` program: every command declared (each in its own file, cli/*_command.hpp), the command line parsed,
// and the command it names run. With no command it runs the main job on the embedded default scene
// (cli/main_job.hpp): the oracle's report, then every engine checked against the correctly rounded oracle step by
// step.
#include "cli/check_trace_command.hpp"
#include "cli/conform_command.hpp"
#include "cli/main_job.hpp"
#include "cli/merge_command.hpp"
#include "cli/oracle_command.hpp"
#include "cli/run.hpp"  // TraceError
#include "cli/run_command.hpp"
#include "cli/serve_command.hpp"
#include "cli/usage.hpp"
#include "cli/vectors.hpp"
#include "cli/version.hpp"
#include "engines/registry.hpp"
#include "formats/scene.hpp"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>

namespace {

using namespace circles::cli;

// Every command's options, and the command each is parsed into.
struct Commands {
  SceneOptions scene;  // of oracle and run
  OracleCommandOptions oracle_options;
  ServeCommandOptions serve_options;
  RunCommandOptions run_options;
  ConformCommandOptions conform_options;
  MergeCommandOptions merge_options;
  VectorsOptions vectors_options;
  CheckTraceCommandOptions check_trace_options;
  CLI::App *oracle = nullptr, *serve = nullptr, *run = nullptr, *conform = nullptr, *merge = nullptr,
           *vectors = nullptr, *check_trace = nullptr;
};

// The commands, in the order --help lists them.
void declare(CLI::App& app, Commands& c) {
  c.oracle = add_oracle_command(app, c.scene, c.oracle_options);
  c.serve = add_serve_command(app, c.serve_options);
  c.run = add_run_command(app, c.scene, c.run_options);
  c.conform = add_conform_command(app, c.conform_options);
  c.merge = add_report_command(app, c.merge_options);
  c.vectors = add_vectors_command(app, c.vectors_options);
  c.check_trace = add_check_trace_command(app, c.check_trace_options);
}

// Parses the command line; the exit status when the program ends there (--help, --version, a usage error).
std::optional<int> parse(CLI::App& app, Commands& c, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    // `circles run SCENE --help`: the default of --steps shown is that scene's "steps", when it has one.
    if (!c.scene.path.empty()) try {
        if (const std::optional<std::uint64_t> scene_steps = load_scene_world(c.scene.path).steps)
          for (CLI::Option* o : {c.oracle_options.steps_option, c.run_options.steps_option})
            o->default_str(std::to_string(*scene_steps));
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
  return std::nullopt;
}

// The command parsed, run. A progress line or bar only on a terminal: output to a pipe, a file or CI stays free
// of it.
int dispatch(Commands& c) {
  if (*c.serve) {
    std::ios::sync_with_stdio(false);  // serve reads and writes only through the C++ streams
    return serve_command(c.serve_options, std::cin, std::cout, std::cerr);
  }
  if (*c.vectors) return vectors_command(c.vectors_options, std::cout, std::cerr);
  if (*c.merge) return merge_command(c.merge_options.out, c.merge_options.reports, std::cout, std::cerr);
  if (*c.check_trace)
    return check_trace_command(c.check_trace_options.file, trace_reference(c.check_trace_options.engine), std::cout,
                               std::cerr);
  if (*c.conform) {
    note_given(*c.conform, c.conform_options);
    if (isatty(STDOUT_FILENO)) c.conform_options.progress = &std::cout;
    return conform_command(c.conform_options, std::cout, std::cerr);
  }
  if (*c.run) {
    if (isatty(STDERR_FILENO)) c.run_options.progress = &std::cerr;
    return run_command(c.scene, c.run_options, std::cout, std::cerr);
  }
  if (*c.oracle) return oracle_command(c.scene, c.oracle_options, std::cout, std::cerr);
  return main_job(c.oracle_options.steps, std::cout);
}

// A world too large for memory that got past the checks (a huge scene file, or --random N near the limit).
int out_of_memory(const Commands& c) {
  const std::size_t n = c.scene.random.circles;
  const std::size_t per_circle = *c.oracle ? circles::formats::kOracleBytesPerCircle
                                           : circles::engines::engine(c.run_options.engine).bytes_per_circle;
  if (n > 0 && n <= std::numeric_limits<std::size_t>::max() / per_circle)
    std::cerr << "circles: world too large for memory: " << n << " circles need about " << n * per_circle
              << " bytes, and an allocation failed\n";
  else
    std::cerr << "circles: out of memory: an allocation failed\n";
  return 2;
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
  Commands commands;
  declare(app, commands);
  if (const std::optional<int> status = parse(app, commands, argc, argv)) return *status;
  try {
    return dispatch(commands);
  } catch (const SceneError& e) {
    std::cerr << "circles: " << e.what() << "\n";
    return 2;
  } catch (const TraceError& e) {
    std::cerr << "circles: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return out_of_memory(commands);
  }
}
