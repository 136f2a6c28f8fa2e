// The double engines: the resolved step of the oracle (spec/equations.hpp, docs/math.md) over doubles.
//
//   Invariant: for every World w whose next positions are finite,
//              DoubleEngine(w).step() leaves world() equal, by value (−0 == +0), to spec::resolved_step_rounded(w):
//              circle k takes the velocity of the least circle it intersects exactly (least in lexicographic
//              order on (px, py, vx, vy, r), then by index), or keeps its own, and then
//              p ← RN(p + v_new/60) per coordinate. Every circle reads the old world. The result does not depend
//              on EngineOptions: every thread count and every horizon of the pair lists give the same bits.
//
// Pieces: the cell grid (impl/broad_phase.hpp, conservative) on radii inflated by a proven skin → a list of the
// pairs that can meet within the horizon, each from its first step (impl/pair_list.hpp) → the arithmetic's
// intersect test → the
// lexicographic minimum (double < and == are exact; −0 == +0 as for the oracle's rationals) → the arithmetic's
// update. RoundedArithmetic (intersect_exact, advance_rounded) makes the invariant hold; NaiveArithmetic
// (intersect_naive, advance_naive) is the same engine without exactness, to measure what exactness costs.
// docs/engine.md describes the layout, the step and the proofs of the broad phase and the pair lists.
#pragma once

#include "impl/arithmetic.hpp"
#include "impl/cell_layout.hpp"
#include "impl/overflow.hpp"
#include "impl/threads.hpp"
#include "spec/outside_c.hpp"

#include <cstddef>
#include <cstdint>
#include <numeric>
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
  explicit World(const spec::Circles& circles);

  // Back to [px, py, vx, vy, r] per circle, the same doubles bit for bit.
  spec::Circles circles() const;

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
  friend World step_from_contacts(const World& w, std::span<const std::size_t> least);
  Buffer<double> px_, py_, vx_, vy_, r_;
};

// The engine: circles kept in cell order (impl/broad_phase.hpp), a list of the pairs that can meet before
// the next rebuild (impl/pair_list.hpp), and the arithmetic's pair test and update.
template <class Arithmetic>
class BasicEngine {
 public:
  BasicEngine() : BasicEngine(World{}) {}
  // Throws std::invalid_argument for more threads than kMaxThreads.
  explicit BasicEngine(World w, EngineOptions options = {});

  // The current world, circle k at index k as given to the constructor.
  World world() const;
  // The current world read a slice at a time, without the copy world() makes (for a trace of a big world):
  // slots() gives each circle's place in the engine's own order, valid until the next step; then
  // read_circles(slots, first, out) sets out[i] to circle first + i as world() has it, [px, py, vx, vy, r].
  // It only reads, so threads may call it at once on any slices.
  std::vector<std::uint32_t> slots() const;
  void read_circles(std::span<const std::uint32_t> slots, std::size_t first,
                    std::span<spec::CircleDoubles> out) const;
  // Steps taken since construction.
  std::uint64_t steps() const noexcept { return stats_.steps; }
  // Steps whose list was empty: no pair was tested, every circle only moved.
  std::uint64_t quiet_steps() const noexcept { return stats_.quiet_steps; }
  const EngineStats& stats() const noexcept { return stats_; }
  unsigned threads() const noexcept { return threads_; }
  // How threads() is chosen: as asked, or for EngineOptions::threads 0 from the machine's load, read again
  // during the run (impl/threads.hpp).
  const ThreadCount& thread_count() const noexcept { return thread_count_; }

  // One resolved step. Throws PositionOverflow (world unchanged) when a position would become infinite.
  void step();

  // A test hook, which no step calls: the pairs {i, j}, i < j (circle indices), that the next step's narrow
  // phase would test, once each (the tests hold it to candidates_cover_all_intersecting_pairs). O(n + pairs).
  std::vector<CandidatePair> candidates() const;

  static constexpr unsigned kMaxThreads = 256;

 private:
  struct Circles {  // the circles by slot (CellLayout: slot t holds circle layout_.id()[t])
    Buffer<double> px, py, vx, vy, r;
  };
  // A new velocity for a slot, kept until every new velocity of the step is known (all read world t).
  struct Move {
    std::uint32_t slot;
    double vx, vy;
  };

  bool precedes(std::size_t a, std::size_t b) const noexcept;
  void rebuild();
  void advance();

  EngineOptions options_;
  ThreadCount thread_count_;
  unsigned threads_ = 1;
  EngineStats stats_;
  bool overflow_free_ = false;  // proven at the rebuild: no position can overflow before the next one
  CellLayout layout_;
  Circles now_;
  // Scratch: the slots touched per chunk and their moves, the gather's target, the inflated and padded radii,
  // the positions of world t while a step may overflow.
  std::vector<Buffer<Move>> moves_;
  Buffer<double> scratch_, inflated_, padded_, backup_px_, backup_py_;
};

using DoubleEngine = BasicEngine<RoundedArithmetic>;
using NaiveEngine = BasicEngine<NaiveArithmetic>;
extern template class BasicEngine<RoundedArithmetic>;
extern template class BasicEngine<NaiveArithmetic>;
// The accuracy benchmark's baselines (impl/arithmetic.hpp, docs/accuracy.md); not conformant.
extern template class BasicEngine<NaiveSqrtArithmetic>;
extern template class BasicEngine<FloatNaiveArithmetic>;
extern template class BasicEngine<ExactDecisionArithmetic>;

// The reference engine for tests: the exact step with every pair tested (no broad phase). O(n²).
// Throws PositionOverflow (step 1) like DoubleEngine::step.
World step_all_pairs(const World& w);

// Circle a's least contact so far (least[a] == a while it has none) after contact b is offered: the least by
// World::precedes. The order of the offers does not matter, since precedes is a strict total order.
inline void offer_contact(const World& w, std::vector<std::size_t>& least, std::size_t a, std::size_t b) {
  if (least[a] == a || w.precedes(b, least[a])) least[a] = b;
}

// The end of the references' step, from each circle's least contact (itself when it has none): v ← v[least],
// then p ← advance_rounded(p, v). Throws PositionOverflow (step 1) for the first circle, then px before py,
// whose position overflows, like DoubleEngine::step.
World step_from_contacts(const World& w, std::span<const std::size_t> least);

// The references' step over the pairs that `pairs` offers (step_all_pairs every pair, step_grid those of
// neighbouring cells): pairs(visit) calls visit(a, b) once for each pair a < b it offers, which must include
// every pair that intersects; each is tested with intersect_exact, each circle's least contact kept by
// offer_contact, and step_from_contacts ends the step. Throws PositionOverflow (step 1) like it.
template <class Pairs>
World step_over_pairs(const World& w, Pairs pairs) {
  std::vector<std::size_t> least(w.size());
  std::iota(least.begin(), least.end(), std::size_t{0});
  const auto px = w.px(), py = w.py(), r = w.r();
  pairs([&](std::size_t a, std::size_t b) {
    if (intersect_exact(px[a], py[a], r[a], px[b], py[b], r[b])) {
      offer_contact(w, least, a, b);
      offer_contact(w, least, b, a);
    }
  });
  return step_from_contacts(w, least);
}

}  // namespace circles::impl
