// EngineOptions change the work, never the bits: pair lists kept across steps, their horizons, and thread
// counts (the golden tests cover whole trajectories in every build; these look at the lists' proof where it
// is tight; tests/pair_list_test.cpp puts each of its bounds at its edge).
#include "impl/engine.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include "spec/oracle.hpp"
#include "tests/thrown.hpp"

namespace circles::impl {
namespace {

using spec::Circles;

// Steps an engine that keeps its pair lists and one that builds a list for every step side by side and
// requires the same bits after every step; returns the step (1-based) at which circle 0 first changed
// velocity, or 0. `quiet` is the keeping engine's count of steps that tested no pair.
int lockstep(const Circles& w, int steps, std::uint64_t& quiet) {
  DoubleEngine skipping{World{w}, {1, true}};
  DoubleEngine every{World{w}, {1, false}};
  int first_change = 0;
  for (int s = 1; s <= steps; ++s) {
    skipping.step();
    every.step();
    const Circles a = skipping.world().circles(), b = every.world().circles();
    for (std::size_t k = 0; k < a.size(); ++k)
      for (std::size_t f = 0; f < 5; ++f)
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a[k][f]), std::bit_cast<std::uint64_t>(b[k][f]))
            << "step " << s << ", circle " << k << ", field " << f;
    if (first_change == 0 && a[0][2] != w[0][2]) first_change = s;
  }
  quiet = skipping.quiet_steps();
  EXPECT_EQ(every.stats().rebuilds, every.steps());
  EXPECT_LT(skipping.stats().rebuilds, skipping.steps() / 4 + 2) << "the lists were not kept";
  return first_change;
}

TEST(engine_options, kept_lists_stop_exactly_at_a_tangency_reached_after_many_steps) {
  // Two unit circles 2 + 2·K apart close the gap by exactly 2 per step (v = ±60: every move is exact), so
  // world K is the first in which they touch, exactly tangent; the step from it exchanges their velocities.
  for (const int k : {1, 7, 100, 1000, 4097}) {
    const double gap = 2 + 2.0 * k;
    const Circles w{{0, 0, 60, 0, 1}, {gap, 0, -60, 0, 1}};
    std::uint64_t quiet = 0;
    EXPECT_EQ(lockstep(w, k + 3, quiet), k + 1) << "K = " << k;
    if (k >= 100) {
      EXPECT_GT(quiet, 0u) << "K = " << k << ": no step was skipped";
    }
    // The oracle agrees on the moment: world K is tangent.
    Circles now = w;
    for (int s = 0; s < k; ++s) now = spec::resolved_step_rounded(now);
    EXPECT_EQ(now[1][0] - now[0][0], 2.0);
  }
}

TEST(engine_options, kept_lists_stop_in_time_for_moves_no_double_holds) {
  // v = 1 moves 1/60 per step, never exact: positions are rounded every step. The circles meet after about
  // 60·gap/2 steps; both engines must see the first contact in the same world.
  for (const double gap : {2.5, 3.0, 10.0, 40.0}) {
    const Circles w{{0.1, 0.3, 1, 0, 1}, {0.1 + gap, 0.3, -1, 0, 1}};
    std::uint64_t quiet = 0;
    const int changed = lockstep(w, static_cast<int>(30 * gap) + 40, quiet);
    EXPECT_GT(changed, 0) << "gap " << gap << ": they never met";
    if (gap >= 10) {
      EXPECT_GT(quiet, 0u) << "gap " << gap;
    }
  }
}

TEST(engine_options, kept_lists_keep_the_overflow_error_and_its_step) {
  // A lone circle running into DBL_MAX in quiet steps (steps with an empty list, updating in place only while
  // the rebuild proved no overflow possible) (v/60 = 2^971, one ulp of the top binade per step,
  // from 100 ulps below DBL_MAX: step 101 overflows): the error names the step at which the oracle's position first becomes
  // infinite, and the world stays the one before.
  const double m = 0x1.fffffffffffffp1023;
  const Circles w{{m - 0x1p971 * 100, 0, 0x1.ep976, 0, 1}, {0, 0, 0, 0, 1}};
  Circles now = w;
  int overflow_at = 0;
  for (int s = 1; s <= 400 && overflow_at == 0; ++s) {
    const Circles next = spec::resolved_step_rounded(now);
    if (std::isinf(next[0][0]))
      overflow_at = s;
    else
      now = next;
  }
  ASSERT_GT(overflow_at, 1);
  DoubleEngine e{World{w}};
  std::optional<PositionOverflow> error;
  for (int s = 1; s <= 400 && !error; ++s) {
    try {
      e.step();
    } catch (const PositionOverflow& caught) {
      error = caught;
    }
  }
  ASSERT_TRUE(error);
  EXPECT_EQ(error->step, static_cast<std::uint64_t>(overflow_at));
  EXPECT_EQ(error->index, 0u);
  EXPECT_EQ(e.world().circles(), now);
  EXPECT_GT(e.quiet_steps(), 0u);
}

TEST(engine_options, threads_split_large_worlds_into_chunks_and_agree_with_the_all_pairs_reference) {
  // 12000 circles (several chunks per thread from 2 threads on) with radii over three decades, so several
  // grid levels and contacts that cross chunk boundaries; each step against the exact all-pairs step.
  std::mt19937_64 g(12000);
  std::uniform_real_distribution<double> unit(0, 1);
  Circles w;
  for (int k = 0; k < 12000; ++k)
    w.push_back({1000 * unit(g), 1000 * unit(g), 200 * unit(g) - 100, 200 * unit(g) - 100,
                 std::exp2(-2 + 9 * unit(g) * unit(g) * unit(g))});
  for (const unsigned threads : {2u, 4u}) {
    DoubleEngine e{World{w}, {threads, true}};
    for (int s = 0; s < 2; ++s) {
      const World reference = step_all_pairs(e.world());
      e.step();
      const Circles got = e.world().circles(), want = reference.circles();
      std::size_t differ = 0, changed = 0;
      for (std::size_t k = 0; k < got.size(); ++k) {
        differ += got[k] != want[k];
        changed += got[k][2] != w[k][2];
      }
      EXPECT_EQ(differ, 0u) << threads << " threads, step " << s + 1;
      EXPECT_GT(changed, 1000u) << "too few contacts to mean anything";
    }
  }
}

TEST(engine_options, refuses_more_threads_than_it_supports) {
  const auto error = testing::thrown<std::invalid_argument>([] { DoubleEngine{World{}, {DoubleEngine::kMaxThreads + 1, true}}; });
  ASSERT_TRUE(error);
  EXPECT_STREQ(error->what(), "EngineOptions::threads: 257 is more than 256");
}

}  // namespace
}  // namespace circles::impl
