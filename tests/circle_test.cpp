// Inputs outside C are rejected with spec::OutsideC, naming the circle and the field; the messages are exact.
#include "spec/oracle.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace circles::spec {
namespace {

using circles::testing::thrown;

TEST(from_doubles, names_the_circle_and_field_of_a_nan) {
  const auto e = thrown<OutsideC>([] { from_doubles({1, 2, 3, std::nan(""), 5}, 7, Radii::non_negative); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->index, 7u);
  EXPECT_EQ(e->field, Field::vy);
  EXPECT_STREQ(e->what(), "circle 7, field vy: NaN (not an element of C)");
}

TEST(from_doubles, names_the_sign_of_an_infinity) {
  EXPECT_STREQ(thrown<OutsideC>([] { from_doubles({-HUGE_VAL, 0, 0, 0, 1}, 0, Radii::positive); }).value().what(),
               "circle 0, field px: -infinity (not an element of C)");
  EXPECT_STREQ(thrown<OutsideC>([] { from_doubles({0, 0, 0, 0, HUGE_VAL}, 2, Radii::positive); }).value().what(),
               "circle 2, field r: +infinity (not an element of C)");
}

TEST(from_doubles, takes_radius_zero_only_in_the_resolved_profile) {
  EXPECT_EQ(from_doubles({0, 0, 0, 0, 0}, 0, Radii::non_negative).r, 0);
  EXPECT_STREQ(thrown<OutsideC>([] { from_doubles({0, 0, 0, 0, -0.0}, 3, Radii::positive); }).value().what(),
               "circle 3, field r: radius -0 is not in R+ (r > 0, the literal profile) (not an element of C)");
}

TEST(from_doubles, rejects_a_negative_radius_in_both_profiles) {
  EXPECT_STREQ(thrown<OutsideC>([] { from_doubles({0, 0, 0, 0, -0.5}, 1, Radii::non_negative); }).value().what(),
               "circle 1, field r: radius -0.5 is negative (r >= 0, the resolved profile) (not an element of C)");
}

TEST(resolved_step, names_the_index_of_a_circle_with_negative_radius) {
  const auto e = thrown<OutsideC>([] { resolved_step({circle(0, 0, 0, 0, 1), circle(0, 0, 0, 0, -1)}); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->index, 1u);
  EXPECT_EQ(e->field, Field::r);
}

TEST(resolved_step_rounded, rejects_non_finite_input_by_circle_and_field) {
  const auto e = thrown<OutsideC>([] { resolved_step_rounded({{0, 0, 0, 0, 1}, {0, 0, HUGE_VAL, 0, 1}}); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->index, 1u);
  EXPECT_EQ(e->field, Field::vx);
}

TEST(resolved_step_rounded, rounds_each_coordinate_of_the_exact_step_to_nearest) {
  // p = 1, v = 100: exactly 1 + 100/60 = 8/3, whose nearest double is IEEE's 8.0 / 3.0 (division is correctly
  // rounded). Both naive double formulas round twice and land one ulp above it.
  const auto next = resolved_step_rounded({{1, -0.0, 100, 0, 1}});
  EXPECT_EQ(next.at(0)[0], 8.0 / 3.0);
  EXPECT_NE(next.at(0)[0], 1.0 + 100.0 * (1.0 / 60.0));
  EXPECT_NE(next.at(0)[0], 1.0 + 100.0 / 60.0);
  EXPECT_EQ(next.at(0)[1], 0.0);
}

}  // namespace
}  // namespace circles::spec
