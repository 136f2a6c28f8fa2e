// The families the public generators mix (properties/generators.hpp). Each family shrinks within itself
// towards its simplest member; the mix then shrinks across families towards the first listed.
#pragma once

#include "spec/circle.hpp"

#include <rapidcheck.h>

namespace circles::properties::detail {

// ── Doubles (detail/doubles.cpp); every family gives both signs, shrinking towards + ──────────────────

rc::Gen<double> zero();           // +0 and −0
rc::Gen<double> small_integer();  // 0 … 16
rc::Gen<double> dyadic();         // n / 2^k, n ≤ 4096, 1 ≤ k ≤ 24: exact binary fractions such as 3/8
rc::Gen<double> decimal();        // k / 10^d, |x| ≤ 1000, d ≤ 3: 0.1, 12.345 — none of them exact in binary
rc::Gen<double> physics();        // uniform on [−1000, 1000] with all 53 significand bits random
rc::Gen<double> edge();           // the named boundaries: 2^-1074, the largest subnormal, DBL_MIN, 1 ± ulp, …
rc::Gen<double> subnormal();      // any subnormal: a random nonzero 52-bit significand with exponent field 0
rc::Gen<double> binade();         // a binade 2^e, −1074 ≤ e ≤ 1023, chosen uniformly, then a random value in it
rc::Gen<double> bit_pattern();    // a random finite bit pattern: uniform over the finite doubles themselves
rc::Gen<double> near_max();       // within 2^20 ulps of DBL_MAX

// ── Rationals and circle fields (detail/circles.cpp) ─────────────────────────────────────────────────

rc::Gen<spec::Q> small_fraction();           // n / d with |n| ≤ 12, 1 ≤ d ≤ 12: 1/3, −5/7 — mostly not dyadic
rc::Gen<spec::Q> wide_fraction();            // n / d with n, d up to 2^64: far from any double
rc::Gen<spec::Q> lattice();                  // the integers −4 … 4: positions on this lattice tie and touch often
rc::Gen<spec::Q> half_lattice();             // k / 2, −8 ≤ k ≤ 8
rc::Gen<spec::Q> velocity();                 // a few velocities (0, ±1, ±2, ±1/2, ±60), so that velocities tie
rc::Gen<spec::Q> radius(spec::Radii radii);  // 1/2 … 3 in halves, 0 when allowed, rarely any rational

}  // namespace circles::properties::detail
