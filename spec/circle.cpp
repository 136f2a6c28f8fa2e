#include "spec/circle.hpp"

#include <cmath>

namespace circles::spec {

Circle circle(const Q& px, const Q& py, const Q& vx, const Q& vy, const Q& r) {
  return Circle{Vec2(px, py), Vec2(vx, vy), r};
}

void check_radius(const Circle& c, std::size_t index, Radii radii) {
  if (radii == Radii::positive && c.r <= 0)
    throw OutsideC(index, Field::r, "radius " + to_string(c.r) + " is not in R+ (r > 0, the literal profile)");
  if (radii == Radii::non_negative && c.r < 0)
    throw OutsideC(index, Field::r, "radius " + to_string(c.r) + " is negative (r >= 0, the resolved profile)");
}

Circle from_doubles(const CircleDoubles& fields, std::size_t index, Radii radii) {
  check_doubles(fields, index, radii);
  return circle(exact(fields[0]), exact(fields[1]), exact(fields[2]), exact(fields[3]), exact(fields[4]));
}

std::vector<Circle> from_doubles(const Circles& circles, Radii radii) {
  std::vector<Circle> out;
  out.reserve(circles.size());
  for (std::size_t k = 0; k < circles.size(); ++k) out.push_back(from_doubles(circles[k], k, radii));
  return out;
}

CircleDoubles nearest_doubles(const Circle& c) {
  return {nearest_double(c.p.x()), nearest_double(c.p.y()), nearest_double(c.v.x()), nearest_double(c.v.y()),
          nearest_double(c.r)};
}

std::string to_string(const Circle& c) {
  // Appended piece by piece: GCC 12 at -O3 warns falsely (-Wrestrict) on "(" + std::string&&.
  std::string out = "(";
  for (const Q* field : {&c.p.x(), &c.p.y(), &c.v.x(), &c.v.y(), &c.r}) {
    if (out.size() > 1) out += ", ";
    out += to_string(*field);
  }
  return out + ")";
}

std::ostream& operator<<(std::ostream& os, const Circle& c) { return os << to_string(c); }

}  // namespace circles::spec
