// The families' constructions. Every coordinate is an integer number of units 2^e on a Grid, so that sums,
// differences and the tangency |p_b − p_a| = r_a + r_b hold exactly in doubles at every scale, from the
// subnormals to 2^1000; those integers are RapidCheck picks, which is how a world shrinks within its family.
// Picks are made in statement order (never two in one argument list, whose order C++ leaves open), so that a
// seed gives the same world whatever the compiler.
#include "properties/detail/boundaries.hpp"

#include "properties/detail/choice.hpp"
#include "properties/detail/families.hpp"
#include "properties/generators.hpp"
#include "spec/circle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace circles::properties::detail {
namespace {

using spec::CircleDoubles;
using I = std::int64_t;
enum Field : std::size_t { px, py, vx, vy, r };
constexpr double inf = std::numeric_limits<double>::infinity();

// Draws, inside rc::gen::exec.
template <class T>
T pick(T lo, T hi, T target) {
  return *uniform<T>(lo, hi, target);
}
I pick(I lo, I hi) { return pick<I>(lo, hi, std::clamp<I>(0, lo, hi)); }
bool flip() { return *coin(); }

// n·2^e, exactly: |n| < 2^53 and e >= −1074 make it a multiple of 2^-1074 with at most 53 significant bits.
double times_two_to(I n, int e) { return std::ldexp(static_cast<double>(n), e); }

// Where a family builds: every coordinate an integer number of units 2^e, translated by (ox, oy) units. The
// scale 2^k = 2^j units is the size of the family's features: radii and distances are a few scales.
struct Grid {
  int k, j, e;
  I ox, oy;
  I scale() const { return I{1} << j; }
  double x(I n) const { return times_two_to(ox + n, e); }
  double y(I n) const { return times_two_to(oy + n, e); }
  double length(I n) const { return times_two_to(n, e); }
};

// A grid at scale 2^k, k in [k_lo, k_hi] (shrinking towards 2^0), of 2^j <= 2^20 units per scale, translated
// by up to 2^50 units but never beyond 2^top. Features stay below 2^34 units (Pythagorean sides below 2^11
// scales), so every coordinate is an integer below 2^53 units: exact. With top <= 1010 and k <= 1000 the
// next positions p + v/60 stay finite.
Grid grid(int k_lo, int k_hi, int top = 1010) {
  const int k = pick<int>(k_lo, k_hi, std::clamp(0, k_lo, k_hi));
  const int j = pick<int>(0, std::min(20, k + 1074), 0);
  const int e = k - j;
  const int bits = pick<int>(0, std::clamp(top - e, 0, 50), 0);
  const I span = (I{1} << bits) - 1;
  const I ox = pick(-span, span);
  const I oy = pick(-span, span);
  return Grid{k, j, e, ox, oy};
}

// A velocity on the grid's scale: 0, a multiple of 2^(k−4) (whose sixtieth may or may not be a double), or 53
// random bits within 2^±8 of 2^k. Below 2^1015, so that p + v/60 stays finite.
double velocity(const Grid& g) {
  switch (pick<int>(0, 2, 0)) {
    case 0: return 0.0;
    case 1: return times_two_to(pick(-64, 64), std::max(g.k - 4, -1074));
    default: {
      const I most = (I{1} << 53) - 1;
      const I m = pick(-most, most);
      return times_two_to(m, std::clamp(g.k + pick<int>(-8, 8, 0) - 52, -1074, 962));
    }
  }
}

// A circle at (x, y) units with radius `radius` units and a velocity on the grid's scale.
CircleDoubles at(const Grid& g, I x, I y, I radius) {
  const double vx_ = velocity(g);
  const double vy_ = velocity(g);
  return {g.x(x), g.y(y), vx_, vy_, g.length(radius)};
}

// a² + b² = c²: the axis (1, 0, 1), when `axis` allows it, or Euclid's (m² − n², 2mn, m² + n²) for
// 1 <= n < m <= 32, turned to one of eight orientations. Shrinks towards (1, 0, 1), then (3, 4, 5).
struct Triple {
  I a, b, c;
};
Triple triple(bool axis) {
  Triple t{1, 0, 1};
  if (!axis || flip()) {
    const I m = pick<I>(2, 32, 2);
    const I n = pick<I>(1, m - 1, 1);
    t = {m * m - n * n, 2 * m * n, m * m + n * n};
  }
  if (flip()) std::swap(t.a, t.b);
  if (flip()) t.a = -t.a;
  if (flip()) t.b = -t.b;
  return t;
}

// Two circles exactly tangent: b at (dx, dy) = f·(a, b) scales from a, r_a + r_b = f·c scales split at a
// random unit (both radii > 0 when `positive`; f = 2 only where one unit could not be split so).
struct Pair {
  CircleDoubles a, b;
  I dx, dy;  // in units
  I f;       // the triple's factor in scales
  Triple t;
};
Pair tangent_pair(const Grid& g, bool positive, bool axis = true) {
  const Triple t = triple(axis);
  const I s = g.scale();
  const I f = positive && t.c * s < 2 ? 2 : 1;
  const I sum = f * t.c * s;
  const I ra = positive ? pick<I>(1, sum - 1, sum / 2) : pick<I>(0, sum, sum / 2);
  const CircleDoubles a = at(g, 0, 0, ra);
  const CircleDoubles b = at(g, f * t.a * s, f * t.b * s, sum - ra);
  return {a, b, f * t.a * s, f * t.b * s, f, t};
}

double nudged(double x, int n, bool up) {
  for (int k = 0; k < n; ++k) x = std::nextafter(x, up ? inf : -inf);
  return x;
}

// One of the six coordinates px, py, r of a or b moved by ±1 … 3 ulps. A radius moves up where down would
// take it below 0 (or to 0, when `positive`).
void nudge(CircleDoubles& a, CircleDoubles& b, bool positive) {
  const int which = pick<int>(0, 5, 0);
  const int n = pick<int>(1, 3, 1);
  bool up = flip();
  CircleDoubles& c = which % 2 == 0 ? a : b;
  const Field f = which < 2 ? px : which < 4 ? py : r;
  const double down = nudged(c[f], n, false);
  if (f == r && (down < 0 || (positive && down == 0))) up = true;
  c[f] = nudged(c[f], n, up);
}

// Up to two circles near the family's own: within 8 scales of the grid's origin, radius up to 4 scales.
void add_bystanders(Circles& w, const Grid& g, bool positive) {
  const I s = g.scale();
  for (int n = pick<int>(0, 2, 0); n > 0; --n) {
    const I x = pick(-8 * s, 8 * s);
    const I y = pick(-8 * s, 8 * s);
    const I radius = pick<I>(positive ? 1 : 0, 4 * s, s);
    w.push_back(at(g, x, y, radius));
  }
}

// x + by (by >= 0), or the next double above x when `strictly` and the sum rounds back to x.
double raised(double x, double by, bool strictly) {
  const double y = x + by;
  return strictly && !(y > x) ? std::nextafter(x, inf) : y;
}

// A circle at or above c in every field (the product order (6), (7)): positions up by 0 … 1 scale (by at
// least one unit in px when `apart`), velocities up by |velocity(g)|, the radius up by 0 … 1 scale.
CircleDoubles above(const Grid& g, const CircleDoubles& c, bool apart) {
  const I s = g.scale();
  const I up_x = pick<I>(apart ? 1 : 0, s, apart ? 1 : 0);
  const I up_y = pick<I>(0, s, 0);
  const double up_vx = std::fabs(velocity(g));
  const double up_vy = std::fabs(velocity(g));
  const I up_r = pick<I>(0, s, 0);
  return {c[px] + g.length(up_x), c[py] + g.length(up_y), raised(c[vx], up_vx, false), raised(c[vy], up_vy, false),
          c[r] + g.length(up_r)};
}

// Makes a[f] < b[f]: swaps the two if a[f] > b[f], moves b[f] up one ulp if they are equal. Either keeps both
// at or above anything they were both at or above.
void below(CircleDoubles& a, CircleDoubles& b, std::size_t f) {
  if (a[f] > b[f]) std::swap(a[f], b[f]);
  if (a[f] == b[f]) b[f] = std::nextafter(b[f], inf);
}

}  // namespace

// ── The families ──────────────────────────────────────────────────────────────────────────────────────

Circles tangency(bool positive) {
  const Grid g = grid(-1074, 1000);
  const Pair p = tangent_pair(g, positive);
  Circles w{p.a, p.b};
  add_bystanders(w, g, positive);
  return w;
}

Circles ulp_nudge(bool positive) {
  const Grid g = grid(-1074, 1000);
  Pair p = tangent_pair(g, positive);
  nudge(p.a, p.b, positive);
  Circles w{p.a, p.b};
  add_bystanders(w, g, positive);
  return w;
}

// From 2^512 up, (r_a + r_b)² and |p_b − p_a|² overflow: a tangent pair, one nudged, or one overlapping.
Circles square_overflow(bool positive) {
  const Grid g = grid(512, 1000);
  Pair p = tangent_pair(g, positive);
  switch (pick<int>(0, 2, 0)) {
    case 1: nudge(p.a, p.b, positive); break;
    case 2: p.b[r] += g.length(pick<I>(1, g.scale(), 1)); break;  // integers in units: exact
    default: break;
  }
  Circles w{p.a, p.b};
  add_bystanders(w, g, positive);
  return w;
}

// Scales 2^-1074 … 2^-1035 on a grid translated below 2^-1023: radii, offsets and most positions and
// velocities are subnormal. A tangent pair, half the time nudged.
Circles subnormals(bool positive) {
  const Grid g = grid(-1074, -1035, -1023);
  Pair p = tangent_pair(g, positive);
  if (flip()) nudge(p.a, p.b, positive);
  Circles w{p.a, p.b};
  add_bystanders(w, g, positive);
  return w;
}

// A tangent pair in w_1: q = λ·(a, b) units towards each other plus a common drift (g_x, g_y), w_0 at P − q and
// v = 60·q, so that v/60 = q and p + v/60 = P exactly. |60·q| < 2^28 units, so v is exact up to k = 960.
Circles tangent_after_step(bool positive) {
  const Grid g = grid(-1074, 960);
  const Pair p = tangent_pair(g, positive);
  const I lambda = pick<I>(1, 1024, 1);
  const I gx = pick(-1024, 1024);
  const I gy = pick(-1024, 1024);
  const I ta = p.f * p.t.a, tb = p.f * p.t.b;
  const I qax = lambda * ta + gx, qay = lambda * tb + gy, qbx = -lambda * ta + gx, qby = -lambda * tb + gy;
  const CircleDoubles a{g.x(-qax), g.y(-qay), g.length(60 * qax), g.length(60 * qay), p.a[r]};
  const CircleDoubles b{g.x(p.dx - qbx), g.y(p.dy - qby), g.length(60 * qbx), g.length(60 * qby), p.b[r]};
  return {a, b};  // no bystanders: one that touched either circle in w_0 would turn it away from the tangency
}

// Circle c and two contacts x, y equal in the first `tie` fields of the key (px, py, vx, vy, r) and different
// in the next one; tie = 5: x = y. Resolved: c's radius of 8 … 12 scales covers x and y (within 4 scales), the
// other fields are random. Literal: c <= x <= y in every field and every radius >= 8 scales, so that all three
// touch and each S has a least element; where x and y share p, r_y > r_x, so that the two (which take c's
// velocity) do not merge.
Circles ties(int tie, bool literal) {
  const Grid g = grid(-1000, 1000);
  const I s = g.scale();
  const I rc = pick<I>(8 * s, 12 * s, 8 * s);
  const CircleDoubles c = at(g, 0, 0, rc);
  CircleDoubles x, y;
  if (!literal) {
    const I x_x = pick<I>(0, 4 * s, 0), x_y = pick<I>(0, 4 * s, 0), x_r = pick<I>(0, 4 * s, s);
    x = at(g, x_x, x_y, x_r);
    const I y_x = pick<I>(0, 4 * s, 0), y_y = pick<I>(0, 4 * s, 0), y_r = pick<I>(0, 4 * s, s);
    y = at(g, y_x, y_y, y_r);
    for (int f = 0; f < tie; ++f) y[f] = x[f];
    if (tie < 5 && y[tie] == x[tie]) y[tie] = std::nextafter(x[tie], inf);  // up: a radius stays >= 0
  } else {
    x = above(g, c, true);
    const CircleDoubles fresh = above(g, x, false);
    y = x;
    for (int f = tie; f < 5; ++f) y[f] = f == tie ? raised(x[f], fresh[f] - x[f], true) : fresh[f];
    if (tie < 3 && y[px] == x[px] && y[py] == x[py]) y[r] = raised(x[r], fresh[r] - x[r], true);
  }
  Circles w{c, x, y};
  add_bystanders(w, g, literal);
  return w;
}

// Two contacts x, y of one circle c that (6) does not order: x below y in field f1, above it in f2 > f1.
// Resolved: c covers both (as in ties), which the lexicographic key still orders. Literal: z <= c <= x, y in
// every field and every radius >= 8 scales, so that all four touch and every S has a least element (z, or c
// for S = i(z, W)) while c's S = {z, x, y} holds the incomparable pair.
Circles incomparable(bool literal) {
  const Grid g = grid(-1000, 1000);
  const I s = g.scale();
  const int f1 = pick<int>(0, 3, 0);
  const int f2 = pick<int>(f1 + 1, 4, f1 + 1);
  const I rc = pick<I>(8 * s, 12 * s, 8 * s);
  Circles w;
  if (!literal) {
    const CircleDoubles c = at(g, 0, 0, rc);
    const I x_x = pick<I>(0, 4 * s, 0), x_y = pick<I>(0, 4 * s, 0), x_r = pick<I>(0, 4 * s, s);
    CircleDoubles x = at(g, x_x, x_y, x_r);
    const I y_x = pick<I>(0, 4 * s, 0), y_y = pick<I>(0, 4 * s, 0), y_r = pick<I>(0, 4 * s, s);
    CircleDoubles y = at(g, y_x, y_y, y_r);
    below(x, y, static_cast<std::size_t>(f1));
    below(y, x, static_cast<std::size_t>(f2));
    w = {c, x, y};
  } else {
    const CircleDoubles z = at(g, 0, 0, rc);
    const CircleDoubles c = above(g, z, true);
    CircleDoubles x = above(g, c, true);
    CircleDoubles y = above(g, c, true);
    below(x, y, static_cast<std::size_t>(f1));
    below(y, x, static_cast<std::size_t>(f2));
    w = {z, c, x, y};
  }
  add_bystanders(w, g, literal);
  return w;
}

// Three to five circles that all touch each other. Resolved: half the time a mutually tangent triple, the
// corners of a right triangle with Pythagorean sides (a, b, c) and radii (a + b − c)/2, (a + c − b)/2,
// (b + c − a)/2 scales (integers: Euclid's sides make each numerator even), sometimes with a fourth circle over
// all three; else 3 … 5 circles within 4 scales of each other with radii of 4 … 8 scales. Literal: a chain
// c_1 <= c_2 <= … in every field, px strictly rising (so none merge), radii of 4 scales and up. (No mutually
// tangent triple is in the literal domain: each S = {other two} needs the three in a chain, and along a chain
// of positions the middle circle has the smallest radius.)
Circles mutual_contacts(bool literal) {
  const Grid g = grid(-1000, 1000);
  const I s = g.scale();
  Circles w;
  if (!literal && flip()) {
    const Triple t = triple(false);
    const I a = std::abs(t.a), b = std::abs(t.b), c = t.c;
    w.push_back(at(g, 0, 0, (a + b - c) / 2 * s));
    w.push_back(at(g, t.a * s, 0, (a + c - b) / 2 * s));
    w.push_back(at(g, 0, t.b * s, (b + c - a) / 2 * s));
    if (flip()) w.push_back(at(g, 0, 0, c * s));
  } else if (!literal) {
    for (int n = pick<int>(3, 5, 3); n > 0; --n) {
      const I x = pick<I>(0, 4 * s, 0), y = pick<I>(0, 4 * s, 0), radius = pick<I>(4 * s, 8 * s, 4 * s);
      w.push_back(at(g, x, y, radius));
    }
  } else {
    w.push_back(at(g, 0, 0, pick<I>(4 * s, 8 * s, 4 * s)));
    for (int n = pick<int>(2, 4, 2); n > 0; --n) w.push_back(above(g, w.back(), true));
  }
  add_bystanders(w, g, literal);
  return w;
}

// p ≈ −v/60: p = −RN(v/60) moved by −3 … 3 ulps, so that the exact p + v/60 is the rounding error of v/60 and
// a few ulps of p, far below p itself. Two to four circles, each with 53 random bits of velocity in a binade
// from 2^-247 to 2^153 (or the velocity of the circle before, so that two share a position), and a radius of
// 0, 1 or 2 times its larger |p| (circles of radius >= |p| all cover the origin, so they touch).
Circles cancellation(bool positive) {
  Circles w;
  for (int n = pick<int>(2, 4, 2); n > 0; --n) {
    CircleDoubles c{};
    const bool same = !w.empty() && flip();
    for (const std::size_t f : {vx, vy}) {
      if (same) {
        c[f] = w.back()[f];
      } else {
        const I most = (I{1} << 53) - 1;
        const I m = pick(-most, most);
        c[f] = times_two_to(m, pick<int>(-300, 100, -52));
      }
      const int ulps = pick<int>(-3, 3, 0);
      c[f - 2] = nudged(-(c[f] / 60), std::abs(ulps), ulps > 0);
    }
    const double span = std::max(std::fabs(c[px]), std::fabs(c[py]));
    const int times = pick<int>(positive ? 1 : 0, 2, 1);
    c[r] = times * span;
    if (positive && c[r] == 0) c[r] = std::numeric_limits<double>::denorm_min();
    w.push_back(c);
  }
  return w;
}

// Two to five circles whose fields are mostly +0 or −0 (else ±1/2, ±1, ±2): equal by value, different in sign;
// the first two have px = −0 and +0. Radii ±0 (resolved only), 1/2, 1 or 2.
Circles signed_zeros(bool positive) {
  const rc::Gen<double> field =
      weighted_one_of<double>({{3, zero()}, {1, either_sign(element_of<double>({0.5, 1, 2}))}});
  const rc::Gen<double> radius = positive ? element_of<double>({0.5, 1, 2})
                                          : weighted_one_of<double>({{1, zero()}, {1, element_of<double>({0.5, 1, 2})}});
  Circles w;
  for (int n = pick<int>(2, 5, 2); n > 0; --n) {
    CircleDoubles c{};
    for (double& x : c) x = *field;
    c[r] = *radius;
    w.push_back(c);
  }
  w[0][px] = -0.0;  // so that every world has both zeros, equal by value, in the first key field
  w[1][px] = 0.0;
  return w;
}

// A circle of radius c scales and a point (r = ±0) on its boundary at (a, b) scales from its centre, exactly;
// then one of: nothing, a second point at the same place (the two touch: 0 <= 0 + 0), the point moved by 1 … 3
// ulps (just inside or outside), or a point at the circle's centre.
Circles zero_radius(bool) {
  const Grid g = grid(-1074, 1000);
  const I s = g.scale();
  const Triple t = triple(true);
  Circles w{at(g, 0, 0, t.c * s)};
  CircleDoubles point = at(g, t.a * s, t.b * s, 0);
  if (flip()) point[r] = -0.0;
  switch (pick<int>(0, 3, 0)) {
    case 1: {
      CircleDoubles other = at(g, t.a * s, t.b * s, 0);
      w.push_back(other);
      break;
    }
    case 2: {
      const std::size_t f = flip() ? py : px;
      const int n = pick<int>(1, 3, 1);
      const bool up = flip();
      point[f] = nudged(point[f], n, up);
      break;
    }
    case 3: w.push_back(at(g, 0, 0, 0)); break;
    default: break;
  }
  w.insert(w.begin() + 1, point);
  add_bystanders(w, g, false);
  return w;
}

Circles lattice(bool positive) {
  const auto rounded = rc::gen::map(gen::world(positive ? spec::Radii::positive : spec::Radii::non_negative, 8),
                                    [](const std::vector<spec::Circle>& w) {
                                      Circles out;
                                      for (const spec::Circle& c : w) out.push_back(spec::nearest_doubles(c));
                                      return out;
                                    });
  return *rc::gen::suchThat(rounded, [](const Circles& w) {
    return std::all_of(w.begin(), w.end(), [](const CircleDoubles& c) {
      return std::all_of(c.begin(), c.end(), [](double x) { return std::isfinite(x); });
    });
  });
}

Circles random_doubles(bool positive) {
  Circles w = *gen::double_world(8, gen::finite_double());
  if (positive)
    for (CircleDoubles& c : w)
      if (c[r] == 0) c[r] = std::numeric_limits<double>::denorm_min();
  return w;
}

}  // namespace circles::properties::detail

namespace circles::properties::detail {

// 2 … 8 circles whose every field is a value with many spellings (formats/spelling.hpp, which conform sends for
// this family): zeros, which a request may spell 1e-400; the least and the largest subnormals and DBL_MIN;
// decimals that no double is (0.1, 1/3, 1e23); integers around 2^53 and beyond 2^64; DBL_MAX; and any double
// with 53 bits. Circles far apart keep each one's numbers in its answer (copied, or in p + v/60), so that a
// number read wrong is a number answered wrong. A velocity whose sign would carry a position beyond 2^1020
// over DBL_MAX is turned back, so that every world has a next one.
Circles wire(bool positive) {
  const rc::Gen<double> magnitude = weighted_one_of<double>(
      {{3, element_of<double>({0.0})},
       {3, element_of<double>({std::numeric_limits<double>::denorm_min(), 0x1p-1022 - 0x1p-1074, 0x1p-1022, 0.1,
                               1.0 / 3, 1.0 / 60, 60, 0x1p53, 0x1p53 + 2, 0x1p64, 1e21, 1e22, 1e23, 1e300,
                               std::numeric_limits<double>::max()})},
       {1, subnormal()},
       {2, physics()},
       {1, binade()}});
  const rc::Gen<double> field = either_sign(magnitude);
  Circles w;
  for (int n = pick<int>(2, 8, 2); n > 0; --n) {
    CircleDoubles c{};
    for (double& x : c) x = *field;
    c[r] = std::fabs(c[r]);
    if (c[r] == 0 && (positive || flip())) c[r] = positive ? 1.0 : -0.0;
    for (const Field p : {px, py})
      if (std::fabs(c[p]) >= 0x1p1020 && std::signbit(c[p]) == std::signbit(c[p + 2])) c[p + 2] = -c[p + 2];
    w.push_back(c);
  }
  return w;
}

}  // namespace circles::properties::detail
