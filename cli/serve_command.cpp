#include "cli/serve_command.hpp"

#include "cli/options.hpp"
#include "conform/serve.hpp"
#include "engines/registry.hpp"

namespace circles::cli {

CLI::App* add_serve_command(CLI::App& app, ServeCommandOptions& options) {
  CLI::App* serve = app.add_subcommand(
      "serve", "Answer step-protocol requests on stdin, one JSON line each, on stdout (see protocol.md in the docs)");
  add_engine_options(serve, options.engine, options.threads);
  return serve;
}

int serve_command(const ServeCommandOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  return conform::serve(engines::engine(options.engine), options.threads, in, out, err);
}

}  // namespace circles::cli
