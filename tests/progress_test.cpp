// The progress bar of `circles run` and `circles conform` (pictures/progress.hpp), driven by given times: when
// it appears, how often it is redrawn, what its line says, and that it leaves nothing behind.
#include "pictures/progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace circles::pictures {
namespace {

// The time point `seconds` after the start.
Progress::Clock::time_point after(double seconds) {
  return Progress::Clock::time_point{} +
         std::chrono::duration_cast<Progress::Clock::duration>(std::chrono::duration<double>(seconds));
}

TEST(progress, stays_quiet_for_a_run_that_ends_within_half_a_second_and_is_not_estimated_at_a_second) {
  std::ostringstream out;
  {
    Progress p(&out, 1000, 1, after(0));
    p.update(0, 10, after(0.01));
    p.update(0, 500, after(0.25));  // estimate 0.5 s
    p.update(0, 990, after(0.49));
    EXPECT_FALSE(p.shown());
  }
  EXPECT_EQ(out.str(), "");
}

TEST(progress, appears_after_half_a_second_whatever_the_estimate) {
  std::ostringstream out;
  Progress p(&out, 1000, 1, after(0));
  p.update(0, 990, after(0.51));
  EXPECT_TRUE(p.shown());
  EXPECT_EQ(out.str(), "\r[###################.]  99%  step 990 of 1000  0.0 s left");
}

// 100 of 1000 steps in 0.25 s: 2.25 s to go at that rate, so the bar comes at once.
TEST(progress, appears_from_a_fifth_of_a_second_on_when_the_run_is_estimated_at_a_second_or_more) {
  std::ostringstream out;
  Progress p(&out, 1000, 1, after(0));
  p.update(0, 1, after(0.19));
  EXPECT_FALSE(p.shown());
  p.update(0, 100, after(0.25));
  EXPECT_TRUE(p.shown());
  EXPECT_EQ(out.str(), "\r[##..................]  10%  step 100 of 1000  2.2 s left");
}

// With --fit: the first pass ends at its last update (0.65 s); the second's first 10 steps take 0.06 s, so its
// 990 others are estimated at 5.94 s.
TEST(progress, redraws_at_most_every_tenth_of_a_second_each_pass_with_its_own_bar_and_erases_its_line_at_the_end) {
  std::ostringstream out;
  Progress p(&out, 1000, 2, after(0));
  p.update(0, 100, after(0.6));
  const std::string first = out.str();
  EXPECT_EQ(first, "\r[##..................]  10%  step 100 of 1000 (fit pass)  5.4 s left");
  p.update(0, 200, after(0.65));
  EXPECT_EQ(out.str(), first) << "redrawn within 0.1 s";
  p.update(1, 10, after(0.71));
  const std::string second = "[....................]   1%  step 10 of 1000 (run)  5.9 s left";
  EXPECT_EQ(out.str(), first + "\r" + second + std::string(first.size() - 1 - second.size(), ' '));
  p.finish();
  EXPECT_FALSE(p.shown());
  std::string blank(first.size() + 1, ' ');  // "\r", the line's width in spaces, "\r"
  blank.front() = blank.back() = '\r';
  EXPECT_TRUE(out.str().ends_with(blank)) << out.str();
}

TEST(progress, is_silent_without_a_terminal) {
  Progress p(nullptr, 1000, 1, after(0));
  p.update(0, 1, after(5));
  EXPECT_FALSE(p.shown());
}

TEST(progress, draws_a_bar_of_twenty_with_the_percentage_step_pass_and_time_left) {
  EXPECT_EQ(progress_line(0, 1, 500, 1000, 1.5), "[##########..........]  50%  step 500 of 1000  1.5 s left");
  EXPECT_EQ(progress_line(0, 2, 500, 1000, 1.5),
            "[##########..........]  50%  step 500 of 1000 (fit pass)  1.5 s left");
  EXPECT_EQ(progress_line(1, 2, 1000, 1000, 0), "[####################] 100%  step 1000 of 1000 (run)  0.0 s left");
  EXPECT_EQ(progress_line(0, 1, 0, 7, INFINITY), "[....................]   0%  step 0 of 7");
}

}  // namespace
}  // namespace circles::pictures
