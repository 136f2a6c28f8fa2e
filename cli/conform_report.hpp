// What `circles conform` prints of a verdict (conform/conform.hpp) on the terminal, and the picture of its
// counterexample; the text it shares with the reports for CI is conform/verdict_text.hpp's.
#pragma once

#include "conform/conform.hpp"

#include <filesystem>
#include <ostream>
#include <string>

namespace circles::cli {

// Where to draw a counterexample's picture: `svg` if given, else beside the stored counterexample in the
// verdict's --save directory (the file it was saved as or replayed from, with .svg), else nowhere: a picture
// is drawn only when asked for, so that runs in a loop leave nothing behind.
std::filesystem::path picture_path(const conform::Verdict& verdict, const std::filesystem::path& svg);

// Prints the verdict on `out` ("circles conform: … conforms: 1000 cases, …" with the cases per family, or the
// counterexample with its worlds, where it was saved, its picture and its replay line), drawing the picture
// to picture_path(verdict, svg); a verdict that cannot check goes to `err` as "circles conform: reason (seed
// S)". A verdict that passes only because an expectation file lists its failures does not say "conforms":
// "… passes with 22 expected failures, 3 families pass: …".
// With --keep-going (Options::keep_going) it prints a table instead: a row per family with its cases, status
// and, for a family that failed, its counterexample in a line and its replay line, and draws the picture of the
// run's counterexample (the first failure not expected). Returns the exit status:
// 0, 1 or 2.
int print_verdict(const conform::Verdict& verdict, const std::filesystem::path& svg, std::ostream& out,
                  std::ostream& err);

}  // namespace circles::cli
