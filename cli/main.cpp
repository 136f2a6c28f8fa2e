// The `circles` program: every command declared (each in its own file, cli/*_command.hpp), the command line parsed,
// and the command it names run. With no command it runs the main job on the embedded default scene
// (cli/main_job.hpp): the oracle's report, then every engine checked against the correctly rounded oracle step by
// step.
#include "cli/check_trace_command.hpp"
#include "cli/conform_command.hpp"
#include "cli/families_command.hpp"
#include "cli/help.hpp"
#include "cli/interrupt.hpp"
#include "cli/main_job.hpp"
#include "cli/merge_command.hpp"
#include "cli/oracle_command.hpp"
#include "cli/run.hpp"  // TraceError
#include "cli/run_command.hpp"
#include "cli/serve_command.hpp"
#include "cli/usage.hpp"
#include "cli/vectors_command.hpp"
#include "cli/version.hpp"
#include "conform/interrupt.hpp"
#include "engines/registry.hpp"
#include "formats/output_file.hpp"
#include "formats/scene.hpp"
#include "properties/boundaries.hpp"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace circles::cli;
using circles::conform::trace_reference;
using circles::conform::VectorsOptions;
using circles::formats::load_scene_world;
using circles::formats::SceneError;

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
  FamiliesCommandOptions families_options;
  std::vector<std::string> help_topic;  // `circles help COMMAND...`
  CLI::App *oracle = nullptr, *serve = nullptr, *run = nullptr, *conform = nullptr, *merge = nullptr,
           *vectors = nullptr, *check_trace = nullptr, *families = nullptr, *help = nullptr;
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
  c.families = add_families_command(app, c.families_options);
  c.help = app.add_subcommand("help", "Show the help of circles, or of COMMAND (as `circles COMMAND --help` does)");
  takes(c.help->add_option("command", c.help_topic, "The command, and the subcommand for one that has them"),
        "COMMAND", "commands of circles");
  for (CLI::App* command : app.get_subcommands({})) command->group("Commands");
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
  } catch (const CLI::ParseError& e) {
    // --help, --version: printed on stdout, status 0. A usage error: usage_error's line on stderr (the
    // failure-message hook), and status 2, like every other bad input.
    return app.exit(e) == 0 ? 0 : 2;
  }
  return std::nullopt;
}

// The command parsed, run. A progress line or bar only on a terminal, always on stderr: output to a pipe, a file
// or CI stays free of it, and stdout holds only what the command says. Every command but serve ends on SIGINT,
// SIGTERM and SIGHUP as cli/interrupt.hpp says; conform's first signal stops its candidates and reports the
// cases checked (conform/interrupt.hpp), and a second ends it at once.
int dispatch(CLI::App& app, Commands& c) {
  if (*c.help) return help_command(app, c.help_topic, std::cout, std::cerr);
  if (*c.families) {
    print_family_list(circles::properties::parse_profile(c.families_options.profile), std::cout);
    return 0;
  }
  if (*c.serve) {
    std::ios::sync_with_stdio(false);  // serve reads and writes only through the C++ streams
    return serve_command(c.serve_options, std::cin, std::cout, std::cerr);
  }
  if (*c.conform) {
    note_given(*c.conform, c.conform_options);
    // --families with nothing after it: the list, as `circles families` prints it.
    if (c.conform_options.families_given && c.conform_options.families.empty()) {
      print_family_list(circles::properties::parse_profile(c.conform_options.profile), std::cout);
      return 0;
    }
    if (isatty(STDERR_FILENO)) c.conform_options.progress = &std::cerr;
    // A report on stdout keeps stdout to itself: the verdict goes to stderr.
    const ConformCommandOptions& o = c.conform_options;
    const std::vector<std::pair<std::string, std::string>> outputs = output_files(o);
    if (const std::string both = two_on_stdout(outputs); !both.empty()) {
      std::cerr << "circles conform: " << both << "\n";
      return 2;
    }
    const bool stdout_taken = any_on_stdout(outputs);
    end_cleanly_on_interrupt("circles conform", circles::conform::interrupt);
    return conform_command(c.conform_options, stdout_taken ? std::cerr : std::cout, std::cerr);
  }
  const CLI::App* command = &app;  // the command parsed, "circles report merge" for one
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  end_cleanly_on_interrupt(command_of(*command));
  if (*c.vectors) return vectors_command(c.vectors_options, std::cout, std::cerr);
  if (*c.merge) return merge_command(c.merge_options, std::cout, std::cerr);
  if (*c.check_trace)
    return check_trace_command(c.check_trace_options.file, trace_reference(c.check_trace_options.engine), std::cout,
                               std::cerr);
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
               "engine checked against the oracle step by step; exit 0 when all agree",
               "circles"};
  // Set before the commands are declared, which take them from the program.
  app.formatter(std::make_shared<HelpFormatter>(help_width()));
  app.failure_message([](const CLI::App* at, const CLI::Error& e) {
    const auto* parse_error = dynamic_cast<const CLI::ParseError*>(&e);
    return (parse_error ? usage_error(*at, *parse_error) : "circles: " + std::string(e.what())) + "\n";
  });
  // A flag takes no value: `--fit=abc` is refused by name (usage_error) rather than converted.
  app.option_defaults()->disable_flag_override();
  app.set_help_flag("-h,--help", "Show this help and exit");
  app.set_version_flag("-V,--version", "circles " CIRCLES_VERSION, "Show the version and exit");
  app.require_subcommand(0, 1);
  Commands commands;
  declare(app, commands);
  // After the commands, which would copy it.
  app.footer("A FILE of - is stdout for an output and stdin for an input. `circles help COMMAND` shows the options "
             "of a command.");
  if (const std::optional<int> status = parse(app, commands, argc, argv)) return *status;
  try {
    return dispatch(app, commands);
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
