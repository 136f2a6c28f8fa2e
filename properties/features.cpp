#include "properties/features.hpp"

#include "spec/equations.hpp"

#include <cfloat>
#include <cmath>

namespace circles::properties {

const char* family(double x) {
  const double a = std::fabs(x);
  if (a == 0) return std::signbit(x) ? "-0" : "+0";
  if (a < DBL_MIN) return "subnormal";
  if (a == DBL_MIN) return "DBL_MIN";
  if (a < std::ldexp(1.0, -512)) return "tiny normal";
  if (a >= std::ldexp(1.0, 1023)) return "top binade";
  if (a >= std::ldexp(1.0, 512)) return "huge";
  if (a <= 16 && std::trunc(a) == a) return "small integer";
  if (a <= 1000 && std::trunc(std::ldexp(a, 24)) == std::ldexp(a, 24)) return "dyadic";
  if (a <= 1000) return "|x| <= 1000";
  return "other normal";
}

Features features(const std::vector<spec::Circle>& w) {
  Features f;
  for (std::size_t a = 0; a < w.size(); ++a) {
    f.zero_radius = f.zero_radius || w[a].r == 0;
    for (std::size_t b = a + 1; b < w.size(); ++b) {
      const spec::Circle& x = w[a];
      const spec::Circle& y = w[b];
      const spec::Q s = x.r + y.r;
      f.contact = f.contact || spec::intersect(x, y);
      f.tangency = f.tangency || (s >= 0 && (y.p - x.p).squaredNorm() == s * s);
      f.duplicate = f.duplicate || x == y;
      f.tie = f.tie || (!(x == y) && (x.p.x() == y.p.x() || x.p.y() == y.p.y()));
    }
  }
  return f;
}

}  // namespace circles::properties
