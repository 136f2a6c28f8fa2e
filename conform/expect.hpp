// Expectation files (`circles conform --expect FILE`, `--write-expect FILE`): the families an implementation
// is known to fail, each with a reason, as test262 runners keep them. Against the file, a listed family that
// fails is an expected failure and does not fail the run; a listed family that passes is an unexpected pass,
// and does, so that the file stays honest (delete its line).
//
// The format (docs/conform.md, "Expectation files"), UTF-8 text, one entry a line:
//   # a comment, and blank lines, are ignored
//   FAMILY fail REASON
// FAMILY a family of the profile (properties/boundaries.hpp), "fail" the one expectation there is, REASON the
// rest of the line (not empty). A family listed twice, an unknown family, a line that names none, another word
// than "fail" and a missing reason are errors (ExpectError) that name the file and line.
#pragma once

#include "conform/conform.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace circles::conform {

class ExpectError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Expectation {
  properties::Family family;
  std::string reason;
  std::size_t line = 0;  // its line in the file, 1-based
};

struct Expectations {
  std::filesystem::path file;  // where they were read from, for messages
  std::vector<Expectation> entries;
  const Expectation* find(properties::Family family) const;
};

// Parses `text`, named `file` in messages. Throws ExpectError("FILE:LINE: why").
Expectations parse_expectations(std::string_view text, const std::filesystem::path& file, Profile profile);
// Reads and parses `file` ("-": the standard input). Throws ExpectError, also for a file that cannot be read,
// with the system's reason: "x.expect: cannot open the file: No such file or directory".
Expectations read_expectations(const std::filesystem::path& file, Profile profile);

// Judges the verdict against the expectations: a listed family that failed becomes expected_failure, one that
// passed unexpected_pass. Verdict::counterexample becomes the first unexpected one (found_before: the lowest case,
// a stored one first), or none; then the outcome (unless cannot_check) is checked_outcome's: does_not_conform
// when a family failed unexpectedly, passed unexpectedly or a stored counterexample of no family failed, else
// conforms.
void apply(Verdict& verdict, const Expectations& expectations);

// The lines of an unexpected pass, one per family: "FAMILY: unexpected pass (N cases checked): delete its line,
// FILE:LINE" ("1 case checked" for one).
std::vector<std::string> unexpected_passes(const Verdict& verdict, const Expectations& expectations);

// The expectation file of the verdict's failures (failed and expected failure), each with the summary of its
// counterexample as a comment and the reason "TODO: why it fails" to fill in.
std::string expectations_text(const Verdict& verdict);

}  // namespace circles::conform
