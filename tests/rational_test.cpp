// The exact bridges between binary64 and Q: spec::exact and spec::nearest_double.
// Expected values are derived by hand from the definition of binary64, never from the code under test.
#include "spec/oracle.hpp"
#include "spec/rational.hpp"
#include "tests/pow2.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace circles::spec {
namespace {

using testing::pow2;

TEST(exact, gives_the_dyadic_value_of_a_double) {
  // 0.1 is stored as 3602879701896397 / 2^55.
  EXPECT_EQ(exact(0.1), Q(Z(3602879701896397), Z(1) << 55));
  EXPECT_EQ(exact(-0.0), Q(0));
  EXPECT_EQ(exact(std::numeric_limits<double>::denorm_min()), pow2(-1074));
  EXPECT_EQ(exact(DBL_MAX), (pow2(53) - 1) * pow2(971));
}

TEST(exact, rejects_nan_and_infinities) {
  EXPECT_THROW(exact(std::nan("")), std::domain_error);
  EXPECT_THROW(exact(HUGE_VAL), std::domain_error);
  EXPECT_THROW(exact(-HUGE_VAL), std::domain_error);
}

TEST(nearest_double, is_the_ieee_quotient_for_one_sixtieth) {
  // IEEE division is correctly rounded, so 1.0 / 60.0 is RN(1/60).
  EXPECT_EQ(nearest_double(Q(1, 60)), 1.0 / 60.0);
  EXPECT_EQ(nearest_double(Q(-1, 3)), -1.0 / 3.0);
}

TEST(nearest_double, rounds_ties_to_even) {
  const Q two53 = pow2(53);
  EXPECT_EQ(nearest_double(two53 + 1), 9007199254740992.0);  // tie between 2^53 and 2^53+2: even is 2^53
  EXPECT_EQ(nearest_double(two53 + 3), 9007199254740996.0);  // tie between 2^53+2 and 2^53+4: even is +4
  EXPECT_EQ(nearest_double(two53 + 1 + pow2(-60)), 9007199254740994.0);  // just above the tie: up
  EXPECT_EQ(nearest_double(-(two53 + 1)), -9007199254740992.0);
}

TEST(nearest_double, rounds_in_the_subnormal_range_at_two_to_the_minus_1074) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(nearest_double(pow2(-1074)), tiny);
  EXPECT_EQ(nearest_double(pow2(-1075)), 0.0);                // tie between 0 and 2^-1074: even is 0
  EXPECT_EQ(nearest_double(3 * pow2(-1076)), tiny);           // 0.75·2^-1074
  EXPECT_EQ(nearest_double(3 * pow2(-1075)), 2 * tiny);       // tie between 1 and 2 quanta: even is 2
  EXPECT_EQ(nearest_double(pow2(-1022) - pow2(-1075)), DBL_MIN);  // tie at the top of the subnormals: even is DBL_MIN
}

TEST(nearest_double, overflows_to_infinity_exactly_at_the_ieee_threshold) {
  // Beyond DBL_MAX = (2^53 − 1)·2^971 the next "value" would be 2^1024; halfway is 2^1024 − 2^970.
  const Q threshold = pow2(1024) - pow2(970);
  EXPECT_EQ(nearest_double(threshold - pow2(900)), DBL_MAX);
  EXPECT_EQ(nearest_double(threshold), HUGE_VAL);  // a tie, and DBL_MAX's significand is odd
  EXPECT_EQ(nearest_double(-pow2(2000)), -HUGE_VAL);
}

TEST(nearest_double, gives_positive_zero_for_an_exact_zero) {
  EXPECT_FALSE(std::signbit(nearest_double(Q(0))));
}

// So the oracle does write −0: `circles serve --engine oracle` answers [[0, 0, -5e-324, 0, 1]] with px = -0.0.
TEST(nearest_double, gives_minus_0_for_a_negative_value_that_underflows) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(std::signbit(nearest_double(-pow2(-1075))));  // a tie between −0 and −2^-1074: even is −0
  EXPECT_EQ(nearest_double(-pow2(-1075)), 0.0);
  const double px = resolved_step_rounded({{0, 0, -tiny, 0, 1}}).at(0)[0];  // −2^-1074/60, far below half a quantum
  EXPECT_EQ(px, 0.0);
  EXPECT_TRUE(std::signbit(px));
}

}  // namespace
}  // namespace circles::spec
