// The time budget (conform/ladder.hpp, Options::budget) and the jobs (conform/checker.hpp, Options::jobs): the
// ladder climbs as far as measured times predict and no further; a budget run's counterexample on a big world
// replays exactly from its case and size, whatever the budget; and the verdict of a fixed schedule is the same
// for any number of jobs.
#include "conform/conform.hpp"
#include "conform/deadline.hpp"
#include "conform/ladder.hpp"
#include "impl/engine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "tests/function_candidate.hpp"

namespace circles::conform {
namespace {

using circles::testing::FunctionCandidate;

// The ladder's stages as a program whose stage at n circles takes seconds(n), in a budget of `budget`: the
// sizes asked, in order.
std::vector<std::size_t> climb(std::size_t top, double budget, double (*seconds)(std::size_t)) {
  Ladder ladder(top);
  std::vector<std::size_t> asked;
  double spent = 0;
  while (const auto size = ladder.next(budget - spent)) {
    asked.push_back(*size);
    spent += seconds(*size);
    ladder.took(*size, seconds(*size));
    if (asked.size() > 100000) break;
  }
  return asked;
}

TEST(ladder, doubles_from_512_up_to_the_top) {
  EXPECT_EQ(Ladder(4096).rungs(), (std::vector<std::size_t>{512, 1024, 2048, 4096}));
  EXPECT_EQ(Ladder(1'000'000).rungs().size(), 12u);
  EXPECT_EQ(Ladder(1'000'000).rungs().back(), 1'000'000u);
  EXPECT_EQ(Ladder(1'000'000).rungs()[10], 524'288u);
  EXPECT_EQ(Ladder(320).rungs(), (std::vector<std::size_t>{320}));
}

TEST(ladder, climbs_a_linear_program_to_the_top_and_then_gives_each_rung_an_equal_share_of_the_time) {
  // 1 µs a circle: 10^6 circles take 1 s, so a budget of 20 s climbs every rung (in about 2 s), then spends the
  // rest at the rung with the least time so far: about as much time at each rung, so that a rung of n circles
  // is asked about 1/n as often.
  const auto seconds = [](std::size_t n) { return 1e-6 * static_cast<double>(n); };
  const auto asked = climb(1'000'000, 20, seconds);
  const std::vector<std::size_t> rungs = Ladder(1'000'000).rungs();
  ASSERT_GE(asked.size(), 12u);
  for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(asked[k], rungs[k]) << k;
  std::vector<double> spent(rungs.size());
  for (const std::size_t n : asked) spent[std::find(rungs.begin(), rungs.end(), n) - rungs.begin()] += seconds(n);
  // The top rung's stages take 1 s; every other rung ends within a stage of the top's time.
  for (std::size_t k = 0; k < rungs.size(); ++k) {
    EXPECT_LE(spent[k], spent.back() + seconds(rungs[k])) << rungs[k];
    EXPECT_GE(spent[k] + seconds(rungs[k]), spent.back() - 1.0) << rungs[k];
  }
  EXPECT_GT(std::count(asked.begin(), asked.end(), 512u), 100);
}

TEST(ladder, stops_a_quadratic_program_where_the_next_rung_would_pass_the_budget) {
  // 10^-7 s a pair of circles: 512 take 0.026 s, 8192 take 6.7 s, 16384 take 27 s, which twice over do not fit
  // in the 51 s left after climbing to 8192.
  const auto seconds = [](std::size_t n) { return 1e-7 * static_cast<double>(n) * static_cast<double>(n); };
  const auto asked = climb(1'000'000, 60, seconds);
  std::size_t largest = 0;
  double spent = 0;
  for (const std::size_t n : asked) {
    largest = std::max(largest, n);
    spent += seconds(n);
  }
  EXPECT_EQ(largest, 8192u);
  // Every stage after the first was predicted to fit with kMargin to spare, and the predictions were right.
  EXPECT_LE(spent, 60.0);
  EXPECT_GT(spent, 40.0);  // and the rest of the budget went to more stages at rungs that fit
}

TEST(ladder, a_stage_cut_ends_at_its_time_and_not_after_it_is_gone) {
  throw_if_cut();  // no cut alive: nothing to end
  {
    const StageCut cut(std::chrono::steady_clock::now() + std::chrono::hours(1));
    throw_if_cut();  // its time has not come
  }
  {
    const StageCut cut(std::chrono::steady_clock::now());
    EXPECT_THROW(throw_if_cut(), StageCutOff);
  }
  throw_if_cut();  // gone with its scope
}

TEST(ladder, predicts_from_the_growth_measured_over_the_last_two_rungs) {
  Ladder ladder(8192);
  ladder.took(512, 1);
  EXPECT_DOUBLE_EQ(*ladder.predicted(1), 4);  // n² before a second rung is measured
  ladder.took(1024, 2);                       // then linear, as measured
  EXPECT_DOUBLE_EQ(*ladder.predicted(2), 4);
  EXPECT_DOUBLE_EQ(*ladder.predicted(3), 8);
}

// A candidate that can be copied (for --jobs): every copy answers with the same step function.
class CopyableCandidate : public FunctionCandidate {
 public:
  CopyableCandidate(Step step, std::string name) : FunctionCandidate(step, name), step_(std::move(step)), name_(std::move(name)) {}
  std::unique_ptr<Candidate> copy() const override { return std::make_unique<CopyableCandidate>(step_, name_); }

 private:
  Step step_;
  std::string name_;
};

// The double engine's step, fast at any size.
formats::Circles fast_step(const formats::Circles& w) {
  impl::DoubleEngine engine(impl::World{w}, impl::EngineOptions{.threads = 1, .keep_pairs = false, .horizon = 0});
  engine.step();
  return engine.world().circles();
}

// Right on worlds of up to 512 circles; above, circle 0's vx is off by one: a bug only the ladder's second rung
// shows.
formats::Circles wrong_above_512(const formats::Circles& w) {
  formats::Circles out = fast_step(w);
  if (w.size() > 512) out[0][2] = std::nextafter(out[0][2], 1e300);
  return out;
}

// A budget run of `seconds` with 2 jobs, big worlds up to `max` circles.
Options budget_run(std::uint64_t seed, double seconds, std::size_t max) {
  Options options;
  options.seed = seed;
  options.budget = seconds;
  options.jobs = 2;
  options.max_circles = max;
  return options;
}

TEST(budget, a_counterexample_on_a_ladder_world_replays_from_its_case_and_size_whatever_the_budget) {
  CopyableCandidate candidate(wrong_above_512, "wrong above 512");
  Options options = budget_run(5, 5, 4096);
  options.simplify = false;
  const Verdict v = check(candidate, options);
  ASSERT_EQ(v.outcome, Outcome::does_not_conform) << v.error;
  ASSERT_TRUE(v.counterexample && v.counterexample->case_index);
  const Counterexample& found = *v.counterexample;
  EXPECT_NE(found.replay.find(" --case " + std::to_string(*found.case_index) + " --circles 1024 "), std::string::npos)
      << found.replay;
  EXPECT_EQ(found.replay.find("--max-circles"), std::string::npos) << found.replay;
  EXPECT_EQ(found.circles_before, 1024u);
  // The replay line's options, without a budget: the same world drawn, the same shrunk counterexample.
  Options replay;
  replay.seed = 5;
  replay.only_case = found.case_index;
  replay.circles = 1024;
  replay.simplify = false;
  const Verdict again = check(candidate, replay);
  ASSERT_TRUE(again.counterexample);
  EXPECT_EQ(again.counterexample->shrink_path.front(), found.shrink_path.front());
  EXPECT_EQ(again.counterexample->input, found.input);
  EXPECT_GT(found.input.size(), 512u);
}

TEST(budget, checks_every_family_and_says_how_far_the_big_worlds_went) {
  CopyableCandidate candidate(fast_step, "the double engine's step");
  const Verdict v = check(candidate, budget_run(2, 3, 1 << 14));
  ASSERT_EQ(v.outcome, Outcome::conforms) << v.error;
  for (const FamilyResult& f : v.families) EXPECT_GT(f.checked, 0u) << properties::name(f.family);
  EXPECT_GE(v.largest_world, 1024u);
  EXPECT_LE(v.largest_world, std::size_t{1} << 14);
  EXPECT_LT(v.elapsed.count(), 3 * 1.5 + 2);
}

// A step wrong on worlds with a circle whose radius is 3 (the lattice family draws them): a failure among the
// first rounds of a fixed schedule.
formats::Circles wrong_on_radius_3(const formats::Circles& w) {
  formats::Circles out = fast_step(w);
  for (auto& c : out)
    if (c[4] == 3) c[0] = std::nextafter(c[0], 1e300);
  return out;
}

TEST(jobs, give_the_verdict_of_one_job_on_a_fixed_schedule) {
  for (const bool keep_going : {false, true}) {
    std::vector<Verdict> verdicts;
    for (const unsigned jobs : {1u, 2u, 5u}) {
      CopyableCandidate candidate(wrong_on_radius_3, "wrong on radius 3");
      Options options;
      options.seed = 7;
      options.cases = 300;
      options.jobs = jobs;
      options.keep_going = keep_going;
      verdicts.push_back(check(candidate, options));
    }
    for (const Verdict& v : verdicts) {
      SCOPED_TRACE(keep_going);
      ASSERT_EQ(v.outcome, Outcome::does_not_conform) << v.error;
      EXPECT_EQ(v.cases, verdicts[0].cases);
      EXPECT_EQ(v.counterexample->case_index, verdicts[0].counterexample->case_index);
      EXPECT_EQ(v.counterexample->input, verdicts[0].counterexample->input);
      EXPECT_EQ(v.counterexample->replay, verdicts[0].counterexample->replay);
      for (std::size_t f = 0; f < v.families.size(); ++f) {
        EXPECT_EQ(v.families[f].checked, verdicts[0].families[f].checked);
        EXPECT_EQ(v.families[f].status, verdicts[0].families[f].status);
      }
    }
  }
}

}  // namespace
}  // namespace circles::conform
