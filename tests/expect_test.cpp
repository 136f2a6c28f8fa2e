// Expectation files (conform/expect.hpp): entries read or refused naming the file and line, and a verdict
// judged against a file of known failures, where an unexpected pass fails the run as an unexpected failure does.
#include "conform/expect.hpp"

#include "conform/conform.hpp"
#include "tests/function_candidate.hpp"
#include "tests/naive_step.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace circles::conform {
namespace {

using circles::testing::exact_step;
using circles::testing::FunctionCandidate;
using circles::testing::keep_going;
using circles::testing::kNaiveFails;
using circles::testing::Mistakes;
using circles::testing::naive_step;
using circles::testing::TempDir;
using circles::testing::thrown;
using circles::testing::with_status;

TEST(expectations, refuse_entries_they_cannot_read_naming_the_file_and_line) {
  const auto error = [](std::string text) {
    const auto e = thrown<ExpectError>([&] { parse_expectations(text, "x.expect", Profile::resolved); });
    return e ? std::string(e->what()) : std::string("nothing thrown");
  };
  EXPECT_EQ(error("# ok\nfail rounding\n"), "x.expect:2: the entry names no family: expected FAMILY fail REASON");
  EXPECT_EQ(error("latice fail why\n"),
            "x.expect:1: family: unknown family \"latice\"; the families of the resolved profile are lattice, "
            "random-doubles, tangency, ulp-nudge, tie-px, tie-p, tie-p-vx, tie-p-v, duplicates, incomparable, "
            "mutual-contacts, tangent-after-step, square-overflow, subnormals, cancellation, signed-zeros, "
            "zero-radius, wire, sizes, crowds, cell-crowds, radius-spread, long-rows, index-bits, order-borders, big-chains");
  EXPECT_EQ(error("lattice pass why\n"), "x.expect:1: expected \"fail\" after the family lattice, found \"pass\": FAMILY fail REASON");
  EXPECT_EQ(error("lattice fail   \n"), "x.expect:1: the entry for lattice gives no reason: FAMILY fail REASON");
  EXPECT_EQ(error("lattice fail a\n\ntangency fail b\nlattice fail c\n"),
            "x.expect:4: the family lattice is listed already, on line 1");
  const Expectations e = parse_expectations("  # c\r\n\ttangency  fail  hypot, twice \r\n", "x", Profile::resolved);
  ASSERT_EQ(e.entries.size(), 1u);
  EXPECT_EQ(e.entries[0].reason, "hypot, twice");
  EXPECT_EQ(e.entries[0].line, 2u);
}

TEST(expectations, read_a_file_with_the_line_and_reason_of_each_family_or_name_the_file_they_cannot_read) {
  const TempDir dir;
  const auto missing = thrown<ExpectError>([&] { read_expectations(dir.path / "missing.expect", Profile::resolved); });
  ASSERT_TRUE(missing);
  EXPECT_EQ(std::string(missing->what()),
            (dir.path / "missing.expect").string() + ": cannot open the file: No such file or directory");
  const auto directory = thrown<ExpectError>([&] { read_expectations(dir.path, Profile::resolved); });
  ASSERT_TRUE(directory);
  EXPECT_EQ(std::string(directory->what()), dir.path.string() + ": cannot read the file: it is a directory");
  const std::string file = dir.write("known.expect", "# why\ntangency fail hypot\n\nlattice fail naive update\n");
  const Expectations read = read_expectations(file, Profile::resolved);
  EXPECT_EQ(read.file, std::filesystem::path(file));
  ASSERT_EQ(read.entries.size(), 2u);
  const Expectation* tangency = read.find(properties::Family::tangency);
  const Expectation* lattice = read.find(properties::Family::lattice);
  ASSERT_TRUE(tangency && lattice);
  EXPECT_EQ(tangency->line, 2u);
  EXPECT_EQ(tangency->reason, "hypot");
  EXPECT_EQ(lattice->line, 4u);
  EXPECT_EQ(lattice->reason, "naive update");
  EXPECT_EQ(read.find(properties::Family::tie_px), nullptr);
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
