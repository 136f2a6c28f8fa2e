// The boundary families (properties/boundaries.hpp): every world of a family has the boundary the family
// promises, decided here independently with the oracle's exact rationals; the literal profile's worlds are
// inside its domain, which outside_literal_domain decides as the literal oracle does; and the two profiles'
// expected answers (properties/conformance.hpp) agree wherever both are defined.
#include "properties/boundaries.hpp"
#include "properties/conformance.hpp"
#include "properties/generators.hpp"
#include "spec/oracle.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cfloat>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace {

namespace properties = circles::properties;
namespace spec = circles::spec;
using properties::Circles;
using properties::Family;
using properties::Profile;
using spec::CircleDoubles;
using spec::Q;

std::vector<Circles> sample(const rc::Gen<Circles>& g, int n, std::uint64_t seed) {
  rc::Random random(seed);
  std::vector<Circles> out;
  for (int k = 0; k < n; ++k) out.push_back(g(random.split(), k % 100).value());
  return out;
}

Q q(double x) { return spec::exact(x); }

bool touch(const CircleDoubles& a, const CircleDoubles& b) {
  return spec::intersect(spec::from_doubles(a, 0, spec::Radii::non_negative), spec::from_doubles(b, 1, spec::Radii::non_negative));
}

bool tangent(const CircleDoubles& a, const CircleDoubles& b) {
  const Q dx = q(b[0]) - q(a[0]), dy = q(b[1]) - q(a[1]), s = q(a[4]) + q(b[4]);
  return dx * dx + dy * dy == s * s;
}

bool product_leq(const CircleDoubles& a, const CircleDoubles& b) {
  for (std::size_t f = 0; f < 5; ++f)
    if (!(q(a[f]) <= q(b[f]))) return false;
  return true;
}

double nudged(double x, int n) {
  for (int k = 0; k < std::abs(n); ++k) x = std::nextafter(x, n > 0 ? INFINITY : -INFINITY);
  return x;
}

bool any_pair(const Circles& w, const std::function<bool(const CircleDoubles&, const CircleDoubles&)>& p) {
  for (std::size_t a = 0; a < w.size(); ++a)
    for (std::size_t b = a + 1; b < w.size(); ++b)
      if (p(w[a], w[b])) return true;
  return false;
}

// Some circle c has two contacts x and y (different places in w) for which `p(x, y)` holds.
bool two_contacts(const Circles& w, const std::function<bool(const CircleDoubles&, const CircleDoubles&)>& p) {
  for (std::size_t c = 0; c < w.size(); ++c)
    for (std::size_t x = 0; x < w.size(); ++x)
      for (std::size_t y = 0; y < w.size(); ++y)
        if (x != c && y != c && x != y && touch(w[c], w[x]) && touch(w[c], w[y]) && p(w[x], w[y])) return true;
  return false;
}

// x and y equal in the first t fields of the key (px, py, vx, vy, r), by value, and different in the next.
bool tie(const CircleDoubles& x, const CircleDoubles& y, std::size_t t) {
  for (std::size_t f = 0; f < t; ++f)
    if (!(x[f] == y[f])) return false;
  return t == 5 || x[t] != y[t];
}

// tie(x, y, t) as a test of a pair, for two_contacts.
auto tied(std::size_t t) {
  return [t](const CircleDoubles& x, const CircleDoubles& y) { return tie(x, y, t); };
}

// The boundary each family promises.
bool has_boundary(Family family, const Circles& w) {
  switch (family) {
    case Family::lattice:
    case Family::random_doubles: return true;
    case Family::tangency: return any_pair(w, tangent);
    case Family::ulp_nudge:
      return any_pair(w, [](const CircleDoubles& a, const CircleDoubles& b) {
        if (tangent(a, b)) return false;
        for (const std::size_t f : {0, 1, 4})
          for (int n = -3; n <= 3; ++n)
            for (const bool first : {true, false}) {
              CircleDoubles x = a, y = b;
              (first ? x : y)[f] = nudged((first ? a : b)[f], n);
              if ((first ? x : y)[4] >= 0 && tangent(x, y)) return true;
            }
        return false;
      });
    case Family::tie_px: return two_contacts(w, tied(1));
    case Family::tie_p: return two_contacts(w, tied(2));
    case Family::tie_p_vx: return two_contacts(w, tied(3));
    case Family::tie_p_v: return two_contacts(w, tied(4));
    case Family::duplicates: return two_contacts(w, tied(5));
    case Family::incomparable:
      return two_contacts(w, [](const CircleDoubles& x, const CircleDoubles& y) {
        return !product_leq(x, y) && !product_leq(y, x);
      });
    case Family::mutual_contacts:
      for (std::size_t a = 0; a < w.size(); ++a)
        for (std::size_t b = a + 1; b < w.size(); ++b)
          for (std::size_t c = b + 1; c < w.size(); ++c)
            if (touch(w[a], w[b]) && touch(w[a], w[c]) && touch(w[b], w[c])) return true;
      return false;
    case Family::tangent_after_step: {
      const Circles next = spec::resolved_step_rounded(w);
      for (std::size_t a = 0; a < w.size(); ++a)
        for (std::size_t b = a + 1; b < w.size(); ++b)
          if (!touch(w[a], w[b]) && tangent(next[a], next[b])) return true;
      return false;
    }
    case Family::square_overflow:
      return any_pair(w, [](const CircleDoubles& a, const CircleDoubles& b) {
        const Q s = q(a[4]) + q(b[4]);
        return s * s > q(DBL_MAX);
      });
    case Family::subnormals:
      for (const CircleDoubles& c : w)
        for (const double x : c)
          if (std::fpclassify(x) == FP_SUBNORMAL) return true;
      return false;
    case Family::cancellation:
      // |p + v/60| <= 2^-40 |p| with p != 0, exactly.
      for (const CircleDoubles& c : w)
        for (std::size_t f = 0; f < 2; ++f) {
          const Q sum = q(c[f]) + q(c[f + 2]) / 60, bound = abs(q(c[f])) / Q(spec::Z(1) << 40);
          if (c[f] != 0 && abs(sum) <= bound) return true;
        }
      return false;
    case Family::signed_zeros: {
      bool plus = false, minus = false;
      for (const CircleDoubles& c : w)
        for (const double x : c)
          if (x == 0) (std::signbit(x) ? minus : plus) = true;
      return plus && minus;
    }
    case Family::zero_radius:
      for (const CircleDoubles& c : w)
        if (c[4] == 0) return true;
      return false;
    case Family::wire:
      // Every world has a next one (no velocity carries a position past DBL_MAX), so that each of its requests,
      // with its spellings, is asked rather than skipped.
      return !w.empty() && std::holds_alternative<Circles>(properties::expected_step(w, Profile::resolved));
    default: break;  // the big families' promises: tests/big_worlds_test.cpp
  }
  return false;
}

TEST(boundary_world, every_world_of_a_family_has_its_boundary) {
  for (const Profile profile : {Profile::resolved, Profile::literal})
    for (const Family family : properties::families(profile)) {
      if (properties::is_big(family)) continue;  // tests/big_worlds_test.cpp
      const std::vector<Circles> worlds = sample(properties::gen::boundary_world(family, profile), 300, 2026);
      int with = 0;
      for (const Circles& w : worlds) {
        ASSERT_LE(w.size(), 8u);
        for (const CircleDoubles& c : w) {
          for (const double x : c) ASSERT_TRUE(std::isfinite(x));
          ASSERT_GE(c[4], 0);
        }
        if (profile == Profile::literal) {
          ASSERT_EQ(properties::outside_literal_domain(w), std::nullopt);
        }
        with += has_boundary(family, w);
      }
      // Resolved: by construction, every world. Literal: a world cut down to the domain may lose it.
      const int least = profile == Profile::resolved ? 300 : 270;
      EXPECT_GE(with, least) << properties::name(family) << " in the " << properties::name(profile) << " profile";
    }
}

TEST(boundary_world, tangencies_reach_the_subnormals_and_the_top_binades) {
  int subnormal = 0, huge = 0;
  for (const Circles& w : sample(properties::gen::boundary_world(Family::tangency, Profile::resolved), 2000, 7))
    for (std::size_t a = 0; a < w.size(); ++a)
      for (std::size_t b = a + 1; b < w.size(); ++b)
        if (tangent(w[a], w[b])) {
          const Q s = q(w[a][4]) + q(w[b][4]);
          subnormal += s > 0 && s < q(DBL_MIN);
          huge += s >= q(std::ldexp(1.0, 900));
        }
  EXPECT_GE(subnormal, 10);
  EXPECT_GE(huge, 100);
}

TEST(boundary_world, shrinks_by_dropping_a_circle_first) {
  rc::Random random(11);
  for (const Family family : properties::families(Profile::resolved)) {
    if (properties::is_big(family)) continue;  // a big world shrinks by delta debugging in conform, not here
    const rc::Gen<Circles> g = properties::gen::boundary_world(family, Profile::resolved);
    for (int k = 0; k < 20; ++k) {
      const rc::Shrinkable<Circles> s = g(random.split(), 50);
      const std::size_t n = s.value().size();
      if (n == 0) continue;
      const auto first = s.shrinks().next();
      ASSERT_TRUE(first) << properties::name(family);
      EXPECT_EQ(first->value().size(), n - 1) << properties::name(family);
    }
  }
}

TEST(boundary_case, tags_every_family_of_the_profile) {
  rc::Random random(3);
  std::map<std::string, int> seen;
  for (int k = 0; k < 1000; ++k)
    ++seen[properties::name(properties::gen::boundary_case(Profile::literal)(random.split(), 50).value().first)];
  EXPECT_EQ(seen.size(), properties::families(Profile::literal).size());
  EXPECT_FALSE(seen.contains("zero-radius"));
  EXPECT_FALSE(seen.contains("duplicates"));
}

TEST(outside_literal_domain, names_each_reason_with_its_circles) {
  EXPECT_EQ(properties::outside_literal_domain({{0, 0, 0, 0, 1}, {5, 0, 0, 0, 1}}), std::nullopt);
  EXPECT_EQ(properties::outside_literal_domain({{0, 0, 0, 0, 1}, {0, 0, 0, 0, 0}}),
            "circle 1: r is not > 0 (the literal profile's C has r in R+)");
  EXPECT_EQ(properties::outside_literal_domain({{0, 0, 0, 0, 1}, {-0.0, 0, 0, 0, 1}}),
            "circles 0 and 1 are one circle (a world is a set)");
  // Circle 0 touches 1 and 2, which (6) does not order (px 1 < 2, py 2 > 1).
  EXPECT_EQ(properties::outside_literal_domain({{0, 0, 0, 0, 10}, {1, 2, 0, 0, 1}, {2, 1, 0, 0, 1}}),
            "circle 0: e(c, S) (8) has no least element: S holds circles 1 and 2, which (6) does not order");
  // Circles 0 and 1 share p and r, and both take the velocity of circle 2, the least of each one's contacts.
  EXPECT_EQ(properties::outside_literal_domain({{0, 0, 1, 0, 1}, {0, 0, 2, 0, 1}, {-1, 0, 0, 0, 1}}),
            "circles 0 and 1 merge: their images under (4) are equal");
}

TEST(outside_literal_domain, agrees_with_the_literal_oracle) {
  // Inside the domain exactly when the literal step of the set of the circles is defined and has as many
  // circles as the list: no two equal, none merged.
  const auto rounded = rc::gen::map(properties::gen::world(spec::Radii::positive, 6), [](const std::vector<spec::Circle>& w) {
    Circles out;
    for (const spec::Circle& c : w) out.push_back(spec::nearest_doubles(c));
    return out;
  });
  int inside = 0, outside = 0;
  for (const Circles& w : sample(rounded, 2000, 5)) {
    bool finite = true;
    for (const CircleDoubles& c : w)
      for (const double x : c) finite = finite && std::isfinite(x);
    if (!finite) continue;
    std::vector<spec::Circle> list;
    for (std::size_t k = 0; k < w.size(); ++k) list.push_back(spec::from_doubles(w[k], k, spec::Radii::positive));
    const auto next = spec::literal_step(spec::literal_world(list));
    const auto* defined = std::get_if<spec::LiteralWorld>(&next);
    const bool oracle_inside = defined && defined->size() == w.size();
    const bool ours_inside = !properties::outside_literal_domain(w);
    EXPECT_EQ(ours_inside, oracle_inside) << testing::PrintToString(w);
    ++(oracle_inside ? inside : outside);
  }
  EXPECT_GE(inside, 300);
  EXPECT_GE(outside, 300);
}

TEST(expected_step, is_the_same_in_both_profiles_inside_the_literal_domain) {
  for (const Family family : properties::families(Profile::literal))
    for (const Circles& w : sample(properties::gen::boundary_world(family, Profile::literal), 100, 9)) {
      const auto literal = properties::expected_step(w, Profile::literal);
      const auto resolved = properties::expected_step(w, Profile::resolved);
      ASSERT_EQ(literal.index(), resolved.index()) << properties::name(family);
      if (const auto* answer = std::get_if<Circles>(&literal)) {
        EXPECT_EQ(*answer, std::get<Circles>(resolved)) << properties::name(family);
      }
    }
  EXPECT_EQ(std::get<properties::NoAnswer>(properties::expected_step({{0, 0, 0, 0, 0}}, Profile::literal)),
            properties::NoAnswer::outside_literal_domain);
  EXPECT_EQ(std::get<properties::NoAnswer>(properties::expected_step({{DBL_MAX, 0, DBL_MAX, 0, 1}}, Profile::resolved)),
            properties::NoAnswer::overflow);
}

}  // namespace

namespace {

// The table of families: each family's row is where everything reads it. A family has exactly one
// construction, a big one when it is big; names are distinct; the literal profile has no big family and no
// family whose worlds leave its domain; a big world of a small family is empty.
TEST(family_rows, hold_one_construction_each_and_the_profiles_read_them) {
  std::map<std::string, int> names;
  std::size_t literal = 0, big = 0;
  for (const properties::FamilyRow& r : properties::family_rows()) {
    SCOPED_TRACE(r.name);
    EXPECT_EQ(&properties::row(r.family), &r);
    EXPECT_EQ(++names[r.name], 1);
    EXPECT_NE(r.build_small == nullptr, r.build_big == nullptr);
    EXPECT_EQ(r.big, r.build_big != nullptr);
    EXPECT_EQ(properties::is_big(r.family), r.big);
    EXPECT_GE(r.steps, 1u);
    EXPECT_GT(std::string(r.aim).size(), 20u);
    if (r.big) {
      EXPECT_FALSE(r.literal);
    } else {
      EXPECT_TRUE(properties::gen::big_world(r.family, 0, 4097, rc::Random(1)).empty());
    }
    literal += r.literal;
    big += r.big;
  }
  EXPECT_EQ(properties::families(Profile::resolved).size(), properties::family_rows().size());
  EXPECT_EQ(properties::families(Profile::literal).size(), literal);
  EXPECT_EQ(big, 8u);
  EXPECT_EQ(properties::steps_to_decide(Family::tangent_after_step), 2u);
  EXPECT_EQ(properties::steps_to_decide(Family::big_chains), 10u);
  EXPECT_FALSE(properties::row(Family::zero_radius).literal);
  EXPECT_FALSE(properties::row(Family::duplicates).literal);
}

}  // namespace
