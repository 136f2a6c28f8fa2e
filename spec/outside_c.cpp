#include "spec/outside_c.hpp"

#include <charconv>
#include <cmath>

namespace circles::spec {

const char* name(Field f) {
  switch (f) {
    case Field::px: return "px";
    case Field::py: return "py";
    case Field::vx: return "vx";
    case Field::vy: return "vy";
    case Field::r: return "r";
  }
  return "?";
}

OutsideC::OutsideC(std::size_t i, Field f, const std::string& reason)
    : std::invalid_argument("circle " + std::to_string(i) + ", field " + name(f) + ": " + reason +
                            " (not an element of C)"),
      index(i),
      field(f) {}

namespace {

// The shortest decimal that reads back as x.
std::string shortest(double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  return std::string(text, end);
}

}  // namespace

void check_doubles(const CircleDoubles& fields, std::size_t index, Radii radii) {
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const double x = fields[k];
    if (std::isnan(x)) throw OutsideC(index, Field(k), "NaN");
    if (std::isinf(x)) throw OutsideC(index, Field(k), x > 0 ? "+infinity" : "-infinity");
  }
  const double r = fields[4];
  if (radii == Radii::positive && !(r > 0))
    throw OutsideC(index, Field::r, "radius " + shortest(r) + " is not in R+ (r > 0, the literal profile)");
  if (radii == Radii::non_negative && r < 0)
    throw OutsideC(index, Field::r, "radius " + shortest(r) + " is negative (r >= 0, the resolved profile)");
}

}  // namespace circles::spec
