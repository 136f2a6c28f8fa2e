// The position update of equation (5) over binary64, per coordinate: x' = p + Δt·v with Δt = 1/60.
//
// Two numerical tiers, named by what they promise:
//   advance_naive    p + v·RN(1/60): two roundings and an inexact constant. NOT correctly rounded: it is
//                    off by up to ~1.1 ulp for same-sign inputs and unboundedly (relative to x') under
//                    cancellation. Kept for benchmarks and for the error study.
//   advance_rounded  RN(p + v/60), the correctly rounded value of the exact x' (round to nearest, ties
//                    to even), bit for bit, for every pair of finite doubles. A certified fast path and
//                    an exact fallback ladder; docs/rounding.md has the proofs.
//
// Conventions of advance_rounded (all of them agree with spec::nearest_double(exact(p) + exact(v)/60)
// except the one marked *):
//   - an exact zero result is +0: (1, −60) → +0, (−0, +0) → +0;
//   * (−0, −0) → −0, as IEEE −0 + (−0)/60 gives (the oracle, a rational, has no sign of zero: +0);
//   - a nonzero x' that underflows keeps the sign of x': (+0, −2^-1074) → −0;
//   - finite p, v whose x' rounds beyond DBL_MAX give ±inf, the correctly rounded overflow, as a single
//     IEEE operation would; the engine tests isfinite to detect and report it;
//   - a NaN or infinite p or v gives exactly what IEEE p + v/60.0 gives (±inf or NaN).
// Floating-point exception flags are not part of the contract (the fast path may raise inexact or
// invalid on inputs whose result is exact or finite). The contract assumes the default floating-point
// environment: round to nearest, no flush-to-zero or denormals-are-zero (as -ffast-math's startup code
// would set), since the exactness arguments use subnormal arithmetic.
//
// rounding.cpp must be compiled with -ffp-contract=off (circles::numeric does it): a contracted
// p + v·C would replace q = RN(v·C) inside the TwoSum and break its exactness.
//
// Build: the fast path's remainder uses hardware FMA when __FMA__ is defined (-mfma or an
// -march that has it), and an FMA-free form otherwise; both are exact and give identical results. The
// whole program must be compiled one way or the other (the choice is made in rounding.cpp only).
#pragma once

#include "impl/double_bounds.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>

namespace circles::impl {

// ── Constants, each with its derivation (tests/rounding_test.cpp recomputes every one exactly) ────────
// Notation: u = 2^-53 (unit roundoff), η = 2^-1075 (half the smallest subnormal; not a double).
namespace rounding {

// 1/Δt. 60 = 64 − 4, which the FMA-free remainder uses.
inline constexpr double kInverseDt = 60.0;
inline constexpr double kRemainderHigh = 64.0;  // kInverseDt + kRemainderLow, a power of two
inline constexpr double kRemainderLow = 4.0;    // a power of two

// C = RN(1/60). 1/60 = 0x0.0444…(hex) = 2^-6 · 0x1.111…; the 14th hex digit is 1 < 8, so RN truncates:
// C = 0x1.1111111111111p-6 and 1/60 − C = 2^-58/15 = (16/15)·2^-62 ≈ 1.07·2^-62, exactly 2^-56·(1/60):
// a relative error of u/8.
inline constexpr double kC = 0x1.1111111111111p-6;

// The fast path's and the fallback's bounds (kRemainderGuard, kBoundScale, kBoundOffset, kCancellationRatio,
// kTinyLimit), each with its derivation, are in impl/double_bounds.hpp, namespace rounding.

// The batch form works in blocks of this many elements: a block's reject flags live on the stack (2 KiB).
inline constexpr std::size_t kBatchBlock = 256;

}  // namespace rounding

// ── The naive tier ───────────────────────────────────────────────────────────────────────────────────

// p + v·RN(1/60), two roundings (no FMA contraction: the library is built with -ffp-contract=off).
// Not correctly rounded; see the file comment.
double advance_naive(double p, double v) noexcept;

// p[i] = advance_naive(p[i], v[i]) for every i. p and v must have the same size and must not overlap.
// Throws std::invalid_argument if the sizes differ.
void advance_naive(std::span<double> p, std::span<const double> v);

// ── The correctly rounded tier ───────────────────────────────────────────────────────────────────────

// RN(p + v/60), bit for bit, with the conventions in the file comment.
double advance_rounded(double p, double v) noexcept;

// p[i] = advance_rounded(p[i], v[i]) for every i: the same bits as the scalar form. The fast path runs over
// blocks of kBatchBlock elements as a branch-free loop that GCC 12 vectorizes at plain -O2 once AVX2 is
// enabled (-mavx2 or -march=x86-64-v3; with SSE4.2 it also needs -fvect-cost-model=dynamic; baseline
// SSE2 stays scalar); the inputs it cannot certify are then finished by the scalar fallback. p and v must have the same size and must not
// overlap. Throws std::invalid_argument if the sizes differ.
void advance_rounded(std::span<double> p, std::span<const double> v);

// Which path of advance_rounded decides a result, in the order they are tried.
enum class RoundingPath : std::uint8_t {
  certified,     // fast path: |x − y| < half the gap below |y|, so y = RN(x)
  exact_sum,     // fast path: the remainder r is 0, so x = p + q and y = RN(p + q)
  non_finite,    // p or v is NaN or ±inf: IEEE p + v/60.0
  zeros,         // p = v = 0: p + v
  cancellation,  // |RN(p + q)| ≤ 2^-8|q|: fma(60, s, r)/60
  tiny,          // |fma(60, p, v)| < 2^-1021: that fma is exact, then one division
  exact_integer, // GMP: N·2^E/60 rounded by integer division
};
inline constexpr int kRoundingPathCount = 7;

std::string_view to_string(RoundingPath path) noexcept;

// advance_rounded, also reporting the path that decided the result. Same code, same bits; for tests and
// for studying fallback rates.
double advance_rounded_traced(double p, double v, RoundingPath& path) noexcept;

// The pieces of advance_rounded, exposed so the tests can check each claim on its own.
namespace rounding {

// True when this library was compiled with __FMA__ (hardware FMA in the fast path).
bool uses_fma() noexcept;

// r = v − 60q for q = RN(v·C), exactly, as the fast path computes it (fma(−q, 60, v), or (v − 64q) + 4q
// when |v| ≤ kRemainderGuard in the FMA-free build). Precondition: v finite, q = RN(v·kC), and, in the
// FMA-free build, |v| ≤ kRemainderGuard.
double exact_remainder(double v, double q) noexcept;

// B = RN(RN(RN(|e| + |c|) + 2^-1022)·2^-50), as the fast path computes it.
double certificate_bound(double e, double c) noexcept;

// The last rung of the ladder on its own: RN(p + v/60) for finite p, v by GMP integer arithmetic.
double exact_integer_round(double p, double v) noexcept;

}  // namespace rounding

}  // namespace circles::impl
