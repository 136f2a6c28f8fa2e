// `circles serve`'s line handling (conform/serve.hpp): each request answered with the correctly rounded oracle
// step under its id, a malformed request or an overflow ended with exit 2 and a message naming its line.
#include "conform/serve.hpp"

#include "properties/generators.hpp"
#include "spec/oracle.hpp"
#include "tests/step_worlds.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cfloat>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace circles::conform {
namespace {

using circles::testing::kOverflowsAtStep4;
using circles::testing::kTouching;
using circles::testing::oracle_worlds;
using circles::testing::thrown;
using engines::engine;
using engines::EngineEntry;

TEST(serve, answers_a_request_with_the_oracles_step_under_the_same_id) {
  for (const EngineEntry& e : engines::engines())
    EXPECT_EQ(answer(e, 0, format_line(kId, 42, kTouching), 1),
              format_line(kId, 42, spec::resolved_step_rounded(kTouching)));
}

TEST(serve, names_the_line_id_circle_and_field_of_an_overflow) {
  const Circles w = oracle_worlds(kOverflowsAtStep4, 3).back();
  const auto e = thrown<RequestOverflow>([&] { answer(engine("double"), 1, format_line(kId, 9, w), 3); });
  ASSERT_TRUE(e);
  EXPECT_STREQ(e->what(), "line 3 (id 9): circle 1, field px: the position p + v/60 overflows to infinity");
}

TEST(serve, answers_each_line_until_the_end_of_input_and_exits_0) {
  std::istringstream in(format_line(kId, 1, kTouching) + "\n" + format_line(kId, 2, {}) + "\n" +
                        format_line(kId, 3, spec::resolved_step_rounded(kTouching)));  // no final newline
  std::ostringstream out, err;
  EXPECT_EQ(serve(engine("double"), 1, in, out, err), 0);
  const auto worlds = oracle_worlds(kTouching, 2);
  EXPECT_EQ(out.str(), format_line(kId, 1, worlds[1]) + "\n" + format_line(kId, 2, {}) + "\n" +
                           format_line(kId, 3, worlds[2]) + "\n");
  EXPECT_EQ(err.str(), "");
}

TEST(serve, stops_at_a_malformed_request_with_exit_2_after_answering_the_lines_before_it) {
  std::istringstream in(format_line(kId, 1, kTouching) + "\n{\"id\": 2}\n" + format_line(kId, 3, kTouching) + "\n");
  std::ostringstream out, err;
  EXPECT_EQ(serve(engine("double"), 1, in, out, err), 2);
  EXPECT_EQ(out.str(), format_line(kId, 1, spec::resolved_step_rounded(kTouching)) + "\n");
  EXPECT_EQ(err.str(), "circles serve: malformed request, line 2: missing key \"circles\"\n");
}

TEST(serve, stops_at_an_overflow_with_exit_2) {
  std::istringstream in(format_line(kId, 5, oracle_worlds(kOverflowsAtStep4, 3).back()) + "\n");
  std::ostringstream out, err;
  EXPECT_EQ(serve(engine("oracle"), 1, in, out, err), 2);
  EXPECT_EQ(out.str(), "");
  EXPECT_EQ(err.str(),
            "circles serve: line 1 (id 5): circle 1, field px: the position p + v/60 overflows to infinity; the step "
            "of this request has no finite image in doubles, so there is no response to write\n");
}

// serve's per-line function against the oracle, on a world of doubles: the same circles by value, or the
// overflow of the oracle's first infinite position (circles in order, px before py).
void answers_like_the_oracle(const Circles& w) {
  const Circles want = spec::resolved_step_rounded(w);
  std::optional<std::pair<std::size_t, spec::Field>> first_infinite;
  for (std::size_t k = 0; k < want.size() && !first_infinite; ++k)
    for (const spec::Field f : {spec::Field::px, spec::Field::py})
      if (!first_infinite && std::isinf(want[k][static_cast<std::size_t>(f)])) first_infinite.emplace(k, f);
  const std::string request = format_line(kId, 1, w);
  if (first_infinite) {
    RC_TAG("overflow");
    try {
      answer(engine("double"), 1, request, 1);
      RC_FAIL("no overflow reported");
    } catch (const RequestOverflow& e) {
      RC_ASSERT(e.index == first_infinite->first);
      RC_ASSERT(e.field == first_infinite->second);
    }
    return;
  }
  const Line response = parse_line(answer(engine("double"), 1, request, 1), 1);
  RC_ASSERT(response.number == 1u);
  RC_ASSERT(response.circles == want);  // std::array<double> == compares by value: -0 == +0
  bool contact = false;
  for (std::size_t k = 0; k < w.size(); ++k) contact = contact || want[k][2] != w[k][2] || want[k][3] != w[k][3];
  RC_TAG(contact ? "a circle took a new velocity" : "no contact");
}

RC_GTEST_PROP(serve, answers_like_the_oracle_on_every_world_the_property_suite_generates, ()) {
  Circles w;
  for (const spec::Circle& c : *properties::gen::world(spec::Radii::non_negative, 12))
    w.push_back(spec::nearest_doubles(c));
  // A rational beyond DBL_MAX rounds to infinity, which no request can carry: writing it is refused.
  for (const auto& c : w)
    for (const double x : c)
      if (!std::isfinite(x)) {
        RC_TAG("a coordinate beyond the double range");
        RC_ASSERT_THROWS_AS(format_line(kId, 1, w), std::domain_error);
        return;
      }
  answers_like_the_oracle(w);
}

// Fields from the suite's finite_double, and one in three ±DBL_MAX, so that positions overflow often.
RC_GTEST_PROP(serve, answers_like_the_oracle_or_reports_its_overflow_on_arbitrary_finite_doubles, ()) {
  const auto field = rc::gen::oneOf(properties::gen::finite_double(), properties::gen::finite_double(),
                                    rc::gen::element(DBL_MAX, -DBL_MAX));
  answers_like_the_oracle(*properties::gen::double_world(5, field));
}

}  // namespace
}  // namespace circles::conform
