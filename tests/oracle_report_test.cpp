// `circles oracle`'s report (cli/oracle_report.hpp): what the exact oracle did in each profile, in words that
// agree with their counts.
#include "cli/oracle_report.hpp"

#include "spec/circle.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace circles::cli {
namespace {

std::string report(const std::vector<spec::Circle>& scene, std::size_t steps) {
  std::ostringstream out;
  report_oracle(scene, "a test scene", steps, out);
  return out.str();
}

// spec-notes.md's sets-merge-circles (d, c1 and c2: three contacts, and c1 and c2 merge in the literal profile)
// and a point far away, which the literal profile leaves out: one of each of a step, a merge and a point.
TEST(oracle_report, says_1_step_1_circle_merged_and_1_circle_left_out_in_the_singular) {
  const std::vector<spec::Circle> scene{spec::circle(-2, 0, 0, 0, 1), spec::circle(0, 0, 60, 0, 1),
                                        spec::circle(0, 0, 120, 0, 1), spec::circle(100, 100, 0, 0, 0)};
  EXPECT_EQ(report(scene, 1),
            "circles: the exact oracle on a test scene (4 circles, 1 step of Δt = 1/60)\n"
            "This part runs the oracle alone, in exact rationals; the main job (`circles` with no subcommand) then\n"
            "steps each engine beside the correctly rounded oracle and compares them.\n"
            "\n"
            "resolved profile (the default: circles by index, lexicographic minimum)\n"
            "  1 step; 3 contacts (pairs touching) over 1 step, the first at step 0\n"
            "  w_1, exact (px, py, vx, vy, r), and the nearest doubles where they differ:\n"
            "    0  (-1, 0, 60, 0, 1)\n"
            "    1  (0, 0, 0, 0, 1)\n"
            "    2  (0, 0, 0, 0, 1)\n"
            "    3  (100, 100, 0, 0, 0)\n"
            "\n"
            "literal profile (the seed to the letter: worlds are sets, the minimum is (6)/(7))\n"
            "  1 circle of radius 0 left out (r ∈ R+)\n"
            "  1 step; 3 contacts (pairs touching) over 1 step, the first at step 0\n"
            "  1 circle merged by set semantics\n");
}

TEST(oracle_report, says_1_contact_for_one_pair_touching_and_0_circles_for_none_merged) {
  const std::string text = report({spec::circle(0, 0, 0, 0, 1), spec::circle(2, 0, 0, 0, 1)}, 2);
  EXPECT_NE(text.find("(2 circles, 2 steps of Δt = 1/60)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  2 steps; 2 contacts (pairs touching) over 2 steps, the first at step 0\n"), std::string::npos)
      << text;
  const std::string one = report({spec::circle(0, 0, 0, 0, 1), spec::circle(2, 0, 0, 0, 1)}, 1);
  EXPECT_NE(one.find("  1 step; 1 contact (a pair touching) over 1 step, the first at step 0\n"), std::string::npos)
      << one;
  EXPECT_NE(one.find("  0 circles merged by set semantics\n"), std::string::npos) << one;
}

}  // namespace
}  // namespace circles::cli
