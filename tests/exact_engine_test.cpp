// The exact engine (impl/exact_engine.hpp) against the oracle's exact sequence, as rationals, over whole
// trajectories; its integer kernels (impl/exact_integer.hpp) against GMP; its width choice; its threads.
//
// Every trajectory is checked the same way (follow): the engine and spec::resolved_step run side by side, and
// at every step the engine's exact state must equal the oracle's world and world() its nearest doubles; a
// step whose rounded position is infinite must throw PositionOverflow naming that step and the first circle
// and field, with the state unchanged.
#include "impl/exact_engine.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "formats/scene.hpp"
#include "impl/engine.hpp"
#include "impl/exact_integer.hpp"
#include "formats/random_scene.hpp"
#include "properties/generators.hpp"
#include "spec/circle.hpp"
#include "spec/oracle.hpp"
#include "tests/exact_worlds.hpp"
#include "tests/thrown.hpp"

namespace circles::impl {
namespace {

using spec::Circles;
using formats::random_scene;
using circles::testing::thrown;
using exact::Narrow;
using exact::NarrowMagnitude;
using exact::Wide;
namespace gen = properties::gen;
using spec::Vec2;
using circles::testing::exact_of;
using circles::testing::nearest;


// The first circle and field, in field order up to `last`, whose nearest double is infinite, if any.
std::optional<std::pair<std::size_t, spec::Field>> first_infinite(const spec::Sequence& w, spec::Field last) {
  for (std::size_t k = 0; k < w.size(); ++k) {
    const spec::CircleDoubles rounded = spec::nearest_doubles(w[k]);
    for (std::size_t f = 0; f <= static_cast<std::size_t>(last); ++f)
      if (std::isinf(rounded[f])) return std::pair{k, spec::Field(f)};
  }
  return std::nullopt;
}

// The engine made from w, or std::nullopt where it must refuse w, having checked how: gen::world's rationals
// can lie beyond the double range (a circle tangent to one near DBL_MAX, the shrunk case of a failure CI
// found), where the engine's world() could not follow, so the constructor must throw OutsideC naming the
// first such circle and field, in field order.
std::optional<ExactEngine> made(const spec::Sequence& w, EngineOptions options) {
  const auto beyond = first_infinite(w, spec::Field::r);
  if (!beyond) return ExactEngine(w, options);
  RC_TAG("refused: a field beyond the double range");
  try {
    const ExactEngine engine(w, options);
    RC_FAIL("no OutsideC for circle " + std::to_string(beyond->first) + ", field " + spec::name(beyond->second));
  } catch (const spec::OutsideC& e) {
    RC_ASSERT(e.index == beyond->first);
    RC_ASSERT(e.field == beyond->second);
  }
  return std::nullopt;
}

// Runs `engine` and the oracle from w side by side for `steps` steps (or to an overflow), with RC_ASSERT.
void follow(ExactEngine& engine, spec::Sequence w, int steps) {
  RC_ASSERT(engine.exact() == w);
  for (int t = 1; t <= steps; ++t) {
    const spec::Sequence next = spec::resolved_step(w);
    if (const auto overflow = first_infinite(next, spec::Field::py)) {
      try {
        engine.step();
        RC_FAIL("no PositionOverflow at step " + std::to_string(t));
      } catch (const PositionOverflow& e) {
        RC_ASSERT(e.step == static_cast<std::uint64_t>(t));
        RC_ASSERT(e.index == overflow->first);
        RC_ASSERT(e.field == overflow->second);
      }
      RC_ASSERT(engine.exact() == w);
      RC_ASSERT(engine.steps() == static_cast<std::uint64_t>(t - 1));
      return;
    }
    engine.step();
    w = next;
    RC_ASSERT(engine.exact() == w);
    RC_ASSERT(engine.world().circles() == nearest(w));
  }
}

// ── Trajectories against the oracle ───────────────────────────────────────────────────────────────────

RC_GTEST_PROP(exact_engine, follows_the_oracle_exactly_on_rational_worlds_for_up_to_100_steps, ()) {
  const spec::Sequence w = *gen::world(spec::Radii::non_negative);
  const int steps = *rc::gen::inRange(1, 101);
  std::optional<ExactEngine> engine = made(w, EngineOptions{.threads = 1});
  if (engine) follow(*engine, w, steps);
}

RC_GTEST_PROP(exact_engine, follows_the_oracle_exactly_on_worlds_of_any_finite_doubles_for_up_to_100_steps, ()) {
  // Subnormals, DBL_MAX, every binade: wide states, overflows and the GMP rounding are all likely here.
  const Circles w = *gen::double_world(6, gen::finite_double());
  const int steps = *rc::gen::inRange(1, 101);
  ExactEngine engine(World(w), EngineOptions{.threads = 1});
  follow(engine, exact_of(w), steps);
}

// Circle a moves along (3, 4)·q per step (v = 60·q·(3, 4)) towards b, at rest, and touches it exactly after
// `when` steps (offset 0), or misses by one part in 2^60 of a coordinate either way; q is dyadic (every move
// exact in doubles) or k/60 (a move no double can hold). Other circles of the world look on.
rc::Gen<spec::Sequence> tangency_after_some_steps() {
  return rc::gen::exec([] {
    const spec::Q q = *rc::gen::element(spec::Q(1), spec::Q(3, 8), spec::Q(1, 60), spec::Q(7, 60), spec::Q(5, 1024));
    const int when = *rc::gen::inRange(1, 60);
    const spec::Q ra(*rc::gen::inRange(1, 9), 2), rb(*rc::gen::inRange(0, 9), 2);
    const spec::Q offset = spec::Q(*rc::gen::inRange(-1, 2)) / spec::Q(Wide(1) << 60);
    const spec::Q reach = q * when + (ra + rb) / 5;  // |(3, 4)| = 5
    const spec::Q ax(*rc::gen::inRange(-20, 20)), ay(*rc::gen::inRange(-20, 20));
    spec::Sequence w = *gen::world(spec::Radii::non_negative, 3);
    for (spec::Circle& c : w) c.p += Vec2(spec::Q(100), spec::Q(0));  // onlookers, apart
    w.push_back(spec::circle(ax, ay, 60 * q * 3, 60 * q * 4, ra));
    w.push_back(spec::circle(ax + 3 * reach + offset, ay + 4 * reach, 0, 0, rb));
    return w;
  });
}

RC_GTEST_PROP(exact_engine, follows_the_oracle_through_a_tangency_reached_after_some_steps, ()) {
  const spec::Sequence w = *tangency_after_some_steps();
  std::optional<ExactEngine> engine = made(w, EngineOptions{.threads = 1});
  if (engine) follow(*engine, w, 70);
}

TEST(exact_engine, meets_exactly_at_the_designed_tangency_and_not_one_step_before) {
  // a from (0, 0) at v = (3, 4) (moves of 1/20, 1/15: no double holds them), b at rest touching after 30 steps.
  const spec::Q reach = spec::Q(30, 60) + spec::Q(2, 5);
  const spec::Sequence w{spec::circle(0, 0, 3, 4, 1), spec::circle(3 * reach, 4 * reach, 0, 0, 1)};
  ExactEngine engine(w, EngineOptions{.threads = 1});
  for (int t = 0; t < 30; ++t) engine.step();
  EXPECT_EQ(engine.exact()[0].v, Vec2(spec::Q(3), spec::Q(4)));  // not yet touching before step 30
  engine.step();                                                // world 30 touches: velocities swap
  EXPECT_EQ(engine.exact()[0].v, Vec2(spec::Q(0), spec::Q(0)));
  EXPECT_EQ(engine.exact()[1].v, Vec2(spec::Q(3), spec::Q(4)));
}

TEST(exact_engine, takes_the_contact_of_least_centre_when_two_centres_differ_below_what_their_doubles_resolve) {
  // c at the origin touches a and b, whose centres differ by 2^-70 in x: their approximations (and nearest
  // doubles) are equal, so only the integers order them, and a's x is less. b's velocity is less, and b comes
  // first by index: an order that passed over equal approximations to the velocities, or to the indices,
  // would give c b's velocity.
  const spec::Q tiny = spec::Q(1) / spec::Q(Wide(1) << 70);
  ASSERT_EQ(spec::nearest_double(1 + tiny), 1.0);
  const spec::Sequence w{spec::circle(0, 0, 0, 0, 2), spec::circle(1 + tiny, 0, -1, 0, 1), spec::circle(1, 0, 5, 0, 1)};
  ExactEngine engine(w, EngineOptions{.threads = 1});
  engine.step();
  EXPECT_EQ(engine.exact()[0].v, Vec2(spec::Q(5), spec::Q(0)));
  EXPECT_EQ(engine.exact(), spec::resolved_step(w));
}

TEST(exact_engine, follows_the_oracle_on_the_bundled_scene_and_runs_it_for_10000_steps) {
  const spec::Sequence w0 = formats::default_scene().circles;
  ExactEngine engine(w0, EngineOptions{.threads = 1});
  BasicEngine<RoundedArithmetic> doubles(World(nearest(w0)), EngineOptions{.threads = 1});
  spec::Sequence oracle = w0;
  constexpr int kOracleSteps = 600;  // the cradle, the glancing pair and the incomparable triple all act by then
  for (int t = 1; t <= kOracleSteps; ++t) {
    oracle = spec::resolved_step(oracle);
    engine.step();
    ASSERT_EQ(engine.exact(), oracle) << "step " << t;
  }
  EXPECT_TRUE(engine.narrow());
  for (int t = kOracleSteps + 1; t <= 10000; ++t) engine.step();
  for (int t = 1; t <= 10000; ++t) doubles.step();
  // The double engine rounds every step; the exact engine only its output. They must agree bit for bit on
  // every circle whose every position so far is a double (its moves are exact, so no rounding ever happened);
  // in the bundled scene that is all but circle 9, which moves by (1, −7)/60 and alone. Circle 9 keeps its
  // velocity (it meets no one), so the double engine's error is at most half an ulp per step.
  const Circles exact = engine.world().circles(), rounded = doubles.world().circles();
  ASSERT_EQ(exact.size(), 10u);
  for (std::size_t k = 0; k < 9; ++k) EXPECT_EQ(exact[k], rounded[k]) << "circle " << k;
  EXPECT_EQ(engine.exact()[9].v, Vec2(spec::Q(1), spec::Q(-7)));
  EXPECT_EQ(engine.exact()[9].p, Vec2(spec::Q(1100) + spec::Q(10000, 60), spec::Q(100) - spec::Q(70000, 60)));
  for (std::size_t f = 0; f < 2; ++f) {
    const double ulp = std::nextafter(std::fabs(exact[9][f]), 1e300) - std::fabs(exact[9][f]);
    EXPECT_LE(std::fabs(exact[9][f] - rounded[9][f]), 10000 * ulp / 2) << "field " << f;
  }
}

// ── Width ─────────────────────────────────────────────────────────────────────────────────────────────

TEST(exact_engine, holds_a_small_scene_in_64_bits_over_the_denominator_60_times_2_to_the_k) {
  // 0.375 = 3·2^-3 is the least exponent: K = 3, D = 60·8.
  ExactEngine engine(World({{0.375, 1, 2, 0, 1}, {5, 0, -1, 0, 0.5}}), EngineOptions{.threads = 1});
  EXPECT_TRUE(engine.narrow());
  EXPECT_EQ(engine.width(), 64u);
  EXPECT_EQ(engine.denominator(), Wide(480));
}

// K of a world of doubles the long way: L = 2^K is the largest denominator of the exact rationals.
int least_exponent(const Circles& w) {
  Wide l = 1;
  for (const spec::Circle& c : exact_of(w))
    for (const spec::Q* q : {&c.p.x(), &c.p.y(), &c.v.x(), &c.v.y(), &c.r})
      l = std::max(l, Wide(boost::multiprecision::denominator(*q)));
  return static_cast<int>(boost::multiprecision::msb(l));
}

TEST(exact_engine, holds_the_benchmark_scene_in_128_bits_because_its_least_exponent_needs_more_than_64) {
  // Values drawn with 53 significant bits: the radii 2 + 4u alone are multiples of 2^-51, and the smallest
  // positions side·j·2^-53 set K higher, so X = D·p for positions up to the side (over 2^10 here) is beyond
  // 2^61: the benchmark scene needs the 128-bit width (docs/exact-engine.md).
  const Circles w = random_scene(10'000, 0.1, 1);
  const int k = least_exponent(w);
  EXPECT_GT(k + 6 + 10, exact::kWordBits);  // 60·2^K·2^10 is beyond 2^61
  ExactEngine engine(World(w), EngineOptions{.threads = 1});
  EXPECT_EQ(engine.denominator(), Wide(60) << k);
  EXPECT_EQ(engine.width(), 128u);
  engine.step();
  EXPECT_EQ(engine.world().circles(), step_all_pairs(World(w)).circles());
}

TEST(exact_engine, holds_a_subnormal_scene_in_gmp_integers_and_still_follows_the_oracle) {
  const Circles w{{0x1p-1074, 0, 0x1p-1070, 0, 0x1p-1073}, {0x1p-1072, 0, 0, 0, 0x1p-1073}};
  ExactEngine engine(World(w), EngineOptions{.threads = 1});
  EXPECT_FALSE(engine.narrow());
  spec::Sequence oracle = exact_of(w);
  for (int t = 0; t < 20; ++t) {
    oracle = spec::resolved_step(oracle);
    engine.step();
  }
  EXPECT_EQ(engine.exact(), oracle);
  EXPECT_EQ(engine.world().circles(), nearest(oracle));
}

TEST(exact_engine, moves_to_gmp_integers_exactly_when_the_proven_headroom_runs_out) {
  // D = 60, V = 2^119: X = 2^119·t stays within 2^125 for 64 steps and must not be held in 128 bits after.
  const double v = 0x1p119;
  ExactEngine engine(World({{0, 0, v, 0, 1}, {-1e3, 0, 0, 0, 1}}), EngineOptions{.threads = 1});
  spec::Sequence oracle = engine.exact();
  EXPECT_EQ(engine.width(), 128u);
  for (int t = 1; t <= 70; ++t) {
    engine.step();
    oracle = spec::resolved_step(oracle);
    ASSERT_EQ(engine.exact(), oracle) << "step " << t;
    ASSERT_EQ(engine.narrow(), t <= 64) << "step " << t;
  }
}

TEST(exact_engine, moves_from_64_to_128_bits_exactly_when_the_proven_headroom_runs_out) {
  // D = 60, V = 2^55: X = 2^55·t stays within 2^61 for 64 steps and must not be held in 64 bits after; the
  // first proof gives 63 steps (the other circle's |X| = 60,000 takes some room), the second one more.
  const double v = 0x1p55;
  ExactEngine engine(World({{0, 0, v, 0, 1}, {-1e3, 0, 0, 0, 1}}), EngineOptions{.threads = 1});
  spec::Sequence oracle = engine.exact();
  EXPECT_EQ(engine.width(), 64u);
  for (int t = 1; t <= 70; ++t) {
    engine.step();
    oracle = spec::resolved_step(oracle);
    ASSERT_EQ(engine.exact(), oracle) << "step " << t;
    ASSERT_EQ(engine.world().circles(), nearest(oracle)) << "step " << t;
    ASSERT_EQ(engine.width(), t <= 64 ? 64u : 128u) << "step " << t;
  }
}

TEST(exact_engine, decides_a_tangency_at_the_64_bit_limit_in_integers) {
  // Integer inputs (L = 1, D = 60): a at rest at p = ⌊2^61/60⌋ − 3, so X = 60·p is just within 2^61; b, moving
  // away at v = 1, at p + 2 + offset, both of radius 1: overlapping, tangent, one unit apart. The approximations
  // are off by about 2^-50·p ≈ 34 here, so only the 64-bit integers can decide; if they touch, a takes b's
  // velocity.
  const spec::Q p = spec::Q((Wide(1) << 61) / 60 - 3);
  for (const int offset : {-1, 0, 1}) {
    const spec::Sequence w{spec::circle(p, 0, 0, 0, 1), spec::circle(p + 2 + offset, 0, 1, 0, 1)};
    ExactEngine engine(w, EngineOptions{.threads = 1});
    ASSERT_EQ(engine.width(), 64u);
    engine.step();
    EXPECT_EQ(engine.exact(), spec::resolved_step(w)) << "offset " << offset;
    EXPECT_EQ(engine.exact()[0].v.x(), offset <= 0 ? spec::Q(1) : spec::Q(0)) << "offset " << offset;
  }
}

TEST(exact_engine, reports_the_first_position_that_rounds_to_infinity_and_keeps_its_state) {
  // DBL_MAX + 2^970 is the midpoint below 2^1024 and rounds (to even) to infinity; DBL_MAX + 2^969 does not.
  constexpr double kMax = std::numeric_limits<double>::max();
  const Circles w{{kMax, 0, 60 * 0x1p969, 0, 0}, {0, kMax, 0, 60 * 0x1p970, 0}, {kMax, kMax, 60 * 0x1p970, 0, 0}};
  ExactEngine engine(World(w), EngineOptions{.threads = 1});
  const auto e = thrown<PositionOverflow>([&] { engine.step(); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->step, 1u);
  EXPECT_EQ(e->index, 1u);
  EXPECT_EQ(e->field, spec::Field::py);
  EXPECT_STREQ(e->what(), "step 1, circle 1, field py: the position p + v/60 overflows to infinity");
  EXPECT_EQ(engine.steps(), 0u);
  EXPECT_EQ(engine.exact(), exact_of(w));
}

TEST(exact_engine, writes_its_state_as_rationals_in_lowest_terms) {
  ExactEngine engine(World({{0.5, 0, 1, -90, 0.25}}), EngineOptions{.threads = 1});
  engine.step();
  const std::array<std::string, 5> expected{"31/60", "-3/2", "1", "-90", "1/4"};
  EXPECT_EQ(engine.rationals(), std::vector{expected});
}

TEST(exact_engine, rejects_a_rational_whose_nearest_double_is_infinite_naming_circle_and_field) {
  const spec::Q huge(Wide(1) << 1024);
  const auto e = thrown<spec::OutsideC>([&] { ExactEngine(spec::Sequence{spec::circle(0, 0, 0, 0, 1), spec::circle(0, 0, huge, 0, 1)}); });
  ASSERT_TRUE(e);
  EXPECT_STREQ(e->what(), ("circle 1, field vx: value " + spec::to_string(huge) +
                           " is beyond the double range (not an element of C)").c_str());
}

// ── Threads and scale ─────────────────────────────────────────────────────────────────────────────────

// A benchmark scene with positions on multiples of 1/64 and moves v/60 on multiples of 1/64 too
// (v a multiple of 15/16): every move is exact in doubles, so the correctly rounded double engine never
// rounds and must equal the exact engine bit for bit, on every step.
Circles exact_move_scene(std::size_t n, double coverage = 0.1) {
  Circles w = random_scene(n, coverage, 7);
  for (auto& c : w) {
    c[0] = std::round(c[0] * 64) / 64;
    c[1] = std::round(c[1] * 64) / 64;
    c[2] = std::round(c[2] * 16 / 15) * 15 / 16;
    c[3] = std::round(c[3] * 16 / 15) * 15 / 16;
  }
  return w;
}

TEST(exact_engine, equals_the_double_engine_where_every_move_is_exact_on_every_thread_count) {
  const Circles w = exact_move_scene(12000);  // above kParallelFrom: several chunks on 2 and 4 threads
  BasicEngine<RoundedArithmetic> doubles(World(w), EngineOptions{.threads = 1});
  std::vector<ExactEngine> engines;
  for (const unsigned threads : {1u, 2u, 4u}) engines.emplace_back(World(w), EngineOptions{.threads = threads});
  for (int t = 1; t <= 30; ++t) {
    doubles.step();
    for (ExactEngine& e : engines) e.step();
    const Circles expected = doubles.world().circles();
    for (ExactEngine& e : engines) ASSERT_EQ(e.world().circles(), expected) << "step " << t << ", " << e.threads() << " threads";
  }
  EXPECT_EQ(engines[0].exact(), engines[1].exact());
  EXPECT_EQ(engines[0].exact(), engines[2].exact());
}

TEST(exact_engine, takes_one_correctly_rounded_step_like_the_all_pairs_reference_on_a_large_scene) {
  const Circles w = random_scene(12000, 0.1, 11);  // arbitrary doubles: moves no double holds
  ExactEngine engine(World(w), EngineOptions{.threads = 2});
  engine.step();
  EXPECT_EQ(engine.world().circles(), step_all_pairs(World(w)).circles());
}

// ── Pairs kept across steps ───────────────────────────────────────────────────────────────────────────
//
// The exact engine keeps a PairList like the double engine, with the skin of its speed term alone (moves are
// exact) and radii padded by its approximations' errors (docs/exact-engine.md, "Pairs kept across steps").
// Each bound at its edge, then every horizon and thread count against each other and the oracle.

EngineOptions kept(std::uint64_t horizon, unsigned threads = 1) {
  return {.threads = threads, .keep_pairs = true, .horizon = horizon};
}

// Steps `engine` and the oracle from w side by side for `steps` steps; the first step at which they differ,
// or 0.
int first_difference(ExactEngine& engine, spec::Sequence w, int steps) {
  for (int t = 1; t <= steps; ++t) {
    engine.step();
    w = spec::resolved_step(w);
    if (engine.exact() != w) return t;
  }
  return 0;
}

TEST(exact_engine, kept_lists_hold_a_pair_that_meets_exactly_when_the_horizon_ends) {
  // Two unit circles at ±(1 + H), closing at v = 60 each (one unit a step, exact): world H is the first in
  // which they touch, exactly tangent, and the step from it exchanges their velocities. The list built at
  // world 0 for horizon H must hold the pair. Its slack is kSpeedBound's margin, H·2^-44.2, and the centres'
  // padding, 2.5·e = 2.5·(1 + H)·2^-49 per circle, so a skin below the exact bound H by a relative 2^-46
  // drops the pair for every H here (tried: the list is then empty and the engine misses the contact). One
  // unit of gap more and the pair is not listed.
  for (const std::uint64_t h : {1u, 2u, 7u, 16u, 100u, 1000u}) {
    const double c = 1 + static_cast<double>(h);
    const Circles w{{-c, 0, 60, 0, 1}, {c, 0, -60, 0, 1}};
    ExactEngine engine(World(w), kept(h));
    EXPECT_EQ(engine.candidates(), (std::vector<CandidatePair>{{0, 1}})) << "H = " << h;
    EXPECT_EQ(first_difference(engine, exact_of(w), static_cast<int>(h) + 3), 0) << "H = " << h;
    EXPECT_EQ(engine.world().circles()[0][2], -60) << "H = " << h << ": they never met";
    EXPECT_EQ(engine.stats().rebuilds, 2u) << "H = " << h;
    const Circles farther{{-c - 1, 0, 60, 0, 1}, {c + 1, 0, -60, 0, 1}};
    EXPECT_TRUE(ExactEngine(World(farther), kept(h)).candidates().empty()) << "H = " << h;
  }
}

// The list built at world 0 of `w` for the horizon h holds the pair {0, 1}, the engine follows the oracle
// through that list and the next, and the pair does meet: three steps past the horizon, circle 0 has circle
// 1's velocity.
void expect_kept_and_met(const Circles& w, std::uint64_t h) {
  ExactEngine engine(World(w), kept(h));
  EXPECT_EQ(engine.candidates(), (std::vector<CandidatePair>{{0, 1}})) << "H = " << h;
  EXPECT_EQ(first_difference(engine, exact_of(w), static_cast<int>(h) + 3), 0) << "H = " << h;
  const spec::CircleDoubles got = engine.world().circles()[0];
  EXPECT_TRUE(got[2] == w[1][2] && got[3] == w[1][3]) << "H = " << h << ": they never met";
}

TEST(exact_engine, kept_lists_hold_two_points_that_meet_when_the_horizon_ends_on_the_skin_and_padding_together) {
  // The edge of the skin and the centres' padding together: the padding, 2.5·e per circle with e about 2^-49
  // of its largest coordinate, is slack wherever the centres are doubles, and covers a speed term short of
  // 1/60 by less than it (impl/exact_engine.cpp, the skin's derivation). So the padding is made least: two
  // points (radii 0), one at the origin (e is then 2^-1073 alone), the other at 2H·(3, 4) (e = 8H·2^-49),
  // closing at ±(180, 240), 5 a step each, exactly, and coinciding at H·(3, 4) in world H. The pair is listed
  // iff 2·skin + 20H·2^-49 reaches 10H within the filter's margin: a speed term short of 1/60 by 2^-47.2
  // drops it for every H here and by 2^-47.6 at H = 100 (tried: the engine then misses the contact; 2^-47.8
  // is within the slack), where the unit circles of the test above need 2^-47.2.
  for (const std::uint64_t h : {1u, 2u, 16u, 100u}) {
    const double c = static_cast<double>(h);
    expect_kept_and_met({{0, 0, 180, 240, 0}, {6 * c, 8 * c, -180, -240, 0}}, h);
  }
}

TEST(exact_engine, kept_lists_give_a_pair_whose_squares_underflow_the_first_step_the_absolute_gap_term_allows) {
  // kGapAbsolute's edge, as in tests/pair_list_test.cpp: points c·2^-537 apart on each axis (c just above √½),
  // whose squares each round up to the least subnormal, so that the rounded distance is too long by
  // 2^-538.27; they coincide in world H. The padding here is below 2^-584 and changes nothing: kGapAbsolute
  // below 2^-538.27 drops the pair and the engine misses the contact (tried: zero and 2^-539).
  const double d = 0x1.6a09e8p-1 * 0x1p-537;
  ASSERT_EQ(d * d, 0x1p-1074);
  for (const std::uint64_t h : {1u, 16u}) {
    const double v = 60 * d / static_cast<double>(2 * h);
    expect_kept_and_met({{0, 0, v, v, 0}, {d, d, -v, -v, 0}}, h);
  }
}

TEST(exact_engine, kept_lists_hold_a_pair_whose_speed_no_double_holds_when_it_meets_at_the_horizons_end) {
  // Positions on thirds (L = 3, D = 180) and v = ±20: each circle moves 1/3 a step, exactly; V = 60 and the
  // speed bound reads it as 60·RN(1/3), below 20 by a relative 2^-54, which kSpeedBound's margin must cover.
  // Circles at ±(1 + H/3) touch exactly in world H.
  for (const int h : {1, 2, 7, 16, 100}) {
    const spec::Q c = 1 + spec::Q(h, 3);
    const spec::Sequence w{spec::circle(-c, 0, 20, 0, 1), spec::circle(c, 0, -20, 0, 1)};
    ExactEngine engine(w, kept(static_cast<std::uint64_t>(h)));
    ASSERT_EQ(engine.denominator(), Wide(180));
    EXPECT_EQ(engine.candidates(), (std::vector<CandidatePair>{{0, 1}})) << "H = " << h;
    EXPECT_EQ(first_difference(engine, w, h + 3), 0) << "H = " << h;
    EXPECT_EQ(engine.exact()[0].v.x(), spec::Q(-20)) << "H = " << h << ": they never met";
    const spec::Q d = c + spec::Q(1, 3);
    const spec::Sequence farther{spec::circle(-d, 0, 20, 0, 1), spec::circle(d, 0, -20, 0, 1)};
    EXPECT_TRUE(ExactEngine(farther, kept(static_cast<std::uint64_t>(h))).candidates().empty()) << "H = " << h;
  }
}

TEST(exact_engine, kept_lists_pad_radii_by_one_plus_root_two_errors_with_the_margin_the_derivation_claims) {
  // kCentreSpread ≥ (1 + √2)·(1 + 2^-5), and below (1 + √2)·(1 + 2^-4): by squares, exactly.
  const spec::Q k = spec::exact(exact::kCentreSpread);
  const auto root_two_below = [&](const spec::Q& factor) {  // √2 ≤ k/factor − 1
    const spec::Q x = k / factor - 1;
    return x > 0 && x * x >= 2;
  };
  EXPECT_TRUE(root_two_below(1 + spec::Q(1, 32)));
  EXPECT_FALSE(root_two_below(1 + spec::Q(1, 16)));
}

RC_GTEST_PROP(exact_engine, follows_the_oracle_through_a_tangency_with_any_horizon_or_none, ()) {
  const spec::Sequence w = *tangency_after_some_steps();
  const auto horizon = *rc::gen::inRange<std::uint64_t>(0, 65);
  const bool keep = *rc::gen::arbitrary<bool>();
  std::optional<ExactEngine> engine = made(w, EngineOptions{.threads = 1, .keep_pairs = keep, .horizon = horizon});
  if (engine) follow(*engine, w, 70);
}

RC_GTEST_PROP(exact_engine, follows_the_oracle_on_rational_worlds_with_any_horizon_or_none, ()) {
  const spec::Sequence w = *gen::world(spec::Radii::non_negative);
  const auto horizon = *rc::gen::inRange<std::uint64_t>(0, 65);
  const bool keep = *rc::gen::arbitrary<bool>();
  std::optional<ExactEngine> engine = made(w, EngineOptions{.threads = 1, .keep_pairs = keep, .horizon = horizon});
  if (engine) follow(*engine, w, *rc::gen::inRange(1, 61));
}

// Steps the double engine and `engines` side by side; every engine's world() must equal the double engine's
// after every step.
void lockstep(DoubleEngine& doubles, std::vector<ExactEngine>& engines, int steps) {
  for (int t = 1; t <= steps; ++t) {
    doubles.step();
    const Circles expected = doubles.world().circles();
    for (ExactEngine& e : engines) {
      e.step();
      ASSERT_EQ(e.world().circles(), expected) << "step " << t << ", " << e.threads() << " threads";
    }
  }
}

// ── Walking approximations ───────────────────────────────────────────────────────────────────────────
//
// A kept list in which at least a quarter of the circles are lonely walks: the listed circles' approximations
// take a double move a step, a ← RN(a + w), while the integers wait, and the error bound grows by walked()'s
// term (docs/exact-engine.md, "Walking approximations"). The world below puts a walk and the order's filter at
// their edges. Moves of w = 2^-33 from 2^20, whose spacing is 2^-32, are ties that round to the even 2^20: a
// circle moving right at v = 15·2^-31 (v/60 = 2^-33) keeps its approximation at 2^20 while the exact centre
// gains 2^-33 a step, the largest lag one rounding allows (u·|a|, u = 2^-53); one moving left from an even
// neighbour lags the other way. In units of 2^-33 the bound starts at 2^-49·2^20 = 16 and grows by
// 2^-52·2^20 = 2 a step (twice the lag), so a lag of k after k steps holds; a growth of a quarter of that
// (2^-54) fails after 32 steps, none after 16.
//
// A, pinned to the right-mover by its partner A′ (A′ precedes C, so A keeps A′'s velocity), and B, pinned to
// the left-mover by B′, both touch C and start 400 units apart on x. C takes the velocity of the least of A
// and B: their exact centres meet on x after 200 steps (y puts A first) and pass after 201, so A's in steps 1
// to 201 and B's from step 202, while the approximations still put A 400 units before B. The order's filter
// must leave that to the integers: 400 against a bound of 16 + 2·201, so a filter that trusts a difference
// above s·E for s < 400/418 takes A's velocity at step 202.
constexpr double kEven = 0x1p20, kLag = 0x1p-32;
constexpr double kRightward = 15 * 0x1p-31, kRadiusC = 77.5;
Circles walking_world() {
  const double b = kEven + 200 * kLag;  // B: 2^20 + 400·2^-33, an even multiple of the spacing 2^-32
  return {{kEven, 0, kRightward, 0, 1},              // A
          {kEven - 1.5, 0, kRightward, 0, 1},        // A′: overlaps A, left of C's reach
          {b, 100, -kRightward, 0, 1},               // B
          {b - 1.5, 100, -kRightward, 0, 1},         // B′
          {kEven + 60, 50, 0, 0, kRadiusC},          // C: 78.1 from A and B (≤ 78.5), 79.3 from A′ and B′
          {0, -1000, 0, 0, 1}, {0, -2000, 0, 0, 1}, {0, -3000, 0, 0, 1}};  // lonely
}

TEST(exact_engine, walking_approximations_stay_within_the_bound_when_every_move_rounds_to_a_tie) {
  const Circles w = walking_world();
  ExactEngine engine(World(w), kept(300));
  spec::Sequence oracle = engine.exact();
  ASSERT_TRUE(engine.approximations_hold());
  for (int t = 1; t <= 260; ++t) {
    engine.step();
    oracle = spec::resolved_step(oracle);
    ASSERT_TRUE(engine.walks()) << "step " << t;
    ASSERT_TRUE(engine.approximations_hold()) << "step " << t;
    ASSERT_EQ(engine.exact(), oracle) << "step " << t;
  }
  EXPECT_EQ(engine.stats().rebuilds, 1u);
  // world() rounds the exact state, which the walk never touches: A is 260 moves of 2^-33 from 2^20.
  EXPECT_EQ(engine.world().circles()[0][0], kEven + 130 * kLag);
}

TEST(exact_engine, walking_circles_are_ordered_by_their_integers_when_their_approximations_are_within_the_bound) {
  // C's velocity is A's (rightward) until step 201 and B's (leftward) from step 202, as the oracle says.
  const Circles w = walking_world();
  ExactEngine engine(World(w), kept(300));
  spec::Sequence oracle = engine.exact();
  for (int t = 1; t <= 230; ++t) {
    engine.step();
    oracle = spec::resolved_step(oracle);
    ASSERT_EQ(engine.exact(), oracle) << "step " << t;
    ASSERT_EQ(engine.world().circles()[4][2], t <= 201 ? kRightward : -kRightward) << "step " << t;
  }
}

TEST(exact_engine, every_horizon_and_thread_count_gives_the_same_state_as_the_double_engine_where_moves_are_exact) {
  // 12000 circles at 10% coverage (several chunks on two threads, contacts across chunk boundaries), every
  // move exact in doubles: the double engine is the oracle's trajectory here. Horizons 0 to 64, the
  // schedule's own and a list for each step alone, on one and two threads, after every step.
  const Circles w = exact_move_scene(12000);
  DoubleEngine doubles(World(w), EngineOptions{.threads = 1});
  std::vector<ExactEngine> engines;
  for (const unsigned threads : {1u, 2u}) {
    engines.emplace_back(World(w), EngineOptions{.threads = threads, .keep_pairs = false});
    for (const std::uint64_t h : {0u, 1u, 2u, 3u, 5u, 8u, 17u, 33u, 64u}) engines.emplace_back(World(w), kept(h, threads));
  }
  lockstep(doubles, engines, 16);
  EXPECT_GT(doubles.stats().contacts, 1000u) << "too few contacts to mean anything";
  for (const ExactEngine& e : engines) {
    EXPECT_EQ(e.exact(), engines[0].exact());
    EXPECT_EQ(e.stats().contacts, doubles.stats().contacts);
  }
  EXPECT_EQ(engines[0].stats().rebuilds, 16u);          // a list for each step alone
  EXPECT_EQ(engines[9].stats().rebuilds, 1u);           // H = 64: one list for all 16 steps
  EXPECT_LT(engines[1].stats().rebuilds, 16u / 4 + 2);  // the schedule's: kept
  EXPECT_GT(engines[0].stats().lonely_circle_steps, 0u);
}

TEST(exact_engine, lets_every_integer_wait_in_a_walking_list_and_still_equals_the_double_engine_at_every_step) {
  // 0.1% coverage: most circles are in no listed pair, so the list walks and every slot takes its moves at
  // the next rebuild (settle), while world() and exact() add the pending ones. Every move exact, so the
  // double engine is the oracle.
  const Circles w = exact_move_scene(20000, 0.001);
  DoubleEngine doubles(World(w), EngineOptions{.threads = 1});
  std::vector<ExactEngine> engines;
  for (const unsigned threads : {1u, 2u})
    for (const std::uint64_t h : {0u, 7u, 40u}) engines.emplace_back(World(w), kept(h, threads));
  lockstep(doubles, engines, 45);
  EXPECT_GT(doubles.stats().contacts, 10u) << "too few contacts to mean anything";
  for (const ExactEngine& e : engines) EXPECT_EQ(e.exact(), engines[0].exact());
  EXPECT_GT(engines[1].stats().lonely_circle_steps, 45u * 20000 * 3 / 4) << "the circles were not lonely";
}

TEST(exact_engine, keeps_its_proven_width_through_the_steps_of_a_kept_list) {
  // The width scenes above with lists that span the switch: positions move or wait between rebuilds, and
  // the width still changes exactly when its proof runs out, the state equal to the oracle's at every step.
  for (const std::uint64_t h : {1u, 16u, 64u, 100u}) {
    for (const auto& [v, from, to] : {std::tuple{0x1p55, 64u, 128u}, std::tuple{0x1p119, 128u, 0u}}) {
      ExactEngine engine(World({{0, 0, v, 0, 1}, {-1e3, 0, 0, 0, 1}}), kept(h));
      spec::Sequence oracle = engine.exact();
      ASSERT_EQ(engine.width(), from);
      for (int t = 1; t <= 70; ++t) {
        engine.step();
        oracle = spec::resolved_step(oracle);
        ASSERT_EQ(engine.exact(), oracle) << "H = " << h << ", step " << t;
        ASSERT_EQ(engine.width(), t <= 64 ? from : to) << "H = " << h << ", step " << t;
        ASSERT_TRUE(engine.narrow() || !engine.walks()) << "H = " << h << ", step " << t << ": GMP walks";
        ASSERT_TRUE(engine.approximations_hold()) << "H = " << h << ", step " << t;
      }
    }
  }
}

TEST(exact_engine, catches_its_lonely_circles_up_before_a_width_proof_in_the_middle_of_a_kept_list) {
  // Half the circles are in no listed pair, so the list walks and every integer waits; all take their
  // pending moves at once before the proof (settle), which must measure them where they are, the listed pair
  // (which has met, swapped velocities with 8 moves pending, and parted by then) included. D = 60 (every
  // value an integer, the far one a multiple of 8) and max |V| = 60: the far circle, lonely, starts at
  // X = 60·far = 2^61 − 1,472 and gains 60 a step, so the first 64-bit proof holds for 24 steps, inside the
  // list's horizon of 40, and the one at step 24, from X = 2^61 − 32, moves the state to 128 bits. Measured
  // without its 24 pending moves, it would stay at 64.
  const double far = 38430716820228208;  // 60·far = 2^61 − 1,472
  ExactEngine engine(World({{-10, 0, 60, 0, 1}, {10, 0, -60, 0, 1}, {0, 1000, 0, 60, 1}, {far, 0, 60, 0, 1}}),
                     kept(40));
  ASSERT_EQ(engine.width(), 64u);
  spec::Sequence oracle = engine.exact();
  for (int t = 1; t <= 40; ++t) {
    engine.step();
    oracle = spec::resolved_step(oracle);
    ASSERT_EQ(engine.exact(), oracle) << "step " << t;
    ASSERT_EQ(engine.width(), t <= 24 ? 64u : 128u) << "step " << t;
  }
  EXPECT_EQ(engine.stats().rebuilds, 1u);
  EXPECT_EQ(engine.stats().contacts, 1u) << "the pair touches at step 9 alone, then parts";
  EXPECT_EQ(engine.stats().lonely_circle_steps, 40u * 2);
}

TEST(exact_engine, stops_walking_when_the_state_moves_to_gmp_integers_in_the_middle_of_a_kept_list) {
  // The test above at the 128-bit limit: a radius of 2^-60 makes D = 60·2^60 and V = 60·2^60 for |v| = 60.
  // The far circle starts at X = 2^125 − 2^69 (p = 128·(2^56 − 1)/15, a double), so the first proof holds
  // for ⌊2^69/V⌋ = 8 steps and the one at step 8, from X = 2^125 − 32·2^60, finds no 128-bit headroom: GMP
  // from step 9, in the middle of the list's horizon of 40, with the pair meeting at step 9. GMP states
  // settle every step, so the list stops walking and every approximation is computed from the integers.
  const double far = 128.0 * static_cast<double>(((std::uint64_t{1} << 56) - 1) / 15);  // exact: below 2^53
  ExactEngine engine(World({{-10, 0, 60, 0, 1}, {10, 0, -60, 0, 1}, {0, 1000, 0, 60, 1}, {far, 0, 60, 0, 1},
                            {0, -1000, 0, 0, 0x1p-60}}),
                     kept(40));
  ASSERT_EQ(engine.width(), 128u);
  spec::Sequence oracle = engine.exact();
  for (int t = 1; t <= 40; ++t) {
    engine.step();
    oracle = spec::resolved_step(oracle);
    ASSERT_EQ(engine.exact(), oracle) << "step " << t;
    ASSERT_EQ(engine.width(), t <= 8 ? 128u : 0u) << "step " << t;
    ASSERT_EQ(engine.walks(), t <= 8) << "step " << t;
    ASSERT_TRUE(engine.approximations_hold()) << "step " << t;
  }
  EXPECT_EQ(engine.stats().rebuilds, 1u);
  EXPECT_EQ(engine.stats().contacts, 1u);
}

TEST(exact_engine, counts_its_work_as_the_double_engine_does) {
  // Two circles far apart: every step is quiet, no circle is tested, and the schedule lengthens the horizon
  // as it does for the double engine; then a fixed horizon on a busy scene whose moves are exact: the same
  // steps, lists and contacts.
  const Circles apart{{0, 0, 1, 0, 1}, {100, 0, -1, 0, 1}};
  ExactEngine exact(World(apart), EngineOptions{.threads = 1});
  DoubleEngine doubles(World(apart), EngineOptions{.threads = 1});
  for (int t = 0; t < 50; ++t) {
    exact.step();
    doubles.step();
  }
  EXPECT_EQ(exact.stats().steps, 50u);
  EXPECT_EQ(exact.stats().quiet_steps, 50u);
  EXPECT_EQ(exact.stats().lonely_circle_steps, 100u);
  EXPECT_EQ(exact.stats().pairs_tested, 0u);
  EXPECT_EQ(exact.stats().rebuilds, doubles.stats().rebuilds);
  const Circles busy = exact_move_scene(3000);
  ExactEngine e(World(busy), kept(8));
  DoubleEngine d(World(busy), kept(8));
  for (int t = 0; t < 30; ++t) {
    e.step();
    d.step();
  }
  EXPECT_EQ(e.stats().steps, 30u);
  EXPECT_EQ(e.stats().rebuilds, d.stats().rebuilds);
  EXPECT_EQ(e.stats().contacts, d.stats().contacts);
  EXPECT_GT(e.stats().contacts, 100u);
  EXPECT_GE(e.stats().pairs_tested, e.stats().contacts);
  EXPECT_GT(e.stats().pairs_listed, 0u);
}

// ── The integer kernels ───────────────────────────────────────────────────────────────────────────────

Narrow narrow(std::uint64_t hi, std::uint64_t lo, int shift) {
  return static_cast<Narrow>(((NarrowMagnitude{hi} << 64) | lo) >> shift);
}
Wide wide(Narrow x) {
  const bool negative = x < 0;
  const NarrowMagnitude m = negative ? NarrowMagnitude{0} - static_cast<NarrowMagnitude>(x) : static_cast<NarrowMagnitude>(x);
  Wide w(static_cast<std::uint64_t>(m >> 64));
  w <<= 64;
  w += Wide(static_cast<std::uint64_t>(m));
  return negative ? Wide(-w) : w;
}

RC_GTEST_PROP(exact_round_quotient, is_the_nearest_double_of_the_quotient_ties_included, ()) {
  // d up to 2^127; n of any size below 2^127, or a tie: an odd q in [2^53, 2^54) times d (n/d = q lies
  // halfway between the even integers that are its neighbouring doubles), or one off it.
  const int dshift = *rc::gen::inRange(1, 128);
  const auto d = std::max<NarrowMagnitude>(1, static_cast<NarrowMagnitude>(narrow(*rc::gen::arbitrary<std::uint64_t>(),
                                                                                     *rc::gen::arbitrary<std::uint64_t>(), dshift)));
  Narrow n = narrow(*rc::gen::arbitrary<std::uint64_t>(), *rc::gen::arbitrary<std::uint64_t>(), *rc::gen::inRange(1, 128));
  if (*rc::gen::arbitrary<bool>() && d < (NarrowMagnitude{1} << 70)) {
    const auto q = (*rc::gen::inRange<std::uint64_t>(std::uint64_t{1} << 52, std::uint64_t{1} << 53)) * 2 + 1;
    n = static_cast<Narrow>(NarrowMagnitude{q} * d) + *rc::gen::inRange(-1, 2);
  }
  if (*rc::gen::arbitrary<bool>()) n = -n;
  const double got = exact::round_quotient(n, d);
  RC_ASSERT(got == spec::nearest_double(spec::Q(wide(n)) / spec::Q(wide(static_cast<Narrow>(d)))));
  RC_ASSERT(got == exact::round_quotient(wide(n), wide(static_cast<Narrow>(d))));
}

TEST(exact_round_quotient, rounds_halfway_cases_to_even_and_zero_to_plus_zero) {
  const Narrow two53 = Narrow{1} << 53;
  EXPECT_EQ(exact::round_quotient(2 * two53 + 1, 2), 0x1p53);          // 2^53 + 1/2: down to 2^53
  EXPECT_EQ(exact::round_quotient(2 * two53 + 3, 2), 0x1p53 + 2);      // 2^53 + 3/2: up to the even 2^53 + 2
  EXPECT_EQ(exact::round_quotient(-(2 * two53 + 3), 2), -(0x1p53 + 2));
  EXPECT_EQ(exact::round_quotient(1, 3), 1.0 / 3);
  EXPECT_FALSE(std::signbit(exact::round_quotient(Narrow{0}, 7)));
}

RC_GTEST_PROP(exact_intersect_scaled, decides_as_gmp_on_random_and_tangent_arguments, ()) {
  // Tangent families (3, 4, 5)·m·2^j up to 2^125, moved by −1, 0 or +1 in one argument, or random values.
  Narrow s, dx, dy;
  if (*rc::gen::arbitrary<bool>()) {
    const int j = *rc::gen::inRange(0, 100);
    const Narrow m = *rc::gen::inRange<std::int64_t>(1, std::int64_t{1} << 20);
    s = 5 * m << j;
    dx = 3 * m << j;
    dy = 4 * m << j;
    Narrow* moved = *rc::gen::element(&s, &dx, &dy);
    *moved += *rc::gen::inRange(-1, 2);
    if (*rc::gen::arbitrary<bool>()) dx = -dx;
  } else {
    const auto draw = [] { return narrow(*rc::gen::arbitrary<std::uint64_t>(), *rc::gen::arbitrary<std::uint64_t>(), *rc::gen::inRange(2, 128)); };
    s = draw();
    s = s < 0 ? -s : s;
    dx = draw();
    dy = draw();
  }
  const Wide ws = wide(s), wx = wide(dx), wy = wide(dy);
  const bool expected = ws * ws >= wx * wx + wy * wy;
  RC_ASSERT(exact::intersect_scaled(s, dx, dy) == expected);
  RC_ASSERT(exact::intersect_scaled(ws, wx, wy) == expected);
}

RC_GTEST_PROP(exact_intersect_scaled, decides_as_gmp_in_64_bits_up_to_2_to_the_62, ()) {
  // Within the 64-bit width's range (|S|, |dX|, |dY| ≤ 2^62): (3, 4, 5) tangencies moved by one, or random.
  exact::Word s, dx, dy;
  if (*rc::gen::arbitrary<bool>()) {
    const exact::Word m = *rc::gen::inRange<exact::Word>(1, exact::Word{1} << 59);
    s = 5 * m;
    dx = 3 * m;
    dy = 4 * m;
    exact::Word* moved = *rc::gen::element(&s, &dx, &dy);
    *moved += *rc::gen::inRange(-1, 2);
  } else {
    const auto draw = [] { return *rc::gen::inRange<exact::Word>(-(exact::Word{1} << 62), (exact::Word{1} << 62) + 1); };
    s = std::abs(draw());
    dx = draw();
    dy = draw();
  }
  if (*rc::gen::arbitrary<bool>()) dy = -dy;
  const Wide ws(s), wx(dx), wy(dy);
  RC_ASSERT(exact::intersect_scaled(s, dx, dy) == (ws * ws >= wx * wx + wy * wy));
}

RC_GTEST_PROP(exact_to_double, is_the_nearest_double_of_any_128_bit_integer, ()) {
  // Any magnitude, and the fast path's edge: |x| just below and at 2^105, where the split changes.
  Narrow x = narrow(*rc::gen::arbitrary<std::uint64_t>(), *rc::gen::arbitrary<std::uint64_t>(), *rc::gen::inRange(1, 128));
  if (*rc::gen::arbitrary<bool>()) x = (Narrow{1} << 105) + *rc::gen::inRange(-3, 4);
  if (*rc::gen::arbitrary<bool>()) x = -x;
  RC_ASSERT(exact::to_double(x) == spec::nearest_double(spec::Q(wide(x))));
}

// A double ≥ the rational q.
double upper(const spec::Q& q) {
  const double d = spec::nearest_double(q);
  return spec::exact(d) < q ? std::nextafter(d, std::numeric_limits<double>::infinity()) : d;
}

RC_GTEST_PROP(exact_intersect_approximate, never_contradicts_the_exact_test_for_approximations_within_their_errors, ()) {
  // Exact circles, tangent along (3, 4)/5 (then moved by 2^-40 or 2^-60 of the distance, or not), or
  // arbitrary; approximations off by up to a chosen scale (none, 10^-12, 10^-6 relative, or 10^-3); each
  // circle's error bound the largest of its three errors, rounded up, sometimes doubled.
  const auto draw = [](int range) { return spec::Q(*rc::gen::inRange(-range, range + 1), *rc::gen::inRange(1, 1000)); };
  const spec::Q xa = draw(1'000'000), ya = draw(1'000'000);
  const spec::Q ra = abs(draw(10'000)), rb = abs(draw(10'000));
  spec::Q xb, yb;
  if (*rc::gen::arbitrary<bool>()) {
    const spec::Q nudge = spec::Q(*rc::gen::inRange(-1, 2)) / spec::Q(Wide(1) << *rc::gen::element(40, 60));
    xb = xa + (ra + rb) * 3 / 5 * (1 + nudge);
    yb = ya + (ra + rb) * 4 / 5 * (1 + nudge);
  } else {
    xb = xa + draw(20'000);
    yb = ya + draw(20'000);
  }
  const double scale = *rc::gen::element(0.0, 1e-12, 1e-6, 1e-3);
  const auto approximate = [scale](const spec::Q& x) {
    const double d = spec::nearest_double(x);
    const double off = scale * static_cast<double>(*rc::gen::inRange(-1000, 1001)) / 1000;
    return d + (scale < 1e-3 ? off * std::fabs(d) : off);
  };
  // ρ ≥ 0, as the engine's are.
  const double ax = approximate(xa), ay = approximate(ya), pa = std::max(0.0, approximate(ra));
  const double bx = approximate(xb), by = approximate(yb), pb = std::max(0.0, approximate(rb));
  const auto error = [](std::initializer_list<std::pair<double, const spec::Q*>> fields) {
    spec::Q largest = 0;
    for (const auto& [d, q] : fields) largest = std::max(largest, spec::Q(abs(spec::exact(d) - *q)));
    return upper(largest) * (*rc::gen::arbitrary<bool>() ? 2 : 1);
  };
  const double ea = error({{ax, &xa}, {ay, &ya}, {pa, &ra}}), eb = error({{bx, &xb}, {by, &yb}, {pb, &rb}});
  const bool expected = (ra + rb) * (ra + rb) >= (xb - xa) * (xb - xa) + (yb - ya) * (yb - ya);
  const Decision d = exact::intersect_approximate(ax, ay, pa, ea, bx, by, pb, eb);
  RC_CLASSIFY(d == Decision::undecided, "undecided");
  if (d != Decision::undecided) RC_ASSERT((d == Decision::intersect) == expected);
}

TEST(exact_intersect_approximate, decides_clear_pairs_and_leaves_tangency_to_the_integers) {
  // Radii 2 and 2 at distance 3 (overlap), 5 (apart), 4 (tangent), centres known to within 10^-9.
  EXPECT_EQ(exact::intersect_approximate(1000, 1000, 2, 1e-9, 1003, 1000, 2, 1e-9), Decision::intersect);
  EXPECT_EQ(exact::intersect_approximate(1000, 1000, 2, 1e-9, 1000, 1005, 2, 1e-9), Decision::disjoint);
  EXPECT_EQ(exact::intersect_approximate(1000, 1000, 2, 1e-9, 1000, 1004, 2, 1e-9), Decision::undecided);
  // 10^-9 off tangency is decided with errors of 10^-13, left with errors of 10^-9.
  EXPECT_EQ(exact::intersect_approximate(0, 0, 2, 1e-13, 4 + 1e-9, 0, 2, 1e-13), Decision::disjoint);
  EXPECT_EQ(exact::intersect_approximate(0, 0, 2, 1e-9, 4 + 1e-9, 0, 2, 1e-9), Decision::undecided);
}

TEST(exact_intersect_approximate, leaves_a_pair_to_the_integers_when_its_squares_underflow_and_round_against_the_exact_sign) {
  // Approximations exact (e = 0) and no rounding of s, dx, dy: only the squares' underflow is off, by 2^-1074
  // in all, far beyond any relative bound on sums of squares this small.
  const auto w = circles::testing::underflowing_intersecting_pair();
  const double r = w[0][4], x = w[1][0], y = w[1][1];
  const spec::Q s = spec::exact(r) + spec::exact(r), dx = spec::exact(x), dy = spec::exact(y);
  ASSERT_TRUE(s * s >= dx * dx + dy * dy);                       // they intersect
  ASSERT_LT((r + r) * (r + r) - (x * x + y * y), 0.0);            // the squares say they do not
  const Decision d = exact::intersect_approximate(0, 0, r, 0, x, y, r, 0);
  EXPECT_NE(d, Decision::disjoint);
}

TEST(exact_engine, meets_a_pair_whose_squares_underflow_and_round_against_the_exact_sign) {
  const Circles w = circles::testing::underflowing_intersecting_pair();
  ExactEngine engine(World(w), EngineOptions{.threads = 1});
  const spec::Sequence next = spec::resolved_step(exact_of(w));
  ASSERT_EQ(next[0].v, exact_of(w)[1].v);  // they meet
  engine.step();
  EXPECT_EQ(engine.exact(), next);
}

TEST(exact_intersect_scaled, holds_at_tangency_and_fails_one_unit_past_it_at_2_to_the_120) {
  const Narrow unit = Narrow{1} << 100, m = (Narrow{1} << 20) - 1;
  EXPECT_TRUE(exact::intersect_scaled(5 * m * unit, 3 * m * unit, 4 * m * unit));
  EXPECT_FALSE(exact::intersect_scaled(5 * m * unit - 1, 3 * m * unit, 4 * m * unit));
  EXPECT_TRUE(exact::intersect_scaled(5 * m * unit, 3 * m * unit - 1, 4 * m * unit));
}

}  // namespace
}  // namespace circles::impl
