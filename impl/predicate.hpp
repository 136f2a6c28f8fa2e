// The intersect predicate (3) of the seed over doubles, exact, in tiers (after Shewchuk and CGAL).
//
//   Invariant: intersect_exact(a…, b…) == (3) on the exact values of the doubles, for all finite inputs:
//              a intersect b ⟺ |p_b − p_a| ≤ r_a + r_b ⟺ S ≥ 0 ∧ F ≥ 0, with
//              S = r_a + r_b,  X = b_x − a_x,  Y = b_y − a_y,  F = S² − X² − Y²  (all exact reals).
//   It equals spec::intersect on the exact values, negative radii included (then S < 0 gives false).
//
// Tiers:
//   intersect_naive      s² >= dx² + dy² in doubles. Wrong near tangency, on overflow and underflow.
//   intersect_filter     Stage A: the same squares plus a certified error bound; decides when it can.
//   intersect_rescaled   Stage A': scales dx, dy, s into [1, 4) first: no overflow, negligible underflow.
//   intersect_gmp        Stage B: exact integers (GMP). Always decides.
//   intersect_exact      Stage A inline, then A' (only where rescaling can help) and B out of line.
//
// The proofs of the bounds are in docs/predicate.md; the constants below carry their derivation in brief,
// and tests/predicate_test.cpp recomputes each one from it in exact rational arithmetic.
// Notation: u = 2^-53 (unit roundoff), η = 2^-1075 (half the least subnormal: the absolute error of a
// product that underflows). Sums and differences of doubles have no absolute error: a result below 2^-1022
// is a multiple of 2^-1074 and so exact.
//
// The proofs model every operation as exact or rounded once, so they hold with or without FMA
// contraction; the project still compiles this with -ffp-contract=off (circles::numeric). They need IEEE
// binary64 semantics otherwise: -ffast-math (reassociation, no infinities) would void every bound.
#pragma once

#include "impl/detail/steer.hpp"
#include "impl/double_bounds.hpp"

#include <cmath>
#include <cstdint>

namespace circles::impl {

// A filter's answer: the sign of F decided, or not.
enum class Decision : std::uint8_t { disjoint = 0, intersect = 1, undecided = 2 };

// Which stage gave intersect_exact its answer.
enum class Stage : std::uint8_t { filter, rescaled, gmp };

// The bounds of the filter (kRelative, kAbsolute, kAbsoluteRescaled, kRescaleBelow), each with its derivation, are
// in impl/double_bounds.hpp, namespace filter.

// Stage A's two computed terms from q = RN(RN(dx²) + RN(dy²)) and s, where dx, dy, s are X, Y, S rounded once
// each (plus, in Stage A', the absolute error kAbsoluteRescaled allows for): D = RN(s² − q), the computed F,
// and its certified error bound RN(RN(M·2^-50) + absolute) with M = RN(s² + q). `absolute` is kAbsolute or
// kAbsoluteRescaled. The sign of F is decided when |D| > bound.
struct FilterTerms {
  double d, bound;
};
inline FilterTerms filter_terms(double q, double s, double absolute) {
  const double p = s * s;
  const double m = p + q;  // +inf on any overflow, and then the bound is +inf: undecided
  return {p - q, m * filter::kRelative + absolute};
}

// The certified sign of F = S² − X² − Y² from those terms.
// Branch-free so that a loop over it vectorizes: both comparisons are always made and combined as integers
// (GCC does not if-convert a floating-point comparison that the source makes conditionally).
inline Decision sign_filter_of_squares(double q, double s, double absolute) {
  const auto [d, bound] = filter_terms(q, s, absolute);
  detail::steer(std::fabs(d), bound);  // the decision of (3): its margin, for the step fuzzer
  const bool decided = std::fabs(d) > bound;
  const bool positive = d > 0;
  // intersect (1) if decided and positive, disjoint (0) if decided and not, undecided (2) otherwise
  return static_cast<Decision>((decided & positive) | (!decided) << 1);
}
// sign_filter_of_squares(q, s, absolute) == Decision::disjoint, in fewer operations, for the loops that
// mostly reject (the pair lists' broad phase). "Decided and not positive" is |d| > bound ∧ d ≤ 0, which is
// −d > bound: for d ≤ 0, |d| = −d, and for d > 0, −d < 0 < bound (bound ≥ absolute > 0, or +∞ or NaN, where
// both forms are false). tests/predicate_test.cpp holds the two equal.
inline bool certainly_disjoint_of_squares(double q, double s, double absolute) {
  const auto [d, bound] = filter_terms(q, s, absolute);
  return -d > bound;
}
// sign_filter_of_squares(q, s, absolute) == Decision::intersect, likewise: d > bound (then d > 0 and |d| = d).
inline bool certainly_intersecting_of_squares(double q, double s, double absolute) {
  const auto [d, bound] = filter_terms(q, s, absolute);
  return d > bound;
}
// The same from dx and dy: q = RN(RN(dx²) + RN(dy²)).
inline Decision sign_filter(double dx, double dy, double s, double absolute) {
  return sign_filter_of_squares(dx * dx + dy * dy, s, absolute);
}

// Naive: (ar + br)² >= dx² + dy² in doubles. Kept for benchmarks only.
inline bool intersect_naive(double ax, double ay, double ar, double bx, double by, double br) {
  const double dx = bx - ax;
  const double dy = by - ay;
  const double s = ar + br;
  return s * s >= dx * dx + dy * dy;
}

// Stage A. RN(ar + br) has the sign of S (a sum of doubles rounds to 0 only when it is 0), so s < 0 ⟺ S < 0.
// Branch-free like sign_filter: S < 0 turns any answer into disjoint (0).
inline Decision intersect_filter(double ax, double ay, double ar, double bx, double by, double br) {
  const double s = ar + br;
  const bool negative = s < 0;
  return static_cast<Decision>(static_cast<int>(sign_filter(bx - ax, by - ay, s, filter::kAbsolute)) * !negative);
}

// Stage A': rescaled filter. Decides every input that is not within about 2^-50 of tangency.
Decision intersect_rescaled(double ax, double ay, double ar, double bx, double by, double br);

// Stage B: exact, always.
bool intersect_gmp(double ax, double ay, double ar, double bx, double by, double br);

// Stages A' (when M is infinite or below kRescaleBelow) and B, for inputs Stage A left undecided.
// Sets `stage` to the stage that decided.
bool intersect_fallback(double ax, double ay, double ar, double bx, double by, double br, Stage& stage);

// The exact predicate, reporting which stage decided.
inline bool intersect_exact(double ax, double ay, double ar, double bx, double by, double br, Stage& stage) {
  if (const Decision d = intersect_filter(ax, ay, ar, bx, by, br); d != Decision::undecided) [[likely]] {
    stage = Stage::filter;
    return d == Decision::intersect;
  }
  return intersect_fallback(ax, ay, ar, bx, by, br, stage);
}

// The exact predicate: (3) on the exact values of the doubles, for all finite inputs.
inline bool intersect_exact(double ax, double ay, double ar, double bx, double by, double br) {
  Stage stage;
  return intersect_exact(ax, ay, ar, bx, by, br, stage);
}

}  // namespace circles::impl
