// The pair list's bounds (impl/pair_list.hpp, their constants in impl/double_bounds.hpp), each recomputed
// exactly and each put at its edge: a world in which a pair meets exactly when the list's horizon ends, so
// that a bound any lower lets the pair escape the list and the engine misses the contact that step_all_pairs
// finds.
#include "impl/pair_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "impl/engine.hpp"
#include "impl/predicate.hpp"
#include "formats/random_scene.hpp"
#include "spec/rational.hpp"

namespace circles::impl {
namespace {

using spec::Circles;
using formats::random_scene;
using spec::exact;
using spec::Q;

// Steps `w` with a fixed list horizon and with step_all_pairs side by side; returns the first step at which
// they differ (0: none within `steps`).
int first_divergence(const Circles& w, std::uint64_t horizon, int steps) {
  DoubleEngine e{World{w}, {.threads = 1, .keep_pairs = true, .horizon = horizon}};
  World reference{w};
  for (int s = 1; s <= steps; ++s) {
    e.step();
    reference = step_all_pairs(reference);
    const Circles got = e.world().circles(), want = reference.circles();
    for (std::size_t k = 0; k < got.size(); ++k)
      for (std::size_t f = 0; f < 5; ++f)
        if (std::bit_cast<std::uint64_t>(got[k][f]) != std::bit_cast<std::uint64_t>(want[k][f])) return s;
  }
  return 0;
}

// The list built at world 0 of `w` for the horizon h holds the pair {0, 1}, the engine follows step_all_pairs
// bit for bit through that list and the next, and the pair does meet: three steps past the horizon, circle 0
// has circle 1's velocity.
void expect_listed_and_met(const Circles& w, std::uint64_t h) {
  DoubleEngine e{World{w}, {.threads = 1, .keep_pairs = true, .horizon = h}};
  EXPECT_EQ(e.candidates(), (std::vector<CandidatePair>{{0, 1}})) << "H = " << h;
  EXPECT_EQ(first_divergence(w, h, static_cast<int>(h) + 3), 0) << "H = " << h;
  DoubleEngine plain{World{w}, {.threads = 1, .keep_pairs = false}};
  for (std::uint64_t s = 0; s < h + 3; ++s) plain.step();
  const spec::CircleDoubles got = plain.world().circles()[0];
  EXPECT_TRUE(got[2] == w[1][2] && got[3] == w[1][3]) << "H = " << h << ": they never met";
}

TEST(pair_list, the_speed_bound_is_at_least_one_sixtieth_with_the_margin_its_derivation_claims) {
  // kSpeedBound ≥ (1/60)(1 + 2^-45), and only just: it is 1/60 rounded up at 44 bits, below (1/60)(1 + 2^-44).
  const Q k = exact(kSpeedBound), sixtieth = Q(1) / 60;
  EXPECT_GE(k, sixtieth * (1 + Q(1) / Q(std::exp2(45))));
  EXPECT_LT(k, sixtieth * (1 + Q(1) / Q(std::exp2(44))));
  // The drift bound covers √2·2^-53 with a margin of 2^-14: compare squares, which are rational.
  const Q d = exact(kDriftBound) * Q(std::exp2(53));
  const Q margin = 1 + Q(1) / Q(std::exp2(14));
  EXPECT_GE(d * d, 2 * margin * margin);
  EXPECT_LT(d * d, 2 * (1 + Q(1) / Q(std::exp2(12))));
  // The absolute term covers 2·√2 times half the least subnormal, (2^-1073)² ≥ 8·(2^-1075)², and what is left
  // covers norm_upper's absolute 2^-1074 at the speed 1/60: 2^-1073 − 2√2·2^-1075 ≥ 2^-1074/60.
  const Q half_least = exact(0x1p-1074) / 2;
  EXPECT_GE(exact(kDriftAbsolute) * exact(kDriftAbsolute), 8 * half_least * half_least);
  const Q left = exact(kDriftAbsolute) - exact(0x1p-1074) / 60;
  EXPECT_GE(left * left, 8 * half_least * half_least);
}

TEST(pair_list, norm_upper_is_within_its_stated_rounding_of_the_exact_norm_either_way) {
  // |v| ≤ n·(1 + 2^-50) + 2^-1074, the bound the skin relies on, and n ≤ |v|·(1 + 2^-50) + 2^-1074 (tight, so
  // the skin is): both by squares, exactly, on random velocities over every binade and on extreme ones.
  std::mt19937_64 g(60);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> binade(-1070, 1000);
  const Q up = 1 + Q(1) / Q(std::exp2(50));
  for (int i = 0; i < 20000; ++i) {
    const double vx = std::ldexp(unit(g), binade(g)), vy = i % 3 ? std::ldexp(unit(g), binade(g)) : 0.0;
    const double n = norm_upper(vx, vy);
    const Q square = exact(vx) * exact(vx) + exact(vy) * exact(vy);
    const Q above = exact(n) * up + exact(0x1p-1074);
    ASSERT_LE(square, above * above) << vx << ", " << vy;
    if (n > 0x1p-1074) {
      const Q below = (exact(n) - exact(0x1p-1074)) / up;
      ASSERT_LE(below * below, square) << vx << ", " << vy;
    }
  }
  EXPECT_EQ(norm_upper(60, 0), 60);
  EXPECT_EQ(norm_upper(0, -3), 3);
  EXPECT_EQ(norm_upper(0, 0), 0);
  EXPECT_EQ(norm_upper(0x1p-1074, 0x1p-1074), 0x1p-1074 * std::sqrt(2.0));
}

TEST(pair_list, first_step_is_never_later_than_the_first_step_a_pair_can_meet_and_at_most_one_earlier) {
  // first_step(…) = e claims: the pair cannot intersect at step e − 1, i.e. D > S + 2(e − 1)·step, with D the
  // exact distance and S the exact sum of the radii (kNever: D > S + 2H·step); and it is tight: the pair
  // could meet at step e + 1 or earlier, D ≤ S + 2(e + 1)·step (up to a relative 2^-40). Both checked in
  // rationals by squares, on pairs whose distance lands within 2^-50 of a whole number of steps, where a
  // rounding taken the wrong way would show.
  std::mt19937_64 g(2026);
  std::uniform_real_distribution<double> unit(0, 1);
  const auto q = [](double x) { return exact(x); };
  int near_integer = 0;
  for (int i = 0; i < 20000; ++i) {
    const double step = std::ldexp(0.5 + unit(g), static_cast<int>(unit(g) * 40) - 20);
    const double ar = std::ldexp(unit(g), static_cast<int>(unit(g) * 20) - 10) * step * 8;
    const double br = i % 5 == 0 ? 0.0 : ar * unit(g);
    const std::uint64_t horizon = 1 + static_cast<std::uint64_t>(unit(g) * 100);
    const double k = std::floor(unit(g) * static_cast<double>(horizon + 2));
    const double jitter = (unit(g) - 0.5) * 0x1p-49;
    const double target = (ar + br + 2 * k * step) * (1 + jitter);
    const double angle = unit(g) * 6.283185307179586;
    const double ax = std::ldexp(unit(g) - 0.5, static_cast<int>(unit(g) * 30)), ay = ax * unit(g);
    const double bx = ax + target * std::cos(angle), by = ay + target * std::sin(angle);
    const std::uint32_t e = first_step(ax, ay, ar, bx, by, br, step, horizon);
    const Q d2 = (q(bx) - q(ax)) * (q(bx) - q(ax)) + (q(by) - q(ay)) * (q(by) - q(ay));
    const Q sum = q(ar) + q(br);
    const auto reach = [&](std::uint64_t j) {  // (S + 2j·step)²
      const Q r = sum + 2 * Q(static_cast<long>(j)) * q(step);
      return r * r;
    };
    if (e == kNever) {
      ASSERT_GT(d2, reach(horizon)) << i;
      continue;
    }
    ASSERT_LE(e, horizon) << i;
    if (e > 0) {
      ASSERT_GT(d2, reach(e - 1)) << i << ": listed from step " << e << " but can meet before";
    }
    ASSERT_LE(d2, reach(e + 1) * (1 + Q(1) / Q(std::exp2(40)))) << i << ": step " << e << " is too early";
    near_integer += e > 0;
  }
  EXPECT_GT(near_integer, 10000);
}

TEST(pair_list, the_batch_listing_gives_every_pair_the_first_step_of_the_pair_listing_overflowing_distances_too) {
  // Lister::steps, which the list build runs over the candidates the walk keeps, against Lister's one-pair
  // answer (listing_step), on circles from touching to far apart: clusters around 0, around ±2^1000 (where
  // a distance's square overflows, and only norm_upper knows the pair is out of reach) and one subnormal
  // apart; every answer kind must come up, and the batch's must be the pair's, bit for bit.
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<double> px, py, r, ri;
  for (int i = 0; i < 96; ++i) {
    const double centre = i % 3 == 0 ? 0.0 : (i % 3 == 1 ? 0x1p1000 : -0x1p1000);
    const double spread = i % 4 == 0 ? 0x1p-1070 : 40 * unit(g);
    px.push_back(centre + spread * (unit(g) - 0.5));
    py.push_back(centre * unit(g) + spread * (unit(g) - 0.5));
    r.push_back(i % 4 == 0 ? 0.0 : 1 + unit(g));
    ri.push_back(r.back() + 2);
  }
  const std::uint64_t horizon = 6;
  const Lister lister{px.data(), py.data(), r.data(), ri.data(), 0.25, horizon};
  std::vector<std::uint64_t> pairs;
  for (std::uint64_t a = 0; a < px.size(); ++a)
    for (std::uint64_t b = a + 1; b < px.size(); ++b) pairs.push_back(packed_pair(a, b));
  std::vector<std::uint32_t> steps(pairs.size());
  int never = 0, now = 0, later = 0, overflowing = 0;
  for (std::size_t from = 0; from < pairs.size(); from += 100) {
    const std::size_t count = std::min<std::size_t>(100, pairs.size() - from);
    lister.steps(std::span<const std::uint64_t>(pairs.data() + from, count), steps.data() + from);
  }
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const std::size_t a = first_slot(pairs[k]), b = second_slot(pairs[k]);
    ASSERT_EQ(steps[k], lister(a, b)) << "pair " << a << ", " << b;
    const double dx = px[b] - px[a], dy = py[b] - py[a];
    overflowing += std::isfinite(dx) && std::isfinite(dy) && !std::isfinite(dx * dx + dy * dy) && steps[k] == kNever;
    never += steps[k] == kNever;
    now += steps[k] == 0;
    later += steps[k] > 0 && steps[k] <= horizon;
  }
  EXPECT_GT(overflowing, 0);
  EXPECT_GT(never, 0);
  EXPECT_GT(now, 0);
  EXPECT_GT(later, 0);
}

TEST(pair_list, a_pair_that_meets_exactly_when_the_horizon_ends_is_listed_and_its_contact_found) {
  // Two unit circles, centres ±(1 + H) apart from the origin, closing at v = 60 each (every move exact):
  // world H is the first in which they touch, exactly tangent, and the step from it exchanges their
  // velocities. A list built at world 0 for horizon H must hold the pair: its skin is within 2^-36 of H
  // (kSpeedBound) plus a rounding allowance of about 2^-52 relative, so any speed bound below
  // (1/60)(1 − 2^-48) drops the pair at H = 1, and the engine then misses the contact (checked against step_all_pairs).
  for (const std::uint64_t h : {1u, 2u, 7u, 16u, 100u, 1000u}) {
    const double c = 1 + static_cast<double>(h);
    const Circles w{{-c, 0, 60, 0, 1}, {c, 0, -60, 0, 1}};
    DoubleEngine e{World{w}, {.threads = 1, .keep_pairs = true, .horizon = h}};
    const std::vector<CandidatePair> listed = e.candidates();
    EXPECT_EQ(listed, (std::vector<CandidatePair>{{0, 1}})) << "H = " << h;
    EXPECT_EQ(first_divergence(w, h, static_cast<int>(h) + 3), 0) << "H = " << h;
    // One step of gap more than the horizon covers: the pair cannot meet before the list ends, and is not
    // listed (the skin is not loose by a whole step either).
    const Circles farther{{-c - 1, 0, 60, 0, 1}, {c + 1, 0, -60, 0, 1}};
    EXPECT_TRUE(DoubleEngine(World{farther}, {.threads = 1, .keep_pairs = true, .horizon = h}).candidates().empty())
        << "H = " << h;
  }
}

TEST(pair_list, two_points_that_meet_at_the_origin_when_the_horizon_ends_are_listed_on_the_whole_step_bound) {
  // The edge of the whole step bound (speed + drift + absolute term), not of kSpeedBound alone: the terms
  // around the speed term have slack of their own wherever moves are exact, and a speed term below 1/60 by
  // less than that slack drops no pair (impl/pair_list.hpp, beside kSpeedBound). So the world makes it least.
  // Two points (radii 0: nothing for outward_upper to widen but the skin, and the list's filter weighs the
  // distance against the inflated radii alone) at ∓H·(3, 4) close at ±(180, 240), 5 a step each, every move
  // exact, and coincide at the origin in world H. Along (3, 4) the reach is 4H, not 5H, so the drift term,
  // far·kDriftBound with far = 4H + 5H, is 9H·2^-52.5 a step, 2^-51.7 of the motion at H = 1. The pair is
  // listed iff the inflated radii reach 5H within the filter's margin (2^-50 of the distance) and
  // outward_upper's (2^-52): a speed term short of 1/60 by 2^-49 drops it at H = 1 and 2 (tried: the list is
  // then empty and the engine misses the contact; 2^-49.2 is within the slack), where the unit circles of
  // the test above need 2^-48.6. No world with exact moves has less slack: the filter's margin is relative to
  // the distance, least with radii 0, and the drift term grows with H.
  for (const std::uint64_t h : {1u, 2u, 16u}) {
    const double c = static_cast<double>(h);
    expect_listed_and_met({{-3 * c, -4 * c, 180, 240, 0}, {3 * c, 4 * c, -180, -240, 0}}, h);
  }
}

TEST(pair_list, a_pair_whose_squares_underflow_is_given_the_first_step_the_absolute_gap_term_allows) {
  // The edge of kGapAbsolute, the only bound that covers the squares' underflow. Two points c·2^-537 apart on
  // each axis, c = 0x1.6a09e8p-1 just above √½: each square, c²·2^-1074, rounds up to the least subnormal,
  // so RN(√d2) = √2·2^-537 while the distance is √2·c·2^-537, too long by (1 − c)·√2·2^-537 ≈ 2^-538.27.
  // They close it in H exact steps and coincide in world H; the step bound is within 2^-44 of their motion
  // (the drift and absolute terms are below 2^-580 here), so without kGapAbsolute the first step would be
  // ⌈H/c⌉ > H, never: kGapAbsolute below 2^-538.27 (tried: zero and 2^-539) drops the pair and the engine
  // misses the contact. 2^-500 covers √(3η) ≈ 2^-536.7, the most three underflows can add.
  const double c = 0x1.6a09e8p-1;
  ASSERT_GT(c * c, 0.5);
  const double d = c * 0x1p-537;
  ASSERT_EQ(d * d, 0x1p-1074);
  for (const std::uint64_t h : {1u, 2u, 16u}) {
    const double v = 60 * d / static_cast<double>(2 * h);  // d/(2H) a step, exactly
    ASSERT_EQ(v / 60 * static_cast<double>(2 * h), d);
    expect_listed_and_met({{0, 0, v, v, 0}, {d, d, -v, -v, 0}}, h);
  }
}

TEST(pair_list, a_pair_whose_rounding_carries_it_half_an_ulp_further_every_step_is_listed) {
  // Above 2^53 the ulp is 2: a move of v/60 = 1 + 2^-40 rounds up to 2 every step, one half ulp more than the
  // velocity moves it, which is |p'|·2^-53 on that axis. Circles at 2^53 and 2^53 + 2 + 4H close by 4 per
  // step and first touch in world H; the skin covers 2H only with the drift term (the speed term alone gives
  // H·(1 + 2^-40)), so a drift bound below 2^-53 drops the pair. The drift term's edge is on the diagonal,
  // where both coordinates round forward and |e| = √2·|p'|·2^-53: the same circles moving along (1, 1), with
  // radii RN(√2) > √2 each, touch first in world H (2√2 apart); the skin covers their 2√2·H of motion with
  // little more slack than kDriftBound's own margin (2^-14 of the drift, about 2^-13.5 a step), and a drift
  // bound of 2^-53 (the √2 left out) drops the pair for every H here (tried), which the axis alone does not.
  const double v = 60 + 0x1p-40 * 60;
  ASSERT_EQ(v / 60, 1 + 0x1p-40);
  const double root_two = std::sqrt(2.0);
  ASSERT_GT(exact(root_two) * exact(root_two), Q(2));
  for (const std::uint64_t h : {1u, 3u, 16u, 64u}) {
    const double a = 0x1p53, b = 0x1p53 + 2 + 4 * static_cast<double>(h);
    ASSERT_EQ(advance_rounded(a, v), a + 2);
    ASSERT_EQ(advance_rounded(b, -v), b - 2);
    expect_listed_and_met({{a, 0, v, 0, 1}, {b, 0, -v, 0, 1}}, h);
    expect_listed_and_met({{a, a, v, v, root_two}, {b, b, -v, -v, root_two}}, h);
  }
}

// 3000 circles at 10% coverage with contacts every step.
Circles busy_world() {
  std::mt19937_64 g(3000);
  std::uniform_real_distribution<double> unit(0, 1);
  Circles w;
  for (int k = 0; k < 3000; ++k)
    w.push_back({600 * unit(g), 600 * unit(g), 200 * unit(g) - 100, 200 * unit(g) - 100, 2 + 4 * unit(g)});
  return w;
}

TEST(pair_list, every_horizon_and_thread_count_gives_the_same_bits_on_a_busy_world) {
  // Fixed horizons from 0 to 64, the schedule's own, and lists for each step alone, on one and two threads,
  // all equal after 40 steps.
  const Circles w = busy_world();
  DoubleEngine plain{World{w}, {.threads = 1, .keep_pairs = false}};
  for (int s = 0; s < 40; ++s) plain.step();
  const Circles want = plain.world().circles();
  EXPECT_GT(plain.stats().contacts, 1000u) << "too few contacts to mean anything";
  for (const unsigned threads : {1u, 2u})
    for (const std::uint64_t h : {0u, 1u, 2u, 5u, 17u, 64u}) {
      DoubleEngine e{World{w}, {.threads = threads, .keep_pairs = true, .horizon = h}};
      for (int s = 0; s < 40; ++s) e.step();
      EXPECT_EQ(e.world().circles(), want) << "H = " << h << ", " << threads << " threads";
      if (h > 0) {
        EXPECT_LE(e.stats().rebuilds, 40 / (h + 1) + 1) << "H = " << h;
      }
    }
}

TEST(pair_list, a_run_of_known_length_shares_its_steps_evenly_among_the_lists_its_horizon_needs) {
  const CellLayout layout;  // the schedule's first horizon, 8: a list serves up to 9 steps
  ASSERT_EQ(HorizonSchedule::kFirstHorizon, 8u);
  const auto served = [&](EngineOptions options, std::uint64_t taken) { return layout.horizon(options, taken) + 1; };
  EXPECT_EQ(served({.steps = 20}, 0), 7u);   // 3 lists: 7, 7, 6 steps
  EXPECT_EQ(served({.steps = 20}, 14), 6u);  // the last of them
  EXPECT_EQ(served({.steps = 18}, 0), 9u);   // 2 lists of 9: nothing to share
  EXPECT_EQ(served({.steps = 19}, 0), 7u);   // 3 lists: 7, 6, 6
  EXPECT_EQ(served({.steps = 9}, 0), 9u);
  EXPECT_EQ(served({.steps = 5}, 3), 2u);    // cut to the run's end
  EXPECT_EQ(served({}, 0), 9u);              // a run of unknown length: the schedule's horizon
  EXPECT_EQ(served({.horizon = 2, .steps = 7}, 0), 3u);  // a fixed horizon is shared the same way: 3, 2, 2
  EXPECT_EQ(served({.keep_pairs = false, .steps = 7}, 0), 1u);
  // No overflow at the ends of the range.
  constexpr std::uint64_t kAll = std::numeric_limits<std::uint64_t>::max();
  EXPECT_EQ(served({.horizon = kAll, .steps = kAll}, 0), kAll);
  EXPECT_EQ(served({.horizon = kAll - 1, .steps = kAll}, 1), kAll - 1);
  EXPECT_EQ(layout.horizon({.steps = kAll}, 0), 8u);  // ⌈(2^64 − 1) / 9⌉ lists: the first serves 9 steps
}

TEST(pair_list, a_run_of_known_length_lists_nothing_past_its_last_step_and_gives_the_same_bits) {
  // EngineOptions::steps cuts every horizon to the run's end. A 1-step run lists only the pairs that touch in
  // world 0 (horizon 0: every listed pair is tested in step 0), where the schedule's first horizon of 8 lists
  // pairs that meet later; a 3-step run needs one list; a 12-step run two, which share its steps evenly; every
  // run ends in the bits of lists for each step.
  const Circles w = busy_world();
  DoubleEngine open{World{w}, {.threads = 1}};
  open.step();
  ASSERT_GT(open.stats().pairs_listed, open.stats().pairs_tested) << "the schedule's first list has no skin to cut";
  for (const std::uint64_t steps : {1u, 3u, 12u}) {
    DoubleEngine plain{World{w}, {.threads = 1, .keep_pairs = false}};
    DoubleEngine planned{World{w}, {.threads = 2, .steps = steps}};
    for (std::uint64_t s = 0; s < steps; ++s) {
      plain.step();
      planned.step();
    }
    EXPECT_EQ(planned.world().circles(), plain.world().circles()) << steps << " steps";
    if (steps == 1) {
      EXPECT_EQ(planned.stats().pairs_listed, planned.stats().pairs_tested);
      EXPECT_LT(planned.stats().pairs_listed, open.stats().pairs_listed);
    }
    if (steps == 3) {  // one list, of horizon 2: the pairs a fixed horizon of 2 lists
      DoubleEngine fixed{World{w}, {.threads = 1, .horizon = 2}};
      fixed.step();
      EXPECT_EQ(planned.stats().rebuilds, 1u);
      EXPECT_EQ(planned.stats().pairs_listed, fixed.stats().pairs_listed);
      EXPECT_LT(planned.stats().pairs_listed, open.stats().pairs_listed);
    }
    if (steps == 12) {  // the first horizon of 8 needs two lists for 12 steps: two of 6 steps (horizon 5), not 9 and 3
      DoubleEngine first{World{w}, {.threads = 1, .steps = steps}};
      DoubleEngine fixed{World{w}, {.threads = 1, .horizon = 5}};
      first.step();
      fixed.step();
      EXPECT_EQ(first.stats().pairs_listed, fixed.stats().pairs_listed);
      EXPECT_LT(first.stats().pairs_listed, open.stats().pairs_listed);
    }
  }
}

TEST(pair_list, the_schedule_grows_fourfold_far_below_balance_twofold_below_half_and_halves_above_twice) {
  HorizonSchedule s;
  EXPECT_EQ(s.horizon(), HorizonSchedule::kFirstHorizon);
  ASSERT_EQ(s.horizon(), 8u);
  // A rebuild of 1000 circles costs 8·1000 pair tests, whatever the steps its list serves. No pairs: far below
  // a sixteenth of that, ×4.
  s.update(0, 1000);
  ASSERT_EQ(s.horizon(), 32u);
  // Its sixteenth is 500: 499 tests over the list's steps are below it, ×4; 500 are not below, ×2 (below
  // half, 4000).
  HorizonSchedule far = s;
  far.update(499, 1000);
  EXPECT_EQ(far.horizon(), 128u);
  s.update(500, 1000);
  ASSERT_EQ(s.horizon(), 64u);
  // 3999 tests are below half of it, ×2; 4000 are not, and not above twice it either, kept; 16,000 are twice
  // it, kept; 16,001 are above, halved.
  HorizonSchedule below_half = s;
  below_half.update(3999, 1000);
  EXPECT_EQ(below_half.horizon(), 128u);
  s.update(4000, 1000);
  EXPECT_EQ(s.horizon(), 64u);
  s.update(16000, 1000);
  EXPECT_EQ(s.horizon(), 64u);
  s.update(16001, 1000);
  EXPECT_EQ(s.horizon(), 32u);
  for (int i = 0; i < 40; ++i) s.update(0, 1000);
  EXPECT_EQ(s.horizon(), HorizonSchedule::kMaxHorizon);
  s.collapse();
  EXPECT_EQ(s.horizon(), 0u);
  s.update(0, 10);
  EXPECT_EQ(s.horizon(), 1u);
}

// A step with no list to keep (horizon 0) writes none: it tests each pair as the broad phase finds it. It must
// test exactly the pairs the list would have held (candidates() builds that list), find the contacts among
// them, count what the list would count, and give the world a kept list gives; on two threads, across chunks.
TEST(pair_list, a_step_without_a_list_tests_the_pairs_the_list_would_hold_and_no_others) {
  const Circles w = random_scene(20000, 0.1, 7);
  for (const unsigned threads : {1u, 2u}) {
    DoubleEngine now{World{w}, {.threads = threads, .keep_pairs = false}};
    const std::vector<CandidatePair> listed = now.candidates();
    std::size_t intersecting = 0;
    std::vector<bool> in_pair(w.size(), false);
    for (const CandidatePair& p : listed) {
      intersecting += intersect_exact(w[p.i][0], w[p.i][1], w[p.i][4], w[p.j][0], w[p.j][1], w[p.j][4]);
      in_pair[p.i] = in_pair[p.j] = true;
    }
    ASSERT_GT(intersecting, 1000u);
    now.step();
    EXPECT_EQ(now.stats().pairs_tested, listed.size()) << threads << " threads";
    EXPECT_EQ(now.stats().pairs_listed, listed.size());
    EXPECT_EQ(now.stats().contacts, intersecting);
    EXPECT_EQ(now.stats().lonely_circle_steps,
              static_cast<std::uint64_t>(std::count(in_pair.begin(), in_pair.end(), false)));
    DoubleEngine kept{World{w}, {.threads = threads, .keep_pairs = true, .horizon = 4}};
    kept.step();
    const Circles got = now.world().circles(), want = kept.world().circles();
    for (std::size_t k = 0; k < got.size(); ++k)
      for (std::size_t f = 0; f < 5; ++f)
        ASSERT_EQ(std::bit_cast<std::uint64_t>(got[k][f]), std::bit_cast<std::uint64_t>(want[k][f]))
            << threads << " threads, circle " << k << ", field " << f;
  }
}

}  // namespace
}  // namespace circles::impl
