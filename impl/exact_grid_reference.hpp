// The exact reference on a grid, for checking the traces of exact engines on big worlds: the oracle's resolved
// step (spec/equations.hpp), its exact sequence from w_0, with the pairs (3) is asked about taken from a uniform
// grid.
//
//   Invariant: after t steps, exact() equals spec::resolved_step applied t times to the input, as rationals,
//              and rounded() is it with each coordinate rounded to nearest, ties to even (an exact zero as +0);
//              a step whose position rounds to ±infinity throws PositionOverflow like ExactEngine.
//              tests/exact_grid_reference_test.cpp holds it equal to the oracle.
//
// It is deliberately not the engine it judges (impl/exact_engine.hpp: widths proven per scene, slots in cell
// order, levelled cells, pair lists, threads). The state is the exact engine's representation in one width:
// with L the least common multiple of the inputs' denominators and D = 60·L, the GMP integers X = D·p, V = L·v
// and R = D·r, circle k at index k; a step is X ← X + V of the least contact. The grid is step_grid's
// (impl/grid_reference.hpp: cells of side 4·max ρ, the 3×3 around each) over the nearest doubles of the
// centres, which a proof (exact_grid_reference.cpp) shows to lose no intersecting pair. Every pair it offers is
// decided exactly, with the exact engine's kernels: exact::intersect_approximate on the nearest doubles within
// their error bound (below), and where that cannot tell, exact::intersect_scaled on the integers. The least
// contact is by the lexicographic order (7) on the integers, then the index. Where the proof does not hold,
// every pair is asked.
#pragma once

#include "impl/engine.hpp"
#include "impl/exact_integer.hpp"
#include "spec/oracle.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace circles::impl {

// The smallest cell side the exact grid takes: below it the nearest doubles' absolute error (2^-1075 for
// subnormals) is no longer small against h, and every pair is asked instead.
inline constexpr double kExactGridMinSide = 0x1p-1000;

// The error of a nearest double x̃ = RN(x) of a finite x̃, as exact::intersect_approximate takes it: circle k's
// e = max(m·kNearestRelative, kNearestFloor) with m the largest of |x̃|, |ỹ| and ρ bounds the error of each.
// RN is within half an ulp, |x̃ − x| ≤ 2^-53·|x̃| + 2^-1075 (2^-1075: half the subnormal spacing). For
// m ≥ 2^-969, m·2^-52 is exact and is 2^-53·m + 2^-53·m ≥ 2^-53·m + 2^-1022; below, 2^-53·m + 2^-1075 <
// 2^-1022 + 2^-1075 < 2^-1021.
// The floor keeps each circle's own bound; the filter needs only the pair's sum E = e_a + e_b, which holds
// without it: two circles with m < 2^-1021 have |s|, |dx|, |dy| < 2^-1019, whose squares round to 0, so no E
// lets the filter decide them; beside one with m ≥ 2^-1021, its RN(m·2^-52) ≥ 2^-52·m − 2^-1075 ≥ 2^-53·m +
// 2^-1075 bounds its own error (2^-53·m) and the other's (2^-1075, half the spacing below 2^-1021) together.
inline constexpr double kNearestRelative = 0x1p-52;
inline constexpr double kNearestFloor = 0x1p-1021;

// The side of the exact grid's cells for a world whose nearest doubles are `rounded` (each circle
// [px, py, vx, vy, r]): uniform_side of the largest rounded radius and the rounded centres, when it is at least
// kExactGridMinSide; else nothing (every pair is asked).
std::optional<double> exact_grid_side(const spec::Circles& rounded);

class ExactGrid {
 public:
  // From rationals (any denominators). Throws spec::OutsideC for a negative radius, and for a field whose
  // nearest double is infinite, naming the circle and field, as ExactEngine does.
  explicit ExactGrid(const spec::Sequence& w0);
  // From doubles, each taken at its exact value. Throws spec::OutsideC for NaN, infinities and r < 0.
  explicit ExactGrid(const spec::Circles& w0);

  // One resolved step. Throws PositionOverflow (state unchanged) for the first circle, px before py, whose
  // new position rounds to ±infinity.
  void step();

  std::uint64_t steps() const noexcept { return steps_; }
  std::size_t size() const noexcept { return rounded_.size(); }
  // The state rounded to doubles, circle k at index k.
  const spec::Circles& rounded() const noexcept { return rounded_; }
  // The exact state as rationals.
  spec::Sequence exact() const;

 private:
  // Intersect (3) for circles a and b: the filter on the nearest doubles, else intersect_exactly on the
  // integers.
  bool intersect(std::size_t a, std::size_t b);
  [[gnu::noinline]] bool intersect_exactly(std::size_t a, std::size_t b);
  // The order (7) of the resolved profile: (px, py, vx, vy, r) lexicographically, then the index.
  bool precedes(std::size_t a, std::size_t b) const noexcept;

  exact::Wide den_, den_v_;  // D = 60·L and L
  std::vector<exact::Wide> x_, y_, vx_, vy_, r_;
  std::vector<exact::Wide> next_x_, next_y_, next_vx_, next_vy_;  // the step's results before they are kept
  exact::Wide sum_, dx_, dy_;                                      // intersect's scratch
  std::vector<double> error_;  // per circle, this step: the error bound of its nearest doubles (kNearestRelative)
  spec::Circles rounded_, next_rounded_;
  std::uint64_t steps_ = 0;
};

// One step of the exact grid reference: spec::resolved_step(w) (as an ExactGrid's first step). Throws as
// ExactGrid does.
spec::Sequence step_grid(const spec::Sequence& w);

}  // namespace circles::impl
