// --keep-going, --families and expectation files, checked as data (conform::Verdict): a status per family, a
// shrunk counterexample per failing family, and the judgement against a file of known failures
// (conform/expect.hpp). tests/conform_end_to_end.sh checks the same through the program and the Python examples.
#include "conform/conform.hpp"
#include "conform/expect.hpp"
#include "tests/function_candidate.hpp"
#include "tests/gallery.hpp"
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
using circles::testing::Mistakes;

// The message of the E that run() throws ("" if none).
template <class E, class F>
std::string message_of(F&& run) {
  const std::optional<E> e = circles::testing::thrown<E>(run);
  return e ? e->what() : "";
}

// The naive step of examples/python/step_naive.py: hypot distance and p + v·(1/60).
Circles naive_step(const Circles& w) {
  Mistakes m;
  m.contact = Mistakes::Contact::hypot;
  m.naive_update = true;
  return circles::testing::mistaken_step(w, m);
}

Circles exact_step(const Circles& w) { return circles::testing::mistaken_step(w, Mistakes{}); }

Options keep_going(std::uint64_t seed) {
  Options o;
  o.seed = seed;
  o.keep_going = true;
  return o;
}

std::set<std::string> with_status(const Verdict& v, FamilyStatus status) {
  std::set<std::string> names;
  for (const FamilyResult& f : v.families)
    if (f.status == status) names.insert(properties::name(f.family));
  return names;
}

// The 22 families the naive step's two mistakes reach in seed 1's 1000 cases: every one but tangent-after-step,
// signed-zeros and long-rows, on whose worlds there its answers are the nearest doubles.
const std::set<std::string> kNaiveFails = {"lattice",    "random-doubles", "tangency",        "ulp-nudge",
                                           "tie-px",     "tie-p",          "tie-p-vx",        "tie-p-v",
                                           "duplicates", "incomparable",   "mutual-contacts", "square-overflow",
                                           "subnormals", "cancellation",   "zero-radius",     "sizes",
                                           "crowds",     "cell-crowds",    "radius-spread",   "index-bits",
                                           "order-borders", "big-chains"};

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
            "zero-radius, sizes, crowds, cell-crowds, radius-spread, long-rows, index-bits, order-borders, big-chains");
}

TEST(expectations, refuse_entries_they_cannot_read_naming_the_file_and_line) {
  const auto error = [](std::string text) {
    return message_of<ExpectError>([&] { parse_expectations(text, "x.expect", Profile::resolved); });
  };
  EXPECT_EQ(error("# ok\nfail rounding\n"), "x.expect:2: the entry names no family: expected FAMILY fail REASON");
  EXPECT_EQ(error("latice fail why\n"),
            "x.expect:1: family: unknown family \"latice\"; the families of the resolved profile are lattice, "
            "random-doubles, tangency, ulp-nudge, tie-px, tie-p, tie-p-vx, tie-p-v, duplicates, incomparable, "
            "mutual-contacts, tangent-after-step, square-overflow, subnormals, cancellation, signed-zeros, "
            "zero-radius, sizes, crowds, cell-crowds, radius-spread, long-rows, index-bits, order-borders, big-chains");
  EXPECT_EQ(error("lattice pass why\n"), "x.expect:1: expected \"fail\" after the family lattice, found \"pass\": FAMILY fail REASON");
  EXPECT_EQ(error("lattice fail   \n"), "x.expect:1: the entry for lattice gives no reason: FAMILY fail REASON");
  EXPECT_EQ(error("lattice fail a\n\ntangency fail b\nlattice fail c\n"),
            "x.expect:4: the family lattice is listed already, on line 1");
  const Expectations e = parse_expectations("  # c\r\n\ttangency  fail  hypot, twice \r\n", "x", Profile::resolved);
  ASSERT_EQ(e.entries.size(), 1u);
  EXPECT_EQ(e.entries[0].reason, "hypot, twice");
  EXPECT_EQ(e.entries[0].line, 2u);
}

TEST(expectations, the_file_written_for_the_naive_step_passes_it_and_fails_the_exact_step_with_an_unexpected_pass_each) {
  FunctionCandidate naive(naive_step), exact(exact_step);
  Verdict v = check(naive, keep_going(1));
  const Expectations file = parse_expectations(expectations_text(v), "naive.expect", Profile::resolved);
  EXPECT_EQ(file.entries.size(), kNaiveFails.size());
  apply(v, file);
  EXPECT_EQ(v.outcome, Outcome::conforms);
  EXPECT_EQ(with_status(v, FamilyStatus::expected_failure), kNaiveFails);
  EXPECT_FALSE(v.counterexample);

  Verdict right = check(exact, keep_going(1));
  apply(right, file);
  EXPECT_EQ(right.outcome, Outcome::does_not_conform);
  EXPECT_EQ(with_status(right, FamilyStatus::unexpected_pass), kNaiveFails);
  const std::vector<std::string> lines = unexpected_passes(right, file);
  ASSERT_EQ(lines.size(), kNaiveFails.size());
  EXPECT_EQ(lines.front().substr(0, lines.front().find('(')), "lattice: unexpected pass ");
  EXPECT_TRUE(lines.front().ends_with("cases checked): delete its line, naive.expect:5")) << lines.front();
}

TEST(expectations, a_failure_the_file_does_not_list_still_fails_the_run) {
  Mistakes strict;
  strict.contact = Mistakes::Contact::strict;
  FunctionCandidate wrong([&](const Circles& w) { return circles::testing::mistaken_step(w, strict); });
  Verdict v = check(wrong, keep_going(7));
  const std::set<std::string> failed = with_status(v, FamilyStatus::failed);
  ASSERT_FALSE(failed.empty());
  // The file lists every family it fails but one.
  std::string text;
  for (auto f = std::next(failed.begin()); f != failed.end(); ++f) text += *f + " fail known\n";
  apply(v, parse_expectations(text, "partial.expect", Profile::resolved));
  EXPECT_EQ(v.outcome, Outcome::does_not_conform);
  EXPECT_EQ(with_status(v, FamilyStatus::failed), std::set<std::string>{*failed.begin()});
  ASSERT_TRUE(v.counterexample);
  EXPECT_EQ(v.counterexample->family, *failed.begin());
}

}  // namespace
}  // namespace circles::conform
