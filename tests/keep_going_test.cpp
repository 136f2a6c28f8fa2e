// --keep-going and --families, checked as data (conform::Verdict): a status per family and a shrunk
// counterexample per failing family. tests/conform_end_to_end.sh checks the same through the program and the
// Python examples.
#include "conform/conform.hpp"
#include "tests/function_candidate.hpp"
#include "tests/naive_step.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::conform {
namespace {

using circles::testing::FunctionCandidate;
using circles::testing::exact_step;
using circles::testing::keep_going;
using circles::testing::kNaiveFails;
using circles::testing::naive_step;
using circles::testing::with_status;

// The message of the E that run() throws ("" if none).
template <class E, class F>
std::string message_of(F&& run) {
  const std::optional<E> e = circles::testing::thrown<E>(run);
  return e ? e->what() : "";
}

TEST(keep_going, fails_exactly_the_families_the_naive_steps_two_mistakes_reach_with_a_counterexample_each) {
  FunctionCandidate naive(naive_step);
  const Verdict v = check(naive, keep_going(1));
  EXPECT_EQ(v.outcome, Outcome::does_not_conform);
  EXPECT_EQ(with_status(v, FamilyStatus::failed), kNaiveFails);
  EXPECT_EQ(with_status(v, FamilyStatus::passed), (std::set<std::string>{"tangent-after-step", "signed-zeros", "long-rows"}));
  for (const FamilyResult& f : v.families) {
    EXPECT_GT(f.checked, 0u) << properties::name(f.family);
    if (f.status != FamilyStatus::failed) {
      EXPECT_FALSE(f.counterexample) << properties::name(f.family);
      continue;
    }
    ASSERT_TRUE(f.counterexample) << properties::name(f.family);
    const Counterexample& c = *f.counterexample;
    EXPECT_EQ(c.family, properties::name(f.family));
    EXPECT_EQ(c.expected, exact_step(c.input));
    EXPECT_EQ(c.actual, naive_step(c.input));
    EXPECT_EQ(c.replay, "circles conform --seed 1 --case " + std::to_string(*c.case_index) + " --level exact");
    // Its count stops at its failure: its cases drawn are those up to the failing one (one a round of F cases),
    // though the cases after it in the same batch were asked.
    EXPECT_EQ(f.drawn, *c.case_index / v.families.size() + 1) << properties::name(f.family);
  }
  // The run's counterexample is the first of them, of the lowest case.
  ASSERT_TRUE(v.counterexample);
  for (const FamilyResult& f : v.families)
    if (f.counterexample) {
      EXPECT_LE(*v.counterexample->case_index, *f.counterexample->case_index);
    }
}

TEST(keep_going, gives_the_same_per_family_results_for_the_same_seed) {
  FunctionCandidate naive(naive_step);
  const Verdict a = check(naive, keep_going(4)), b = check(naive, keep_going(4));
  ASSERT_EQ(a.families.size(), b.families.size());
  for (std::size_t k = 0; k < a.families.size(); ++k) {
    EXPECT_EQ(a.families[k].status, b.families[k].status);
    EXPECT_EQ(a.families[k].checked, b.families[k].checked);
    ASSERT_EQ(a.families[k].counterexample.has_value(), b.families[k].counterexample.has_value());
    if (a.families[k].counterexample) {
      EXPECT_EQ(a.families[k].counterexample->case_index, b.families[k].counterexample->case_index);
      EXPECT_EQ(a.families[k].counterexample->input, b.families[k].counterexample->input);
    }
  }
}

TEST(keep_going, without_it_the_run_stops_at_its_first_counterexample_and_later_families_are_not_reached) {
  FunctionCandidate naive(naive_step);
  Options o;
  o.seed = 1;
  const Verdict v = check(naive, o);
  EXPECT_EQ(with_status(v, FamilyStatus::failed).size(), 1u);
  EXPECT_FALSE(with_status(v, FamilyStatus::not_reached).empty());
}

TEST(keep_going, skipped_families_are_not_asked_and_the_others_keep_their_worlds) {
  FunctionCandidate naive(naive_step);
  const Verdict all = check(naive, keep_going(1));
  Options some = keep_going(1);
  some.skip = parse_families("--skip-families", "lattice,tangency", Profile::resolved);
  const Verdict v = check(naive, some);
  EXPECT_EQ(with_status(v, FamilyStatus::skipped), (std::set<std::string>{"lattice", "tangency"}));
  for (std::size_t k = 0; k < v.families.size(); ++k) {
    if (v.families[k].status == FamilyStatus::skipped) {
      EXPECT_EQ(v.families[k].drawn, 0u);
      continue;
    }
    EXPECT_EQ(v.families[k].status, all.families[k].status);
    if (v.families[k].counterexample) {
      EXPECT_EQ(v.families[k].counterexample->case_index, all.families[k].counterexample->case_index);
    }
  }
}

TEST(keep_going, refuses_an_unknown_family_listing_the_known_ones) {
  EXPECT_EQ(message_of<std::invalid_argument>([] { parse_families("--families", "lattice,sideways", Profile::resolved); }),
            "--families: unknown family \"sideways\"; the families of the resolved profile are lattice, "
            "random-doubles, tangency, ulp-nudge, tie-px, tie-p, tie-p-vx, tie-p-v, duplicates, incomparable, "
            "mutual-contacts, tangent-after-step, square-overflow, subnormals, cancellation, signed-zeros, "
            "zero-radius, wire, sizes, crowds, cell-crowds, radius-spread, long-rows, index-bits, order-borders, big-chains");
}

}  // namespace
}  // namespace circles::conform
