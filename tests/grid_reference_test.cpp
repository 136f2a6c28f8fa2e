// The grid reference (impl/grid_reference.hpp) against step_all_pairs, bit for bit: worlds large enough that the
// grid prunes pairs (and so could miss one), worlds where its proof is at its edge (neighbouring cells, tangency
// across a cell border, the fallback's limits), and overflow reported for the same step, circle and field.
// engine_test.cpp's families (tangency in every binade, ties, duplicates, signed zeros, radius 0, subnormals,
// huge and tiny radii) hold it equal too, in Check::world.
#include "impl/grid_reference.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "formats/random_scene.hpp"
#include "tests/thrown.hpp"

namespace circles::impl {
namespace {

using spec::Circles;
using formats::random_scene;
using circles::testing::thrown;

// step_grid(w) and step_all_pairs(w) give the same bits, or both throw PositionOverflow for the same circle and
// field. Returns the number of circles whose velocity changed, so that a test can show it found contacts.
long same_step(const Circles& w) {
  const World world{w};
  std::optional<Circles> want, got;
  std::optional<PositionOverflow> want_fault, got_fault;
  try {
    want = step_all_pairs(world).circles();
  } catch (const PositionOverflow& e) {
    want_fault = e;
  }
  try {
    got = step_grid(world).circles();
  } catch (const PositionOverflow& e) {
    got_fault = e;
  }
  EXPECT_EQ(want.has_value(), got.has_value());
  if (want_fault && got_fault) {
    EXPECT_EQ(got_fault->index, want_fault->index);
    EXPECT_EQ(got_fault->field, want_fault->field);
    EXPECT_STREQ(got_fault->what(), want_fault->what());
  }
  if (!want || !got) return 0;
  long changed = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    changed += (*want)[k][2] != w[k][2] || (*want)[k][3] != w[k][3];
    for (std::size_t f = 0; f < 5; ++f)
      EXPECT_EQ(std::bit_cast<std::uint64_t>((*got)[k][f]), std::bit_cast<std::uint64_t>((*want)[k][f]))
          << "circle " << k << " field " << f;
  }
  return changed;
}

TEST(grid_reference, equals_all_pairs_on_random_scenes_of_3000_circles_for_five_steps_at_every_coverage) {
  for (const double coverage : {0.01, 0.1, 0.5, 1.0}) {
    Circles w = random_scene(3000, coverage, 7);
    ASSERT_TRUE(grid_side(World{w}).has_value());
    long changed = 0;
    for (int step = 0; step < 5; ++step) {
      changed += same_step(w);
      w = step_all_pairs(World{w}).circles();
    }
    EXPECT_GT(changed, 0) << "coverage " << coverage << ": no contact, so nothing was tested";
  }
}

TEST(grid_reference, equals_all_pairs_when_circles_touch_across_every_cell_border_at_exact_tangency) {
  // Radius 1 everywhere, so h = 4: pairs at distance exactly 2 = r_a + r_b (tangent, intersecting) and one ulp
  // more (disjoint), straddling cell borders x = 4k in x, y and the diagonal; plus a far circle that is alone.
  Circles w;
  for (int k = -3; k <= 3; ++k) {
    const double b = 4.0 * k;
    w.push_back({b - 1, 0, 1, 0, 1});
    w.push_back({b + 1, 0, -1, 0, 1});  // tangent across x = b
    w.push_back({b - 1, 100, 1, 0, 1});
    w.push_back({std::nextafter(b + 1, INFINITY), 100, -1, 0, 1});  // one ulp apart
    w.push_back({0, b - 1, 0, 1, 1});
    w.push_back({0.5, b + 1, 0, -1, 1});  // distance √(4.25) > 2: disjoint
    w.push_back({b - 0.5, b - 0.5 + 300, 2, 2, 1});
    w.push_back({b + 0.5, b + 0.5 + 300, -2, -2, 1});  // √2 apart across a corner: intersecting
  }
  ASSERT_EQ(grid_side(World{w}), 4.0);
  EXPECT_GT(same_step(w), 20);
}

TEST(grid_reference, equals_all_pairs_with_duplicates_signed_zeros_and_radius_zero) {
  Circles w;
  for (int k = 0; k < 50; ++k) {
    w.push_back({0.0, -0.0, 1, 2, 0});
    w.push_back({-0.0, 0.0, 3, 4, 0});
    w.push_back({1.0 * k, 0.0, -1.0 * k, 0, 0.5});
    w.push_back({1.0 * k, 0.0, -1.0 * k, 0, 0.5});  // exact duplicates: ties to the lower index
  }
  EXPECT_GT(same_step(w), 100);
  Circles points;  // every radius 0: h = 1, contacts only between equal centres
  for (int k = 0; k < 200; ++k) points.push_back({k % 7 * 0.25, k % 5 * 0.25, 1.0 * k, 0, 0});
  ASSERT_EQ(grid_side(World{points}), 1.0);
  EXPECT_GT(same_step(points), 100);
}

TEST(grid_reference, falls_back_to_all_pairs_where_its_proof_does_not_hold_and_still_agrees) {
  // 4·r overflows.
  const Circles huge{{0, 0, 1, 0, DBL_MAX / 2}, {DBL_MAX / 2, 0, 2, 0, 1}, {-DBL_MAX, 0, 3, 0, 1}};
  EXPECT_FALSE(grid_side(World{huge}).has_value());
  EXPECT_GT(same_step(huge), 0);
  // A centre more than 2^40 cells out; at exactly 2^40 cells the grid is still used.
  Circles spread{{0, 0, 1, 0, 0.25}, {0.5, 0, 2, 0, 0.25}, {0x1p40, 0, 3, 0, 0.25}};
  EXPECT_EQ(grid_side(World{spread}), 1.0);
  EXPECT_GT(same_step(spread), 0);
  spread[2][0] = std::nextafter(0x1p40, INFINITY);
  EXPECT_FALSE(grid_side(World{spread}).has_value());
  EXPECT_GT(same_step(spread), 0);
  // Tiny radii among ordinary positions: subnormal h.
  const Circles tiny{{1, 1, 1, 0, 0x1p-1074}, {1, 1, 2, 0, 0x1p-1074}, {0, 0, 3, 0, 0}};
  EXPECT_FALSE(grid_side(World{tiny}).has_value());
  EXPECT_GT(same_step(tiny), 0);
  // Subnormal h = 2^-1072 with subnormal centres: tangent pairs within a cell and across a border.
  const double u = 0x1p-1074;
  const Circles subnormal{{0, 0, 1, 0, u}, {2 * u, 0, 2, 0, u}, {4 * u, 0, 3, 0, u}};
  ASSERT_EQ(grid_side(World{subnormal}), 4 * u);
  EXPECT_GT(same_step(subnormal), 0);
}

TEST(grid_reference, reports_the_same_overflow_as_all_pairs_naming_the_first_circle_and_field) {
  const double m = DBL_MAX;
  // On the fallback (centres at DBL_MAX are 2^1021 cells out): circle 1 overflows in py by the velocity it
  // takes from circle 2; circle 3 by its own, in px.
  const Circles taken{{0, 0, 0, 0, 1}, {0, m, 0, 0, 1}, {0, m, 0, m, 1}, {-m, 0, -m, 0, 0}};
  EXPECT_EQ(same_step(taken), 0);
  const auto fault = thrown<PositionOverflow>([&] { step_grid(World{taken}); });
  ASSERT_TRUE(fault);
  EXPECT_EQ(fault->index, 1u);
  EXPECT_EQ(fault->field, spec::Field::py);
  // On the grid's own path (a radius of 2^1000 makes h = 2^1002, so DBL_MAX is 2^22 cells out): 1000 touching
  // circles, and one alone at DBL_MAX that overflows in px by its own velocity.
  Circles w;
  for (int k = 0; k < 1000; ++k) w.push_back({0.5 * k, 1.0 * (k % 3), 1.0 * (k % 5), 0, 1});
  w.push_back({m, 0, m, 0, 0x1p1000});
  ASSERT_TRUE(grid_side(World{w}).has_value());
  const auto own = thrown<PositionOverflow>([&] { step_grid(World{w}); });
  ASSERT_TRUE(own);
  EXPECT_EQ(own->index, 1000u);
  EXPECT_EQ(own->field, spec::Field::px);
  same_step(w);
}

}  // namespace
}  // namespace circles::impl
