// Classifications for RC_TAG and RC_CLASSIFY, so that a run reports which kinds of input it exercised.
#pragma once

#include "spec/circle.hpp"

#include <vector>

namespace circles::properties {

// The kind of a finite double, the first that applies: "+0", "-0", "subnormal", "DBL_MIN", "tiny normal"
// (|x| < 2^-512), "top binade" (|x| >= 2^1023, near DBL_MAX), "huge" (|x| >= 2^512), "small integer"
// (|x| <= 16), "dyadic" (a multiple of 2^-24 with |x| <= 1000), "|x| <= 1000" or "other normal".
const char* family(double x);

// What a list of circles holds that exercises the equations' cases. Pairs are pairs of positions in the
// list, so two entries that are the same circle count as a pair.
struct Features {
  bool contact = false;      // some pair intersects (3)
  bool tangency = false;     // some pair touches exactly: |p_b - p_a| = r_a + r_b
  bool duplicate = false;    // some pair is one circle twice
  bool tie = false;          // some pair of different circles shares px or py
  bool zero_radius = false;  // some circle has r = 0
};
Features features(const std::vector<spec::Circle>& w);

}  // namespace circles::properties
