// The double engines: the resolved step of the oracle (spec/equations.hpp, docs/math.md) over doubles.
//
//   Invariant: for every World w whose next positions are finite,
//              Engine(w).step() leaves world() equal, by value (−0 == +0), to spec::resolved_step_rounded(w):
//              circle k takes the velocity of the least circle it intersects exactly (least in lexicographic
//              order on (px, py, vx, vy, r), then by index), or keeps its own, and then
//              p ← RN(p + v_new/60) per coordinate. Every circle reads the old world. The result does not depend
//              on EngineOptions: every thread count and every skipped step give the same bits.
//
// Pieces: the cell grid (impl/broad_phase.hpp, conservative) → the arithmetic's intersect test → the
// lexicographic minimum (double < and == are exact; −0 == +0 as for the oracle's rationals) → the arithmetic's
// update. ExactArithmetic (intersect_exact, advance_rounded) makes the invariant hold; NaiveArithmetic
// (intersect_naive, advance_naive) is the same engine without exactness, to measure what exactness costs.
// docs/engine.md describes the layout, the step and the quiet-step proof.
#pragma once

#include "impl/arithmetic.hpp"
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
//   Invariant: all five arrays have size() < 2^32; every value is finite and every r[k] ≥ 0 (−0 allowed), i.e.
//   every circle is in C of the resolved profile.
class World {
 public:
  World() = default;
  // From [px, py, vx, vy, r] per circle. Throws spec::OutsideC for the first circle outside C of the resolved
  // profile, with the oracle's own check (spec::check_doubles), and std::length_error for 2^32 circles or more.
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
  template <class>
  friend class BasicEngine;
  friend World step_all_pairs(const World& w);
  std::vector<double> px_, py_, vx_, vy_, r_;
};

// A step whose position overflows: at step `step` (the step that would make world `step` from world
// `step` − 1), circle `index`'s coordinate `field` ("px" or "py") would become ±infinity. The world is left
// as it was before that step.
class PositionOverflow : public std::overflow_error {
 public:
  PositionOverflow(std::uint64_t step, std::size_t index, const char* field);
  std::uint64_t step;
  std::size_t index;
  const char* field;
};

struct EngineOptions {
  // Worker threads; 0 means one per core (std::thread::hardware_concurrency()). Results are the same bits
  // for every value.
  unsigned threads = 0;
  // Prove stretches of steps in which no pair can meet and run them without the broad or narrow phase.
  bool skip_quiet_steps = true;
};

// The engine: circles kept in cell order (impl/broad_phase.hpp) across steps.
template <class Arithmetic>
class BasicEngine {
 public:
  BasicEngine() : BasicEngine(World{}) {}
  // Throws std::invalid_argument for more threads than kMaxThreads.
  explicit BasicEngine(World w, EngineOptions options = {});

  // The current world, circle k at index k as given to the constructor.
  World world() const;
  // Steps taken since construction.
  std::uint64_t steps() const noexcept { return steps_; }
  // Steps taken without the broad and narrow phases, proven quiet.
  std::uint64_t quiet_steps() const noexcept { return quiet_steps_; }
  unsigned threads() const noexcept { return threads_; }

  // One resolved step. Throws PositionOverflow (world unchanged) when a position would become infinite.
  void step();

  // For the debug validator: the pairs {i, j}, i < j (circle indices), that the next step's narrow phase
  // would test, once each. O(n + pairs).
  std::vector<CandidatePair> candidates() const;

  static constexpr unsigned kMaxThreads = 256;

 private:
  struct Layout {  // circles in cell order; slot t holds circle id[t]
    std::vector<double> px, py, vx, vy, r;
    std::vector<std::uint32_t> id;
    std::vector<CellKey> key;
    std::vector<unsigned> levels;  // the levels that hold a circle, ascending, the global level excluded
    std::array<std::size_t, CellGrid::kLevels + 1> level_begin{};  // level L: [level_begin[L], level_begin[L + 1])
  };

  bool precedes(std::size_t a, std::size_t b) const noexcept;
  void relayout();
  void find_contacts();
  void advance(bool with_contacts);
  void commit();
  bool quiet_for(std::uint64_t steps);

  EngineOptions options_;
  unsigned threads_ = 1;
  std::uint64_t steps_ = 0, quiet_steps_ = 0;
  std::uint64_t quiet_left_ = 0, horizon_ = 0, retry_at_ = 0;
  bool keys_stale_ = false;
  std::size_t contacts_ = 0;
  CellGrid grid_;
  CellOrder order_;
  Layout now_;
  // Scratch of one step: each slot's least contact (itself if none), the next positions and velocities and
  // keys by slot, the sorting permutation, offers found across levels (one list per chunk).
  std::vector<std::uint32_t> least_, permutation_, scratch_id_;
  std::vector<double> next_px_, next_py_, next_vx_, next_vy_, scratch_r_;
  std::vector<CellKey> next_key_;
  std::vector<std::vector<ContactOffer>> offers_;
};

using Engine = BasicEngine<ExactArithmetic>;
using NaiveEngine = BasicEngine<NaiveArithmetic>;
extern template class BasicEngine<ExactArithmetic>;
extern template class BasicEngine<NaiveArithmetic>;
// The accuracy benchmark's baselines (impl/arithmetic.hpp, docs/accuracy.md); not conformant.
extern template class BasicEngine<NaiveSqrtArithmetic>;
extern template class BasicEngine<FloatNaiveArithmetic>;
extern template class BasicEngine<ExactDecisionArithmetic>;

// The reference engine for tests: the exact step with every pair tested (no broad phase). O(n²).
// Throws PositionOverflow (step 1) like Engine::step.
World step_all_pairs(const World& w);

}  // namespace circles::impl
