// The exact engine's integer kernels; the contracts are in exact_integer.hpp.
#include "impl/exact_integer.hpp"

#include <gmp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

namespace circles::impl::exact {
namespace {

// The filter's bound: with each input within a relative ε = 2^-52 = 2u and three more roundings,
// |RN(P − Q) − F| ≤ 7.01u·(S² + dX² + dY²) (docs/exact-engine.md), and RN(P + Q) ≥ (1 − 7u)(S² + dX² + dY²),
// so RN(P + Q)·2^-48 = 32u·RN(P + Q) bounds the error with a margin of four. The product is exact: P + Q is 0
// or at least about 1 (the inputs approximate integers), far from underflow.
constexpr double kFilterScale = 0x1p-48;
// Wide arguments above this many bits skip the filter: their squares would overflow a double (2^1024).
constexpr std::size_t kFilterBits = 500;

// A 256-bit unsigned integer as two halves; enough for a sum of two squares below 2^253.
struct U256 {
  NarrowMagnitude hi, lo;
};

NarrowMagnitude magnitude(Narrow x) noexcept {
  return x < 0 ? NarrowMagnitude{0} - static_cast<NarrowMagnitude>(x) : static_cast<NarrowMagnitude>(x);
}

// a² for a < 2^126, by 64-bit halves: a = a1·2^64 + a0, a² = a1²·2^128 + 2·a1·a0·2^64 + a0², where
// a1 < 2^62 makes 2·a1·a0 < 2^127 and a1² + carries < 2^128.
U256 square(NarrowMagnitude a) noexcept {
  constexpr NarrowMagnitude kLow = std::numeric_limits<std::uint64_t>::max();
  const NarrowMagnitude a0 = a & kLow, a1 = a >> 64;
  const NarrowMagnitude cross = 2 * a1 * a0, low = a0 * a0;
  const NarrowMagnitude lo = low + (cross << 64);
  return {a1 * a1 + (cross >> 64) + (lo < low ? 1 : 0), lo};
}

U256 add(U256 a, U256 b) noexcept {
  const NarrowMagnitude lo = a.lo + b.lo;
  return {a.hi + b.hi + (lo < a.lo ? 1 : 0), lo};
}

// Leading zero bits of a nonzero 128-bit value (std::countl_zero takes standard unsigned types only).
int leading_zeros(NarrowMagnitude x) noexcept {
  const auto hi = static_cast<std::uint64_t>(x >> 64);
  return hi != 0 ? std::countl_zero(hi) : 64 + std::countl_zero(static_cast<std::uint64_t>(x));
}

// x = (q + f)·2^e with 0 ≤ f < 1, f ≠ 0 exactly when `sticky`, and q ≥ 2^53 (at least 54 bits): RN(x).
// The bits of q below its leading 53 and f decide: above half an ulp when the first of them is 1 and anything
// after it is not 0; exactly half when only the first is 1, and then to even.
double round_scaled(NarrowMagnitude q, bool sticky, int e) noexcept {
  const int shift = 128 - leading_zeros(q) - 53;  // ≥ 1
  const NarrowMagnitude rest = q & ((NarrowMagnitude{1} << shift) - 1), half = NarrowMagnitude{1} << (shift - 1);
  auto m = static_cast<std::uint64_t>(q >> shift);
  if (rest > half || (rest == half && (sticky || (m & 1)))) ++m;
  // m ≤ 2^53 is a double, and the scaling by 2^(shift + e) is exact: narrow quotients lie in [2^-128, 2^128].
  return std::ldexp(static_cast<double>(m), shift + e);
}

}  // namespace

int intersect_filter(double s, double dx, double dy) noexcept {
  const double p = s * s, q = dx * dx + dy * dy;
  const double difference = p - q, bound = (p + q) * kFilterScale;
  if (difference > bound) return 1;
  if (difference < -bound) return 0;
  return -1;
}

bool intersect_scaled(Narrow s, Narrow dx, Narrow dy) noexcept {
  // Either difference beyond the sum of the radii: the circles' boxes are apart, exactly.
  const NarrowMagnitude ms = magnitude(s), mx = magnitude(dx), my = magnitude(dy);
  if (mx > ms || my > ms) return false;
  // Each conversion is RN, within a relative 2^-53 ≤ 2^-52; magnitudes below 2^126 < 2^500.
  const int filtered = intersect_filter(to_double(s), to_double(dx), to_double(dy));
  if (filtered >= 0) return filtered == 1;
  const U256 left = square(ms), right = add(square(mx), square(my));
  return std::tie(left.hi, left.lo) >= std::tie(right.hi, right.lo);
}

bool intersect_scaled(const Wide& s, const Wide& dx, const Wide& dy) {
  if (mpz_cmpabs(raw(dx), raw(s)) > 0 || mpz_cmpabs(raw(dy), raw(s)) > 0) return false;
  // |dx|, |dy| ≤ s here, so s's size bounds all three. mpz_get_d truncates: within a relative 2^-52.
  if (mpz_sizeinbase(raw(s), 2) <= kFilterBits) {
    const int filtered = intersect_filter(mpz_get_d(raw(s)), mpz_get_d(raw(dx)), mpz_get_d(raw(dy)));
    if (filtered >= 0) return filtered == 1;
  }
  return s * s >= dx * dx + dy * dy;
}

double round_quotient(Narrow n, NarrowMagnitude d) noexcept {
  if (n == 0) return 0.0;
  const NarrowMagnitude a = magnitude(n);
  // Normalize a to 128 bits (exact, a power-of-two scaling), then divide: q ≥ 2^127/d.
  const int lead = leading_zeros(a);
  const NarrowMagnitude top = a << lead;
  NarrowMagnitude q = top / d, r = top % d;
  int e = -lead;
  // Long division, one bit at a time, until q has 54 bits: the next bit is 1 when 2r ≥ d, tested as r ≥ d − r
  // so that nothing overflows. At most 54 rounds, and none when d < 2^74.
  while (q >> 53 == 0) {
    const bool bit = r >= d - r;
    r = bit ? r - (d - r) : 2 * r;
    q = 2 * q + (bit ? 1 : 0);
    --e;
  }
  const double x = round_scaled(q, r != 0, e);
  return n < 0 ? -x : x;
}

double round_quotient(const Wide& n, const Wide& d) {
  if (n == 0) return 0.0;
  // |n| < 2^126 and 0 < d < 2^127 fit the fixed-width division above; its two low limbs are then the values.
  static_assert(sizeof(mp_limb_t) == 8, "64-bit GMP limbs");
  if (mpz_sizeinbase(raw(n), 2) <= 126 && mpz_sizeinbase(raw(d), 2) <= 127) {
    const auto limbs = [](const Wide& z) {
      return (NarrowMagnitude{mpz_getlimbn(raw(z), 1)} << 64) | mpz_getlimbn(raw(z), 0);
    };
    const auto a = static_cast<Narrow>(limbs(n));
    return round_quotient(n < 0 ? -a : a, limbs(d));
  }
  spec::Q q(n);
  q /= spec::Q(d);
  return spec::nearest_double(q);
}

double approximate(const Wide& n, const Wide& d) noexcept {
  // Each mantissa is truncated to 53 bits (within a relative 2^-52), one division (2^-53) and one scaling
  // (exact, or within 2^-1075 below the normal range): 5u in all, under the promised 2^-50.
  long en = 0, ed = 0;
  const double mn = mpz_get_d_2exp(&en, raw(n)), md = mpz_get_d_2exp(&ed, raw(d));
  const long e = std::clamp(en - ed, long{-2000}, long{2000});  // beyond ±1100 the result is 0 or clamped anyway
  const double x = std::ldexp(mn / md, static_cast<int>(e));
  constexpr double kMax = std::numeric_limits<double>::max();
  return std::clamp(x, -kMax, kMax);
}

Scaled scale(const std::vector<spec::Circle>& circles) {
  const std::size_t n = circles.size();
  Scaled out;
  Wide l = 1;
  out.rounded.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const spec::Circle& c = circles[k];
    spec::check_radius(c, k, spec::Radii::non_negative);
    out.rounded.push_back(spec::nearest_doubles(c));
    const spec::Q* fields[5] = {&c.p.x(), &c.p.y(), &c.v.x(), &c.v.y(), &c.r};
    for (std::size_t f = 0; f < 5; ++f) {
      if (!std::isfinite(out.rounded[k][f]))
        throw spec::OutsideC(k, static_cast<spec::Field>(f),
                             "value " + spec::to_string(*fields[f]) + " is beyond the double range");
      mpz_lcm(raw(l), raw(l), raw(boost::multiprecision::denominator(*fields[f])));
    }
  }
  out.den_v = l;
  out.den = 60 * l;
  // q·scale for a rational q whose denominator divides scale.
  const auto at_scale = [](const spec::Q& q, const Wide& scale) -> Wide {
    return boost::multiprecision::numerator(q) * (scale / boost::multiprecision::denominator(q));
  };
  for (std::vector<Wide>& column : out.columns) column.reserve(n);
  for (const spec::Circle& c : circles) {
    const spec::Q* fields[5] = {&c.p.x(), &c.p.y(), &c.v.x(), &c.v.y(), &c.r};
    for (std::size_t f = 0; f < 5; ++f) out.columns[f].push_back(at_scale(*fields[f], f == 2 || f == 3 ? out.den_v : out.den));
  }
  return out;
}

}  // namespace circles::impl::exact
