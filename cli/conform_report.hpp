// What `circles conform` prints of a verdict (conform/conform.hpp), and the picture of its counterexample.
#pragma once

#include "conform/conform.hpp"

#include <filesystem>
#include <ostream>

namespace circles::cli {


// Where to draw a counterexample's picture: `svg` if given, else beside the stored counterexample in the
// verdict's --save directory (the file it was saved as or replayed from, with .svg), else nowhere: a picture
// is drawn only when asked for, so that runs in a loop leave nothing behind.
std::filesystem::path picture_path(const conform::Verdict& verdict, const std::filesystem::path& svg);

// Prints the verdict on `out` ("circles conform: … conforms: 1000 cases, …" with the cases per family, or the
// counterexample with its worlds, where it was saved, its picture and its replay line), drawing the picture
// to picture_path(verdict, svg); a verdict that cannot check goes to `err` as "circles conform: reason".
// Returns the exit status: 0, 1 or 2.
int print_verdict(const conform::Verdict& verdict, const std::filesystem::path& svg, std::ostream& out,
                  std::ostream& err);

}  // namespace circles::cli
