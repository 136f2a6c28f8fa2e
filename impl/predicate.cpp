// Stages A' and B of the exact intersect predicate (predicate.hpp; proofs in docs/predicate.md).
#include "impl/predicate.hpp"

#include "impl/detail/exact_int.hpp"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cstdint>

namespace circles::impl {
namespace {

using detail::Dyadic;
using detail::dyadic;

// The biased exponent field of a double: 0 for zero and subnormals, 1..2046 for normals.
int biased_exponent(double x) { return static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff); }

// 2^k for −1022 ≤ k ≤ 1023, exactly (a normal double, built from its bits).
double power_of_two(int k) { return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52); }

static_assert(sizeof(long) >= sizeof(std::int64_t), "mpz_set_si must take a 53-bit significand");

}  // namespace

// Stage A'. s, dx, dy as in Stage A; if one overflowed, recompute all three from halved inputs (inputs then
// hold a value ≥ 2^1023, the halves are exact except for inputs below 2^-1021, off by ≤ η each). Then scale
// by 2^-e, e = the binade of the largest, clamped to [−1022, 1022], so the largest lies in [1, 4) (or all
// were exact subnormal differences, scaled exactly). The filter's proof with kAbsoluteRescaled covers the
// extra errors.
Decision intersect_rescaled(double ax, double ay, double ar, double bx, double by, double br) {
  double s = ar + br;
  if (s < 0) return Decision::disjoint;
  double dx = bx - ax;
  double dy = by - ay;
  if (std::isinf(s) || std::isinf(dx) || std::isinf(dy)) {
    s = ar * 0.5 + br * 0.5;
    dx = bx * 0.5 - ax * 0.5;
    dy = by * 0.5 - ay * 0.5;
  }
  const double m = std::max({std::fabs(dx), std::fabs(dy), std::fabs(s)});
  // m = 0 only without halving (else m ≥ 2^1022); sums of doubles round to 0 only when exactly 0: F = 0.
  if (m == 0) return Decision::intersect;
  const int e = std::min(std::max(biased_exponent(m), 1) - 1023, 1022);
  const double f = power_of_two(-e);
  return sign_filter(dx * f, dy * f, s * f, filter::kAbsoluteRescaled);
}

// Stage B. Every input is m·2^e; with E the least e, the integers N = m·2^(e−E) give
// F·2^(−2E) = (N_ar + N_br)² − (N_bx − N_ax)² − (N_by − N_ay)², computed exactly. The integers are kept per
// thread so that a call allocates nothing once they have grown.
bool intersect_gmp(double ax, double ay, double ar, double bx, double by, double br) {
  const std::array<Dyadic, 6> x{dyadic(ax), dyadic(ay), dyadic(ar), dyadic(bx), dyadic(by), dyadic(br)};
  int least = INT_MAX;
  for (const Dyadic& d : x)
    if (d.m != 0) least = std::min(least, d.e);  // zeros have no exponent
  if (least == INT_MAX) return true;  // all zero
  thread_local std::array<detail::Mpz, 4> z;
  const auto set = [least](mpz_ptr n, const Dyadic& d) {
    mpz_set_si(n, static_cast<long>(d.m));
    if (d.m != 0) mpz_mul_2exp(n, n, static_cast<mp_bitcnt_t>(d.e - least));
  };
  mpz_ptr s = z[0].get(), dx = z[1].get(), dy = z[2].get(), t = z[3].get();
  set(s, x[2]);
  set(t, x[5]);
  mpz_add(s, s, t);
  if (mpz_sgn(s) < 0) return false;
  set(dx, x[3]);
  set(t, x[0]);
  mpz_sub(dx, dx, t);
  set(dy, x[4]);
  set(t, x[1]);
  mpz_sub(dy, dy, t);
  mpz_mul(s, s, s);
  mpz_mul(dx, dx, dx);
  mpz_mul(dy, dy, dy);
  mpz_add(dx, dx, dy);
  return mpz_cmp(s, dx) >= 0;
}

bool intersect_fallback(double ax, double ay, double ar, double bx, double by, double br, Stage& stage) {
  const double s = ar + br;
  const double dx = bx - ax;
  const double dy = by - ay;
  const double m = s * s + (dx * dx + dy * dy);  // Stage A's M
  if (std::isinf(m) || m < filter::kRescaleBelow) {
    if (const Decision d = intersect_rescaled(ax, ay, ar, bx, by, br); d != Decision::undecided) {
      stage = Stage::rescaled;
      return d == Decision::intersect;
    }
  }
  stage = Stage::gmp;
  return intersect_gmp(ax, ay, ar, bx, by, br);
}

}  // namespace circles::impl
