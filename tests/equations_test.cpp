// Equations (1)-(9), one suite per equation, on hand-computed cases with exact expected values.
// Each expectation is derived in the comment beside it from the seed, not read off the code.
#include "spec/oracle.hpp"
#include "tests/pow2.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace circles::spec {
namespace {

using testing::pow2;

// A circle at rest: (px, py, 0, 0, r).
Circle at(const Q& px, const Q& py, const Q& r) { return circle(px, py, 0, 0, r); }

// ── (3) intersect ───────────────────────────────────────────────────────────────────────────────────────

TEST(intersect, holds_at_exact_tangency_of_a_3_4_5_triangle_at_every_binade) {
  // Centres (0, 0) and (3, 4)·2^k are 5·2^k apart, and r_a + r_b = (2 + 3)·2^k: equality, so ≤ holds.
  for (long k = -1074; k <= 1023; ++k) {
    const Q s = pow2(k);
    ASSERT_TRUE(intersect(at(0, 0, 2 * s), at(3 * s, 4 * s, 3 * s))) << "k = " << k;
  }
}

TEST(intersect, fails_one_ulp_beyond_tangency_and_holds_one_ulp_inside_it) {
  // From tangency at scale 2^k: moving b one ulp away, or shrinking r_b by one ulp, separates the circles;
  // moving b one ulp closer, or growing r_b by one ulp, makes them overlap. 4·2^k stays below DBL_MAX.
  for (int k = -1070; k <= 1021; k += 7) {
    const double bx = std::ldexp(3.0, k), by = std::ldexp(4.0, k);
    const double ra = std::ldexp(2.0, k), rb = std::ldexp(3.0, k);
    const auto c = [](double px, double py, double r) { return at(exact(px), exact(py), exact(r)); };
    const Circle a = c(0, 0, ra);
    ASSERT_TRUE(intersect(a, c(bx, by, rb))) << k;
    EXPECT_FALSE(intersect(a, c(std::nextafter(bx, HUGE_VAL), by, rb))) << k;
    EXPECT_FALSE(intersect(a, c(bx, by, std::nextafter(rb, 0.0)))) << k;
    EXPECT_TRUE(intersect(a, c(std::nextafter(bx, 0.0), by, rb))) << k;
    EXPECT_TRUE(intersect(a, c(bx, by, std::nextafter(rb, HUGE_VAL)))) << k;
  }
}

TEST(intersect, ignores_velocity) {
  // (3) reads p and r only.
  EXPECT_TRUE(intersect(circle(0, 0, 5, -7, 1), circle(2, 0, -60, 1, 1)));
  EXPECT_FALSE(intersect(circle(0, 0, 5, -7, 1), circle(Q(201, 100), 0, -60, 1, 1)));
}

TEST(intersect, holds_for_coincident_circles_of_radius_zero) {
  // |0| ≤ 0 + 0.
  EXPECT_TRUE(intersect(at(7, 7, 0), at(7, 7, 0)));
  EXPECT_FALSE(intersect(at(7, 7, 0), at(7, Q(7) + pow2(-1074), 0)));
}

TEST(intersect, is_false_when_the_radii_sum_is_negative) {
  // Outside C, but (3) still has a meaning: no norm is ≤ a negative number, even though 0² ≤ (−2)².
  EXPECT_FALSE(intersect(at(0, 0, -1), at(0, 0, -1)));
}

// ── (2) i ───────────────────────────────────────────────────────────────────────────────────────────────

TEST(i, excludes_c_itself_though_c_intersects_c) {
  const Circle c = at(0, 0, 1);
  ASSERT_TRUE(intersect(c, c));
  EXPECT_TRUE(i(c, LiteralWorld{c}).empty());
}

TEST(i, is_the_set_of_the_other_circles_that_c_intersects) {
  // b is 2 = 1 + 1 from c (tangent), d is 3 from c (apart), a touches nothing but c is not a.
  const Circle c = at(0, 0, 1), b = at(2, 0, 1), d = at(0, 3, 1);
  EXPECT_EQ(i(c, LiteralWorld{c, b, d}), (LiteralWorld{b}));
}

TEST(i, compares_by_index_in_the_resolved_profile) {
  // Two equal circles are two elements when tagged with their indices, so each sees the other.
  const Circle c = at(0, 0, 1);
  const World<Indexed> W = resolved_world({c, c});
  EXPECT_EQ(i(Indexed{0, c}, W), (World<Indexed>{Indexed{1, c}}));
}

// ── (5) u and Δt ────────────────────────────────────────────────────────────────────────────────────────

TEST(u, moves_by_exactly_one_sixtieth_of_the_velocity) {
  // v = (1, 0): p + Δt v = (1/60, 0), a rational, not the double nearest to it.
  const Circle moved = u(circle(0, 0, 1, 0, 1));
  EXPECT_EQ(moved.p, Vec2(Q(1, 60), Q(0)));
  EXPECT_NE(moved.p.x(), exact(1.0 / 60.0));
  EXPECT_EQ(u(circle(1, 2, 60, -120, 3)), circle(2, 0, 60, -120, 3));
}

TEST(u, keeps_velocity_and_radius) {
  const Circle c = circle(Q(1, 3), Q(-2, 7), Q(5, 11), Q(-13, 17), Q(19, 23));
  EXPECT_EQ(u(c).v, c.v);
  EXPECT_EQ(u(c).r, c.r);
}

TEST(dt, is_one_sixtieth_exactly) { EXPECT_EQ(dt * 60, 1); }

// ── (6) the order on ℝ² ─────────────────────────────────────────────────────────────────────────────────

TEST(leq, compares_both_coordinates) {
  EXPECT_TRUE(leq(Vec2(0, 0), Vec2(0, 1)));
  EXPECT_TRUE(leq(Vec2(0, 0), Vec2(0, 0)));
  EXPECT_FALSE(leq(Vec2(0, 1), Vec2(0, 0)));
}

TEST(leq, leaves_points_across_the_diagonal_incomparable) {
  EXPECT_FALSE(leq(Vec2(0, 1), Vec2(1, 0)));
  EXPECT_FALSE(leq(Vec2(1, 0), Vec2(0, 1)));
}

// ── (7) m ───────────────────────────────────────────────────────────────────────────────────────────────

TEST(m, returns_the_lesser_of_two_comparable_circles_in_either_argument_order) {
  const Circle lo = circle(0, 0, 0, 0, 1), hi = circle(1, 0, 0, 5, 2);
  EXPECT_EQ(m(lo, hi), lo);
  EXPECT_EQ(m(hi, lo), lo);
}

TEST(m, returns_its_second_argument_for_incomparable_circles) {
  // p_a = (0, 1) and p_b = (1, 0) are incomparable, so the first case fails both ways.
  const Circle a = at(0, 1, 1), b = at(1, 0, 1);
  EXPECT_EQ(m(a, b), b);
  EXPECT_EQ(m(b, a), a);
}

TEST(m, compares_radius_last) {
  // Equal p and v: the smaller radius is less.
  EXPECT_EQ(m(at(0, 0, 2), at(0, 0, 1)), at(0, 0, 1));
}

TEST(m, in_the_resolved_profile_is_lexicographic_then_by_index) {
  // px decides first, even against py, v and r; equal circles fall back to the index.
  const Indexed a{5, circle(0, 9, 9, 9, 9)}, b{1, circle(1, 0, 0, 0, 0)};
  EXPECT_EQ(m(a, b), a);
  EXPECT_EQ(m(b, a), a);
  const Indexed twin{0, a.c};
  EXPECT_EQ(m(a, twin), twin);
}

// ── (8) e ───────────────────────────────────────────────────────────────────────────────────────────────

TEST(e, is_the_least_circle_when_there_is_one) {
  const Circle c = at(9, 9, 1), lo = at(0, 0, 1), mid = at(1, 1, 1), hi = circle(2, 1, 3, 0, 1);
  EXPECT_EQ(e(c, LiteralWorld{hi, lo, mid}), lo);
  EXPECT_EQ(e(c, LiteralWorld{hi}), hi);
}

TEST(e, is_undefined_for_two_incomparable_circles) {
  const Circle c = at(0, 0, 1);
  EXPECT_EQ(e(c, LiteralWorld{at(0, 1, 1), at(1, 0, 1)}), std::nullopt);
}

// Incomparability is necessary for an undefined e, not sufficient: a third contact below both is the least.
TEST(e, is_defined_for_incomparable_circles_when_a_third_is_below_both) {
  const Circle a = at(0, 2, 1), b = at(2, 0, 1), d = at(0, 0, 1);
  ASSERT_EQ(m(a, b), b);  // a and b are incomparable: each argument order "wins"
  ASSERT_EQ(m(b, a), a);
  EXPECT_EQ(e(at(1, 1, 2), LiteralWorld{a, b, d}), d);
  EXPECT_EQ(e(at(1, 1, 2), LiteralWorld{a, b}), std::nullopt);
}

TEST(e, is_defined_in_the_resolved_profile_where_the_literal_one_is_not) {
  // (0, 1, …) <lex (1, 0, …): px decides.
  const Indexed c{0, at(0, 0, 1)}, a{1, at(1, 0, 1)}, b{2, at(0, 1, 1)};
  EXPECT_EQ(e(c, World<Indexed>{a, b}), b);
}

TEST(e, does_not_depend_on_c) {
  const LiteralWorld S{at(0, 0, 1), at(1, 1, 1)};
  EXPECT_EQ(e(at(5, 5, 5), S), e(at(-5, 0, 1), S));
}

// ── (9) h ───────────────────────────────────────────────────────────────────────────────────────────────

TEST(h, takes_position_and_radius_from_a_and_velocity_from_b) {
  EXPECT_EQ(h(circle(1, 2, 3, 4, 5), circle(6, 7, 8, 9, 10)), circle(1, 2, 8, 9, 5));
}

// ── (4) f ───────────────────────────────────────────────────────────────────────────────────────────────

TEST(f, moves_a_circle_that_touches_nothing_by_its_own_velocity) {
  const Circle c = circle(0, 0, 60, 0, 1);
  EXPECT_EQ(f(c, LiteralWorld{c, at(10, 0, 1)}), circle(1, 0, 60, 0, 1));
}

TEST(f, moves_a_touching_circle_by_the_velocity_of_the_least_circle_it_touches) {
  // c touches lo (distance 2) and hi (distance 2); lo ≤ hi, so c takes v_lo = (0, 120) and moves by (0, 2).
  const Circle c = circle(0, 0, 60, 0, 1), lo = circle(-2, 0, 0, 120, 1), hi = circle(0, 2, 60, 120, 1);
  EXPECT_EQ(f(c, LiteralWorld{c, lo, hi}), circle(0, 2, 0, 120, 1));
}

TEST(f, is_undefined_when_e_is) {
  const Circle c = at(0, 0, 1);
  EXPECT_EQ(f(c, LiteralWorld{c, at(0, 2, 1), at(2, 0, 1)}), std::nullopt);
}

// ── (1) the step and the sequence D ─────────────────────────────────────────────────────────────────────

TEST(step, reads_the_old_world_for_every_circle) {
  // Newton's cradle of two: a = (0, 0) moving at (60, 0) touches b = (2, 0) at rest. From the old world,
  // a takes v_b = 0 and stays; b takes v_a and moves to (3, 0). Updating in place in index order would
  // let b see the new a, at rest, and b would stay too.
  const Sequence next = resolved_step({circle(0, 0, 60, 0, 1), circle(2, 0, 0, 0, 1)});
  EXPECT_EQ(next, (Sequence{circle(0, 0, 0, 0, 1), circle(3, 0, 60, 0, 1)}));
}

TEST(step, keeps_the_image_of_circle_k_at_index_k_in_the_resolved_profile) {
  // Listed out of lexicographic order on purpose.
  const Sequence w{circle(5, 0, 0, 60, 1), circle(-5, 0, 0, -60, 1), circle(0, 0, 60, 60, 1)};
  EXPECT_EQ(resolved_step(w), (Sequence{circle(5, 1, 0, 60, 1), circle(-5, -1, 0, -60, 1), circle(1, 1, 60, 60, 1)}));
}

TEST(step, reports_every_circle_whose_e_is_undefined) {
  // c at the origin touches a = (0, 2) and b = (2, 0), which are incomparable and do not touch each other.
  const Circle c = at(0, 0, 1), a = at(0, 2, 1), b = at(2, 0, 1);
  const auto next = literal_step(literal_world({c, a, b}));
  ASSERT_TRUE(std::holds_alternative<Undefined<Circle>>(next));
  const auto& at_ = std::get<Undefined<Circle>>(next).at;
  ASSERT_EQ(at_.size(), 1u);
  EXPECT_EQ(at_[0].c, c);
  EXPECT_EQ(at_[0].S, (LiteralWorld{a, b}));
}

TEST(D, holds_w_0_to_w_n) {
  // One circle at v = (1, 0): w_n = {((n/60, 0), (1, 0), 1)}; after 60 steps p = (1, 0) exactly.
  const auto t = D(literal_world({circle(0, 0, 1, 0, 1)}), 60);
  ASSERT_EQ(t.w.size(), 61u);
  EXPECT_FALSE(t.undefined);
  EXPECT_EQ(t.w[0], LiteralWorld{circle(0, 0, 1, 0, 1)});
  EXPECT_EQ(t.w[30], LiteralWorld{circle(Q(1, 2), 0, 1, 0, 1)});
  EXPECT_EQ(t.w[60], LiteralWorld{circle(1, 0, 1, 0, 1)});
}

TEST(D, stops_at_the_first_undefined_step) {
  // Step 0 → 1 is defined (the three circles do not touch); at w_1 the middle circle touches both
  // incomparable neighbours, so w_2 does not exist.
  const Circle c = circle(0, 0, 0, 0, 1), a = circle(0, 3, 0, -60, 1), b = circle(3, 0, -60, 0, 1);
  const auto t = D(literal_world({c, a, b}), 5);
  ASSERT_EQ(t.w.size(), 2u);
  ASSERT_TRUE(t.undefined);
  ASSERT_EQ(t.undefined->at.size(), 1u);
  EXPECT_EQ(t.undefined->at[0].c, c);
}

}  // namespace
}  // namespace circles::spec
