// One test per note of docs/spec-notes.md: each shows the defect, ambiguity or surprise on its minimal
// exact example world and pins the chosen resolution, so it fails if the documented behaviour changes.
// The note's heading anchor is the test's name.
#include "pictures/render.hpp"
#include "pictures/video.hpp"
#include "impl/predicate.hpp"
#include "spec/oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <type_traits>

namespace circles::spec {
namespace {

Circle at(const Q& px, const Q& py, const Q& r) { return circle(px, py, 0, 0, r); }

const LiteralWorld& defined(const std::variant<LiteralWorld, Undefined<Circle>>& step_result) {
  return std::get<LiteralWorld>(step_result);
}

Vec2 momentum(const Sequence& w) {
  Vec2 total(0, 0);
  for (const Circle& c : w) total += c.v;  // unit masses (Note 1, ii)
  return total;
}

// d-for-m: (8) is written with d, which is defined nowhere; reading it as m makes e the least element.
TEST(spec_notes, d_for_m) {
  const Circle lo = circle(0, 0, -1, 0, 1), hi = circle(1, 0, 0, 0, 1);
  const LiteralWorld S{hi, lo};
  ASSERT_EQ(e(at(5, 5, 1), S), lo);
  for (const Circle& a : S) EXPECT_EQ(m(*e(at(5, 5, 1), S), a), lo);
}

// partial-order-minimum: (6) is a partial order, so (7) is not commutative and (8) may have no answer.
TEST(spec_notes, partial_order_minimum) {
  const Circle c = at(0, 0, 1), a = circle(0, 2, 0, -60, 1), b = circle(2, 0, -60, 0, 1);
  EXPECT_EQ(m(a, b), b);  // not commutative:
  EXPECT_EQ(m(b, a), a);  // each argument order "wins"
  const auto literal = literal_step(literal_world({c, a, b}));
  ASSERT_TRUE(std::holds_alternative<Undefined<Circle>>(literal));
  EXPECT_EQ(std::get<Undefined<Circle>>(literal).at.at(0).c, c);
  // Resolved: a = (0, 2, …) <lex b = (2, 0, …), so c takes v_a = (0, −60) and moves to (0, −1).
  EXPECT_EQ(resolved_step({c, a, b}).at(0), circle(0, -1, 0, -60, 1));
  // Even a Newton's cradle meets it: the middle ball touches the moving one, (0, 0, 60, 0, 1), and the one at
  // rest, (4, 0, 0, 0, 1); positions compare one way and velocities the other.
  const Circle moving = circle(0, 0, 60, 0, 1), middle = at(2, 0, 1), rest = at(4, 0, 1);
  const auto cradle = literal_step(literal_world({moving, middle, rest}));
  ASSERT_TRUE(std::holds_alternative<Undefined<Circle>>(cradle));
  EXPECT_EQ(std::get<Undefined<Circle>>(cradle).at.at(0).c, middle);
  // Resolved: the middle ball takes v of the moving one (px 0 < 4) and the moving one stops.
  EXPECT_EQ(resolved_step({moving, middle, rest}), (Sequence{at(0, 0, 1), circle(3, 0, 60, 0, 1), at(4, 0, 1)}));
}

// sets-merge-circles: the worlds are sets, so two circles whose images are equal become one circle.
TEST(spec_notes, sets_merge_circles) {
  // c1 and c2 share p and r; both touch d, the least circle of each one's S, so both become (0, 0, 0, 0, 1).
  const Circle d = at(-2, 0, 1), c1 = circle(0, 0, 60, 0, 1), c2 = circle(0, 0, 120, 0, 1);
  const LiteralWorld w_1 = defined(literal_step(literal_world({d, c1, c2})));
  EXPECT_EQ(w_1, (LiteralWorld{at(0, 0, 1), circle(-1, 0, 60, 0, 1)}));
  // Resolved: three circles stay three.
  EXPECT_EQ(resolved_step({d, c1, c2}), (Sequence{circle(-1, 0, 60, 0, 1), at(0, 0, 1), at(0, 0, 1)}));
  // And already in w_0: a set holds a duplicate once.
  EXPECT_EQ(literal_world({d, d}).size(), 1u);
}

// value-identity: "x ≠ c" compares values, so a circle never collides with its exact twin.
TEST(spec_notes, value_identity) {
  // Twins t at (0, 0) moving at (60, 0) touch b at rest at (2, 0).
  const Circle t = circle(0, 0, 60, 0, 1), b = at(2, 0, 1);
  // Literal: the twins are one circle; it sees only b, takes v_b = 0 and stays; b takes v_t.
  EXPECT_EQ(defined(literal_step(literal_world({t, t, b}))), (LiteralWorld{at(0, 0, 1), circle(3, 0, 60, 0, 1)}));
  // Resolved: each twin also sees the other, which is less than b, so it keeps (60, 0) and moves on.
  EXPECT_EQ(resolved_step({t, t, b}),
            (Sequence{circle(1, 0, 60, 0, 1), circle(1, 0, 60, 0, 1), circle(3, 0, 60, 0, 1)}));
}

// dt-not-binary: Δt = 1/60 has no binary floating-point form.
TEST(spec_notes, dt_not_binary) {
  EXPECT_NE(exact(1.0 / 60.0), dt);
  // Sixty exact steps at v = 1 reach p = 1; sixty double steps p + v·RN(1/60) do not.
  const auto t = D(literal_world({circle(0, 0, 1, 0, 1)}), 60);
  EXPECT_EQ(t.w.back().begin()->p.x(), 1);
  double p = 0;
  for (int n = 0; n < 60; ++n) p = p + 1.0 * (1.0 / 60.0);
  EXPECT_NE(p, 1.0);
  // The oracle's rounded step rounds once, at the end of each step: RN(0 + 1/60) = RN(1/60).
  EXPECT_EQ(resolved_step_rounded({{0, 0, 1, 0, 1}}).at(0)[0], 1.0 / 60.0);
}

// momentum-not-conserved: with three or more contacts velocities are copied one way.
TEST(spec_notes, momentum_not_conserved) {
  // a ≤ b, so c takes v_a = 0; a and b each see only c and take v_c = (60, 0).
  const Sequence w{at(-2, 0, 1), circle(0, 0, 60, 0, 1), circle(2, 0, 120, 0, 1)};
  const Sequence next = resolved_step(w);
  EXPECT_EQ(next, (Sequence{circle(-1, 0, 60, 0, 1), at(0, 0, 1), circle(3, 0, 60, 0, 1)}));
  EXPECT_EQ(momentum(w), Vec2(180, 0));
  EXPECT_EQ(momentum(next), Vec2(120, 0));
  // The literal profile agrees here: every e is defined and nothing merges.
  EXPECT_EQ(defined(literal_step(literal_world(w))), (LiteralWorld{next.begin(), next.end()}));
}

// stuck-overlap: overlapping circles swap velocities every step and never separate.
TEST(spec_notes, stuck_overlap) {
  // Moving apart at ±60 while overlapping: each takes the other's velocity, so they cross each step.
  const Circle a = circle(0, 0, -60, 0, 1), b = circle(1, 0, 60, 0, 1);
  // As a set the world is a fixed point: the images of a and b are b and a.
  const auto t = D(literal_world({a, b}), 10);
  ASSERT_EQ(t.w.size(), 11u);
  for (const LiteralWorld& w_n : t.w) EXPECT_EQ(w_n, t.w[0]);
  // As a sequence the two circles trade places every step, period 2, always overlapping.
  EXPECT_EQ(resolved_step({a, b}), (Sequence{b, a}));
  EXPECT_EQ(resolved_step(resolved_step({a, b})), (Sequence{a, b}));
  EXPECT_TRUE(intersect(a, b));
}

// glancing-contact: whole velocity vectors are exchanged, not their normal components.
TEST(spec_notes, glancing_contact) {
  // a moves along the common tangent; elastic disks would not interact (both normal components are 0).
  const Sequence next = resolved_step({circle(0, 0, 0, 60, 1), at(2, 0, 1)});
  EXPECT_EQ(next, (Sequence{at(0, 0, 1), circle(2, 1, 0, 60, 1)}));
}

// tunnelling: contacts are sampled at the steps, not swept between them.
TEST(spec_notes, tunnelling) {
  const auto t = D(literal_world({circle(0, 0, 600, 0, 1), at(5, 0, 1)}), 1);
  ASSERT_EQ(t.w.size(), 2u);
  EXPECT_EQ(t.w[1], (LiteralWorld{circle(10, 0, 600, 0, 1), at(5, 0, 1)}));  // passed through b untouched
}

// theorem-4-drops-v: the proof writes a = (p_a, r_a); intersect indeed reads no velocity.
TEST(spec_notes, theorem_4_drops_v) {
  const Circle a = circle(0, 0, 7, 7, 1), b = circle(2, 0, -3, 5, 1);
  EXPECT_TRUE(intersect(a, b));
  EXPECT_TRUE(intersect(circle(0, 0, 0, 0, 1), circle(2, 0, 100, -100, 1)));
  EXPECT_TRUE(intersect(a, a));  // reflexive: |0| ≤ r_a + r_a, where the proof writes r_a + r_b
  EXPECT_EQ(intersect(a, b), intersect(b, a));
}

// r-plus: C takes r ∈ ℝ⁺, the proof of Theorem 4 takes r ≥ 0.
TEST(spec_notes, r_plus) {
  EXPECT_THROW(literal_world({at(0, 0, 0)}), OutsideC);
  EXPECT_EQ(resolved_step({at(0, 0, 0), circle(0, 0, 60, 0, 0)}),
            (Sequence{circle(1, 0, 60, 0, 0), at(0, 0, 0)}));  // coincident points touch and swap
  EXPECT_THROW(resolved_step({at(0, 0, -1)}), OutsideC);
}

// i-returns-a-set: i is typed C × P(C) → C but returns a set of circles.
TEST(spec_notes, i_returns_a_set) {
  static_assert(std::is_same_v<decltype(i(std::declval<Circle>(), std::declval<LiteralWorld>())), LiteralWorld>);
  const Circle c = at(0, 0, 1);
  EXPECT_EQ(i(c, LiteralWorld{c, at(1, 0, 1), at(0, 1, 1)}).size(), 2u);
}

// e-ignores-c: e(c, S) never reads c.
TEST(spec_notes, e_ignores_c) {
  const LiteralWorld S{at(0, 0, 1), at(1, 1, 1)};
  EXPECT_EQ(e(at(100, 100, 1), S), e(at(-100, 0, 7), S));
}

// infinite-worlds: P(C) holds infinite sets, where e may have no value even under a total order.
TEST(spec_notes, infinite_worlds) {
  // c touches every (1/n, 0, 0, 0, 1); among the first N of them the least is the N-th, below all before it, so
  // in the infinite set every contact has one below it and none is least.
  const Circle c = at(0, 0, 2);
  LiteralWorld W{c};
  for (int n = 1; n <= 20; ++n) {
    const Circle next = at(Q(1, n), 0, 1);
    W.insert(next);
    const LiteralWorld S = i(c, W);
    EXPECT_EQ(S.size(), static_cast<std::size_t>(n));
    ASSERT_EQ(e(c, S), next) << "the least of the first " << n << " contacts";
    // The resolved profile's total order has the same least element: a total order does not help.
    EXPECT_EQ(lex_compare(next, at(Q(1, n + 1), 0, 1)), 1);
  }
}

// render-function: the seed names r: P(C) → M_1280×720 and says nothing more; these are the project's choices.
TEST(spec_notes, render_function) {
  EXPECT_EQ(pictures::kFrameWidth, 1280);
  EXPECT_EQ(pictures::kFrameHeight, 720);
  pictures::Frame frame;
  frame.draw({{300.5, 100.5, 0, 0, 3}}, pictures::View::pixels());
  EXPECT_EQ(frame.pixel(300, 100), pictures::fill_colour(0));  // one unit a pixel, from the top-left corner
  EXPECT_EQ(frame.pixel(300, 719 - 100), pictures::kBackground);  // y points down: not the mirrored row
  EXPECT_EQ(Q(pictures::kVideoFrameRate) * dt, 1);               // a world every Δt: the seed's own pace
}

// overflow: the seed is over ℝ; doubles end at DBL_MAX.
TEST(spec_notes, overflow) {
  constexpr double M = std::numeric_limits<double>::max();
  // The exact next position 61M/60 is a rational above the largest double, so it rounds to +∞.
  const Sequence next = resolved_step({circle(exact(M), 0, exact(M), 0, 1)});
  EXPECT_EQ(next.at(0).p.x(), exact(M) * 61 / 60);
  EXPECT_GT(next.at(0).p.x(), exact(M));
  EXPECT_TRUE(std::isinf(resolved_step_rounded({{M, 0, M, 0, 1}}).at(0)[0]));
  // (3) near the top of the range: M − (−M) overflows in doubles, yet the circles touch exactly, and one ulp
  // less radius parts them; the oracle and the double engine's predicate both decide it exactly.
  EXPECT_TRUE(std::isinf(M - (-M)));
  EXPECT_TRUE(intersect(circle(-exact(M), 0, 0, 0, exact(M)), circle(exact(M), 0, 0, 0, exact(M))));
  EXPECT_TRUE(impl::intersect_exact(-M, 0, M, M, 0, M));
  const double below = std::nextafter(M, 0.0);
  EXPECT_FALSE(intersect(circle(-exact(M), 0, 0, 0, exact(M)), circle(exact(M), 0, 0, 0, exact(below))));
  EXPECT_FALSE(impl::intersect_exact(-M, 0, M, M, 0, below));
}

// e-second-case: (8)'s second case, "we already proved S ≠ ∅", defines nothing; e is partial and f never asks it.
TEST(spec_notes, e_second_case) {
  const Circle c = circle(0, 0, 60, 0, 1);
  EXPECT_EQ(e(c, LiteralWorld{}), std::nullopt);
  EXPECT_EQ(e(Indexed{0, c}, World<Indexed>{}), std::nullopt);
  EXPECT_TRUE(i(c, LiteralWorld{c}).empty());
  EXPECT_EQ(f(c, LiteralWorld{c}), circle(1, 0, 60, 0, 1));  // u(c): the second case of (4)
}

// reflexive-needs-x-ne-c: every circle intersects itself, so without "x ≠ c" c would be its own contact.
TEST(spec_notes, reflexive_needs_x_ne_c) {
  const Circle c = circle(0, 0, 60, 0, 1), b = at(2, 0, 1);
  const World<Indexed> W = resolved_world({c, b});
  const Indexed& ci = *W.begin();
  ASSERT_EQ(ci.c, c);
  EXPECT_TRUE(intersect(ci, ci));
  World<Indexed> S = i(ci, W);
  EXPECT_EQ(S, (World<Indexed>{Indexed{1, b}}));
  EXPECT_EQ(resolved_step({c, b}).at(0), at(0, 0, 1));  // with x ≠ c: c takes v_b = 0 and stays
  // Without it, c joins its own S, is the least there, and would keep (60, 0) and move into b.
  S.insert(ci);
  EXPECT_EQ(e(ci, S), ci);
  EXPECT_EQ(u(h(ci, *e(ci, S))).c, circle(1, 0, 60, 0, 1));
}

// containment-intersects: (3) tests the disks, so a circle inside another intersects it.
TEST(spec_notes, containment_intersects) {
  const Circle a = at(0, 0, 10), b = circle(1, 0, 60, 0, 1);
  const Q distance = b.p.x() - a.p.x();
  EXPECT_LT(distance + b.r, a.r);  // b lies inside a: the boundaries share no point
  EXPECT_TRUE(intersect(a, b));
  EXPECT_EQ(resolved_step({a, b}), (Sequence{circle(1, 0, 60, 0, 10), at(1, 0, 1)}));
}

// not-invariant-under-reflection: the mirror image (here also the rotation by 180°) of a world need not step to
// the mirror image of its next world.
TEST(spec_notes, not_invariant_under_reflection) {
  const Sequence cradle{circle(0, 0, 60, 0, 1), at(2, 0, 1), at(4, 0, 1)};
  const auto mirrored = [](const Sequence& w) {  // x → 4 − x, v_x → −v_x
    Sequence out;
    for (const Circle& c : w) out.push_back(circle(4 - c.p.x(), c.p.y(), -c.v.x(), c.v.y(), c.r));
    return out;
  };
  const Sequence mirror = mirrored(cradle);
  ASSERT_EQ(mirror, (Sequence{circle(4, 0, -60, 0, 1), at(2, 0, 1), at(0, 0, 1)}));
  EXPECT_EQ(resolved_step(cradle), (Sequence{at(0, 0, 1), circle(3, 0, 60, 0, 1), at(4, 0, 1)}));
  const Sequence stopped = resolved_step(mirror);
  EXPECT_EQ(stopped, (Sequence{at(4, 0, 1), at(2, 0, 1), at(0, 0, 1)}));  // stops dead
  EXPECT_NE(stopped, mirrored(resolved_step(cradle)));
  EXPECT_EQ(momentum(mirror), Vec2(-60, 0));
  EXPECT_EQ(momentum(stopped), Vec2(0, 0));
  EXPECT_EQ(momentum(resolved_step(cradle)), Vec2(60, 0));
  // The rotation by 180° about (2, 0), (x, y) → (4 − x, −y), v → −v, gives the same world here.
  for (std::size_t k = 0; k < cradle.size(); ++k)
    EXPECT_EQ(mirror[k], circle(4 - cradle[k].p.x(), -cradle[k].p.y(), -cradle[k].v.x(), -cradle[k].v.y(), 1));
  EXPECT_TRUE(std::holds_alternative<Undefined<Circle>>(literal_step(literal_world(mirror))));
}

// u-adds-dt-v: the prose of (5) says "adding the velocity"; (5) adds Δt·v.
TEST(spec_notes, u_adds_dt_v) {
  const Circle c = circle(0, 0, 60, 0, 1);
  EXPECT_EQ(u(c), circle(1, 0, 60, 0, 1));
  EXPECT_NE(u(c).p, c.p + c.v);
}

// d-is-a-sequence: D = {w_n} is written as a set, but worlds recur and their order matters.
TEST(spec_notes, d_is_a_sequence) {
  const auto t = D(literal_world({at(0, 0, 1)}), 5);
  ASSERT_EQ(t.w.size(), 6u);  // w_0 … w_5, in order
  for (const LiteralWorld& w_n : t.w) EXPECT_EQ(w_n, t.w[0]);  // so the set {w_n} has one element
  // The stuck pair: as a sequence of worlds it alternates; as a set it is {w_0, w_1}, in no order.
  const Sequence pair{circle(0, 0, -60, 0, 1), circle(1, 0, 60, 0, 1)};
  EXPECT_NE(resolved_step(pair), pair);
  EXPECT_EQ(resolved_step(resolved_step(pair)), pair);
}

}  // namespace
}  // namespace circles::spec
