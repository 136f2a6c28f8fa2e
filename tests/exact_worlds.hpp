// Between the doubles of a world and the oracle's rationals, for the tests of the exact engine and the exact
// grid reference: nearest(w) rounds each field to nearest (spec::nearest_doubles), exact_of(w) takes each
// double at its exact value (spec::from_doubles, radii r ≥ 0); and a world at the exact filter's underflow edge.
#pragma once

#include "spec/circle.hpp"
#include "spec/oracle.hpp"

namespace circles::testing {

inline spec::Circles nearest(const spec::Sequence& w) {
  spec::Circles out;
  for (const spec::Circle& c : w) out.push_back(spec::nearest_doubles(c));
  return out;
}

inline spec::Sequence exact_of(const spec::Circles& w) {
  return spec::from_doubles(w, spec::Radii::non_negative);
}

// Two circles of radius 0.61·2^-537 with centres (0.72, 0.72)·2^-537 apart: they intersect (S² = 1.4884·2^-1074
// against X² + Y² = 1.0368·2^-1074), but their squares underflow and round against that sign, s² to 2^-1074
// and dx², dy² (0.5184·2^-1074 each) up to 2^-1074, so s² − (dx² + dy²) computes to −2^-1074. Only a filter's
// absolute term keeps it from calling them disjoint (exact::intersect_approximate's kApproximateAbsolute). Each
// takes the other's velocity.
inline spec::Circles underflowing_intersecting_pair() {
  const double v = 0x1p-537;
  return {{0, 0, v, 0, 0.61 * v}, {0.72 * v, 0.72 * v, 0, v, 0.61 * v}};
}

}  // namespace circles::testing
