#include "properties/generators.hpp"

#include "properties/detail/choice.hpp"
#include "properties/detail/families.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace circles::properties::gen {

using spec::Circle;
using spec::Q;

// The weights favour the families that find bugs in arithmetic on ordinary values (small integers, decimals,
// physics-like values) while giving each boundary family a few cases in every run of 100. The order is the
// shrinking order: a failing case moves towards ±0, then small integers, and so on.
rc::Gen<double> finite_double() {
  return detail::weighted_one_of<double>({
      {2, detail::zero()},
      {3, detail::small_integer()},
      {2, detail::dyadic()},
      {2, detail::decimal()},
      {3, detail::physics()},
      {2, detail::edge()},
      {2, detail::subnormal()},
      {3, detail::binade()},
      {2, detail::bit_pattern()},
      {1, detail::near_max()},
  });
}

rc::Gen<Q> rational() {
  return detail::weighted_one_of<Q>({
      {4, detail::small_fraction()},
      {3, rc::gen::map(finite_double(), [](double x) { return spec::exact(x); })},
      {1, detail::wide_fraction()},
  });
}

rc::Gen<Circle> circle(spec::Radii radii) {
  const rc::Gen<Q> position =
      detail::weighted_one_of<Q>({{8, detail::lattice()}, {2, detail::half_lattice()}, {1, rational()}});
  const rc::Gen<Q> velocity = detail::weighted_one_of<Q>({{8, detail::velocity()}, {1, rational()}});
  return rc::gen::apply(
      [](const Q& px, const Q& py, const Q& vx, const Q& vy, const Q& r) { return spec::circle(px, py, vx, vy, r); },
      position, position, velocity, velocity, detail::radius(radii));
}

namespace {

// How a circle of a world relates to the circles before it. Mostly it is itself; otherwise it copies an
// earlier circle exactly, copies it but for one field (redrawn, or moved up or down so that the copy is
// comparable with the original in the product order (6)), or touches it exactly.
enum class Relation { itself, copy, copy_but_one_field, copy_comparable, tangent };

struct Drawn {
  Circle own;            // the circle drawn for this place
  Relation relation;     // how it is used
  std::size_t earlier;   // which earlier circle: `earlier` mod j places back, j being this one's place
  std::size_t selector;  // which field (the copies) or direction (tangent)
};

// Unit vectors with rational coordinates: the axes and the (3, 4, 5) directions. A circle placed at
// p + (r + r') u touches the circle (p, r) exactly, and Q decides that exactly.
const std::vector<spec::Vec2>& directions() {
  static const std::vector<spec::Vec2> units = [] {
    std::vector<spec::Vec2> u;
    const int fifths[][2] = {{5, 0},  {0, 5},  {-5, 0}, {0, -5}, {3, 4},   {4, 3},
                             {-3, 4}, {-4, 3}, {3, -4}, {4, -3}, {-3, -4}, {-4, -3}};
    for (const auto& [x, y] : fifths) u.emplace_back(Q(x, 5), Q(y, 5));
    return u;
  }();
  return units;
}

// Field selector mod 5 of c, in the order px, py, vx, vy, r.
template <class C>  // Circle or const Circle
auto& field(C& c, std::size_t selector) {
  switch (selector % 5) {
    case 0: return c.p.x();
    case 1: return c.p.y();
    case 2: return c.v.x();
    case 3: return c.v.y();
    default: return c.r;
  }
}

Circle place(const Drawn& d, const Circle& earlier) {
  switch (d.relation) {
    case Relation::itself: return d.own;
    case Relation::copy: return earlier;
    case Relation::copy_but_one_field: {
      Circle c = earlier;
      field(c, d.selector) = field(d.own, d.selector);
      return c;
    }
    case Relation::copy_comparable: {
      // Up by 1/2, 1 or 3/2, or down by as much; a radius goes down by halving, so that it stays allowed.
      Circle c = earlier;
      const Q step(1 + d.selector / 5 % 3, 2);
      const bool down = d.selector / 15 % 2 == 1;
      Q& x = field(c, d.selector);
      x = !down ? Q(x + step) : d.selector % 5 == 4 ? Q(x / 2) : Q(x - step);
      return c;
    }
    case Relation::tangent: {
      const spec::Vec2& u = directions()[d.selector % directions().size()];
      Circle c = d.own;
      c.p = earlier.p + (earlier.r + c.r) * u;
      return c;
    }
  }
  return d.own;
}

}  // namespace

rc::Gen<std::vector<Circle>> world(spec::Radii radii, std::size_t max_size) {
  // Each place relates to an earlier one with probability 1/2: a copy (1/10), a copy with one field
  // redrawn (1/10: all but one coordinate tie) or moved (1/10: the two are comparable under (6), so sets
  // with a least element, where (8) is defined, are common), or a tangent circle (1/5). The relations
  // follow the circles they refer to as those shrink, and dropping circles (RapidCheck's container
  // shrinking) keeps every reference meaningful; a relation shrinks towards `itself`.
  const rc::Gen<Relation> relation =
      detail::weighted_one_of<Relation>({{5, rc::gen::just(Relation::itself)},
                                         {1, rc::gen::just(Relation::copy)},
                                         {1, rc::gen::just(Relation::copy_but_one_field)},
                                         {1, rc::gen::just(Relation::copy_comparable)},
                                         {2, rc::gen::just(Relation::tangent)}});
  const rc::Gen<Drawn> drawn = rc::gen::apply(
      [](const Circle& c, Relation rel, std::size_t earlier, std::size_t selector) {
        return Drawn{c, rel, earlier, selector};
      },
      circle(radii), relation, detail::uniform<std::size_t>(0, 63, 0), detail::uniform<std::size_t>(0, 59, 0));
  // gen::container draws its length uniformly from 0 … size: resize fixes the size at max_size (the
  // element generators ignore the size).
  return rc::gen::map(rc::gen::resize(static_cast<int>(max_size), rc::gen::container<std::vector<Drawn>>(drawn)),
                      [](const std::vector<Drawn>& d) {
                        std::vector<Circle> w;
                        w.reserve(d.size());
                        for (std::size_t j = 0; j < d.size(); ++j)
                          w.push_back(j == 0 ? d[j].own : place(d[j], w[j - 1 - d[j].earlier % j]));
                        return w;
                      });
}

rc::Gen<std::vector<Circle>> distinct_world(spec::Radii radii, std::size_t max_size) {
  return rc::gen::map(world(radii, max_size), [](const std::vector<Circle>& w) {
    std::vector<Circle> s;
    for (const Circle& c : w)
      if (std::find(s.begin(), s.end(), c) == s.end()) s.push_back(c);
    return s;
  });
}

rc::Gen<std::vector<Circle>> set_for_e(spec::Radii radii, std::size_t max_size) {
  return rc::gen::apply(
      [](std::vector<Circle> s, bool add_least, std::size_t place) {
        if (!add_least || s.empty()) return s;
        Circle least = s.front();
        for (const Circle& c : s)
          for (std::size_t f = 0; f < 5; ++f) field(least, f) = std::min(field(least, f), field(c, f));
        if (std::find(s.begin(), s.end(), least) == s.end())
          s.insert(s.begin() + static_cast<std::ptrdiff_t>(place % (s.size() + 1)), least);
        return s;
      },
      distinct_world(radii, max_size == 0 ? 0 : max_size - 1), detail::coin(), detail::uniform<std::size_t>(0, 63, 0));
}

rc::Gen<std::vector<std::size_t>> permutation(std::size_t n) {
  // Fisher–Yates: step i swaps position i with position i + u_i mod (n − i). Every u_i = 0 is the identity,
  // and each u_i shrinks towards 0, so a permutation shrinks towards fewer displaced elements.
  return rc::gen::map(
      rc::gen::container<std::vector<std::uint64_t>>(n, detail::uniform<std::uint64_t>(0, UINT64_MAX, 0)),
      [n](const std::vector<std::uint64_t>& u) {
        std::vector<std::size_t> perm(n);
        std::iota(perm.begin(), perm.end(), std::size_t{0});
        for (std::size_t i = 0; i < n; ++i) std::swap(perm[i], perm[i + u[i] % (n - i)]);
        return perm;
      });
}

rc::Gen<spec::Circles> double_world(std::size_t max_size, rc::Gen<double> field) {
  const rc::Gen<spec::CircleDoubles> circle = rc::gen::map(rc::gen::tuple(field, field, field, field, field), [](const auto& t) {
    const auto& [px, py, vx, vy, r] = t;
    return spec::CircleDoubles{px, py, vx, vy, std::fabs(r)};
  });
  return rc::gen::mapcat(rc::gen::inRange<std::size_t>(0, max_size + 1),
                         [circle](std::size_t n) { return rc::gen::container<spec::Circles>(n, circle); });
}

}  // namespace circles::properties::gen
