// Worlds checked step by step against the spec: the main job's engines beside the oracle (compare_with_oracle,
// printed by cli/run.hpp), and the check of `circles check-trace FILE [--engine double|exact]` (printed by
// cli/check_trace_command.hpp), which checks a trace recorded by any implementation
// (formats/trace_reader.hpp) step by step against the spec, and names the first step, circle and field that differ
// (docs/vectors.md, "Checking a trace").
//
//   double  (the default) each world must be the correctly rounded resolved step of the world on the line
//           before it: the trace of an engine that steps in doubles, as `circles run --engine double` records.
//           The reference is impl::step_grid: the exact-decision step conform uses (impl::step_all_pairs,
//           conform/conform.cpp) with a uniform grid in front, held bit-equal to it by tests; O(n log n) per
//           step for alike radii.
//   exact   each world must be the oracle's exact sequence from the first world, rounded: the trace of an
//           engine that keeps the exact state, as `circles run --engine exact` records. The reference is
//           impl::ExactGrid: the oracle's exact sequence in integers, with pairs from the same uniform grid,
//           held equal to spec::resolved_step by tests; O(n log n) per step for alike radii.
// Values are compared by value (−0 == +0), every field exactly: velocities and radii are copies, and each
// position must be the nearest double.
#pragma once

#include "conform/conform.hpp"
#include "engines/registry.hpp"
#include "formats/trace_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace circles::conform {

using spec::Circles;
using formats::Line;
using formats::TraceReader;
using formats::TraceReadError;

enum class TraceReference { rounded, exact };  // --engine double, --engine exact

// "double" or "exact". Throws std::invalid_argument for any other name.
TraceReference trace_reference(std::string_view engine);

// The first world that is not the reference's.
struct TraceDivergence {
  std::size_t line = 0;      // its line in the file
  std::uint64_t step = 0;    // its step number
  std::size_t input_line = 0;  // the line of the world it was stepped from (double) or of the first world (exact)
  std::optional<Difference> difference;  // the first circle and field that differ, in index and field order
  std::string overflow;  // instead of a difference: where the reference's step overflows, so no world can follow
};

struct TraceCheck {
  std::uint64_t first_step = 0, last_step = 0;  // the steps of the worlds that agree: first_step … last_step
  std::size_t circles = 0;
  std::uint64_t last_hash = 0;        // formats::state_hash of world last_step
  std::uint64_t trajectory_hash = 0;  // formats::StateHash of worlds first_step … last_step
  std::optional<TraceDivergence> divergence;
  std::uint64_t steps() const noexcept { return last_step - first_step; }  // steps checked and agreeing
};

// Reads the trace and checks each world as it comes, stopping at the first divergence (the lines after it are
// not read). Throws TraceReadError for the first line before it that breaks a rule of the reader.
TraceCheck check_trace(TraceReader& reader, TraceReference reference);

// The main job's check (`circles` with no command), as check_trace's but with the engine stepped in process:
// `engine` and its reference (engines::reference) stepped side by side from w_0 = `world` for `steps` steps,
// compared by value after each step (-0 == +0).
struct Comparison {
  std::uint64_t steps = 0;                // steps after which both agreed
  std::optional<std::string> difference;  // the first difference: "step 5, circle 3, field vx: oracle 120
                                          // (0x1.ep+6), engine 0 (0x0p+0)"
  std::optional<engines::StepOverflow> overflow;  // both stopped at this same overflow
};
Comparison compare_with_oracle(const engines::EngineEntry& engine, const Circles& world, std::uint64_t steps,
                               unsigned threads);

}  // namespace circles::conform
