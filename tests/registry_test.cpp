// The engine registry (engines/registry.hpp): the names `--engine` takes, and each engine held to
// spec::resolved_step_rounded, the correctly rounded oracle step, and to its report of an overflow.
#include "engines/registry.hpp"

#include "spec/oracle.hpp"
#include "tests/step_worlds.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <cfloat>

namespace circles::engines {
namespace {

using circles::testing::kOverflowsAtStep4;
using circles::testing::kTouching;
using circles::testing::thrown;

TEST(engines, lists_the_double_engine_the_exact_engine_and_the_oracle) {
  EXPECT_EQ(engine_names(), "double, exact, oracle");
  EXPECT_EQ(&engine("double"), find_engine("double"));
  EXPECT_TRUE(engine("exact").exact);
  EXPECT_FALSE(engine("double").exact);
  EXPECT_EQ(find_engine("fast"), nullptr);
}

TEST(engines, names_the_valid_engines_for_an_unknown_name) {
  const auto e = thrown<UnknownEngine>([] { engine("fast"); });
  ASSERT_TRUE(e);
  EXPECT_STREQ(e->what(), R"(unknown engine "fast" (the engines are: double, exact, oracle))");
}

TEST(engines, each_steps_like_the_rounded_oracle) {
  const Circles want = spec::resolved_step_rounded(kTouching);
  ASSERT_EQ(want[0][2], -1.0) << "the test world must collide";
  for (const EngineEntry& e : engines())
    for (const unsigned threads : {0u, 1u, 2u}) EXPECT_EQ(step_once(e, kTouching, threads), want) << e.name;
}

TEST(engines, each_reports_an_overflow_with_its_step_circle_and_field_and_keeps_the_world) {
  for (const EngineEntry& e : engines()) {
    const auto stepper = e.start(kOverflowsAtStep4, 1, 0);
    for (int t = 0; t < 3; ++t) stepper->step();
    const Circles w3 = stepper->circles();
    EXPECT_EQ(w3[1][0], DBL_MAX) << e.name;
    const auto overflow = thrown<StepOverflow>([&] { stepper->step(); });
    ASSERT_TRUE(overflow) << e.name;
    EXPECT_EQ(overflow->step, 4u);
    EXPECT_EQ(overflow->index, 1u);
    EXPECT_EQ(overflow->field, spec::Field::px);
    EXPECT_STREQ(overflow->what(), "step 4, circle 1, field px: the position p + v/60 overflows to infinity");
    EXPECT_EQ(stepper->steps(), 3u) << e.name;
    EXPECT_EQ(stepper->circles(), w3) << e.name;
  }
}

}  // namespace
}  // namespace circles::engines
