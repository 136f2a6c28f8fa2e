// The exact engine's error bounds on its approximations (impl/exact_engine.cpp): each a named constant with
// its derivation beside it, and the one function that applies it. Each function is RN of sums and products of
// non-negative doubles, so it is monotone in every argument: the bound of the largest input bounds them all.
// tests/exact_bounds_test.cpp recomputes every claim below in exact rationals, at the inputs where it is
// tightest, so that a constant lowered past what its claim needs fails there.
//   u = 2^-53 (the unit roundoff), η = 2^-1075 (half the least subnormal).
#pragma once

#include <cmath>
#include <limits>

namespace circles::impl::exact {

// A centre. exact::approximate puts each coordinate within 2^-50·|a| + η of the exact one, a being the
// approximation. The bound of a largest coordinate m is c = RN(RN(m·2^-49) + 2^-1073).
//   Claim: c ≥ 2^-49·m and c ≥ 2^-1073, twice each term, so c ≥ 2·(2^-50·m + η) less nothing that matters:
//   the factor of two covers c's own roundings and those of adding a radius's bound to it (error_bound).
// m·2^-49 is exact unless it is subnormal, where it is off by at most η, which the 2^-1073 (= 4η) added
// covers; RN of a sum of non-negative doubles is at least each of them.
inline constexpr double kBoxRelative = 0x1p-49;
inline constexpr double kBoxAbsolute = 0x1p-1073;
inline double centre_bound(double m) noexcept { return m * kBoxRelative + kBoxAbsolute; }

// A radius that is no double: ρ = RN(r) is within u·ρ + η of it. The bound kept is RN(RN(2^-52·ρ) + 2^-1074).
//   Claim: it is ≥ 2^-52·ρ and ≥ 2^-1074, twice each term, so that RN(c + it) still bounds the sum of both
//   errors (error_bound).
inline constexpr double kRadiusRelative = 0x1p-52;
inline constexpr double kRadiusAbsolute = 0x1p-1074;
inline double radius_bound(double rho) noexcept { return rho * kRadiusRelative + kRadiusAbsolute; }

// E for a step: the centres' bound for a largest coordinate m, plus the largest radius's bound (0 when every
// radius is a double). Claim: at least the sum of the two errors they bound, each with its factor of two
// less two roundings: RN(c + ρ_e) ≥ (1 − u)·(c + ρ_e) for normal sums, exact for subnormal ones.
inline double error_bound(double m, double radius) noexcept { return centre_bound(m) + radius; }

// The walk (ExactEngine::walk, docs/exact-engine.md): a fixed-width step adds w = V·RN(1/D) to a walked
// slot's approximations instead of computing them from X + V. Per coordinate, with P the exact position and
// a′ = RN(a + w),
//   |a′ − P′| ≤ |a − P| + |w − v/60| + |a′ − (a + w)| ≤ E + (2^-50·W + η) + u·A,
// for W ≥ |w| (exact::approximate's bound) and A ≥ |a′| (a sum of two doubles rounds by at most u of its
// result, and is exact where that is subnormal).
//   Claim: walked(E, W, A) ≥ E + 2^-50·W + η + u·A, exactly.
// Each term is taken twice, W·2^-49 + A·2^-52 + 2^-1073, so that its two products (exact, or off by η each
// where subnormal, which 2^-1073 − 2^-1075 covers) and its two sums (a factor 1 − u each) still leave at
// least the terms; E + x rounds to nearest, and the next double up is at least the exact E + x. The tests
// find the claim's edges at 2^-50 for kWalkMove (W = 1) and 2^-53 for kWalkSum (A = 1). kWalkAbsolute is
// slack there (no input tried fails without it: the next double above RN(s) is at least s + η); it stays so
// that the derivation does not lean on that. proofs/smt/walk.smt2 proves the claim by z3 for every finite E, W,
// A ≥ 0, refuses kWalkMove = 2^-51 and kWalkSum = 2^-54, and proves it with kWalkAbsolute = 0 as well.
inline constexpr double kWalkMove = 0x1p-49;
inline constexpr double kWalkSum = 0x1p-52;
inline constexpr double kWalkAbsolute = 0x1p-1073;
inline double walked(double bound, double largest_move, double reach) noexcept {
  const double growth = (largest_move * kWalkMove + reach * kWalkSum) + kWalkAbsolute;
  return std::nextafter(bound + growth, std::numeric_limits<double>::infinity());
}

// The pair filter (exact::intersect_approximate, impl/exact_integer.hpp): circle a's centre is within e_a of
// (a_x, a_y) on each axis and its radius within e_a of ρ_a (ρ_a, e_a ≥ 0), the same for b. With s, dx, dy the
// rounded ρ_a + ρ_b, b_x − a_x, b_y − a_y and E = e_a + e_b, each of them is within u·|itself| + E of the exact
// value (u = 2^-53), so F = S² − X² − Y² is within
//   (5u + O(u²))·(s² + dx² + dy²)  +  (2 + 2u)·E·(s + |dx| + |dy|) + 3E²
// of the computed s² − (dx² + dy²) (docs/exact-engine.md). The bound below takes 2^-50 = 8u on the computed
// sum of squares (which is at least (1 − u)³ of the exact one) and 4·E·(s + |dx| + |dy| + E), each covering
// its term with the roundings of the bound itself to spare, plus 2^-1069 = 64η for products that underflow
// (η = 2^-1075; at most eight of them, each off by η).
// The relative term has more than twice what it needs, so 4u would hold too: with p = RN(s²), q = RN(RN(dx²) +
// RN(dy²)), the roundings move F by at most 3u·p + 4u·q + O(u²)·m (s's twice and p's own; dx's twice, the
// square's and the sum's), and a wrong sign needs |p − q| ≤ |F − (p − q)|·(1 + 3u), at most 4u·m(1 + O(u)) plus
// the E terms, so 3u·p + 4u·q = 3.5u·(p + q) + 0.5u·(q − p) ≤ (3.5u + O(u²))·m plus 0.5u of the E terms, which
// their factor 4, twice the 2 + 2u they need, covers.
inline constexpr double kApproximateRelative = 0x1p-50;
inline constexpr double kApproximateSpread = 4;
inline constexpr double kApproximateAbsolute = 0x1p-1069;

// The pair list's radii (impl/exact_engine.cpp, rebuild): a circle whose centre is within e of (a_x, a_y) on
// each axis, so within √2·e in the plane, and whose radius is within e of ρ has r + |a − p| ≤ ρ + (1 + √2)·e,
// so the disc of that radius around a holds the exact disc. kCentreSpread = 2.5 ≥ (1 + √2)·(1 + 2^-5) covers
// 1 + √2 = 2.41421… with the two roundings of RN(RN(e·2.5) + skin) to spare (docs/exact-engine.md).
// Where e is subnormal the claim radius ≥ ρ + (1 + √2)·e + skin fails by 0.0711·2^-1074: at e = 5·2^-1074,
// ρ = 2^-1072, skin = (2^52 + 1)·2^-1071, both sums round down by half an ulp to even and outward_upper adds one
// ulp, so the radius is ρ + RN(2.5e) + skin exactly, with RN(2.5e) = 12·2^-1074 (proofs/bounds.tsv). The disc
// still holds by hand, not by machine: the radius is at least ρ + RN(2.5e) + skin ≥ ρ + (1 + √2)·(e − η) + skin,
// and e − η still bounds the errors (centre_bound's c is at least 2^-50·m + 2η, twice each term).
inline constexpr double kCentreSpread = 2.5;

// The order (ExactEngine::precedes): approximations each within E of their coordinate decide the order
// when they are more than 4E apart (the derivation is there; 2E would do). The test at its edge (tests/exact_engine_test.cpp,
// "Walking approximations") fails for any factor below 400/418; between 1 and 2 no world can fail, since E
// is twice the largest error a walk reaches.
inline constexpr double kOrderSpread = 4;

}  // namespace circles::impl::exact
