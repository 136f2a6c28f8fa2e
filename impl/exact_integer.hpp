// The integer kernels of the exact engine (impl/exact_engine.hpp): the intersect test (3) on positions and
// radii scaled to integers, the filter on the broad phase's approximations that runs before it, and the
// rounding of a scaled integer back to a double. Three widths, one meaning:
//   Word    std::int64_t, for scenes whose scaled magnitudes stay within 2^kWordBits (the engine proves it);
//   Narrow  __int128, the same within 2^kNarrowBits;
//   Wide    spec::Z (GMP), for every other scene.
//
//   Invariant: intersect_scaled(S, dX, dY) is the sign test S² ≥ dX² + dY², exact for every argument in range;
//              intersect_approximate decides (3) exactly or says it cannot, given approximations within their
//              stated errors; round_quotient(n, d) is RN(n/d), round to nearest, ties to even, with an exact
//              zero as +0; to_double(x) is RN(x).
// docs/exact-engine.md has the derivations of the filters' bounds and of the headroom.
#pragma once

#include "impl/exact_bounds.hpp"
#include "impl/predicate.hpp"
#include "spec/circle.hpp"
#include "spec/rational.hpp"

#include <gmp.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace circles::impl::exact {

// -Wpedantic rejects __int128 by name; __extension__ marks the use as deliberate (GCC and Clang).
__extension__ typedef __int128 Narrow;
__extension__ typedef unsigned __int128 NarrowMagnitude;
using Wide = spec::Z;
using Word = std::int64_t;

// The GMP integer inside a Wide, for the mpz_* calls that work in place or read limbs.
inline mpz_srcptr raw(const Wide& z) noexcept { return z.backend().data(); }
inline mpz_ptr raw(Wide& z) noexcept { return z.backend().data(); }

// Every scaled position, velocity and radius of a narrow scene has magnitude ≤ 2^kNarrowBits, so a
// difference dX or a sum Ra + Rb is below 2^126 (it fits Narrow with a bit to spare) and their squares below
// 2^252 (they fit the 256-bit sum of squares of intersect_scaled).
inline constexpr int kNarrowBits = 125;
// The same for Word: |S|, |dX|, |dY| ≤ 2^62 < 2^63, and S², dX² + dY² ≤ 2^125 are exact in Narrow.
inline constexpr int kWordBits = 61;

// RN(x), inline: x = h·2^52 + l with 0 ≤ l < 2^52 (the shift floors); for |x| < 2^105, h and l are doubles
// exactly, h·2^52 is an exact scaling, and their sum rounds once. Larger x take the library's conversion.
inline double to_double(Narrow x) noexcept {
  const auto top = static_cast<std::uint64_t>(static_cast<std::int64_t>(x >> 105));  // 0 or all ones below 2^105
  if (top + 1 <= 1) [[likely]] {
    const auto h = static_cast<std::int64_t>(x >> 52);
    const auto l = static_cast<std::int64_t>(static_cast<std::uint64_t>(x) & ((std::uint64_t{1} << 52) - 1));
    return static_cast<double>(h) * 0x1p52 + static_cast<double>(l);
  }
  return static_cast<double>(x);
}

// Ra + Rb ≥ |(dX, dY)|, i.e. S² ≥ dX² + dY², for S ≥ 0. Narrow: |S|, |dX|, |dY| < 2^126.
inline bool intersect_scaled(Word s, Word dx, Word dy) noexcept {
  return Narrow{s} * s >= Narrow{dx} * dx + Narrow{dy} * dy;  // |·| ≤ 2^62: squares ≤ 2^124, their sum ≤ 2^125
}
bool intersect_scaled(Narrow s, Narrow dx, Narrow dy) noexcept;
bool intersect_scaled(const Wide& s, const Wide& dx, const Wide& dy);

// The floating-point filter both widths start with, on approximations s, dx, dy of S, dX, dY, each within
// a relative 2^-52 of the exact value and below 2^500 in magnitude: 1 when S² > dX² + dY² certainly, 0 when
// S² < dX² + dY² certainly, −1 when the filter cannot tell (the exact integers decide).
int intersect_filter(double s, double dx, double dy) noexcept;

// The filter on approximations (the engine's first test of a pair): circle a's centre is within e_a of
// (a_x, a_y) on each axis and its radius within e_a of ρ_a (ρ_a, e_a ≥ 0), the same for b. Its bound and
// the derivation are in impl/exact_bounds.hpp (kApproximate*). A non-finite value anywhere makes the bound +∞
// or NaN: undecided. Branch-free, like impl::sign_filter.
inline Decision intersect_approximate(double ax, double ay, double rho_a, double e_a, double bx, double by,
                                      double rho_b, double e_b) noexcept {
  const double s = rho_a + rho_b, dx = bx - ax, dy = by - ay, e = e_a + e_b;
  const double p = s * s, q = dx * dx + dy * dy;
  const double d = p - q, m = p + q;
  const double spread = ((s + std::fabs(dx)) + std::fabs(dy)) + e;
  const double bound = (m * kApproximateRelative + e * spread * kApproximateSpread) + kApproximateAbsolute;
  const bool decided = std::fabs(d) > bound;
  const bool positive = d > 0;
  return static_cast<Decision>((decided & positive) | (!decided) << 1);
}

// RN(n/d) for d > 0. Narrow is exact integer division with a sticky remainder; Wide takes the same division
// when |n| < 2^126 and d < 2^127, else goes through spec::nearest_double (magnitudes beyond the double range
// give ±infinity there).
double round_quotient(Narrow n, NarrowMagnitude d) noexcept;
double round_quotient(const Wide& n, const Wide& d);

// An approximation of n/d within a relative 2^-50 plus 2^-1075 absolute, for the broad phase's boxes; the
// fixed-width forms take inverse = RN(1/d) (three roundings: 3u + O(u²) < 2^-50). All are finite (the wide
// one clamped at ±DBL_MAX).
inline double approximate(Word n, double inverse) noexcept { return static_cast<double>(n) * inverse; }
inline double approximate(Narrow n, double inverse) noexcept { return to_double(n) * inverse; }
double approximate(const Wide& n, const Wide& d) noexcept;

// Rational circles as the exact engines hold them: L, the least common multiple of every field's
// denominator, D = 60·L, and per circle the integers X = D·p_x, Y = D·p_y, V = L·v, R = D·r, with each
// field's nearest double (spec::nearest_doubles).
struct Scaled {
  Wide den, den_v;  // D and L
  std::array<std::vector<Wide>, 5> columns;  // X, Y, V_x, V_y, R, circle k at index k
  spec::Circles rounded;
};
// Throws spec::OutsideC for a negative radius, and for a field whose nearest double is infinite, naming the
// circle and field.
Scaled scale(const std::vector<spec::Circle>& circles);

}  // namespace circles::impl::exact
