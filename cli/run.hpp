// `circles run` and the main job's check: an engine stepping a world many times, with a trace if asked, and
// an engine stepped side by side with the oracle.
#pragma once

#include "cli/engines.hpp"
#include "spec/circle.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::cli {

// The doubles of a scene: every coordinate of a loaded scene is the exact value of a double (cli/scene.hpp),
// so this gives those doubles back (a -0 as +0: a rational has no sign, and no step can tell them apart).
Circles doubles_of(const std::vector<spec::Circle>& scene);

// A trace that cannot be written: what() names the file and the system's reason.
class TraceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOptions {
  std::uint64_t steps = 0;
  const EngineEntry* engine = nullptr;
  unsigned threads = 0;   // 0: all cores
  std::string trace;      // the trace file, or empty for none
};

struct RunResult {
  std::uint64_t steps = 0;                 // steps taken: the last world is w_steps
  std::optional<StepOverflow> overflow;    // what stopped the run early, if anything
  std::chrono::duration<double> stepping{};  // wall time of the steps alone (not the trace)
};

// Steps w_0 = `world` with options.engine up to options.steps times, stopping at the first overflow. With a
// trace, writes one line {"step": t, "circles": [...]} per world w_0, w_1, ..., w_steps to a temporary file
// beside options.trace and renames it into place at the end, after an overflow too (so the trace holds every
// world before it). Throws TraceError, leaving no file behind, when the trace cannot be written.
RunResult run(const Circles& world, const RunOptions& options);

// "100 steps of 10 circles with the double engine (all cores): 0.000135 s stepping, 135 ns per circle-step".
void print_summary(const RunResult& result, std::size_t circles, const RunOptions& options, std::ostream& out);

// `engine` and the oracle stepped side by side from w_0 = `world` for `steps` steps, compared by value after
// each step (-0 == +0).
struct Comparison {
  std::uint64_t steps = 0;                // steps after which both agreed
  std::optional<std::string> difference;  // the first difference: "step 5, circle 3, field vx: oracle 120
                                          // (0x1.ep+6), engine 0 (0x0p+0)"
  std::optional<StepOverflow> overflow;   // both stopped at this same overflow
};
Comparison compare_with_oracle(const EngineEntry& engine, const Circles& world, std::uint64_t steps, unsigned threads);

// One line: "double engine: agrees with the correctly rounded oracle at each of the 100 steps" or "double
// engine: DIFFERS from the correctly rounded oracle at step 5, circle 3, field vx: ...".
void print_comparison(const EngineEntry& engine, const Comparison& c, std::ostream& out);

}  // namespace circles::cli
