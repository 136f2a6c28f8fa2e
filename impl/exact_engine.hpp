// The exact engine: the resolved step of the oracle (spec/equations.hpp) with no rounding in the state.
//
//   Invariant: after t steps, exact() equals spec::resolved_step applied t times to the input, as rationals,
//              for every input; world() is that state with each coordinate rounded to nearest, ties to even
//              (an exact zero as +0). The result does not depend on EngineOptions::threads.
//
// Velocities are only ever copied (h of (9)), so every position is p0 + (a sum of input velocities)/60. With
// L the least common multiple of the inputs' denominators (2^K for doubles, K fixed by the scene's least
// exponent) and D = 60·L, the engine holds X = D·p, V = L·v and R = D·r, all integers; a step is X ← X + V of
// the least contact. Intersect (3) is R_a + R_b ≥ |X_b − X_a| in integers, after a filter on double
// approximations that decides all but near-tangent pairs; the order of (7) compares the integers (D, L > 0
// keep the order). The width is chosen per scene and re-proven ahead for a number of steps (from max |V|):
// 64 bits while every magnitude stays within 2^61, __int128 within 2^125, GMP integers otherwise. Like the
// double engine, the circles are kept in cell order (slots) and the pairs that can meet are kept across
// steps in a PairList (impl/pair_list.hpp) with a proven skin, the speed term alone: moves are exact.
// docs/exact-engine.md has the representation, the bounds, the rounding, the boxes and the skin.
#pragma once

#include "impl/cell_layout.hpp"
#include "impl/engine.hpp"
#include "impl/exact_integer.hpp"
#include "spec/oracle.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace circles::impl {

class ExactEngine {
 public:
  ExactEngine() : ExactEngine(World{}) {}
  // From doubles, each taken at its exact value. Throws std::invalid_argument for more threads than
  // kMaxThreads.
  explicit ExactEngine(const World& w, EngineOptions options = {});
  // From rationals (any denominators). Throws spec::OutsideC for a negative radius, and for a field whose
  // nearest double is infinite (world() could not hold it), naming the circle and field.
  explicit ExactEngine(const spec::Sequence& circles, EngineOptions options = {});

  // One resolved step. Throws PositionOverflow (state unchanged) when a position's nearest double would be
  // ±infinity: the exact state could hold it, but world() and every output could not.
  void step();

  // The state rounded to doubles, circle k at index k.
  World world() const;
  // The exact state as rationals, circle k at index k.
  spec::Sequence exact() const;
  // The exact state as strings "num/den" in lowest terms ("n" for integers), [px, py, vx, vy, r] per circle.
  std::vector<std::array<std::string, 5>> rationals() const;

  std::uint64_t steps() const noexcept { return stats_.steps; }
  // What the steps did and skipped, as the double engine counts it (impl/pair_list.hpp).
  const EngineStats& stats() const noexcept { return stats_; }
  unsigned threads() const noexcept { return threads_; }
  // How threads() is chosen: as asked, or for EngineOptions::threads 0 from the machine's load, read again
  // during the run (impl/threads.hpp).
  const ThreadCount& thread_count() const noexcept { return thread_count_; }
  std::size_t size() const noexcept { return radius_.size(); }
  // The integers' width: 64 or 128 (fixed, proven to hold the state until the next proof), 0 for GMP.
  unsigned width() const noexcept;
  // True while the state is held in fixed-width integers (64 or 128 bits), false once (or if from the start)
  // it needs GMP integers.
  bool narrow() const noexcept { return width() != 0; }
  // D = 60·L, the common denominator of positions and radii (velocities have L).
  const exact::Wide& denominator() const noexcept { return den_; }

  // Test hooks, which no step calls. The pairs {i, j}, i < j (circle indices), that the next step's pair
  // test would consider, once each (the list it keeps, or the one it would build). O(n + pairs).
  std::vector<CandidatePair> candidates() const;
  // True when the doubles the next step's filters read are where their
  // bound says, checked in rationals: for every slot the step may test (each in a listed pair while the list
  // walks, else every slot), the approximate centre is within the engine's error bound of the exact one on
  // each axis and the approximate radius within it of the exact radius. O(n) rational arithmetic.
  bool approximations_hold() const;
  // True while the kept list walks: the approximations of its circles move by a double per step while the
  // integers wait (docs/exact-engine.md, "Walking approximations").
  bool walks() const noexcept { return walking_; }

  static constexpr unsigned kMaxThreads = BasicEngine<RoundedArithmetic>::kMaxThreads;

 private:
  // The integers of the state. Positions and velocities by slot (cell order, slot t holds circle id_[t]), as
  // the double engine keeps its doubles; radii never change and are read only by exact decisions and ties of
  // the order, so they stay by circle index. spare is the rebuild's gather target.
  // A velocity a step gives slot `slot` (its least contact's), with its move per step (fixed widths).
  template <class Int>
  struct Move {
    std::uint32_t slot;
    Int vx, vy;
    double wx, wy;
  };
  template <class Int>
  struct Columns {
    Buffer<Int> x, y, vx, vy, r, spare;
    std::vector<Buffer<Move<Int>>> moves;  // per chunk, the step's changes of velocity
  };
  // By slot, doubles near the exact state: circle id_[t]'s centre is within error_bound_ of (x[t], y[t]) on
  // each axis and its radius within it of rho[t], for every slot a step may test (those in a listed pair, or
  // every slot). The pair test's filter and the order read them every step; the rebuild's boxes and gaps read
  // them as settle() leaves them, each within error(max(|x[t]|, |y[t]|), id_[t]). In a walking list, wx and
  // wy are the listed slots' moves per step, V·RN(1/D) ≈ v/60, and a step walks x ← RN(x + wx) rather than
  // compute x from X (docs/exact-engine.md, "Walking approximations").
  struct Approximations {
    Buffer<double> x, y, rho, wx, wy;
  };
  // A bound on the errors of the approximations (x, y) and ρ of `circle` as settle() computes them, for
  // m = max(|x|, |y|).
  double error(double m, std::uint32_t circle) const noexcept;
  // The approximations of one circle's centre from its integers (exact::approximate).
  template <class Int>
  void approximate(const Int& x, const Int& y, double& ax, double& ay) const noexcept;
  // X of slot t now: the integers plus the moves they have not taken (pending_ of them, fixed widths only).
  // Fixed widths give a value, GMP a reference to X itself.
  template <class Int>
  decltype(auto) now(const Buffer<Int>& x, const Buffer<Int>& v, std::size_t t) const;
  // The same integers in another width (each value must fit).
  template <class To, class From>
  static Columns<To> converted(const Columns<From>& s);

  // The constructors' work: from rationals, the denominators, the scaled integers in GMP and the radii's
  // doubles; then start with the state by circle index (slot k holds circle k), the width and the
  // approximations (the first step's rebuild sorts the slots).
  void from_rationals(const spec::Sequence& circles);
  template <class Int>
  void start(Columns<Int> s, Buffer<double> radius, Buffer<double> radius_error);
  // The narrowest width that holds the state for at least one more step, and until which step (re-run then).
  void choose_width();
  template <class Int>
  void step_with(Columns<Int>& s);
  template <class Int>
  bool precedes(const Columns<Int>& s, std::size_t a, std::size_t b) const noexcept;
  // Intersect (3) of slots i and j on the integers, for the pairs the filter leaves; out of line, so that the
  // filter inlines into the pair loop.
  template <class Int>
  [[gnu::noinline]] bool intersect_exactly(const Columns<Int>& s, std::size_t i, std::size_t j) const;
  // A double ≥ max |v| over the circles (from the velocities' approximations, norm_upper).
  template <class Int>
  double speed_bound(const Columns<Int>& s) const;
  // The list for the current world and the next horizon: the skin, keys of the inflated boxes, the slots in
  // cell order again, and the broad phase (impl/pair_list.hpp).
  template <class Int>
  void rebuild(Columns<Int>& s);
  // The slots touched by the step's contacts take their least contact's velocity (all read first); a GMP
  // state first checks that no new position rounds to ±infinity (PositionOverflow, nothing changed).
  template <class Int>
  void take_velocities(Columns<Int>& s);
  // A step's move after its contacts: take_velocities, then walk() or settle() by one move.
  template <class Int>
  void move(Columns<Int>& s);
  // Every slot takes `moves` moves, X ← X + moves·V (the pending ones, or one for a step that does not walk),
  // and its approximations from the integers; error_bound_ is then error() of the largest.
  template <class Int>
  void settle(Columns<Int>& s, std::uint64_t moves);
  // A step of a walking list: X waits (++pending_), and the approximations of the slots in a listed pair walk
  // one move, x ← RN(x + wx); error_bound_ grows by the walk's error (exact::walked, impl/exact_bounds.hpp).
  void walk();
  EngineOptions options_;
  ThreadCount thread_count_;
  unsigned threads_ = 1;
  EngineStats stats_;
  std::variant<Columns<exact::Word>, Columns<exact::Narrow>, Columns<exact::Wide>> state_;
  exact::Wide den_, den_v_;  // D = 60·L and L
  exact::Wide overflow_at_;  // (2^1024 − 2^970)·D: |X| at least this rounds to ±infinity
  exact::NarrowMagnitude narrow_den_ = 1, narrow_den_v_ = 1;  // D and L, while fixed-width
  double inverse_den_ = 1, inverse_den_v_ = 1;                // RN(1/D) and RN(1/L), while fixed-width
  std::uint64_t proven_until_ = 0;  // the fixed-width state is proven to fit through this step
  // Per circle (by index): ρ, the nearest double of the radius, and a bound on |ρ − r| (0 for a double input).
  Buffer<double> radius_, radius_error_;
  bool radii_exact_ = true;  // every radius_error_ is 0

  // The slots in cell order (slot t holds circle layout_.id()[t]) and the list of the pairs that can meet
  // before the next rebuild, as the double engine keeps them.
  CellLayout layout_;
  Approximations approx_;
  double error_bound_ = 0;  // at least the error of every approximation a step may test
  // The list walks (fixed width, at least a quarter of the slots in no listed pair): X and Y wait, pending_
  // moves behind, and the listed slots' approximations walk (walk()).
  bool walking_ = false;
  double largest_move_ = 0;  // W ≥ every listed |wx|, |wy| of a walking list (contacts only copy them)
  Buffer<std::uint32_t> listed_;  // the slots in a listed pair, ascending
  double vmax_ = -1;                    // speed_bound of the first world (−1: not yet computed)
  std::uint64_t pending_ = 0;           // steps whose moves X and Y have not taken (a walking list; every slot)
  // The rebuild's radii (inflated by the skin and the centres' errors; padded by the errors alone) and
  // the gather's scratch.
  Buffer<double> inflated_, padded_, scratch_;
};

}  // namespace circles::impl
