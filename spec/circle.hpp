// C, the set of circles (p, v, r), and the errors for inputs outside it.
#pragma once

#include "spec/rational.hpp"

#include <array>
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

// The five coordinates in the protocol's order [px, py, vx, vy, r].
enum class Field { px, py, vx, vy, r };
const char* name(Field f);

// An input that is not an element of C: NaN or infinity in any field, or a radius the profile refuses.
// `index` is the circle's position in the input, `field` the coordinate at fault.
class OutsideC : public std::invalid_argument {
 public:
  OutsideC(std::size_t index, Field field, const std::string& reason);
  std::size_t index;
  Field field;
};

// Which radii belong to C. The seed writes r ∈ ℝ⁺ in the definition of C but uses r ≥ 0 in the proof of
// Theorem 4 (spec-notes: "R+ or r >= 0"); the literal profile takes the definition, the resolved one the proof.
enum class Radii { positive, non_negative };

// Throws OutsideC unless c.r is allowed by `radii`. `index` names the circle in the message.
void check_radius(const Circle& c, std::size_t index, Radii radii);

// The circle with the exact values of five doubles [px, py, vx, vy, r].
// Throws OutsideC naming `index` and the first non-finite field, or the radius refused by `radii`.
Circle from_doubles(const std::array<double, 5>& fields, std::size_t index, Radii radii);

// The five coordinates of c, each rounded to the nearest double (see nearest_double).
std::array<double, 5> nearest_doubles(const Circle& c);

// "(px, py, vx, vy, r)" with exact rationals; operator<< writes the same, so GoogleTest and RapidCheck print
// circles readably in failures.
std::string to_string(const Circle& c);
std::ostream& operator<<(std::ostream& os, const Circle& c);

}  // namespace circles::spec
