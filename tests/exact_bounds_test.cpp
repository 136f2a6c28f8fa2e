// impl/exact_bounds.hpp: each claim recomputed in exact rationals, on inputs where it is tightest (the ones
// that find each constant's edge) and on a fixed-seed stream of doubles over every binade, subnormals and
// zeros included.
#include "impl/exact_bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "spec/rational.hpp"
#include "tests/pow2.hpp"

namespace circles::impl::exact {
namespace {

using circles::testing::pow2;
using spec::exact;
using spec::Q;

const Q kU = pow2(-53);    // the unit roundoff
const Q kEta = pow2(-1075);  // half the least subnormal

// Non-negative doubles: zeros, the least subnormals, the subnormal-normal boundary, 1, large values, then
// random bit patterns and random binades (fixed seed).
std::vector<double> inputs() {
  std::vector<double> x{0.0,    0x1p-1074, 0x3p-1074, 0x1p-1030, 0x1p-1023,      0x1p-1022,
                        1.0,    0x1p-60,   3.0,       0x1p500,   0x1.fffffffffffffp1000};
  std::mt19937_64 random(20261203);
  std::uniform_int_distribution<int> binade(-1074, 1000);
  for (int k = 0; k < 400; ++k) {
    x.push_back(std::ldexp(std::uniform_real_distribution<double>(1, 2)(random), binade(random)));
    x.push_back(static_cast<double>(random() >> 12) * 0x1p-1074);  // subnormal or just above
  }
  return x;
}

TEST(exact_bounds, the_centre_bound_is_at_least_twice_each_term_of_an_approximations_error) {
  for (const double m : inputs()) {
    const Q c = exact(centre_bound(m));
    EXPECT_GE(c, 2 * pow2(-50) * exact(m)) << m;
    EXPECT_GE(c, 4 * kEta) << m;
  }
  // The edges: at m = 1 the relative term alone, at m = 0 the absolute one.
  EXPECT_EQ(exact(centre_bound(1)), pow2(-49));
  EXPECT_EQ(exact(centre_bound(0)), pow2(-1073));
}

TEST(exact_bounds, the_radius_bound_is_at_least_twice_each_term_of_a_rounded_radius_error) {
  for (const double rho : inputs()) {
    const Q b = exact(radius_bound(rho));
    EXPECT_GE(b, 2 * kU * exact(rho)) << rho;
    EXPECT_GE(b, 2 * kEta) << rho;
  }
  EXPECT_EQ(exact(radius_bound(1)), pow2(-52));
  EXPECT_EQ(exact(radius_bound(0)), pow2(-1074));
}

TEST(exact_bounds, the_step_bound_covers_a_centre_error_and_a_radius_error_together) {
  for (const double m : inputs())
    for (const double rho : {0.0, 0x1p-1074, 0x1p-1022, 1.0, m, 2 * m}) {
      const Q centre = pow2(-50) * exact(m) + kEta, radius = kU * exact(rho) + kEta;
      EXPECT_GE(exact(error_bound(m, radius_bound(rho))), centre + radius) << m << " " << rho;
      EXPECT_GE(exact(error_bound(m, 0)), centre) << m;  // every radius a double: no radius error
    }
}

// The claim of walked(): E + 2^-50·W + η + u·A, a step of the walk's worst error.
Q walk_step(double e, double w, double a) { return exact(e) + pow2(-50) * exact(w) + kEta + kU * exact(a); }

TEST(exact_bounds, a_walked_bound_covers_one_step_of_the_walk) {
  const std::vector<double> x = inputs();
  std::mt19937_64 random(3);
  std::uniform_int_distribution<std::size_t> pick(0, x.size() - 1);
  for (int k = 0; k < 20000; ++k) {
    const double e = x[pick(random)], w = x[pick(random)], a = x[pick(random)];
    ASSERT_GE(exact(walked(e, w, a)), walk_step(e, w, a)) << e << " " << w << " " << a;
  }
}

TEST(exact_bounds, a_walked_bound_is_at_each_terms_edge_where_that_term_is_alone) {
  // W = 1 alone: walked is the double after 2^-49, so a move term of 2^-51 (the double after it, below
  // 2^-50) would fail the claim; A = 1 alone: the double after 2^-52, and 2^-54 would fail.
  EXPECT_EQ(walked(0, 1, 0), std::nextafter(0x1p-49, 1.0));
  EXPECT_LT(exact(std::nextafter(0x1p-51, 1.0)), walk_step(0, 1, 0));
  EXPECT_EQ(walked(0, 0, 1), std::nextafter(0x1p-52, 1.0));
  EXPECT_LT(exact(std::nextafter(0x1p-54, 1.0)), walk_step(0, 0, 1));
  // E = 1, W = 2^-60: 1 + 2^-59 rounds to 1, so without the step to the next double the bound would not grow.
  EXPECT_EQ(walked(1, 0x1p-60, 0), std::nextafter(1.0, 2.0));
  EXPECT_GE(exact(walked(1, 0x1p-60, 0)), walk_step(1, 0x1p-60, 0));
  EXPECT_LT(Q(1), walk_step(1, 0x1p-60, 0));
}

}  // namespace
}  // namespace circles::impl::exact
