#include "conform/check_trace.hpp"

#include "engines/registry.hpp"
#include "formats/json_number.hpp"
#include "impl/engine.hpp"
#include "impl/exact_grid_reference.hpp"
#include "impl/grid_reference.hpp"
#include "formats/state_hash.hpp"
#include "properties/chain.hpp"

#include <limits>
#include <new>
#include <stdexcept>
#include <utility>

namespace circles::conform {

namespace {

// The world the reference expects after `input`, or where its step overflows.
class Reference {
 public:
  Reference(TraceReference kind, const Circles& first) {
    if (kind == TraceReference::exact) exact_.emplace(first);
  }

  // The expected world after `input` (the trace's world on the line before): nothing, with `overflow` set,
  // when the reference's step leaves the double range. The exact reference ignores `input`: it follows the
  // exact sequence from the first world, whatever the trace held since.
  std::optional<Circles> next(const Circles& input, std::string& overflow) {
    try {
      if (!exact_) {
        // In two statements, so that the copy of `input` is gone before the result is copied out of its World:
        // at 10^7 circles each world is 400 MB, and check-trace must fit in 2 GB (docs/benchmarks.md).
        const impl::World next = impl::step_grid(impl::World{input});
        return next.circles();
      }
      exact_->step();
      return exact_->rounded();
    } catch (const impl::PositionOverflow& e) {
      overflow = impl::overflow_reason(e.index, e.field);
      return std::nullopt;
    }
  }

 private:
  std::optional<impl::ExactGrid> exact_;
};

}  // namespace

TraceReference trace_reference(std::string_view engine) {
  if (engine == "double") return TraceReference::rounded;
  if (engine == "exact") return TraceReference::exact;
  throw std::invalid_argument("--engine: \"" + std::string(engine) + "\" is not double or exact");
}

TraceCheck check_trace(TraceReader& reader, TraceReference kind) {
  TraceCheck check;
  std::optional<Line> first = reader.next();  // throws for an empty file
  std::size_t previous_line = reader.line();
  const std::size_t first_line = previous_line;
  check.first_step = check.last_step = first->number;
  check.circles = first->circles.size();
  Reference reference(kind, first->circles);
  formats::StateHash trajectory;
  trajectory.add(first->circles);
  // The trace's worlds as a chain's answers (properties/chain.hpp), each against the reference's step of the
  // world before it (rounded) or the oracle's own sequence (exact); the reader holds every line to the first's
  // number of circles. The chain takes the first world itself: a copy would be one world more in memory.
  properties::Chain chain(std::move(first->circles), std::numeric_limits<std::uint64_t>::max());
  while (std::optional<Line> now = reader.next()) {
    std::string overflow;
    std::optional<Circles> expected = reference.next(chain.input(), overflow);
    if (!expected || !chain.judge(std::move(now->circles), std::move(*expected))) {
      std::optional<Difference> difference;
      if (expected) difference = chain.failure()->difference;
      check.divergence = TraceDivergence{reader.line(), now->number,
                                         kind == TraceReference::exact ? first_line : previous_line, difference,
                                         overflow};
      break;
    }
    trajectory.add(chain.input());
    check.last_step = now->number;
    previous_line = reader.line();
  }
  check.last_hash = formats::state_hash(chain.failure() ? chain.failure()->input : chain.input());
  check.trajectory_hash = trajectory.value();
  return check;
}

Comparison compare_with_oracle(const engines::EngineEntry& engine, const Circles& world, std::uint64_t steps, unsigned threads) {
  const auto oracle = engines::reference(engine, world);
  const auto candidate = engine.start(world, threads, steps);
  // The engine's worlds as a chain's answers (properties/chain.hpp), each against the oracle's, compared by value
  // (-0 == +0, every field exactly): the oracle keeps its own sequence, the same worlds while the two agree.
  properties::Chain chain(world, steps);
  Comparison c;
  for (; c.steps < steps; ++c.steps) {
    const std::uint64_t step = c.steps + 1;
    std::optional<engines::StepOverflow> expected, actual;
    try {
      oracle->step();
    } catch (const engines::StepOverflow& e) {
      expected = e;
    }
    try {
      candidate->step();
    } catch (const engines::StepOverflow& e) {
      actual = e;
    }
    if (expected || actual) {
      if (expected && actual && expected->index == actual->index && expected->field == actual->field) {
        c.overflow = expected;
      } else {
        c.difference = "step " + std::to_string(step) + ": " +
                       (expected ? "the oracle stops at " + impl::overflow_reason(expected->index, expected->field)
                                 : std::string("the oracle does not overflow")) +
                       ", the engine " +
                       (actual ? "stops at " + impl::overflow_reason(actual->index, actual->field) : "does not");
      }
      return c;
    }
    Circles want = oracle->circles(), got = candidate->circles();
    if (want.size() != got.size()) {
      c.difference = "step " + std::to_string(step) + ": the oracle has " + std::to_string(want.size()) +
                     " circles, the engine " + std::to_string(got.size());
      return c;
    }
    if (!chain.judge(std::move(got), std::move(want))) {
      const properties::Difference& d = chain.failure()->difference;
      c.difference = "step " + std::to_string(step) + ", circle " + std::to_string(d.circle) + ", field " +
                     spec::name(d.field) + ": oracle " + formats::json_number::decimal_and_hex(d.expected) +
                     ", engine " + formats::json_number::decimal_and_hex(d.actual);
      return c;
    }
  }
  return c;
}

}  // namespace circles::conform
