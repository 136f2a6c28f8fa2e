// The step fuzzer's pieces in the ordinary build (fuzz/step_input.hpp, fuzz/step_judge.hpp): the encoding round
// trips, the mutations keep worlds in C, and the judge that fuzz/step_fuzzer.cpp and fuzz/step_harness.cpp apply
// catches a wrong step fed through it: the naive engine (impl::NaiveEngine, the double predicate without its
// exactness), a step that misses an overflow, an exact chain off by one circle.
#include "fuzz/step_input.hpp"
#include "fuzz/step_judge.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

#include "formats/scene.hpp"
#include "impl/engine.hpp"
#include "properties/generators.hpp"

namespace circles::fuzz {
namespace {

bool same_bits(const StepInput& a, const StepInput& b) {
  if (a.steps != b.steps || a.circles.size() != b.circles.size()) return false;
  for (std::size_t k = 0; k < a.circles.size(); ++k)
    for (std::size_t f = 0; f < 5; ++f)
      if (std::bit_cast<std::uint64_t>(a.circles[k][f]) != std::bit_cast<std::uint64_t>(b.circles[k][f])) return false;
  return true;
}

bool in_c(const Circles& w) {
  for (const auto& c : w) {
    for (const double x : c)
      if (!std::isfinite(x)) return false;
    if (c[4] < 0) return false;
  }
  return w.size() <= kMaxCircles;
}

rc::Gen<StepInput> step_input() {
  return rc::gen::build<StepInput>(
      rc::gen::set(&StepInput::steps, rc::gen::inRange<std::uint64_t>(1, kMaxSteps + 1)),
      rc::gen::set(&StepInput::circles, properties::gen::double_world(12, properties::gen::finite_double())));
}

// A chain of the double engine `Engine` from w0, to its first PositionOverflow.
template <class Engine>
Chain engine_chain(const Circles& w0, std::uint64_t steps) {
  return chain_of(w0, steps, [](const Circles& w) {
    Engine e{impl::World{w}};
    try {
      e.step();
    } catch (const impl::PositionOverflow& o) {
      return Chain{{}, Overflow{o.step, o.index, o.field}};
    }
    return Chain{{e.world().circles()}, std::nullopt};
  });
}

RC_GTEST_PROP(step_input, an_encoded_world_decodes_to_the_same_doubles_bit_for_bit, ()) {
  const StepInput input = *step_input();
  RC_ASSERT(same_bits(decode(encode(input)), input));
}

RC_GTEST_PROP(step_input, any_bytes_decode_to_a_world_of_c_which_encodes_to_bytes_that_decode_to_it_again, ()) {
  const auto bytes = *rc::gen::container<std::vector<std::uint8_t>>(rc::gen::arbitrary<std::uint8_t>());
  const StepInput input = decode(bytes);
  RC_ASSERT(in_c(input.circles));
  RC_ASSERT(input.steps >= 1u && input.steps <= kMaxSteps);
  RC_ASSERT(same_bits(decode(encode(input)), input));
}

TEST(step_input, a_family_byte_and_seed_decode_to_that_familys_world) {
  std::vector<std::uint8_t> bytes(kHeaderBytes, 0);
  bytes[0] = 3;  // 4 steps
  bytes[1] = 1 + static_cast<std::uint8_t>(properties::Family::tangency);
  bytes[2] = 42;
  const StepInput input = decode(bytes);
  EXPECT_EQ(input.steps, 4u);
  EXPECT_EQ(input.circles, family_world(properties::Family::tangency, 42));
  EXPECT_FALSE(input.circles.empty());
}

RC_GTEST_PROP(step_input, every_mutation_keeps_a_world_of_c_that_round_trips, ()) {
  StepInput input = *step_input();
  const auto seeds = *rc::gen::container<std::vector<std::uint64_t>>(8, rc::gen::arbitrary<std::uint64_t>());
  for (const std::uint64_t seed : seeds) {
    input = mutate(input, seed);
    RC_ASSERT(in_c(input.circles));
    RC_ASSERT(same_bits(decode(encode(input)), input));
  }
}

TEST(step_input, the_tangent_mutation_makes_two_circles_exactly_tangent_at_some_seed) {
  // Circles on the integers: the mutation's offsets and radii are exact, so some seed gives an exact tangency.
  const StepInput start{1, {{0, 0, 0, 0, 1}, {10, 10, 0, 0, 1}}};
  int tangent = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const Circles w = mutate(start, seed).circles;
    for (std::size_t a = 0; a < w.size(); ++a)
      for (std::size_t b = a + 1; b < w.size(); ++b) {
        const double dx = w[b][0] - w[a][0], dy = w[b][1] - w[a][1], s = w[a][4] + w[b][4];
        if (s > 0 && dx * dx + dy * dy == s * s) ++tangent;
      }
  }
  EXPECT_GT(tangent, 0);
}

// The nearly tangent mutation puts pairs where the filters' bounds decide: F = S² − X² − Y² not 0, yet within
// 2^-40·S² of it, at several scales, which the exact tangent mutation (F = 0) and random worlds do not reach.
TEST(step_input, the_nearly_tangent_mutation_puts_pairs_a_few_roundings_from_tangency) {
  const StepInput start{1, {{0, 0, 0, 0, 1}, {1000, -1000, 0, 0, 3}}};
  int close = 0;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    const Circles w = mutate(start, seed).circles;
    for (std::size_t a = 0; a < w.size(); ++a)
      for (std::size_t b = a + 1; b < w.size(); ++b) {
        const spec::Q x = spec::Q(w[b][0]) - spec::Q(w[a][0]), y = spec::Q(w[b][1]) - spec::Q(w[a][1]);
        const spec::Q s = spec::Q(w[a][4]) + spec::Q(w[b][4]);
        const spec::Q f = s * s - x * x - y * y;
        if (f != 0 && s != 0 && abs(f) < s * s / spec::Q(std::ldexp(1.0, 40))) ++close;
      }
  }
  EXPECT_GE(close, 10);
}

// The fast references (the exact engine's rounded step, every pair) are the oracle's rounded steps on every
// small family's worlds, and one input in about kOracleSample is judged by the oracle too, the same one each time.
TEST(step_judge, the_fast_references_are_the_oracles_steps_and_the_oracle_judges_a_fixed_sample) {
  for (const properties::Family f : properties::families(properties::Profile::resolved)) {
    if (properties::is_big(f)) continue;
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
      const Circles w = family_world(f, seed);
      const Chain want = rounded_reference(w, 3);
      EXPECT_EQ(difference(want, exact_engine_reference(w, 3)), std::nullopt) << properties::name(f) << " " << seed;
      EXPECT_EQ(difference(want, all_pairs_reference(w, 3)), std::nullopt) << properties::name(f) << " " << seed;
    }
  }
  int sampled = 0;
  for (int k = 0; k < 1600; ++k) {
    const StepInput input{1 + static_cast<std::uint64_t>(k % 16), {{static_cast<double>(k), 0, 1, 0, 1}}};
    sampled += oracle_judges(input);
    EXPECT_EQ(oracle_judges(input), oracle_judges(StepInput(input)));
  }
  EXPECT_GT(sampled, 1600 / static_cast<int>(kOracleSample) / 2);
  EXPECT_LT(sampled, 1600 / static_cast<int>(kOracleSample) * 2);
  EXPECT_FALSE(oracle_judges(StepInput{1, Circles(kOracleCircles + 1, {0, 0, 0, 0, 1})}));  // never a big world
}

TEST(step_judge, the_double_engine_passes_and_the_naive_engine_is_caught_on_the_ulp_nudge_family) {
  int caught = 0;
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    const Circles w = family_world(properties::Family::ulp_nudge, seed);
    const Chain want = rounded_reference(w, 2);
    EXPECT_EQ(difference(want, engine_chain<impl::DoubleEngine>(w, 2)), std::nullopt) << "seed " << seed;
    if (difference(want, engine_chain<impl::NaiveEngine>(w, 2))) ++caught;
  }
  EXPECT_GT(caught, 0);
}

TEST(step_judge, the_naive_engine_is_caught_on_a_big_world_judged_by_the_exact_grid) {
  // Past kOracleCircles the reference is impl::ExactGrid: the crowds' hubs are touched at the edge of tangency.
  int caught = 0, judged = 0;
  for (std::uint64_t seed = 0; seed < 8 && caught == 0; ++seed) {
    const Circles w = family_world(properties::Family::crowds, seed);
    if (w.size() <= kOracleCircles) continue;
    ++judged;
    const Chain want = rounded_reference(w, 1);
    EXPECT_EQ(difference(want, engine_chain<impl::DoubleEngine>(w, 1)), std::nullopt) << "seed " << seed;
    if (difference(want, engine_chain<impl::NaiveEngine>(w, 1))) ++caught;
  }
  EXPECT_GT(judged, 0);
  EXPECT_GT(caught, 0);
}

TEST(step_judge, a_step_that_misses_an_overflow_or_names_another_circle_is_caught) {
  const Circles w{{0, 0, 0, 0, 1}, {DBL_MAX, 0, DBL_MAX, 0, 1}};
  const Chain want = rounded_reference(w, 1);
  ASSERT_TRUE(want.overflow.has_value());
  EXPECT_EQ(want.overflow->index, 1u);
  EXPECT_EQ(want.overflow->field, spec::Field::px);
  EXPECT_EQ(difference(want, engine_chain<impl::DoubleEngine>(w, 1)), std::nullopt);
  // A C step names no circle, so its overflow's field is not compared.
  EXPECT_EQ(difference(want, Chain{{}, Overflow{1, Overflow::kUnknown, spec::Field::py}}), std::nullopt);
  EXPECT_EQ(difference(want, Chain{{w}, std::nullopt}),
            "after 0 steps alike: no overflow, want an overflow at step 1, circle 1 px");
  EXPECT_EQ(difference(want, Chain{{}, Overflow{1, 0, spec::Field::px}}),
            "an overflow at step 1, circle 0 px, want an overflow at step 1, circle 1 px");
  EXPECT_EQ(difference(want, Chain{{}, Overflow{1, 1, spec::Field::py}}),
            "an overflow at step 1, circle 1 py, want an overflow at step 1, circle 1 px");
}

TEST(step_judge, an_exact_chain_with_a_wrong_circle_is_caught_and_named) {
  const Circles w{{0, 0, 60, 0, 1}, {3, 0, 0, 0, 1}};
  const ExactChain want = exact_reference(w, 3);
  ASSERT_EQ(want.worlds.size(), 3u);
  ExactChain wrong = want;
  wrong.worlds[1][1].v[0] = 1;
  EXPECT_EQ(difference(want, want), std::nullopt);
  const auto d = difference(want, wrong);
  ASSERT_TRUE(d.has_value());
  EXPECT_TRUE(d->starts_with("step 2, circle 1: got ")) << *d;
}

TEST(step_judge, the_scene_of_a_failure_reads_back_as_the_same_doubles) {
  const Circles w{{-0.0, 0x1p-1074, DBL_MAX, -DBL_MAX, 0.1}, {1e300, -2.5, 0, 60, 0}};
  const formats::Scene scene = formats::parse_scene(scene_text(w, 7, "a failure"), "failure.json");
  EXPECT_EQ(formats::doubles_of(scene), w);  // by value: the scene keeps −0 as 0
  EXPECT_EQ(scene.steps, 7u);
  EXPECT_EQ(scene.name, "a failure");
}

}  // namespace
}  // namespace circles::fuzz
