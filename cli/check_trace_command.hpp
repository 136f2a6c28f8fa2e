// `circles check-trace`: its options, what it prints of a trace's check (conform/check_trace.hpp), and the command.
#pragma once

#include "conform/check_trace.hpp"

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>

namespace circles::cli {

using conform::TraceCheck;
using conform::TraceReference;

// The verdict, on `out`: "circles check-trace: t.jsonl: agrees with ..." or the divergence, its expected and
// actual values in decimal and hexadecimal, and (for double) which decision differs.
void print_check(const TraceCheck& check, const std::string& source, TraceReference reference, std::ostream& out);

struct CheckTraceCommandOptions {
  std::string file;                // the trace
  std::string engine = "double";  // --engine double|exact (conform::trace_reference)
};

// Declares the command and its options on `app`.
CLI::App* add_check_trace_command(CLI::App& app, CheckTraceCommandOptions& options);

// The command: 0 when the trace agrees, 1 for a divergence (on `out`), 2 for a file that is not a trace (the
// TraceReadError on `err`, "circles check-trace: FILE:LINE: reason").
int check_trace_command(const std::string& path, TraceReference reference, std::ostream& out, std::ostream& err);

}  // namespace circles::cli
