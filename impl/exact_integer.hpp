// The integer kernels of the exact engine (impl/exact_engine.hpp): the intersect test (3) on positions and
// radii scaled to integers, and the rounding of a scaled integer back to a double. Two widths, one meaning:
//   Narrow  __int128, for scenes whose scaled magnitudes stay within 2^kNarrowBits (the engine proves it);
//   Wide    spec::Z (GMP), for every other scene.
//
//   Invariant: intersect_scaled(S, dX, dY) is the sign test S² ≥ dX² + dY², exact for every argument in range;
//              round_quotient(n, d) is RN(n/d), round to nearest, ties to even, with an exact zero as +0.
// docs/exact-engine.md has the derivations of the filter's bound and of the 2^125 headroom.
#pragma once

#include "spec/rational.hpp"

#include <cstdint>

namespace circles::impl::exact {

// -Wpedantic rejects __int128 by name; __extension__ marks the use as deliberate (GCC and Clang).
__extension__ typedef __int128 Narrow;
__extension__ typedef unsigned __int128 NarrowMagnitude;
using Wide = spec::Z;

// Every scaled position, velocity and radius of a narrow scene has magnitude ≤ 2^kNarrowBits, so a
// difference dX or a sum Ra + Rb is below 2^126 (it fits Narrow with a bit to spare) and their squares below
// 2^252 (they fit the 256-bit sum of squares of intersect_scaled).
inline constexpr int kNarrowBits = 125;

// Ra + Rb ≥ |(dX, dY)|, i.e. S² ≥ dX² + dY², for S ≥ 0. Narrow: |S|, |dX|, |dY| < 2^126.
bool intersect_scaled(Narrow s, Narrow dx, Narrow dy) noexcept;
bool intersect_scaled(const Wide& s, const Wide& dx, const Wide& dy);

// The floating-point filter both widths start with, on approximations s, dx, dy of S, dX, dY, each within
// a relative 2^-52 of the exact value and below 2^500 in magnitude: 1 when S² > dX² + dY² certainly, 0 when
// S² < dX² + dY² certainly, −1 when the filter cannot tell (the exact integers decide).
int intersect_filter(double s, double dx, double dy) noexcept;

// RN(n/d) for d > 0. Narrow is exact integer division with a sticky remainder; Wide goes through
// spec::nearest_double (magnitudes beyond the double range give ±infinity there).
double round_quotient(Narrow n, NarrowMagnitude d) noexcept;
double round_quotient(const Wide& n, const Wide& d);

// An approximation of n/d within a relative 2^-50 plus 2^-1075 absolute, for the broad phase's boxes; the
// narrow form takes inverse = RN(1/d). Both are finite (clamped at ±DBL_MAX).
inline double approximate(Narrow n, double inverse) noexcept { return static_cast<double>(n) * inverse; }
double approximate(const Wide& n, const Wide& d) noexcept;

}  // namespace circles::impl::exact
