// The text of a verdict that every rendering of it shares: the lines of a counterexample that `circles conform`
// prints (cli/conform_report.hpp) and that each report for CI carries (conform/report_formats.hpp), and the
// verdict's shard and time as the reports write them.
#pragma once

#include "conform/conform.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace circles::conform {

// "step 1 of 1, circle 0, field px: expected 0.5 (0x1p-1), got 0.25 (0x1p-2)": the line that names where a
// counterexample differs; for a program that broke instead of answering, "step 1 of 1: no answer: the program
// crashed or exited".
std::string difference_line(const Counterexample& c);

// A counterexample other than the run's (which is printed whole) in three lines: its difference_line, which
// decision differs, and its replay line.
std::string counterexample_summary(const Counterexample& c);

// The verdict's shard, "0/1", or the shards a merged verdict combines, "0,1,2,3/4".
std::string shard_text(const Verdict& verdict);

// The verdict's wall time in seconds as the reports write it, "0.43".
std::string elapsed_text(const Verdict& verdict);

// "  TITLE:", then a line "    #k [px, py, vx, vy, r]" per circle, each after `indent`; with `only`, the circles
// it lists alone (sorted), and the title says how many of the world's they are.
std::string world_text(const std::string& title, const Circles& world, const std::string& indent = "",
                       const std::vector<std::size_t>* only = nullptr);

// The title of the world a counterexample asked: "the world asked (w_0)" at its first step, else "the world asked
// (the candidate's own last answer)".
std::string asked_title(const Counterexample& c);

// The lines that open the report of the verdict's counterexample (it must have one), and its picture's legend:
// the candidate and what it does not conform to, where the counterexample came from, its difference_line and
// which decision differs.
std::vector<std::string> head_lines(const Verdict& verdict);

// The head lines and the three worlds of the verdict's counterexample (it must have one): the world asked, the
// expected answer and, unless the program gave none, its answer. A world of more than 64 circles shows only the
// circles that decide the difference: the circle that differs and every circle that touches it.
std::string counterexample_worlds(const Verdict& verdict);

// The counterexample as `circles conform` prints it, without where it was saved or drawn: counterexample_worlds
// and the replay line; "" for a verdict without one. Every report for CI carries it.
std::string counterexample_text(const Verdict& verdict);

}  // namespace circles::conform
