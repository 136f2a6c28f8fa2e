// What step_conforms reports when a step fails (properties/conformance.hpp): the case's family by name, w_0 and
// the world of the step that failed with numbers that read back as the same doubles, so that the failing step
// can be asked again from the report alone; and find_counterexample, which returns that report.
#include "properties/conformance.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <variant>

namespace circles::properties {
namespace {

Circles expected(const Circles& w) { return std::get<Circles>(expected_step(w, Profile::resolved)); }

// Right decisions, positions p + v·(1/60) rounded twice: wrong by an ulp on many worlds.
Circles twice_rounded(const Circles& w) {
  Circles next = expected(w);
  for (std::size_t k = 0; k < w.size(); ++k)
    for (std::size_t f = 0; f < 2; ++f) next[k][f] = w[k][f] + next[k][f + 2] * (1.0 / 60);
  return next;
}

// The world after `label` in the report: "LABEL{{px, py, vx, vy, r}, ...}", each number read with strtod.
Circles world_after(const std::string& report, const std::string& label) {
  const std::size_t at = report.find(label);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no \"" << label << "\" in the report:\n" << report;
    return {};
  }
  const std::size_t end = report.find("}}", at);
  Circles w;
  const char* p = report.c_str() + at + label.size();
  while (p < report.c_str() + end) {
    spec::CircleDoubles c{};
    for (double& x : c) {
      while (*p == '{' || *p == ',' || *p == ' ') ++p;
      char* rest = nullptr;
      x = std::strtod(p, &rest);
      p = rest;
      while (*p == '}') ++p;
    }
    w.push_back(c);
    while (*p == ',' || *p == ' ') ++p;
  }
  return w;
}

std::set<std::string> family_names() {
  std::set<std::string> names;
  for (const Family f : families(Profile::resolved)) names.insert(name(f));
  return names;
}

TEST(conformance_report, names_the_family_and_shows_worlds_that_reproduce_the_failing_step) {
  const std::optional<std::string> report = find_counterexample(twice_rounded);
  ASSERT_TRUE(report) << "the twice-rounded step passed";
  // The case, as RapidCheck shows it: "FAMILY, w_0 = {{...}}".
  std::smatch shown;
  ASSERT_TRUE(std::regex_search(*report, shown, std::regex(R"(\n([a-z-]+), w_0 = \{\{)"))) << *report;
  EXPECT_TRUE(family_names().contains(shown[1].str())) << shown[1];
  EXPECT_NE(report->find("(family " + shown[1].str() + ", resolved profile, level exact): circle "), std::string::npos)
      << *report;
  // The world asked at the failing step, read back from the report, fails again: its numbers are the doubles.
  std::smatch step;
  ASSERT_TRUE(std::regex_search(*report, step, std::regex(R"(the world asked at step (\d+), w_(\d+) = )"))) << *report;
  const Circles asked = world_after(*report, step[0].str());
  ASSERT_FALSE(asked.empty());
  EXPECT_NE(twice_rounded(asked), expected(asked)) << *report;
  // So does w_0: the chain from it meets the same world.
  const Circles w_0 = world_after(*report, ", w_0 = ");
  Circles w = w_0;
  for (int s = 1; s < std::stoi(step[1].str()); ++s) w = twice_rounded(w);
  EXPECT_EQ(w, asked);
}

// Right at the first step of each case, wrong at every later one: the step remembers its last answer, and an
// input equal to it is a world of the chain after w_0.
TEST(conformance_report, shows_the_world_of_the_step_that_failed_not_w_0) {
  Circles last;
  const Step wrong_after_the_first = [&last](const Circles& w) {
    Circles next = expected(w);
    if (w == last && !next.empty()) next[0][0] = std::nextafter(next[0][0], INFINITY);
    last = next;
    return next;
  };
  const std::optional<std::string> report = find_counterexample(wrong_after_the_first, {.steps = 3});
  ASSERT_TRUE(report) << "the step passed";
  EXPECT_NE(report->find("step 2 of 3 (family "), std::string::npos) << *report;
  EXPECT_NE(report->find("circle 0, field px: expected "), std::string::npos) << *report;
  const Circles w_0 = world_after(*report, ", w_0 = ");
  const Circles w_1 = world_after(*report, "the world asked at step 2, w_1 = ");
  EXPECT_EQ(w_1, expected(w_0)) << *report;
  // The answer that differs, beside the expected one, for the circle that differs.
  const std::string expected_circle = report->substr(report->find("circle 0: expected "));
  EXPECT_NE(expected_circle.find(", got {"), std::string::npos) << *report;
}

TEST(conformance_report, finds_nothing_for_the_exact_step) {
  EXPECT_EQ(find_counterexample(expected), std::nullopt);
}

TEST(conformance_report, rapidcheck_shows_a_family_by_its_name) {
  EXPECT_EQ(rc::toString(Family::tie_p_vx), "tie-p-vx");
  EXPECT_EQ(rc::toString(std::pair{Family::square_overflow, Circles{}}), "(square-overflow, [])");
}

}  // namespace
}  // namespace circles::properties
