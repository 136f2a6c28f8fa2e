// The double engine (impl/engine.hpp) against the correctly rounded oracle step spec::resolved_step_rounded.
//
// Every world is checked the same way (Check::world): one DoubleEngine step must equal the oracle step by value
// (−0 == +0) in every coordinate; the all-pairs reference engine and the grid reference (impl/grid_reference.hpp)
// must give the same bits as the engine; and
// the broad phase's candidates must contain every exactly intersecting pair (the all-pairs validator).
// Two properties draw worlds from the property suite's generators (properties/generators.hpp). Random worlds
// run a few steps, each checked against the oracle from the engine's previous world, so the
// broad phase's kept sort order is exercised too. Inputs come from a seeded std::mt19937_64.
#include "impl/engine.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "impl/broad_phase.hpp"
#include "impl/grid_reference.hpp"
#include "impl/predicate.hpp"
#include "properties/generators.hpp"
#include "spec/circle.hpp"
#include "spec/oracle.hpp"
#include "tests/thrown.hpp"

namespace circles::impl {
namespace {

using spec::Circles;
using circles::testing::thrown;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string show(const Circles& w) {
  std::ostringstream o;
  for (std::size_t k = 0; k < w.size(); ++k) {
    o << "  #" << k << " [";
    for (std::size_t f = 0; f < 5; ++f) o << (f ? ", " : "") << hex(w[k][f]);
    o << "]\n";
  }
  return o.str();
}

// Counts for one test; prints itself when the test ends.
struct Check {
  std::string family;
  long worlds = 0, circles = 0, new_velocity = 0, candidates = 0, intersecting = 0, gridded = 0;

  explicit Check(std::string name) : family(std::move(name)) {}
  Check(const Check&) = delete;
  Check& operator=(const Check&) = delete;
  ~Check() {
    std::printf("[ %s ] %ld worlds (%ld on the grid reference's cells), %ld circle-steps, %ld took a new velocity, "
                "%ld candidate pairs, %ld intersecting\n",
                family.c_str(), worlds, gridded, circles, new_velocity, candidates, intersecting);
  }

  // One step of w: engine == oracle by value, engine == all-pairs reference bitwise, candidates cover every
  // intersecting pair. Returns the engine's next world (for multi-step runs).
  Circles world(const Circles& w, DoubleEngine* engine = nullptr) {
    DoubleEngine local{World{w}};
    DoubleEngine& e = engine ? *engine : local;
    const World before = e.world();
    const std::vector<CandidatePair> tested = e.candidates();
    e.step();
    const Circles got = e.world().circles();
    const Circles want = spec::resolved_step_rounded(w);
    const Circles reference = step_all_pairs(before).circles();
    const Circles grid = step_grid(before).circles();
    gridded += grid_side(before).has_value();
    ++worlds;
    circles += static_cast<long>(w.size());
    candidates += static_cast<long>(tested.size());
    EXPECT_EQ(got.size(), want.size());
    for (std::size_t k = 0; k < got.size() && k < want.size(); ++k) {
      new_velocity += got[k][2] != w[k][2] || got[k][3] != w[k][3];
      for (std::size_t f = 0; f < 5; ++f) {
        const char* field = spec::name(spec::Field(f));
        EXPECT_EQ(got[k][f], want[k][f]) << family << ": circle " << k << " field " << field << ": engine "
                                         << hex(got[k][f]) << ", oracle " << hex(want[k][f]) << "\nworld:\n"
                                         << show(w);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(got[k][f]), std::bit_cast<std::uint64_t>(reference[k][f]))
            << family << ": circle " << k << " field " << field << " differs from the all-pairs engine";
        EXPECT_EQ(std::bit_cast<std::uint64_t>(grid[k][f]), std::bit_cast<std::uint64_t>(reference[k][f]))
            << family << ": circle " << k << " field " << field << ": the grid reference differs from the "
            << "all-pairs one\nworld:\n" << show(w);
      }
    }
    EXPECT_TRUE(candidates_cover_all_intersecting_pairs(before.px(), before.py(), before.r(), tested))
        << family << ": the broad phase dropped an intersecting pair\nworld:\n" << show(w);
    for (std::size_t i = 0; i < w.size(); ++i)
      for (std::size_t j = i + 1; j < w.size(); ++j)
        intersecting += intersect_exact(w[i][0], w[i][1], w[i][4], w[j][0], w[j][1], w[j][4]);
    return got;
  }
};

double uniform(std::mt19937_64& g, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }
int integer(std::mt19937_64& g, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g); }

// A dense world of n circles in a box of side 2^s (s random): radii log-uniform from 2^-40 to 2^-6 of the side
// for about a third of them and from 2^-6 to 2^-2 for half, so tiny and large circles share the world; about one circle in eight on a coarse lattice (ties and exact
// tangencies), one in sixteen of radius 0.
Circles random_world(std::mt19937_64& g, std::size_t n) {
  const double side = std::ldexp(1.0, integer(g, -20, 40));
  Circles w;
  for (std::size_t k = 0; k < n; ++k) {
    const int kind = integer(g, 0, 15);
    if (kind < 2) {
      const double q = side / 8;
      w.push_back({q * integer(g, 0, 8), q * integer(g, 0, 8), q * integer(g, -2, 2), q * integer(g, -2, 2),
                   q * integer(g, 0, 3) / 2});
    } else {
      const double r = kind == 2 ? 0.0 : side * std::exp2(kind < 8 ? uniform(g, -40, -6) : uniform(g, -6, -2));
      w.push_back({uniform(g, 0, side), uniform(g, 0, side), uniform(g, -60, 60) * side, uniform(g, -60, 60) * side, r});
    }
  }
  return w;
}

TEST(engine, agrees_with_the_rounded_oracle_on_random_worlds_of_0_to_40_circles_for_three_steps) {
  Check check("random");
  std::mt19937_64 g(20261122);
  for (int t = 0; t < 300; ++t) {
    Circles w = random_world(g, static_cast<std::size_t>(t % 41));
    DoubleEngine e{World{w}};
    for (int s = 0; s < 3; ++s) w = check.world(w, &e);
  }
  EXPECT_GT(check.new_velocity, check.circles / 10) << "the random worlds are too sparse to test contacts";
}

// 3-4-5 triangles scaled by 2^k in every binade that holds them, in four orientations: a at the origin with
// radius 2·2^k and b at (±3, ±4)·2^k with radius 3·2^k touch exactly; c, 1 ulp further out in x, does not touch
// a; d, 1 ulp in, does; e has b's centre and a radius 1 ulp short of tangency; f 1 ulp over.
TEST(engine, agrees_with_the_rounded_oracle_at_exact_tangency_in_every_binade_and_one_ulp_either_side) {
  Check check("tangency");
  for (int k = -1074; k <= 1020; k += (k < -1060 || k > 1000 ? 1 : 7)) {
    const double s = std::ldexp(1.0, k);
    for (const auto& [sx, sy] : {std::array{1.0, 1.0}, {-1.0, 1.0}, {1.0, -1.0}, {-1.0, -1.0}}) {
      const double bx = sx * 3 * s, by = sy * 4 * s;
      const double out = std::nextafter(bx, sx * kInf), in = std::nextafter(bx, 0.0);
      check.world({{0, 0, s, -s, 2 * s},
                   {bx, by, 2 * s, s, 3 * s},
                   {out, by, -s, 3 * s, 3 * s},
                   {in, by, 5 * s, 0, 3 * s}});
      check.world({{0, 0, s, -s, 2 * s}, {bx, by, 2 * s, s, std::nextafter(3 * s, 0.0)}});
      check.world({{0, 0, s, -s, 2 * s}, {bx, by, 2 * s, s, std::nextafter(3 * s, kInf)}});
      check.world({{bx, by, 2 * s, s, 3 * s}, {0, 0, s, -s, 2 * s}, {out, by, -s, 3 * s, 3 * s}});
    }
  }
}

// The centre circle touches A and B, which agree on every key before position j and differ at j; the lesser
// one at j has the higher index, so an index-first or key-skipping comparison would pick the wrong one.
// j = 5 makes A and B equal, and the index decides. Keys equal as −0 and +0 tie too.
TEST(engine, takes_the_velocity_of_the_lexicographically_least_contact_with_ties_at_each_key_position) {
  Check check("ties");
  for (std::size_t j = 0; j <= 5; ++j) {
    for (const double zero : {0.0, -0.0}) {
      spec::CircleDoubles a{1, 1, 2, 3, 1};
      spec::CircleDoubles b = a;
      if (j < 5) b[j] += 0.5;
      for (std::size_t f = 0; f < j && f < 4; ++f) {
        a[f] = f % 2 ? zero : -zero;
        b[f] = f % 2 ? -zero : zero;
      }
      check.world({{0, 0, 7, 11, 10}, b, a});
      check.world({a, {0, 0, 7, 11, 10}, b});
      check.world({{0.5, 0.5, -7, -11, 10}, b, a, b, a});
    }
  }
}

TEST(engine, agrees_with_the_rounded_oracle_on_exact_duplicates) {
  Check check("duplicates");
  const spec::CircleDoubles c{1, 2, 3, 4, 5};
  check.world({c, c});
  check.world({c, c, c, {1, 2, 3, 5, 5}, {1, 2, 2, 4, 5}});
  check.world({{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, 0, 1, 1, 0}});
  check.world({c, {100, 100, -1, -1, 1}, c, {100, 100, -1, -1, 1}});
}

TEST(engine, agrees_with_the_rounded_oracle_on_signed_zeros_and_radius_zero) {
  Check check("zeros");
  for (const double z1 : {0.0, -0.0})
    for (const double z2 : {0.0, -0.0}) {
      check.world({{z1, z2, z1, z2, z1}, {z2, z1, z2, z1, z2}});
      check.world({{z1, z2, z1, z2, 0.0}, {z1, z2, -1, 1, z2}, {3, 4, 1, z1, 5}});
      check.world({{z1, 0, z2, 0, 0}, {std::nextafter(0.0, 1.0), 0, 1, 1, 0}});
      check.world({{3, 4, z1, z2, 0}, {z2, z1, 5, 6, 5}, {3, std::nextafter(4.0, 5.0), 7, 8, 0}});
    }
}

TEST(engine, agrees_with_the_rounded_oracle_on_subnormal_coordinates) {
  Check check("subnormal");
  std::mt19937_64 g(1074);
  const double t = std::numeric_limits<double>::denorm_min();
  for (int n = 0; n < 200; ++n) {
    Circles w;
    for (int k = 0; k < 12; ++k)
      w.push_back({t * integer(g, -40, 40), t * integer(g, -40, 40), t * integer(g, -3000, 3000),
                   t * integer(g, -3000, 3000), t * integer(g, 0, 20)});
    if (n % 2) w.push_back({DBL_MIN * uniform(g, -2, 2), DBL_MIN * uniform(g, -2, 2), uniform(g, -1, 1), 0, DBL_MIN});
    check.world(w);
  }
}

// p ≈ −v/60: the new position cancels to nearly 0, where an inexact 1/60 or a double rounding shows at once.
TEST(engine, agrees_with_the_rounded_oracle_when_the_new_position_cancels) {
  Check check("cancellation");
  std::mt19937_64 g(60);
  for (int n = 0; n < 200; ++n) {
    Circles w;
    const double scale = std::ldexp(1.0, integer(g, -30, 30));
    for (int k = 0; k < 12; ++k) {
      const double vx = uniform(g, -60, 60) * scale, vy = uniform(g, -60, 60) * scale;
      double px = -vx / 60, py = -vy / 60;
      for (int u = integer(g, -3, 3); u != 0; u += u > 0 ? -1 : 1) px = std::nextafter(px, u > 0 ? kInf : -kInf);
      for (int u = integer(g, -3, 3); u != 0; u += u > 0 ? -1 : 1) py = std::nextafter(py, u > 0 ? kInf : -kInf);
      w.push_back({px, py, vx, vy, scale * uniform(g, 0, 0.5)});
    }
    check.world(w);
  }
}

// Near DBL_MAX: differences and the squares of (3) overflow, and so do the broad phase's bounds x ± r.
TEST(engine, agrees_with_the_rounded_oracle_near_dbl_max_and_with_radii_spanning_every_scale) {
  Check check("huge");
  const double m = DBL_MAX;
  check.world({{-m / 2, 0, 1, 0, m / 2}, {m / 2, 0, -1, 0, m / 2}});
  check.world({{-m, -m, 1, 2, m}, {m, m, 3, 4, m}, {0, 0, 5, 6, 0}});
  check.world({{-m, 0, 1, 2, m}, {m, 0, 3, 4, m}, {0, m, 5, 6, std::nextafter(m, 0.0)}});
  std::mt19937_64 g(1024);
  for (int n = 0; n < 100; ++n) {
    Circles w;
    for (int k = 0; k < 20; ++k)
      w.push_back({std::ldexp(uniform(g, -1, 1), integer(g, -1074, 1023)), std::ldexp(uniform(g, -1, 1), integer(g, -1074, 1023)),
                   std::ldexp(uniform(g, -1, 1), integer(g, -1074, 1010)), std::ldexp(uniform(g, -1, 1), integer(g, -1074, 1010)),
                   std::ldexp(uniform(g, 0, 1), integer(g, -1074, 1023))});
    check.world(w);
  }
}

// Larger worlds, no oracle: the broad phase over several steps (the kept order repaired by insertion sort) and
// worlds that defeat a sweep on x (one column, nested radii) must still cover every intersecting pair, and the
// engine must give the all-pairs reference's bits.
TEST(engine, broad_phase_covers_every_intersecting_pair_in_larger_worlds_over_many_steps) {
  std::mt19937_64 g(4096);
  long steps = 0, pairs = 0;
  for (int t = 0; t < 6; ++t) {
    Circles w;
    const std::size_t n = 1500;
    for (std::size_t k = 0; k < n; ++k) {
      const double x = t % 2 ? 0.0 : uniform(g, 0, 1000);
      w.push_back({x, uniform(g, 0, 1000), uniform(g, -600, 600), uniform(g, -600, 600),
                   std::exp2(uniform(g, -30, 7))});
    }
    DoubleEngine e{World{w}};
    for (int s = 0; s < 5; ++s) {
      const World before = e.world();
      const World reference = step_all_pairs(before);
      const std::vector<CandidatePair> tested = e.candidates();
      e.step();
      ++steps;
      pairs += static_cast<long>(tested.size());
      ASSERT_TRUE(candidates_cover_all_intersecting_pairs(before.px(), before.py(), before.r(), tested));
      const Circles got = e.world().circles(), want = reference.circles();
      for (std::size_t k = 0; k < n; ++k)
        for (std::size_t f = 0; f < 5; ++f)
          ASSERT_EQ(std::bit_cast<std::uint64_t>(got[k][f]), std::bit_cast<std::uint64_t>(want[k][f]))
              << "circle " << k << " field " << spec::name(spec::Field(f));
    }
  }
  std::printf("[ broad phase ] %ld steps of 1500 circles, %ld candidate pairs\n", steps, pairs);
}

// The first position of the oracle's step that rounds to ±infinity, in the engine's reporting order (lowest
// index, px before py), or nothing.
std::optional<std::pair<std::size_t, spec::Field>> first_overflow(const Circles& next) {
  for (std::size_t k = 0; k < next.size(); ++k)
    for (const spec::Field f : {spec::Field::px, spec::Field::py})
      if (std::isinf(next[k][static_cast<std::size_t>(f)])) return std::pair{k, f};
  return std::nullopt;
}

// One engine step against the oracle for a world that may overflow: the engine throws PositionOverflow for
// exactly the first circle whose oracle position is infinite, and otherwise agrees by value.
void agrees_or_overflows_like_the_oracle(const Circles& w) {
  const Circles want = spec::resolved_step_rounded(w);
  DoubleEngine e{World{w}};
  const auto overflow = first_overflow(want);
  RC_TAG(overflow ? "overflow" : "finite");
  const std::vector<CandidatePair> tested = e.candidates();
  try {
    e.step();
  } catch (const PositionOverflow& error) {
    RC_ASSERT(overflow.has_value());
    RC_ASSERT(error.step == 1u);
    RC_ASSERT(error.index == overflow->first);
    RC_ASSERT(error.field == overflow->second);
    RC_ASSERT(e.world().circles() == w);
    return;
  }
  RC_ASSERT(!overflow.has_value());
  const Circles got = e.world().circles();
  RC_ASSERT(got == want);  // std::array<double> == compares by value: −0 == +0
  RC_ASSERT(candidates_cover_all_intersecting_pairs(World{w}.px(), World{w}.py(), World{w}.r(), tested));
}

// The property suite's worlds (lattice coordinates, copies, ties, exact axis and 3-4-5 tangencies, some
// arbitrary rationals), each coordinate rounded to the nearest double; those that round to infinity refused.
RC_GTEST_PROP(engine, agrees_with_the_rounded_oracle_on_every_world_the_property_suite_generates, ()) {
  const std::vector<spec::Circle> exact = *properties::gen::world(spec::Radii::non_negative, 12);
  Circles w;
  for (const spec::Circle& c : exact) w.push_back(spec::nearest_doubles(c));
  // A rational beyond DBL_MAX rounds to infinity: such a world is outside C as doubles, and refused.
  for (std::size_t k = 0; k < w.size(); ++k)
    for (std::size_t f = 0; f < 5; ++f)
      if (!std::isfinite(w[k][f])) {
        RC_TAG("refused");
        RC_ASSERT_THROWS_AS(World{w}, spec::OutsideC);
        return;
      }
  agrees_or_overflows_like_the_oracle(w);
}

// Every field from the suite's finite_double (±0, subnormals, near DBL_MAX, every binade), radii |x|; one field
// in three from values at the overflow threshold of p + v/60: DBL_MAX + 60·2^970/60 is the tie at
// 2^1024(1 − 2^-54), which rounds to +infinity (even), and one ulp less of v stays at DBL_MAX.
RC_GTEST_PROP(engine, agrees_with_the_rounded_oracle_or_reports_its_first_overflow_on_arbitrary_finite_doubles, ()) {
  const double tie = 0x1.ep975;  // 60·2^970
  const auto field = rc::gen::oneOf(properties::gen::finite_double(), properties::gen::finite_double(),
                                    rc::gen::element(DBL_MAX, -DBL_MAX, 0x1p1023, tie, -tie, std::nextafter(tie, 0.0)));
  agrees_or_overflows_like_the_oracle(*properties::gen::double_world(8, field));
}

TEST(engine, validator_reports_a_missing_intersecting_pair) {
  const World w{Circles{{0, 0, 0, 0, 1}, {2, 0, 0, 0, 1}, {5, 0, 0, 0, 0}, {0, 0, 0, 0, 0}}};
  const std::vector<CandidatePair> all{{0, 1}, {0, 3}, {1, 3}, {0, 2}};
  EXPECT_TRUE(candidates_cover_all_intersecting_pairs(w.px(), w.py(), w.r(), all));
  const std::vector<CandidatePair> reversed{{1, 0}, {3, 0}};
  EXPECT_TRUE(candidates_cover_all_intersecting_pairs(w.px(), w.py(), w.r(), reversed));
  const std::vector<CandidatePair> missing{{0, 1}, {1, 3}};
  EXPECT_FALSE(candidates_cover_all_intersecting_pairs(w.px(), w.py(), w.r(), missing));
}

// Worlds of 64 circles and more, where the broad phase cuts the plane into strips: lattices of circles of
// diameter q at spacing q (every neighbour tangent exactly, across x and across y, so many tangencies fall on or
// near strip boundaries), in binades from subnormal to near DBL_MAX, with a few circles far larger than the
// median mixed in; checked against the oracle like every other world.
TEST(engine, agrees_with_the_rounded_oracle_on_tangent_lattices_large_enough_to_use_strips) {
  Check check("lattice");
  std::mt19937_64 g(64);
  for (const int e : {-1074, -1040, -300, -20, 0, 7, 500, 1000, 1017}) {
    const double q = std::ldexp(1.0, e);
    for (int variant = 0; variant < 3; ++variant) {
      Circles w;
      const int side = 9;
      for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j)
          w.push_back({q * 2 * i, q * 2 * j, q * integer(g, -3, 3), q * integer(g, -3, 3),
                       variant == 1 && (i + j) % 5 == 0 ? std::nextafter(q, 0.0) : q});
      if (variant == 2) {
        w.push_back({q * 8, q * 8, q, -q, q * 6});
        w.push_back({-q * 4, q * 16, 0, 0, q * 20});
        w.push_back({q * 3, q * 5, q, q, 0});
      }
      check.world(w);
    }
  }
}

// A column of 100 small circles of radius q, 200q high (strips 8q high, so 25 of them), and circles of radius
// 40q that span more than 8 strips, so the broad phase treats them as wide: A and B are tangent exactly to each other
// and overlap the column; C is far from everything; D touches only the column's end.
TEST(engine, agrees_with_the_rounded_oracle_when_circles_span_many_strips) {
  Check check("wide");
  for (const int e : {-1070, -8, 0, 30, 1000}) {
    const double q = std::ldexp(1.0, e);
    Circles w;
    for (int i = 0; i < 100; ++i) w.push_back({0, q * 2 * i, q * (i % 3), -q * (i % 5), q});
    w.push_back({0, q * 100, q, q, q * 40});
    w.push_back({q * 80, q * 100, -q, q, q * 40});
    w.push_back({-q * 200, 0, q, q, q * 40});
    w.push_back({0, -q * 41, 2 * q, q, q * 40});
    check.world(w);
  }
}

TEST(engine, agrees_with_the_rounded_oracle_on_random_worlds_of_64_to_120_circles) {
  Check check("random strips");
  std::mt19937_64 g(120);
  for (int t = 0; t < 12; ++t) {
    Circles w = random_world(g, static_cast<std::size_t>(integer(g, 64, 120)));
    DoubleEngine e{World{w}};
    for (int s = 0; s < 2; ++s) w = check.world(w, &e);
  }
}

TEST(engine, outward_bounds_contain_the_exact_interval_within_a_few_ulps) {
  // Each bound is on the correct side of the exact x ∓ r (checked in rationals) and at most 3 ulps outside.
  // Three ulps toward `to`, held within ±DBL_MAX (the exact x ∓ r are within it too).
  const auto three_ulps = [](double x, double to) {
    for (int k = 0; k < 3; ++k) x = std::nextafter(x, to);
    return std::clamp(x, -DBL_MAX, DBL_MAX);
  };
  const auto check = [&](double x, double r) {
    const double lo = outward_lower(x, r), hi = outward_upper(x, r);
    const spec::Q exact_lo = spec::exact(x) - spec::exact(r), exact_hi = spec::exact(x) + spec::exact(r);
    if (std::isfinite(lo)) {
      EXPECT_LE(spec::exact(lo), exact_lo) << hex(x) << " " << hex(r);
      EXPECT_GE(spec::exact(three_ulps(lo, kInf)), exact_lo) << hex(x) << " " << hex(r);
    }
    if (std::isfinite(hi)) {
      EXPECT_GE(spec::exact(hi), exact_hi) << hex(x) << " " << hex(r);
      EXPECT_LE(spec::exact(three_ulps(hi, -kInf)), exact_hi) << hex(x) << " " << hex(r);
    }
  };
  std::mt19937_64 g(414);
  for (int k = 0; k < 20000; ++k) {
    const double x = std::ldexp(uniform(g, -1, 1), static_cast<int>(integer(g, -1074, 1023)));
    const double r = std::ldexp(uniform(g, 0, 1), static_cast<int>(integer(g, -1074, 1023)));
    check(x, r);
  }
  for (const double x : {0.0, -0.0, 1.0, 0x1p-1074, -0x1p-1022, DBL_MAX, -DBL_MAX, 0x1p52, 0x1.8p-1060})
    for (const double r : {0.0, 0x1p-1074, 0x1p-60, 1.0, DBL_MAX}) check(x, r);
  EXPECT_LT(outward_lower(1.0, 0.0), 1.0);
  EXPECT_GT(outward_upper(1.0, 0.0), 1.0);
  EXPECT_EQ(outward_lower(0.0, 0.0), -0x1p-1073);
  EXPECT_EQ(outward_lower(-DBL_MAX, DBL_MAX), -kInf);
  EXPECT_EQ(outward_upper(DBL_MAX, 1.0), kInf);
}

TEST(engine, throws_position_overflow_naming_the_circle_and_leaves_the_world_unchanged) {
  const double m = DBL_MAX;
  // Circle 2 moves past DBL_MAX in y by its own velocity; the others stay finite.
  const Circles w{{-m, -m, 0, 0, 0}, {0, 0, 1, 1, 1}, {0, m, 0, m, 1}};
  EXPECT_TRUE(std::isinf(spec::resolved_step_rounded(w)[2][1]));
  DoubleEngine e{World{w}};
  const auto own = thrown<PositionOverflow>([&] { e.step(); });
  ASSERT_TRUE(own);
  EXPECT_EQ(own->index, 2u);
  EXPECT_EQ(own->field, spec::Field::py);
  EXPECT_EQ(own->step, 1u);
  EXPECT_STREQ(own->what(), "step 1, circle 2, field py: the position p + v/60 overflows to infinity");
  EXPECT_EQ(e.world().circles(), w);
  // Circle 1 overflows by the velocity it takes from circle 2, which it touches; circle 2 takes circle 1's
  // velocity 0 and stays. Circle 3 overflows in x by its own velocity; the error names the first, circle 1.
  const Circles taken{{0, 0, 0, 0, 1}, {0, m, 0, 0, 1}, {0, m, 0, m, 1}, {-m, 0, -m, 0, 0}};
  const Circles oracle = spec::resolved_step_rounded(taken);
  EXPECT_TRUE(std::isinf(oracle[1][1]));
  EXPECT_EQ(oracle[2][1], m);
  const auto first = thrown<PositionOverflow>([&] { DoubleEngine{World{taken}}.step(); });
  ASSERT_TRUE(first);
  EXPECT_EQ(first->index, 1u);
  EXPECT_EQ(first->field, spec::Field::py);
  EXPECT_THROW(step_all_pairs(World{taken}), PositionOverflow);
  EXPECT_THROW(step_all_pairs(World{taken}), std::overflow_error);
  // At the threshold: DBL_MAX + tie/60 is the midpoint 2^1024(1 − 2^-54), which rounds (to even) to +infinity;
  // one ulp less of velocity rounds to DBL_MAX.
  const double tie = 0x1.ep975;  // 60·2^970
  const Circles below{{m, 0, std::nextafter(tie, 0.0), 0, 0}};
  DoubleEngine stays{World{below}};
  stays.step();
  EXPECT_EQ(stays.world().px()[0], m);
  EXPECT_EQ(spec::resolved_step_rounded(below)[0][0], m);
  const Circles at{{1, 2, 0, 0, 0}, {m, 0, tie, 0, 0}};
  EXPECT_TRUE(std::isinf(spec::resolved_step_rounded(at)[1][0]));
  const auto tie_overflows = thrown<PositionOverflow>([&] { DoubleEngine{World{at}}.step(); });
  ASSERT_TRUE(tie_overflows);
  EXPECT_EQ(tie_overflows->index, 1u);
  EXPECT_EQ(tie_overflows->field, spec::Field::px);
}

TEST(engine, world_refuses_circles_outside_c_naming_index_and_field) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // The oracle's own error, with the same circle, field and message as the oracle gives for the same world.
  const auto refused = [](const Circles& w, std::size_t index, spec::Field field) {
    const auto error = thrown<spec::OutsideC>([&] { World{w}; });
    const auto oracle = thrown<spec::OutsideC>([&] { spec::resolved_step_rounded(w); });
    ASSERT_TRUE(error && oracle) << show(w);
    EXPECT_EQ(error->index, index);
    EXPECT_EQ(error->field, field);
    EXPECT_STREQ(error->what(), oracle->what());
  };
  refused({{0, 0, 0, 0, 1}, {0, 0, 0, nan, 1}}, 1, spec::Field::vy);
  refused({{kInf, 0, 0, 0, 1}}, 0, spec::Field::px);
  refused({{0, 0, 0, 0, 1}, {0, 0, 0, 0, 1}, {0, -kInf, 0, 0, -1}}, 2, spec::Field::py);
  refused({{0, 0, 0, 0, 1}, {0, 0, 0, 0, -DBL_MIN}}, 1, spec::Field::r);
  refused({{0, 0, 0, 0, -1}, {0, 0, nan, 0, 1}}, 0, spec::Field::r);
  refused({{0, 0, 0, 0, kInf}}, 0, spec::Field::r);
}

TEST(engine, world_converts_back_to_the_same_bits) {
  const Circles w{{-0.0, 0.0, DBL_MAX, -DBL_MIN, -0.0}, {0x1p-1074, -0x1p-1074, 1.0 / 3, -2.5, 0.0}};
  const World world{w};
  EXPECT_EQ(world.size(), 2u);
  const Circles back = world.circles();
  for (std::size_t k = 0; k < w.size(); ++k)
    for (std::size_t f = 0; f < 5; ++f)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(back[k][f]), std::bit_cast<std::uint64_t>(w[k][f]));
  EXPECT_EQ(World{}.size(), 0u);
  DoubleEngine empty{World{Circles{}}};
  empty.step();
  EXPECT_EQ(empty.world().size(), 0u);
}

}  // namespace
}  // namespace circles::impl
