// `circles serve`: an engine behind the step protocol on stdin and stdout (docs/protocol.md, conform/serve.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <istream>
#include <ostream>
#include <string>

namespace circles::cli {

struct ServeCommandOptions {
  std::string engine = "double";  // --engine NAME (engines/registry.hpp)
  unsigned threads = 0;           // --threads T (0: chosen from the load, impl::choose_threads)
};

// Declares the command and its options on `app`.
CLI::App* add_serve_command(CLI::App& app, ServeCommandOptions& options);

// The command: answers the requests on `in` until its end (conform::serve).
int serve_command(const ServeCommandOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace circles::cli
