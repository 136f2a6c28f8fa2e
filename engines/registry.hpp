// The engine registry: the names `--engine` takes, each a way to step a world of doubles, for every command that
// steps a world with a named engine (`circles run`, `serve`, `conform --engine`, the main job) and the checks
// that need the oracle beside it (conform/).
//
// Every engine computes the resolved step of the oracle (docs/math.md), each coordinate rounded to the nearest
// double. A rounding engine steps from the last world in doubles and must equal spec::resolved_step_rounded by
// value at every step; an exact engine (docs/exact-engine.md) keeps the exact sequence of the oracle from w_0
// and rounds only what it shows, so its w_t is the oracle's exact w_t rounded. To add one, write a Stepper for
// it in registry.cpp and add a row to the table there; every command and message picks it up.
#pragma once

#include "formats/protocol.hpp"
#include "formats/trace_writer.hpp"  // formats::CircleSource
#include "impl/overflow.hpp"  // impl::PositionOverflow
#include "impl/pair_list.hpp"  // impl::EngineStats
#include "impl/threads.hpp"
#include "spec/oracle.hpp"  // spec::Sequence
#include "spec/outside_c.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace circles::engines {

using spec::Circles;

// A step whose next position is beyond the double range: the position overflow of impl/ (impl/overflow.hpp),
// which every stepper throws, the engines of impl/ and the oracles alike: step, circle `index` and coordinate
// `field` (px or py) of the world the step would produce, w_step. what(): "step 31, " and then
// impl::overflow_reason, "circle 2, field px: the position p + v/60 overflows to infinity".
using StepOverflow = impl::PositionOverflow;

// A world being stepped by one engine.
class Stepper {
 public:
  virtual ~Stepper() = default;

  // w_{steps() + 1} from w_{steps()}. Throws StepOverflow, leaving the world as it was.
  void step();
  std::uint64_t steps() const noexcept { return steps_; }
  virtual Circles circles() const = 0;
  // w_steps() read a slice at a time (formats/trace_writer.hpp), valid until the next step: what circles()
  // returns, without its copy of the world from an engine of impl/, which reads its own arrays; the others
  // hold a copy of circles().
  virtual formats::CircleSource source() const;
  // w_steps() itself, as rationals, from an engine that keeps the exact sequence (EngineEntry::exact); nullopt
  // from one that keeps only doubles.
  virtual std::optional<spec::Sequence> exact() const { return std::nullopt; }
  // What the steps so far did and skipped (impl::EngineStats), from an engine of impl/; nullopt from the
  // oracle, which does everything every step.
  virtual std::optional<impl::EngineStats> work() const { return std::nullopt; }
  // The threads of an engine of impl/ and how they are chosen; nullptr from the oracle, which has none.
  virtual const impl::ThreadCount* threads() const { return nullptr; }

 protected:
  struct Overflow {
    std::size_t index;
    spec::Field field;
  };
  // One step; on an overflow, the first circle and field (in index order, px before py), the world unchanged.
  virtual std::optional<Overflow> advance() = 0;

 private:
  std::uint64_t steps_ = 0;
};

struct EngineEntry {
  std::string_view name;
  std::string_view summary;  // for --help
  bool threaded;             // whether `threads` below means anything to it
  bool exact;                // keeps the exact sequence from w_0 (its reference is reference() below)
  // The bytes per circle that `circles run` with this engine holds at its peak, for the memory check of a
  // random world (formats::random_world). Measured, not derived: registry.cpp gives the figures.
  std::size_t bytes_per_circle;
  // A stepper at w_0 = `world` (circles of C in the resolved profile) using up to `threads` threads (0: one
  // per core that other programs leave free, impl/threads.hpp; engines without threads ignore it), for a run of `steps` steps when the caller knows it (0: not
  // known), which an engine plans for (impl::EngineOptions::steps). It still takes any number of steps.
  std::unique_ptr<Stepper> (*start)(const Circles& world, unsigned threads, std::uint64_t steps);
};

// Every engine, in the order --help lists them.
std::span<const EngineEntry> engines();

// The largest thread count an engine takes.
unsigned max_threads();

// "double, exact, oracle"
std::string engine_names();

// The engine of that name, or nullptr.
const EngineEntry* find_engine(std::string_view name);

// A name that is no engine: "unknown engine "x" (the engines are: double, exact, oracle)".
class UnknownEngine : public std::invalid_argument {
 public:
  explicit UnknownEngine(std::string_view name);
};
const EngineEntry& engine(std::string_view name);

// The oracle that `engine` must equal at every step from w_0 = `world`: the correctly rounded oracle stepped
// from the last world in doubles, or for an exact engine the oracle's exact sequence, each world rounded.
std::unique_ptr<Stepper> reference(const EngineEntry& engine, const Circles& world);

// w_1 from w_0 = `world` with `engine`: the step of one protocol request. Throws StepOverflow (step 1).
Circles step_once(const EngineEntry& engine, const Circles& world, unsigned threads);

}  // namespace circles::engines
