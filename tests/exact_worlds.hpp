// Between the doubles of a world and the oracle's rationals, for the tests of the exact engine and the exact
// grid reference: nearest(w) rounds each field to nearest (spec::nearest_doubles), exact_of(w) takes each
// double at its exact value (spec::from_doubles, radii r ≥ 0).
#pragma once

#include "spec/circle.hpp"
#include "spec/oracle.hpp"

#include <array>
#include <vector>

namespace circles::testing {

inline std::vector<std::array<double, 5>> nearest(const spec::Sequence& w) {
  std::vector<std::array<double, 5>> out;
  for (const spec::Circle& c : w) out.push_back(spec::nearest_doubles(c));
  return out;
}

inline spec::Sequence exact_of(const std::vector<std::array<double, 5>>& w) {
  return spec::from_doubles(w, spec::Radii::non_negative);
}

}  // namespace circles::testing
