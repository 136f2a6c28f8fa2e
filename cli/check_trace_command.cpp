#include "cli/check_trace_command.hpp"

#include "formats/counted.hpp"
#include "cli/options.hpp"
#include "formats/input_file.hpp"
#include "formats/json_number.hpp"
#include "formats/protocol.hpp"
#include "formats/trace_reader.hpp"

namespace circles::cli {

using formats::counted;

namespace json_number = formats::json_number;
using conform::Difference;
using conform::TraceDivergence;
using formats::hash_text;
using formats::TraceReader;
using formats::TraceReadError;

void print_check(const TraceCheck& check, const std::string& source, TraceReference kind, std::ostream& out) {
  const bool exact = kind == TraceReference::exact;
  const std::string range = "steps " + std::to_string(check.first_step) + " to " + std::to_string(check.last_step) +
                            ", " + counted(check.circles, "circle");
  if (!check.divergence) {
    out << "circles check-trace: " << source << ": agrees with "
        << (exact ? "the oracle's exact sequence, rounded," : "the correctly rounded step")
        << (check.steps() == 1 ? " at its one step" : " at each of its " + counted(check.steps(), "step")) << " ("
        << range << "); state hash of step " << check.last_step << ": "
        << hash_text(check.last_hash) << ", trajectory hash: " << hash_text(check.trajectory_hash) << "\n";
    return;
  }
  const TraceDivergence& d = *check.divergence;
  out << "circles check-trace: " << source << ":" << d.line << ": step " << d.step << " differs from "
      << (exact ? "the oracle's exact sequence from line " : "the correctly rounded step of line ") << d.input_line
      << (exact ? ", rounded" : "") << ": ";
  if (d.difference) {
    const Difference& f = *d.difference;
    out << "circle " << f.circle << ", field " << spec::name(f.field) << ": expected "
        << json_number::decimal_and_hex(f.expected) << ", actual " << json_number::decimal_and_hex(f.actual) << "\n";
    // The decision is judged on the world of the line before, which is the reference's input only for double.
    if (!exact) out << "  which decision: " << f.decision << "\n";
  } else {
    out << "the step overflows (" << d.overflow << "), so no world can follow, yet the trace holds one\n";
  }
  out << "  the worlds before it agree (" << range << "; trajectory hash " << hash_text(check.trajectory_hash)
      << ")\n";
}

CLI::App* add_check_trace_command(CLI::App& app, CheckTraceCommandOptions& options) {
  CLI::App* check_trace = app.add_subcommand(
      "check-trace",
      "Check a trace recorded by any implementation step by step against the spec; exits 0 (it agrees), 1 (a world "
      "differs) or 2 (not a trace) (see vectors.md in the docs)");
  // A missing file is reported by the trace reader, as every other bad trace is.
  takes(check_trace
            ->add_option("trace", options.file,
                         "The trace, JSON Lines, one {\"step\": t, \"circles\": [...]} per world, or - for stdin")
            ->required(),
        "TRACE", "a trace file to read, or - for stdin");
  takes_one_of(check_trace
                   ->add_option("--engine", options.engine,
                                "double: each world the correctly rounded step of the one before; exact: the oracle's "
                                "exact sequence from the first world, rounded")
                   ->capture_default_str(),
               "NAME", {"double", "exact"});
  return check_trace;
}

int check_trace_command(const std::string& path, TraceReference kind, std::ostream& out, std::ostream& err) {
  try {
    TraceReader reader(path);
    const TraceCheck check = check_trace(reader, kind);
    print_check(check, reader.source(), kind, out);
    return check.divergence ? 1 : 0;
  } catch (const TraceReadError& e) {
    err << "circles check-trace: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {  // the reader's two worlds fit, the reference's step on them did not
    err << "circles check-trace: " << formats::input_name(path) << ": the worlds are too large to check in memory\n";
    return 2;
  }
}

}  // namespace circles::cli
