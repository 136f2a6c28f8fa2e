// The worked example of docs/properties.md, compiled and run: a user's test of their own step functions with
// the conformance property. This target links only what the document tells a user to link (circles::properties,
// rapidcheck_gtest, GoogleTest), and the last test checks that the document shows this very code.
//
// ── The example, as docs/properties.md shows it ─────────────────────────────────────────────────────────
#include "properties/conformance.hpp"
#include "spec/rational.hpp"  // spec::Q, spec::exact, spec::nearest_double: exact rationals over GMP

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <optional>
#include <string>
#include <utility>

using circles::properties::Circles;

// A correct step, as the spec says: (3) decided exactly, on rationals; the least contact in lexicographic
// order on (px, py, vx, vy, r), then by index; each position p + v/60 rounded once, to nearest.
Circles exact_step(const Circles& w) {
  using circles::spec::exact;
  using circles::spec::Q;
  Circles next = w;
  for (std::size_t k = 0; k < w.size(); ++k) {
    std::size_t least = k;
    for (std::size_t j = 0; j < w.size(); ++j) {
      const Q dx = exact(w[j][0]) - exact(w[k][0]), dy = exact(w[j][1]) - exact(w[k][1]);
      const Q s = exact(w[k][4]) + exact(w[j][4]);
      const bool touch = dx * dx + dy * dy <= s * s;
      if (j != k && touch && (least == k || std::pair(w[j], j) < std::pair(w[least], least))) least = j;
    }
    next[k][2] = w[least][2];
    next[k][3] = w[least][3];
    for (std::size_t f = 0; f < 2; ++f)
      next[k][f] = circles::spec::nearest_double(exact(w[k][f]) + exact(next[k][f + 2]) / 60);
  }
  return next;
}

// The same step in doubles, as it is usually first written: the squares round, and p + v/60 rounds twice.
Circles naive_step(const Circles& w) {
  Circles next = w;
  for (std::size_t k = 0; k < w.size(); ++k) {
    std::size_t least = k;
    for (std::size_t j = 0; j < w.size(); ++j) {
      const double dx = w[j][0] - w[k][0], dy = w[j][1] - w[k][1], s = w[k][4] + w[j][4];
      const bool touch = dx * dx + dy * dy <= s * s;
      if (j != k && touch && (least == k || std::pair(w[j], j) < std::pair(w[least], least))) least = j;
    }
    next[k][2] = w[least][2];
    next[k][3] = w[least][3];
    for (std::size_t f = 0; f < 2; ++f) next[k][f] = w[k][f] + next[k][f + 2] / 60;
  }
  return next;
}

RC_GTEST_PROP(exact_step, steps_as_the_spec_says, ()) { circles::properties::step_conforms(exact_step); }

RC_GTEST_PROP(exact_step, steps_as_the_literal_spec_says_three_steps_in_a_row, ()) {
  circles::properties::step_conforms(exact_step, {.profile = circles::properties::Profile::literal, .steps = 3});
}

// The naive step must fail: find_counterexample runs the property as RC_GTEST_PROP would and returns
// RapidCheck's report of the shrunk counterexample instead of failing the test.
TEST(naive_step, is_caught_with_a_counterexample) {
  const std::optional<std::string> report = circles::properties::find_counterexample(naive_step);
  ASSERT_TRUE(report) << "the naive step passed";
  EXPECT_NE(report->find(": expected "), std::string::npos) << *report;
}
// ── End of the example ──────────────────────────────────────────────────────────────────────────────────

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(properties_example, is_the_code_docs_properties_md_shows) {
  const std::filesystem::path root = CIRCLES_SOURCE_DIR;
  const std::string doc = text_of(root / "docs" / "properties.md");
  const std::string code = text_of(root / "tests" / "properties_example_test.cpp");
  int blocks = 0;
  for (std::size_t at = 0; (at = doc.find("```cpp\n", at)) != std::string::npos; ++blocks) {
    at += 7;
    const std::size_t end = doc.find("```\n", at);
    ASSERT_NE(end, std::string::npos) << "an unclosed ```cpp block";
    const std::string block = doc.substr(at, end - at);
    EXPECT_NE(code.find(block), std::string::npos) << "docs/properties.md shows code that this file does not hold:\n"
                                                   << block;
    at = end;
  }
  EXPECT_GE(blocks, 3);
}

}  // namespace
