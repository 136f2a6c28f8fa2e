// C, the set of circles (p, v, r), and the errors for inputs outside it.
#pragma once

#include "spec/outside_c.hpp"
#include "spec/rational.hpp"

#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::spec {

// An element of C = {(p, v, r) | p, v ∈ ℝ² and r ∈ ℝ⁺}: position p, velocity v, radius r.
struct Circle {
  Vec2 p;
  Vec2 v;
  Q r;

  // Equality of circles is equality of the triples (p, v, r): the seed's "x ≠ c" compares values.
  friend bool operator==(const Circle& a, const Circle& b) { return a.p == b.p && a.v == b.v && a.r == b.r; }
};

// Shorthand for tests and scenes: (px, py, vx, vy, r), each exact.
Circle circle(const Q& px, const Q& py, const Q& vx, const Q& vy, const Q& r);

// Throws OutsideC unless c.r is allowed by `radii`. `index` names the circle in the message.
void check_radius(const Circle& c, std::size_t index, Radii radii);

// The circle with the exact values of five doubles [px, py, vx, vy, r].
// Throws OutsideC as check_doubles does.
Circle from_doubles(const CircleDoubles& fields, std::size_t index, Radii radii);
// A world of doubles [px, py, vx, vy, r] per circle at its exact values, circle k from circles[k] (a
// spec::Sequence). Throws OutsideC for the first circle outside C, as from_doubles does.
std::vector<Circle> from_doubles(const Circles& circles, Radii radii);

// The five coordinates of c, each rounded to the nearest double (see nearest_double).
CircleDoubles nearest_doubles(const Circle& c);

// "(px, py, vx, vy, r)" with exact rationals; operator<< writes the same, so GoogleTest and RapidCheck print
// circles readably in failures.
std::string to_string(const Circle& c);
std::ostream& operator<<(std::ostream& os, const Circle& c);

}  // namespace circles::spec
