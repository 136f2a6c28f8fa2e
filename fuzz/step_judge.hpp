// The step fuzzer's judge (docs/hardening.md, "The step fuzzer"): chains of steps made by a step under test,
// the references they are held to, and the report of a difference as a replayable scene.
//
// A double step is held to two fast references that share no arithmetic with each other, and are held to
// each other on every input:
//   the exact engine's step  impl::ExactEngine, one step from each world, rounded: decisions in integers, the
//                            position rounded from its exact value; no filter bound, no rounding certificate.
//   every pair               impl::step_all_pairs: no broad phase, no grid, no pair list, no skin.
// A bug of the double engine's arithmetic (a filter bound, the rounding certificate) makes it differ from the
// exact engine's step; a bug of the broad phase both engines share makes both differ from every pair; for the
// two references to agree on a wrong answer, both would need the same wrong answer from different code. On a
// sample of the inputs (oracle_judges), worlds of at most kOracleCircles circles are also held to the oracle of
// spec/ (Boost/GMP rationals, every pair, the spec's own order), which shares nothing with impl/, and exact
// chains to its exact steps.
#pragma once

#include "fuzz/step_input.hpp"
#include "spec/oracle.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace circles::fuzz {

// Worlds up to this size are judged by the oracle itself, on a sample of inputs; a step of 48 circles costs it
// about 1 ms, and a chain of 16 steps of 8 circles 1.5 ms, ten times the rest of such an input's judging.
inline constexpr std::size_t kOracleCircles = 48;
// One input in kOracleSample is judged by the oracle too: the rest of the judging then dominates, and the
// oracle still sees hundreds of inputs a minute. Which ones is a function of the input (a hash of its world
// and steps), so that a replay of an input judges it the same way.
inline constexpr std::uint64_t kOracleSample = 16;
bool oracle_judges(const StepInput& input);

// Steps chained from a world of more than kOracleCircles circles: at most kBigSteps of the input's K, since each
// costs the reference (and an O(n²) step under test) about as much as all the small worlds' steps together;
// 3, so that what an engine keeps from one step to the next (its pair list) is used, and the fuzzer's time goes
// to more inputs rather than longer chains (conform's big_chains, checking a program's drift past a skin, asks 10).
inline constexpr std::uint64_t kBigSteps = 3;
std::uint64_t judged_steps(const StepInput& input);

// Where a chain stopped because a position would be ±infinity: at step `step` (1 for the step from w_0), the
// first circle `index` and coordinate `field` (px before py), or index kUnknown when the step under test
// does not say (the C ABI), and then `field` means nothing.
struct Overflow {
  static constexpr std::size_t kUnknown = ~std::size_t{0};
  std::uint64_t step = 0;
  std::size_t index = kUnknown;
  spec::Field field = spec::Field::px;
};

// w_1 … w_m of a chain, then the overflow that stopped it, if any.
template <class World>
struct BasicChain {
  std::vector<World> worlds;
  std::optional<Overflow> overflow;
};
using Chain = BasicChain<Circles>;             // rounded: each step from the previous world of doubles
using ExactChain = BasicChain<spec::Sequence>;  // exact: no rounding in the state

// One step of a reference from a world of doubles: the next world, or where it overflows.
using RoundedStep = std::function<Chain(const Circles&)>;

// `steps` steps chained from w0 by `one` (each a chain of one world or of an overflow), stopping at an overflow.
Chain chain_of(const Circles& w0, std::uint64_t steps, const RoundedStep& one);

// The reference for a double step: `steps` rounded steps from w0, by the oracle (spec::resolved_step_rounded)
// for worlds of at most kOracleCircles circles, else by impl::ExactGrid's rounded step.
Chain rounded_reference(const Circles& w0, std::uint64_t steps);
// The fast references for a double step, each chained from its own previous world: the exact engine's step
// rounded, and impl::step_all_pairs.
Chain exact_engine_reference(const Circles& w0, std::uint64_t steps);
Chain all_pairs_reference(const Circles& w0, std::uint64_t steps);
// The rounded reference of an input: the exact engine's chain, held to every pair's (and on the oracle's sample
// to the oracle's); a difference between them fails the input (fail) as a fault of the references.
Chain judged_reference(const StepInput& input, std::uint64_t steps);
// The reference for an exact step: the oracle's spec::resolved_step chained `steps` times from w0's exact
// values, stopping at the first step with a position whose nearest double is ±infinity (the exact engine's
// PositionOverflow). Bigger worlds' exact steps are held to the double engine instead (fuzz/step_fuzzer.cpp),
// which shares no arithmetic with the exact engine and is itself held to impl::ExactGrid.
ExactChain exact_reference(const Circles& w0, std::uint64_t steps);

// How `got` differs from `want`, or nothing: the same number of worlds, each equal by value (−0 == +0, as the
// spec's rationals), and the same overflow (its circle and field too, when `got` names them).
std::optional<std::string> difference(const Chain& want, const Chain& got);
std::optional<std::string> difference(const ExactChain& want, const ExactChain& got);

// The scene of a world (docs/scenes.md): {"name": ..., "steps": ..., "circles": [[px, py, vx, vy, r], ...]},
// each double written in the fewest digits that read back as it (−0 as -0).
std::string scene_text(const Circles& w, std::uint64_t steps, const std::string& name);

// The report of a difference: writes input's world as a scene to the file named by the environment variable
// CIRCLES_STEP_FUZZER_SCENE (default: step_fuzzer-failure.json in the working directory), prints `who`, `what`
// and how to replay it to stderr, and aborts, so that libFuzzer saves the input as a crash.
[[noreturn]] void fail(const StepInput& input, const std::string& who, const std::string& what);

}  // namespace circles::fuzz
