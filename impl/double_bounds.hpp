// The double engines' error bounds (impl/engine.cpp and what it calls: the predicate, the correctly rounded
// update, the broad phase, the pair lists): each a named constant with its derivation beside it. The exact
// engine's are in impl/exact_bounds.hpp. proofs/bounds.tsv says, for each, which Gappa proofs in proofs/gappa/
// check it by machine or why none does (docs/proofs.md); tests/predicate_test.cpp, tests/rounding_test.cpp and
// tests/pair_list_test.cpp recompute each derivation in exact rationals.
//   u = 2^-53 (the unit roundoff), η = 2^-1075 (half the least subnormal: the absolute error of a product
//   that underflows).
#pragma once

#include <limits>

namespace circles::impl {

// The bounds of the filter (Stage A and A′ of intersect_exact; impl/pair_list.hpp's listing filters use
// kAbsolute too), each with its derivation.
namespace filter {

// kRelative = 2^-50 = 8u: the bound's factor on M = RN(P + Q), the computed S² + X² + Y².
// |D − F| ≤ k·M + γ·(b + η), k = ((1+u)^5 − 1)/(1−u)^5 ≈ 5.0000000000000036u: the X² term passes five
// roundings (dx, twice as it is squared; the square; the sum of squares; D) and M may sit five roundings
// low. The bound, computed as RN(RN(M·2^-50) + c) ≥ (M·2^-50 − η + c)(1 − u), covers k·M when
// 2^-50(1 − u) ≥ k: 8u against the design note's 5.0001u, tight to a factor 1.6.
inline constexpr double kRelative = 0x1p-50;

// kAbsolute = 2^-1072 = 8η: Stage A's absolute term c. Inputs dx, dy, s carry no absolute error (b = 0);
// the three squares may underflow, each by ≤ η, and those errors pass through at most three roundings:
// γ = 3k + 3(1+u)^3 ≈ 3. The bound needs (c − η)(1 − u) ≥ γη, i.e. c ≥ c_min ≈ 4.0000000000000027η;
// 2^-1073 = 4η is just short, 2^-1072 = 8η is the least power of two above: tight to a factor 2.
inline constexpr double kAbsolute = 0x1p-1072;

// kAbsoluteRescaled = 2^-1070 = 32η: the absolute term of Stage A'. After rescaling, |dx|, |dy|, s < 4 and
// each carries an absolute error a ≤ η(1 + 2^-1020) (η from the scaling, 2η·2^-1022 from halving when a
// difference overflowed) on top of its rounding; a square then errs by b = 2Ra(1+u) + a², R = (4 + a)/(1−u),
// so b ≈ 8η, and c_min = η + γ(b + η)/(1 − u) ≈ 28η. 32η is the least power of two above: tight to 8/7.
inline constexpr double kAbsoluteRescaled = 0x1p-1070;

// kRescaleBelow = 2^-900: intersect_exact tries Stage A' only when M is infinite or below this. It is a
// speed choice, not a correctness one (every stage is exact whatever it is): above 2^-900 Stage A's
// absolute term is under 2^-122·M·2^-50, so rescaling would give the same verdict and only cost time.
inline constexpr double kRescaleBelow = 0x1p-900;

}  // namespace filter

namespace rounding {

// |v| above this and the FMA-free remainder (v − 64q) + 4q may overflow in 64q. For |v| ≤ kRemainderGuard,
// |q| = RN(|v|·C) ≤ RN(kRemainderGuard·C) and 64·that ≤ 64·0.93·(1/60)(1 + 2^-52)·DBL_MAX ≈ 0.992·DBL_MAX,
// finite (the exact bound is 0.9375·2^1024; 0.93 leaves room). Only the FMA-free build uses it.
inline constexpr double kRemainderGuard = 0.93 * std::numeric_limits<double>::max();

// The certificate's error bound B = RN(RN(RN(|e| + |c|) + 2^-1022)·2^-50) needs B ≥ 3u(|e| + |c|) + 2η.
// 2^-50 = 8u, and 2^-1022·2^-50 = 2^-1072 = 8η. The first two roundings lose at most a factor (1 − u)
// each, the product at most η (it is exact unless subnormal), so B ≥ 8u(1 − u)²(|e| + |c|) + 8η(1 − u) − η
// ≥ 7.9u(|e| + |c|) + 3η: a margin of more than 2 on both terms. 2^-1022 is the smallest normal double:
// no operand of the bound is subnormal for ordinary data (see bound_of in rounding.cpp for why that matters).
inline constexpr double kBoundScale = 0x1p-50;     // 8u
inline constexpr double kBoundOffset = 0x1p-1022;  // DBL_MIN; times kBoundScale it is 2^-1072 = 8η

// Cancellation path: if |RN(p + q)| ≤ 2^-8|q| then p/(−q) ∈ [1 − 2^-7, 1 + 2^-7] ⊂ [1/2, 2], so p + q is
// exact (Sterbenz), and |60s + r| ≤ 60·2^-8·|q| + |r| < 0.47·2^(e_q+1) + 2^(e_q−45) < 2^e_q, a multiple of
// ulp(q) = 2^(e_q−52): fewer than 2^52 units, so fma(60, s, r) is exact.
inline constexpr double kCancellationRatio = 0x1p-8;

// Tiny path: every double is a multiple of 2^-1074, so 60p + v is; below 2^-1021 = 2^53·2^-1074 it has at
// most 53 significant bits and is a double, so fma(60, p, v) is exact. RN is monotone and 2^-1021 is a
// double, so |RN(60p + v)| < 2^-1021 implies |60p + v| < 2^-1021.
inline constexpr double kTinyLimit = 0x1p-1021;

}  // namespace rounding

// ── The skin ──────────────────────────────────────────────────────────────────────────────────────────
//
// One step moves a circle by d = (RN(px + vx/60) − px, RN(py + vy/60) − py) in the double engines. Per
// coordinate, |RN(p + v/60) − (p + v/60)| ≤ ulp(p′)/2 ≤ |p′|·2^-53 + 2^-1075 (2^-53 relative for a normal p′,
// half the subnormal ulp otherwise), so the rounding error e of d has |e| ≤ √2·(|p′|·2^-53 + 2^-1075), and
// |d| ≤ |v|/60 + |e|. Over H steps, with |v| ≤ vmax and every coordinate within `far` of the origin:
//
//   |p_{t+H} − p_t| ≤ H·(vmax/60 + √2·2^-53·far + √2·2^-1075).
//
// skin_for computes that bound in doubles with each constant rounded up by enough to cover the at most eight
// roundings (relative 2^-53 each) of its own arithmetic and of vmax (norm_upper):
//   kSpeedBound   = 0x1.11111111112p-6 ≥ (1/60)·(1 + 2^-45): 1/60 = 0x1.111…p-6, cut after 44 bits and rounded
//                   up; 2^-45 > 2^-50 > eight roundings of 2^-53; below (1/60)(1 + 2^-44), as
//                   tests/pair_list_test.cpp recomputes. Where moves are exact the drift term is slack
//                   (far·kDriftBound, about 2^-51.7 of a step or more for a pair that closes its gap within
//                   the horizon), and so are the list filter's margin (2^-50 of the distance) and
//                   outward_upper's (2^-52). Whether the other terms' roundings could all go against a speed
//                   term short of 1/60 at once is not proven either way, so kSpeedBound keeps its own margin.
//                   The tests put the whole step bound at its edge: two points that meet at the horizon's end
//                   in the tightest world (tests/pair_list_test.cpp); docs/hardening.md ("Mutants") has the
//                   runs around this margin.
//   kDriftBound   = 0x1.6a1p-53 ≥ √2·2^-53·(1 + 2^-14): √2 = 0x1.6a09e6…, rounded up at 12 bits. Its margin
//                   also covers `far` leaving out the drift itself (H·2^-52 relative, H ≤ kMaxHorizon). Its
//                   edge is on the diagonal, where both coordinates round forward by half an ulp: 2^-53 (the √2
//                   left out) drops such a pair (tests/pair_list_test.cpp).
//   kDriftAbsolute = 0x1p-1073 ≥ 2·√2·2^-1075.
//   far           = reach + H·vmax·kSpeedBound, reach = the largest |coordinate| of world t.
// proofs/gappa/step_bound.g proves step_bound's result covers the step, and skin_for's the H steps, at every vmax
// and reach up to 2^1000, H ≤ 2^16, subnormals included, and refuses each of the three constants lowered to its mutant.
// The exact engine's moves are exact (X ← X + V): its skin is the speed term alone, on its own vmax.
inline constexpr double kSpeedBound = 0x1.11111111112p-6;
inline constexpr double kDriftBound = 0x1.6a1p-53;
inline constexpr double kDriftAbsolute = 0x1p-1073;

// ── When a pair can first meet ────────────────────────────────────────────────────────────────────────
//
// A pair whose gap g = |p_b − p_a| − (r_a + r_b) is positive in world t cannot intersect in world t + j unless
// its two circles closed the gap, each moving at most j·step (step = skin/H, the bound of one step), so
// j ≥ g/(2·step): the pair needs no test before step ⌈g/(2·step)⌉ of the horizon. first_step computes that
// step from below, so the pair is tested no later than it must be:
//   dx = RN(bx − ax), dy likewise, d2 = RN(RN(dx²) + RN(dy²)): d2 ≤ D²(1 + u)^4 + 3η (u = 2^-53, η = 2^-1075
//   for the squares' underflow), so D ≥ RN(√d2)·(1 + u)^-3 − √(3η); where d2 overflows, root = norm_upper(dx,
//   dy) ≤ D·(1 + 2^-50) + 2^-1074 instead (tests/pair_list_test.cpp). And r_a + r_b ≤ RN(r_a + r_b)(1 + u).
//   So g ≥ RN(root·(1 − kGapRelative)) − RN(RN(r_a + r_b)·(1 + kGapRelative)) − kGapAbsolute with
//   kGapRelative = 2^-49 (> 2^-50 + u + 3u) and kGapAbsolute = 2^-500 > √(3η) ≈ 2^-536.7; the last
//   subtraction and the quotient round by u each, which the quotient's factor (1 − 2^-48) absorbs;
//   the step is ⌈RN(g/(2·step))·(1 − 2^-48)⌉, 0 for g ≤ 0, and kNever when it is past the horizon.
// Which of these a test can reach (tests/pair_list_test.cpp; each tried by lowering it):
//   kGapRelative  the root's rounding is u of the distance, not of the gap: without it first_step answers
//                 late for a gap of a whole number of steps that is small beside the distance (its property
//                 test fails). 4u would hold too, with kQuotientShrink: below the overflow RN(root·(1 − 4u)) ≤
//                 D·(1 + u)^4·(1 − 4u) + 2^-536 ≤ D + 2^-536; above it norm_upper's five roundings put root at
//                 most 13u/4 above |(dx, dy)| (2^-50 bounds the other side), 17u/4 above D, so RN(root·(1 − 4u))
//                 ≤ D·(1 + 5u/4 + O(u²)); the sum's side takes 2u·(r_a + r_b) off, so the gap is over by at
//                 most 5u/4·D − 2u·(r_a + r_b) ≤ 5u/4·g, which the quotient's 2^-48 = 32u covers with the
//                 three roundings after it.
//   kQuotientShrink  covered twice over: kGapRelative takes 2^-49·(root + sum) off, of which the root's own
//                 rounding needs at most 4u·root (norm_upper's 2^-50), leaving at least 12u of the gap, and
//                 the subtraction and the quotient round by u of the gap each: a quotient left unshrunk is
//                 never late (tried: no test fails, and none can); it stays for the derivation's sake.
//   kGapAbsolute  where the squares underflow, RN(√d2) exceeds the distance by an absolute amount no
//                 relative margin covers: 2^-538.27 where two squares just above half the least subnormal
//                 round up to it. 2^-539 drops such a pair and the engines miss its contact; 2^-538 does not.
// A non-finite gap (only within reach of the double range) gives 0: test from the first step.
inline constexpr double kGapRelative = 0x1p-49;
inline constexpr double kGapAbsolute = 0x1p-500;
inline constexpr double kQuotientShrink = 1 - 0x1p-48;

// ── Outward bounds ────────────────────────────────────────────────────────────────────────────────────
//
// t = RN(x − r) is within the two doubles that bracket the exact x − r, so pred(t), the double below t, is
// ≤ x − r. With e = RN(RN(|t|·2^-52) + 2^-1073) ≥ ulp(t) (|t|·2^-52 ≥ ulp(t) for normal t, RN is monotone and
// ulp(t) is a double; for subnormal t, ulp(t) = 2^-1074 < 2^-1073), t − e ≤ t − ulp(t) ≤ pred(t) exactly, and
// RN is monotone, so RN(t − e) ≤ pred(t) ≤ x − r. An overflow gives t = −∞, e = +∞ and −∞: no NaN for finite
// x, r ≥ 0. The mirror image gives the upper bound. Four flops, no libm call (std::nextafter is one).
inline constexpr double kOutwardRelative = 0x1p-52;  // |t|·2^-52 ≥ ulp(t) for normal t
inline constexpr double kOutwardAbsolute = 0x1p-1073;  // > ulp of every subnormal, 2^-1074
// For the outward bounds alone kOutwardAbsolute is slack: a subnormal t is x ∓ r exactly, and a normal t has
// |t|·2^-52 ≥ 2^-1074 already (proofs/smt/outward.smt2 proves them by z3 with it at 0 too). The exact engine's
// inflated radii need it: outward_upper(ρ, RN(e·kCentreSpread) + skin) ≥ ρ + (1 + √2)·e + skin rests on it where
// e is subnormal, since RN(5·2^-1074·2.5) = 12·2^-1074 is short of (1 + √2)·5·2^-1074.

// reach + skin below this: positions stay finite through the horizon (a rounded |p| ≤ 2^1023·(1 + 2^-52) <
// DBL_MAX), so steps update in place without checking for overflow.
inline constexpr double kOverflowFreeReach = 0x1p1023;


}  // namespace circles::impl
