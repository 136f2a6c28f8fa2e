// The double engine: the resolved step of the oracle (spec/equations.hpp, docs/math.md) over doubles.
//
//   Invariant: for every World w whose next positions are finite,
//              Engine(w).step() leaves world() equal, by value (−0 == +0), to spec::resolved_step_rounded(w):
//              circle k takes the velocity of the least circle it intersects exactly (least in lexicographic
//              order on (px, py, vx, vy, r), then by index), or keeps its own, and then
//              p ← RN(p + v_new/60) per coordinate. Every circle reads the old world.
//
// Pieces: BroadPhase (impl/broad_phase.hpp, conservative) → intersect_exact (impl/predicate.hpp, exact) →
// the lexicographic minimum (double < and == are exact; −0 == +0 as for the oracle's rationals) →
// advance_rounded (impl/rounding.hpp, correctly rounded).
#pragma once

#include "impl/broad_phase.hpp"
#include "spec/outside_c.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace circles::impl {

// A world as structure of arrays: circle k is (px[k], py[k], vx[k], vy[k], r[k]).
//   Invariant: all five arrays have size(); every value is finite and every r[k] ≥ 0 (−0 allowed), i.e. every
//   circle is in C of the resolved profile.
class World {
 public:
  World() = default;
  // From [px, py, vx, vy, r] per circle. Throws spec::OutsideC for the first circle outside C of the resolved
  // profile, with the oracle's own check (spec::check_doubles).
  explicit World(const std::vector<std::array<double, 5>>& circles);

  // Back to [px, py, vx, vy, r] per circle, the same doubles bit for bit.
  std::vector<std::array<double, 5>> circles() const;

  std::size_t size() const noexcept { return px_.size(); }
  std::span<const double> px() const noexcept { return px_; }
  std::span<const double> py() const noexcept { return py_; }
  std::span<const double> vx() const noexcept { return vx_; }
  std::span<const double> vy() const noexcept { return vy_; }
  std::span<const double> r() const noexcept { return r_; }

  // True when circle a precedes circle b in the resolved profile's order: lexicographic on
  // (px, py, vx, vy, r) by exact comparison of doubles (−0 == +0), then by index. A strict total order.
  bool precedes(std::size_t a, std::size_t b) const noexcept;

 private:
  friend class Engine;
  friend World step_all_pairs(const World& w);
  std::vector<double> px_, py_, vx_, vy_, r_;
};

// A step whose correctly rounded position overflows: circle `index`, coordinate `field` ("px" or "py"),
// would become ±infinity. The step number is the caller's to add. The world is left unchanged.
class PositionOverflow : public std::overflow_error {
 public:
  PositionOverflow(std::size_t index, const char* field);
  std::size_t index;
  const char* field;
};

// The engine: a world and the broad phase's state, which is kept across steps (the strips' member order).
class Engine {
 public:
  Engine() = default;
  explicit Engine(World w) : world_(std::move(w)) {}

  const World& world() const noexcept { return world_; }

  // One resolved step. Throws PositionOverflow (world unchanged) when a position would become infinite.
  void step();

  // The broad phase's candidate pairs of the last step (empty before the first), for the validator.
  std::span<const CandidatePair> last_candidates() const noexcept { return pairs_; }

 private:
  World world_;
  BroadPhase broad_;
  std::vector<CandidatePair> pairs_;
  std::vector<std::size_t> least_;  // per circle: the least circle it intersects, or kNone
  std::vector<double> next_vx_, next_vy_, next_px_, next_py_;
};

// The reference engine for tests: the same step with every pair tested (no broad phase). O(n²).
// Throws PositionOverflow like Engine::step.
World step_all_pairs(const World& w);

}  // namespace circles::impl
