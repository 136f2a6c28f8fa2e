// The exact grid reference (impl/exact_grid_reference.hpp) against the oracle's exact sequence
// (spec::resolved_step), as rationals and rounded, at every step: random scenes large enough that the grid
// prunes pairs (and so could miss one), exact tangencies at rational coordinates whose nearest doubles round
// across a cell border, every boundary family of the property suite (properties/boundaries.hpp), circles on
// the cells' borders, a pair whose squares underflow against the exact sign, a huge radius, one cell for
// all, the empty world and one circle, and overflow reported for the same step, circle and field.
#include "impl/exact_grid_reference.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "impl/grid_reference.hpp"
#include "formats/random_scene.hpp"
#include "properties/boundaries.hpp"
#include "spec/oracle.hpp"
#include "tests/exact_worlds.hpp"
#include "tests/thrown.hpp"

namespace circles::impl {
namespace {

using spec::Circles;
using formats::random_scene;
using circles::testing::thrown;
using spec::Q;
using circles::testing::exact_of;
using circles::testing::nearest;


// What a run of the reference did: the worlds it stepped on the grid (not the all-pairs fallback), and the
// circle-steps that took a contact's velocity (so a test can show it met contacts).
struct Followed {
  long gridded = 0, contacts = 0;
};

// Runs ExactGrid and the oracle side by side from w for `steps` steps, or to the first step whose position
// rounds to ±infinity, which the reference must report for the oracle's first such circle and field, keeping
// its state. At every step the exact states are equal as rationals and rounded() is their nearest doubles,
// bit for bit.
Followed follow(const spec::Sequence& w0, int steps) {
  Followed f;
  ExactGrid grid(w0);
  spec::Sequence w = w0;
  EXPECT_EQ(grid.exact(), w);
  for (int t = 1; t <= steps; ++t) {
    f.gridded += exact_grid_side(grid.rounded()).has_value();
    const spec::Sequence next = spec::resolved_step(w);
    std::optional<std::pair<std::size_t, spec::Field>> overflow;
    for (std::size_t k = 0; k < next.size() && !overflow; ++k)
      if (std::isinf(spec::nearest_double(next[k].p.x())))
        overflow = {k, spec::Field::px};
      else if (std::isinf(spec::nearest_double(next[k].p.y())))
        overflow = {k, spec::Field::py};
    if (overflow) {
      const auto fault = thrown<PositionOverflow>([&] { grid.step(); });
      EXPECT_TRUE(fault) << "step " << t << ": no PositionOverflow";
      if (fault) {
        EXPECT_EQ(fault->step, static_cast<std::uint64_t>(t));
        EXPECT_EQ(fault->index, overflow->first);
        EXPECT_EQ(fault->field, overflow->second);
      }
      EXPECT_EQ(grid.exact(), w);
      EXPECT_EQ(grid.steps(), static_cast<std::uint64_t>(t - 1));
      return f;
    }
    grid.step();
    for (std::size_t k = 0; k < w.size(); ++k) f.contacts += next[k].v != w[k].v;
    w = next;
    EXPECT_EQ(grid.exact(), w) << "step " << t;
    const Circles want = nearest(w), got = grid.rounded();
    EXPECT_EQ(got.size(), want.size());
    for (std::size_t k = 0; k < got.size() && k < want.size(); ++k)
      for (std::size_t field = 0; field < 5; ++field)
        EXPECT_EQ(std::bit_cast<std::uint64_t>(got[k][field]), std::bit_cast<std::uint64_t>(want[k][field]))
            << "step " << t << ", circle " << k << ", field " << field;
  }
  return f;
}

TEST(exact_grid_reference, follows_the_oracle_on_random_scenes_of_250_circles_for_three_steps_at_every_coverage) {
  for (const double coverage : {0.05, 0.3, 1.0}) {
    const Followed f = follow(exact_of(random_scene(250, coverage, 11)), 3);
    EXPECT_EQ(f.gridded, 3) << "coverage " << coverage;
    EXPECT_GT(f.contacts, 0) << "coverage " << coverage << ": no contact, so nothing was tested";
  }
}

// Circles a and b of radius 1 (so h = 4, cell borders at multiples of 4), exactly tangent at rational,
// non-dyadic coordinates: the centre of a is (x, y) and b's is a + 2·(3/5, 4/5) (distance 2 = r_a + r_b), plus
// a copy of the pair with b moved out by 10^-40 along the x axis (apart by far less than an ulp).
void tangent_pair(spec::Sequence& w, const Q& x, const Q& y, bool lower_first) {
  const spec::Circle a = spec::circle(x, y, 1, 0, 1);
  const spec::Circle b = spec::circle(x + Q(6, 5), y + Q(8, 5), -1, 0, 1);
  const spec::Circle apart = spec::circle(x + Q(6, 5) + Q(1) / Q(pow(spec::Z(10), 40)), y + Q(8, 5) + 1000, -1, 0, 1);
  const spec::Circle apart_a = spec::circle(x, y + 1000, 1, 0, 1);
  // lower_first: the lower index is the circle in the lower row, else the one in the upper row.
  if (lower_first) {
    w.insert(w.end(), {a, b, apart_a, apart});
  } else {
    w.insert(w.end(), {b, a, apart, apart_a});
  }
}

// ⌊x/4⌋ of an exact x: its cell for h = 4.
double cell(const Q& x) {
  const Q q = x / 4;
  spec::Z n = boost::multiprecision::numerator(q), d = boost::multiprecision::denominator(q), f = n / d;
  if (f * d > n) f -= 1;  // division truncates towards 0
  return f.convert_to<double>();
}

TEST(exact_grid_reference, follows_the_oracle_at_rational_tangency_where_nearest_doubles_cross_a_cell_border) {
  spec::Sequence w;
  const Q tiny = Q(1) / Q(3 * pow(spec::Z(2), 60));  // far below half an ulp of any centre here
  for (int k = -3; k <= 3; ++k) {
    const Q border(4 * k);
    // Exactly tangent pairs on both sides of a column border x = 4k and of a row border y = 4k + 2000, the
    // centre just below the border by a third of 2^-60: its nearest double is the border, in the next cell.
    tangent_pair(w, border - tiny, Q(1, 7), k % 2 == 0);
    tangent_pair(w, Q(1, 3) + 4000, border + 2000 - Q(8, 5) - tiny, k % 2 == 0);
    tangent_pair(w, Q(1, 3) + 8000, border + 2000 - Q(8, 5) - tiny, k % 2 != 0);
    // A centre just above a border by the same amount: it rounds down onto the border, the same cell.
    tangent_pair(w, border + tiny - Q(6, 5), Q(2, 7) + 3000, k % 2 != 0);
  }
  const Circles rounded = nearest(w);
  ASSERT_EQ(exact_grid_side(rounded), 4.0);
  int across = 0;  // centres whose nearest double lies in another cell than the exact centre
  for (std::size_t k = 0; k < w.size(); ++k)
    across += cell(w[k].p.x()) != std::floor(rounded[k][0] / 4) || cell(w[k].p.y()) != std::floor(rounded[k][1] / 4);
  EXPECT_GE(across, 3 * 7);
  const Followed f = follow(w, 2);
  EXPECT_EQ(f.gridded, 2);
  EXPECT_GE(f.contacts, 4 * 7 * 2);  // every tangent pair met
}

TEST(exact_grid_reference, finds_every_tangent_pair_across_a_row_border_whichever_index_is_lower) {
  // The pairs of the test above with only row borders, one row above the other: a grid that walked fewer
  // than three rows would miss one of each orientation.
  for (const bool lower_first : {true, false}) {
    spec::Sequence w;
    for (int k = 0; k < 20; ++k) tangent_pair(w, Q(1, 3) + 10 * k, Q(4 * k) - Q(4, 5), lower_first);
    const ExactGrid before(w);
    ExactGrid grid(w);
    grid.step();
    EXPECT_EQ(grid.exact(), spec::resolved_step(w)) << (lower_first ? "lower index below" : "lower index above");
    for (std::size_t k = 0; k < w.size(); k += 4)
      EXPECT_NE(grid.exact()[k].v, before.exact()[k].v) << "circle " << k << " missed its tangent partner";
  }
}

TEST(exact_grid_reference, follows_the_oracle_on_every_boundary_family_of_the_property_suite) {
  for (const properties::Family family : properties::families(properties::Profile::resolved)) {
    rc::Random random(0x15e);
    long gridded = 0, contacts = 0;
    // A big family's world holds up to 512 circles here, which the oracle steps in rationals: fewer of them.
    const int worlds = properties::is_big(family) ? 4 : 40;
    for (int k = 0; k < worlds; ++k) {
      const Circles w = properties::gen::boundary_world(family, properties::Profile::resolved)(random.split(), k)
                            .value();
      const Followed f = follow(exact_of(w), static_cast<int>(properties::steps_to_decide(family)) + 1);
      gridded += f.gridded;
      contacts += f.contacts;
    }
    std::printf("[ %s ] %d worlds, %ld steps on the grid, %ld circle-steps with a contact\n",
                properties::name(family), worlds, gridded, contacts);
  }
}

TEST(exact_grid_reference, follows_the_oracle_with_circles_on_and_across_every_cell_border) {
  // Radius 1 (h = 4): centres on the borders x = 4k, pairs tangent across them in x, y and the diagonal, and
  // one ulp apart.
  Circles w;
  for (int k = -3; k <= 3; ++k) {
    const double b = 4.0 * k;
    w.push_back({b, 0, 1, 0, 1});
    w.push_back({b + 2, 0, -1, 0, 1});  // tangent, from a border into the middle of a cell
    w.push_back({b - 1, 100, 1, 0, 1});
    w.push_back({std::nextafter(b + 1, INFINITY), 100, -1, 0, 1});  // one ulp apart across x = b
    w.push_back({0, b - 1, 0, 1, 1});
    w.push_back({0, b + 1, 0, -1, 1});  // tangent across y = b
    w.push_back({b - 0.5, b - 0.5 + 300, 2, 2, 1});
    w.push_back({b + 0.5, b + 0.5 + 300, -2, -2, 1});  // across a corner
  }
  ASSERT_EQ(exact_grid_side(w), 4.0);
  const Followed f = follow(exact_of(w), 3);
  EXPECT_EQ(f.gridded, 3);
  EXPECT_GT(f.contacts, 20);
}

TEST(exact_grid_reference, follows_the_oracle_with_a_huge_radius_and_falls_back_where_the_proof_does_not_hold) {
  // One radius of 2^1000: h = 2^1002, every centre in the cells around 0.
  Circles huge;
  for (int k = 0; k < 60; ++k) huge.push_back({0.5 * k, 1.0 * (k % 3), 1.0 * (k % 5), 0, 1});
  huge.push_back({0x1p1001, 0, -1, 0, 0x1p1000});
  ASSERT_EQ(exact_grid_side(huge), 0x1p1002);
  EXPECT_EQ(follow(exact_of(huge), 2).gridded, 2);
  // 4·r overflows: every pair is asked.
  const Circles overflowing{{0, 0, 1, 0, DBL_MAX / 2}, {DBL_MAX / 2, 0, 2, 0, 1}, {-DBL_MAX / 4, 0, 3, 0, 1}};
  EXPECT_FALSE(exact_grid_side(overflowing).has_value());
  EXPECT_GT(follow(exact_of(overflowing), 2).contacts, 0);
  // h = 4·2^-1010 < kExactGridMinSide, where the nearest doubles' absolute error is not small against h.
  const Circles tiny{{0, 0, 1, 0, 0x1p-1010}, {0x1p-1009, 0, 2, 0, 0x1p-1010}, {0, 0x1p-1000, 3, 0, 0}};
  EXPECT_FALSE(exact_grid_side(tiny).has_value());
  EXPECT_GT(follow(exact_of(tiny), 2).contacts, 0);
  // At the least side the grid takes, it is used.
  const Circles least{{0, 0, 1, 0, 0x1p-1002}, {0x1p-1001, 0, 2, 0, 0x1p-1002}};
  EXPECT_EQ(exact_grid_side(least), kExactGridMinSide);
  EXPECT_GT(follow(exact_of(least), 2).contacts, 0);
}

TEST(exact_grid_reference, meets_a_pair_whose_squares_underflow_and_round_against_the_exact_sign) {
  const Circles w = circles::testing::underflowing_intersecting_pair();
  ASSERT_TRUE(exact_grid_side(w).has_value());
  const Followed f = follow(exact_of(w), 2);
  EXPECT_EQ(f.gridded, 2);
  EXPECT_GT(f.contacts, 0);
}

TEST(exact_grid_reference, follows_the_oracle_when_every_circle_is_in_one_cell) {
  Circles w;  // radius 1, so h = 4: every centre in [0, 4)², the cell (0, 0)
  for (int k = 0; k < 150; ++k)
    w.push_back({(k % 13) * 0.3, (k % 11) * 0.35, (k % 7) - 3.0, (k % 5) - 2.0, k % 4 == 0 ? 1.0 : 0.25 * (k % 4)});
  ASSERT_EQ(exact_grid_side(w), 4.0);
  for (const auto& c : w) ASSERT_TRUE(std::floor(c[0] / 4) == 0 && std::floor(c[1] / 4) == 0);
  const Followed f = follow(exact_of(w), 2);
  EXPECT_EQ(f.gridded, 2);
  EXPECT_GT(f.contacts, 100);
}

TEST(exact_grid_reference, steps_the_empty_world_and_one_circle) {
  EXPECT_EQ(follow({}, 3).contacts, 0);
  ExactGrid empty(spec::Sequence{});
  empty.step();
  EXPECT_EQ(empty.steps(), 1u);
  EXPECT_TRUE(empty.rounded().empty());
  const spec::Sequence one{spec::circle(Q(1, 3), -2, 6, -Q(7, 2), Q(1, 5))};
  EXPECT_EQ(follow(one, 3).contacts, 0);
  EXPECT_EQ(step_grid(one), (spec::Sequence{spec::circle(Q(1, 3) + Q(1, 10), -2 - Q(7, 120), 6, -Q(7, 2), Q(1, 5))}));
}

TEST(exact_grid_reference, reports_the_oracles_first_overflow_and_keeps_its_state) {
  const double m = DBL_MAX;
  // Circle 1 overflows in py by the velocity it takes from circle 2; circle 3 in px by its own.
  const Circles taken{{0, 0, 0, 0, 1}, {0, m, 0, 0, 1}, {0, m, 0, m, 1}, {-m, 0, -m, 0, 0}};
  follow(exact_of(taken), 1);
  ExactGrid grid(taken);
  const auto fault = thrown<PositionOverflow>([&] { grid.step(); });
  ASSERT_TRUE(fault);
  EXPECT_EQ(fault->index, 1u);
  EXPECT_EQ(fault->field, spec::Field::py);
  EXPECT_STREQ(fault->what(), "step 1, circle 1, field py: the position p + v/60 overflows to infinity");
}

TEST(exact_grid_reference, refuses_a_negative_radius_and_a_value_beyond_the_double_range) {
  const auto negative = thrown<spec::OutsideC>([] { ExactGrid{Circles{{0, 0, 0, 0, 1}, {0, 0, 0, 0, -1}}}; });
  ASSERT_TRUE(negative);
  EXPECT_EQ(negative->index, 1u);
  EXPECT_EQ(negative->field, spec::Field::r);
  const Q beyond = spec::exact(DBL_MAX) * 2;
  const auto far = thrown<spec::OutsideC>([&] { ExactGrid{spec::Sequence{spec::circle(0, beyond, 0, 0, 1)}}; });
  ASSERT_TRUE(far);
  EXPECT_EQ(far->index, 0u);
  EXPECT_EQ(far->field, spec::Field::py);
}

TEST(exact_round_quotient, takes_the_fixed_width_division_below_2_to_the_126_and_agrees_with_the_rationals) {
  // Numerators and denominators on both sides of the limits of the fixed-width path (|n| < 2^126,
  // d < 2^127), with halfway cases: each must equal RN of the exact quotient.
  using exact::Wide;
  const Wide one = 1;
  for (const int nb : {60, 125, 126, 127, 200})
    for (const int db : {1, 64, 126, 127, 128, 190})
      for (const Wide& n : {Wide((one << nb) - 1), Wide(-(one << nb) + 3), Wide((one << nb) / 3),
                            Wide((one << (nb - 1)) + (one << (nb - 55)))})
        for (const Wide& d : {Wide((one << db) - 1), Wide((one << db) / 7 + 1), Wide(60) << (db > 6 ? db - 6 : 0)}) {
          const double want = spec::nearest_double(Q(n) / Q(d));
          EXPECT_EQ(exact::round_quotient(n, d), want) << "n = " << n << ", d = " << d;
        }
}

}  // namespace
}  // namespace circles::impl
