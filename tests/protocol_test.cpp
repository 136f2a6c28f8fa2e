// The step protocol's lines (formats/protocol.hpp): every double written reads back as itself, bit for bit, in
// our reader and in a lenient one; every malformed line is refused with the message that names its fault.
#include "formats/protocol.hpp"

#include "formats/json_number.hpp"
#include "properties/generators.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace circles::formats {
namespace {

using circles::testing::thrown;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// x written in a line, then read back by parse_line and by nlohmann's DOM reader (which takes any number
// token for the nearest double): both must give x's bits.
void expect_round_trip(double x) {
  const std::string text = format_line(kId, 7, {{x, x, x, x, std::fabs(x)}});
  const Line line = parse_line(text, 1);
  ASSERT_EQ(line.circles.size(), 1u) << text;
  for (std::size_t f = 0; f < 4; ++f) EXPECT_EQ(bits(line.circles[0][f]), bits(x)) << text;
  EXPECT_EQ(bits(line.circles[0][4]), bits(std::fabs(x))) << text;
  EXPECT_EQ(bits(nlohmann::json::parse(text)["circles"][0][0].get<double>()), bits(x)) << text;
}

std::string written(double x) {
  std::string out;
  json_number::append(out, x);
  return out;
}

// The message of the ProtocolError that parse_line throws for `text` as line 4.
std::string refusal(std::string_view text, std::string_view counter = kId, Reading reading = Reading::strict) {
  const auto e = thrown<ProtocolError>([&] { parse_line(text, 4, counter, reading); });
  return e ? e->what() : "";
}

TEST(protocol, round_trips_every_family_of_doubles_bit_for_bit) {
  const double largest_subnormal = std::nextafter(DBL_MIN, 0.0);
  for (const double x : {0.0, -0.0, 0x1p-1074, -0x1p-1074, largest_subnormal, DBL_MIN, DBL_MAX, -DBL_MAX,
                         std::nextafter(DBL_MAX, 0.0), 0.1, -0.1, 1.0 / 3, 1e300, 1e-300, 1e23, 1e22, 100.0,
                         0x1p53, 0x1p53 - 1, 0x1p53 + 2, -0x1p53, 0x1p60, 0x1p64, 1e15, 1e16, 123456789012345678.0})
    expect_round_trip(x);
}

RC_GTEST_PROP(protocol, round_trips_every_finite_double_the_property_suite_generates, ()) {
  const double x = *properties::gen::finite_double();
  const std::string text = format_line(kId, 0, {{x, 0, 0, 0, std::fabs(x)}});
  const Line line = parse_line(text, 1);
  RC_ASSERT(bits(line.circles.at(0)[0]) == bits(x));
  RC_ASSERT(bits(line.circles.at(0)[4]) == bits(std::fabs(x)));
}

// The shortest decimal that reads back as the double, always as a float token: an integer token would lose
// the sign of -0 and, beyond 2^53, could name a value the double is not.
TEST(protocol, writes_each_double_in_its_shortest_form_as_a_float_token) {
  EXPECT_EQ(written(-0.0), "-0.0");
  EXPECT_EQ(written(0.0), "0.0");
  EXPECT_EQ(written(100.0), "100.0");
  EXPECT_EQ(written(0.1), "0.1");
  EXPECT_EQ(written(0x1p53), "9007199254740992.0");
  EXPECT_EQ(written(1e300), "1e+300");
  EXPECT_EQ(written(0x1p-1074), "5e-324");
  EXPECT_EQ(written(DBL_MAX), "1.7976931348623157e+308");
  EXPECT_EQ(written(-DBL_MIN), "-2.2250738585072014e-308");
}

TEST(protocol, writes_a_line_without_spaces) {
  EXPECT_EQ(format_line(kId, 12, {{1, -0.0, 0.5, 60, 0}, {2, 3, 4, 5, 6}}),
            R"({"id":12,"circles":[[1.0,-0.0,0.5,60.0,0.0],[2.0,3.0,4.0,5.0,6.0]]})");
  EXPECT_EQ(format_line(kStep, 0, {}), R"({"step":0,"circles":[]})");
}

TEST(protocol, refuses_to_write_a_number_that_is_not_finite) {
  EXPECT_THROW(format_line(kId, 1, {{0, 0, std::numeric_limits<double>::infinity(), 0, 1}}), std::domain_error);
  EXPECT_THROW(format_line(kId, 1, {{std::nan(""), 0, 0, 0, 1}}), std::domain_error);
}

TEST(protocol, reads_a_request_with_its_keys_in_either_order_and_json_whitespace) {
  const Line a = parse_line(R"( { "circles" : [ [ 0.5 , -2 , 1e1 , 0 , 3 ] ] , "id" : 18446744073709551615 } )", 1);
  EXPECT_EQ(a.number, std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(a.circles, (Circles{{0.5, -2, 10, 0, 3}}));
  const Line b = parse_line(R"({"id": 0, "circles": []})" "\r", 1);
  EXPECT_EQ(b.number, 0u);
  EXPECT_TRUE(b.circles.empty());
}

TEST(protocol, reads_integers_that_are_exactly_doubles_at_every_size) {
  const Line line = parse_line(R"({"id": 1, "circles": [[9007199254740992, -9007199254740994, )"
                               R"(18446744073709551616, 1180591620717411303424, 0]]})",
                               1);
  EXPECT_EQ(line.circles, (Circles{{0x1p53, -0x1p53 - 2, 0x1p64, 0x1p70, 0}}));
}

// 2^53 + 1 written as a decimal is the tie between 2^53 and 2^53 + 2, which goes to the even 2^53; 1e-400
// is below half the least subnormal, so its nearest double is 0.
TEST(protocol, reads_a_decimal_as_its_nearest_double) {
  const std::string text = R"({"id": 1, "circles": [[0.1, 9007199254740993.0, 1e-400, 0, 0.30000000000000001]]})";
  EXPECT_EQ(parse_line(text, 1).circles, (Circles{{0.1, 0x1p53, 0, 0, 0.3}}));
}

TEST(protocol, keeps_the_sign_of_a_negative_zero_radius) {
  const Line line = parse_line(R"({"id": 1, "circles": [[-0.0, 0, 0, 0, -0.0]]})", 1);
  EXPECT_TRUE(std::signbit(line.circles.at(0)[0]));
  EXPECT_TRUE(std::signbit(line.circles.at(0)[4]));
}

TEST(protocol, reads_a_trace_line_by_its_step_key) {
  EXPECT_EQ(parse_line(R"({"step": 3, "circles": [[1, 2, 3, 4, 5]]})", 1, kStep).number, 3u);
  EXPECT_EQ(refusal(R"({"id": 3, "circles": []})", kStep),
            R"(line 4: unexpected key "id" (a line has exactly the keys "step" and "circles"))");
}

TEST(protocol, names_the_line_and_reason_in_the_error_fields) {
  const auto e = thrown<ProtocolError>([] { parse_line(R"({"id": 1})", 17); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 17u);
  EXPECT_EQ(e->reason, R"(missing key "circles")");
  EXPECT_STREQ(e->what(), R"(line 17: missing key "circles")");
}

TEST(protocol, rejects_a_duplicate_an_extra_or_a_missing_key) {
  EXPECT_EQ(refusal(R"({"id": 1, "id": 2, "circles": []})"), R"(line 4: duplicate key "id")");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [], "circles": []})"), R"(line 4: duplicate key "circles")");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [], "note": 0})"),
            R"(line 4: unexpected key "note" (a line has exactly the keys "id" and "circles"))");
  EXPECT_EQ(refusal(R"({"circles": []})"), R"(line 4: missing key "id")");
  EXPECT_EQ(refusal(R"({"id": 1})"), R"(line 4: missing key "circles")");
}

TEST(protocol, rejects_a_line_with_a_wrong_id) {
  const std::string expected = R"(line 4: "id": expected an integer from 0 to 18446744073709551615, found )";
  EXPECT_EQ(refusal(R"({"id": -1, "circles": []})"), expected + "-1");
  EXPECT_EQ(refusal(R"({"id": 1.0, "circles": []})"), expected + "1.0");
  EXPECT_EQ(refusal(R"({"id": 1e2, "circles": []})"), expected + "1e2");  // an integer, but not an integer token
  EXPECT_EQ(refusal(R"({"id": 18446744073709551616, "circles": []})"), expected + "18446744073709551616");
  EXPECT_EQ(refusal(R"({"id": "1", "circles": []})"), expected + "a string");
  EXPECT_EQ(refusal(R"({"id": null, "circles": []})"), expected + "null");
  EXPECT_EQ(refusal(R"({"id": 1e999, "circles": []})"), R"(line 4: "id": 1e999 is beyond the double range)");
}

// Named where they stand, as the field they would be, rather than by the JSON parser's "invalid literal"; a fault
// before the token is still the one reported, and any other bare word is malformed JSON.
TEST(protocol, rejects_nan_and_infinity_tokens_in_requests_and_traces_which_json_does_not_have) {
  const std::string not_finite = " is not finite: a request or trace holds finite numbers (only an answer to conform "
                                 "may hold NaN, Infinity or -Infinity)";
  EXPECT_EQ(refusal(R"({"id":1,"circles":[[NaN,0,0,0,1]]})"), "line 4: circle 0, field px: NaN" + not_finite);
  EXPECT_EQ(refusal(R"({"id":1,"circles":[[0,0,0,0,1],[0,-Infinity,0,0,1]]})"),
            "line 4: circle 1, field py: -Infinity" + not_finite);
  EXPECT_EQ(refusal(R"({"id":1,"circles":[[0,0,0,0,Infinity]]})"), "line 4: circle 0, field r: Infinity" + not_finite);
  EXPECT_EQ(refusal(R"({"id":NaN,"circles":[]})"),
            R"(line 4: "id": expected an integer from 0 to 18446744073709551615, found NaN)");
  EXPECT_EQ(refusal(R"({"id":1,"circles":[[0,0,0,0,1]],"x":NaN})"),
            R"(line 4: unexpected key "x" (a line has exactly the keys "id" and "circles"))");
  EXPECT_EQ(refusal(R"({"id":1,"circles":[[0,0,0,0 1,NaN]]})"),
            "line 4: malformed JSON at column 29: syntax error while parsing array - unexpected number literal; "
            "expected ']'");
  EXPECT_EQ(refusal(R"({"id":1,"circles":[[nan,0,0,0,1]]})"),
            R"(line 4: malformed JSON at column 22: syntax error while parsing value - invalid literal; )"
            R"(last read: '"circles":[[na')");
}

// Reading an answer (Reading::answer): the tokens NaN, Infinity and -Infinity are the values they mean, and a
// number beyond the double range its nearest double, infinity, so that conform judges them against the expected
// answer; no field is checked against C (a negative radius is a value to judge too).
TEST(protocol, reads_nan_infinity_and_numbers_beyond_the_range_in_an_answer_as_values) {
  const Line line = parse_line(R"({"id":1,"circles":[[NaN,Infinity,-Infinity,1e400,-1],[-1e99999,0.1,NaN,2,3]]})", 4,
                               kId, Reading::answer);
  ASSERT_EQ(line.circles.size(), 2u);
  EXPECT_TRUE(std::isnan(line.circles[0][0]));
  EXPECT_EQ(line.circles[0][1], INFINITY);
  EXPECT_EQ(line.circles[0][2], -INFINITY);
  EXPECT_EQ(line.circles[0][3], INFINITY);
  EXPECT_EQ(line.circles[0][4], -1.0);
  EXPECT_EQ(line.circles[1][0], -INFINITY);
  EXPECT_EQ(bits(line.circles[1][1]), bits(0.1));  // the nearest double, as ever
  EXPECT_TRUE(std::isnan(line.circles[1][2]));
  EXPECT_EQ(line.circles[1][4], 3.0);
}

// Unknown keys in an answer are ignored with their values, however nested, whatever they hold (strings with
// brackets, NaN); `id` and "circles" must still be there exactly once, and a token out of place is named.
TEST(protocol, ignores_unknown_keys_in_an_answer_but_not_a_missing_or_repeated_id_or_circles) {
  const auto answer = [](std::string_view text) { return parse_line(text, 4, kId, Reading::answer); };
  const Line line = answer(R"({"ms": 0.1, "id": 9, "x": {"a": [1, [NaN, {"]": "}"}]], "b": null}, )"
                           R"("circles": [[1, 2, 3, 4, 5]], "y": "[[", "z": [true, 1e999]})");
  EXPECT_EQ(line.number, 9u);
  EXPECT_EQ(line.circles, (Circles{{1, 2, 3, 4, 5}}));
  const auto answer_refusal = [](std::string_view text) { return refusal(text, kId, Reading::answer); };
  EXPECT_EQ(answer_refusal(R"({"ms": 0.1, "circles": []})"), R"(line 4: missing key "id")");
  EXPECT_EQ(answer_refusal(R"({"id": 1, "ms": [1]})"), R"(line 4: missing key "circles")");
  EXPECT_EQ(answer_refusal(R"({"id": 1, "ms": 0, "id": 1, "circles": []})"), R"(line 4: duplicate key "id")");
  EXPECT_EQ(answer_refusal(R"({"id": 1, "circles": [], "circles": []})"), R"(line 4: duplicate key "circles")");
  EXPECT_EQ(answer_refusal(R"({"id": NaN, "circles": []})"),
            R"(line 4: "id": expected an integer from 0 to 18446744073709551615, found NaN)");
  EXPECT_EQ(answer_refusal(R"({"id": 1, "circles": [[0, 0, 0, 0, 1, -Infinity]]})"),
            "line 4: circle 0: expected 5 numbers [px, py, vx, vy, r], found more");
  // Only the three tokens: columns in messages are those of the line as written.
  EXPECT_EQ(answer_refusal(R"({"id":1,"circles":[[nan,0,0,0,1]]})"),
            R"(line 4: malformed JSON at column 22: syntax error while parsing value - invalid literal; )"
            R"(last read: '"circles":[[na')");
  EXPECT_EQ(answer_refusal(R"({"id":1,"circles":[[-NaN,0,0,0,1]]})"),
            R"(line 4: malformed JSON at column 22: syntax error while parsing value - invalid number; )"
            R"(expected digit after '-'; last read: '-N')");
}

TEST(protocol, rejects_a_number_beyond_the_double_range_naming_its_circle_and_field) {
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, 0, 0, 1], [0, 0, -1e309, 0, 1]]})"),
            "line 4: circle 1, field vx: -1e309 is beyond the double range");
}

// Any number token means the double nearest to it, ties to even (docs/protocol.md, Numbers), integers too:
// 2^53 + 1 and 2^53 + 3 are ties, -(2^63 - 1) an int64, 2^64 + 1 and 2^64 + 2049 beyond 64 bits (the second
// just above a tie, which a reader rounding twice misses), 4783255246441940000 how JavaScript writes a double.
TEST(protocol, reads_every_number_token_as_the_double_nearest_to_it) {
  const Line line = parse_line(R"({"id": 1, "circles": [[9007199254740993, 9007199254740995, -9223372036854775807,
                                   18446744073709551617, 18446744073709553665], [4783255246441940000, 0, 0, 0, 1]]})",
                               4);
  ASSERT_EQ(line.circles.size(), 2u);
  EXPECT_EQ(line.circles[0], (spec::CircleDoubles{0x1p53, 0x1p53 + 4, -0x1p63, 0x1p64, 0x1p64 + 4096}));
  EXPECT_EQ(line.circles[1][0], 4.78325524644194e18);
}

TEST(protocol, rejects_a_value_of_the_wrong_type) {
  EXPECT_EQ(refusal(R"([1])"),
            R"(line 4: expected an object {"id": N, "circles": [[px, py, vx, vy, r], ...]}, found an array)");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": {}})"),
            R"(line 4: "circles": expected an array of circles [px, py, vx, vy, r], found an object)");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [7]})"),
            "line 4: circle 0: expected an array [px, py, vx, vy, r], found 7");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, 0, 0, 1], [0, "x", 0, 0, 1]]})"),
            "line 4: circle 1, field py: expected a number, found a string");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, true, 0, 1]]})"),
            "line 4: circle 0, field vx: expected a number, found true");
}

TEST(protocol, rejects_a_circle_of_the_wrong_arity) {
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, 0, 1]]})"),
            "line 4: circle 0: expected 5 numbers [px, py, vx, vy, r], found 4");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, 0, 0, 1, 2]]})"),
            "line 4: circle 0: expected 5 numbers [px, py, vx, vy, r], found more");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[]]})"),
            "line 4: circle 0: expected 5 numbers [px, py, vx, vy, r], found 0");
}

TEST(protocol, rejects_a_negative_radius_with_the_oracles_message) {
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, 0, 0, 1], [0, 0, 0, 0, -2]]})"),
            "line 4: circle 1, field r: radius -2 is negative (r >= 0, the resolved profile) (not an element of C)");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, 0, 0, -5e-324]]})"),
            "line 4: circle 0, field r: radius -5e-324 is negative (r >= 0, the resolved profile) "
            "(not an element of C)");
}

// A million '[' would overflow a recursive reader's stack; this one refuses the fourth.
TEST(protocol, rejects_nesting_beyond_a_circle_at_its_first_level_however_deep) {
  const std::string deep = R"({"id": 1, "circles": [[)" + std::string(1000000, '[');
  EXPECT_EQ(refusal(deep), "line 4: circle 0, field px: expected a number, found an array");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, {"a": 1}, 0, 0, 1]]})"),
            "line 4: circle 0, field py: expected a number, found an object");
}

// Columns count bytes from 1: the first line has 38, so its end of input is at 39; in the second, the
// stray '{' follows the 24 bytes of the object and a space.
TEST(protocol, rejects_malformed_json_trailing_text_and_an_empty_line) {
  EXPECT_EQ(refusal(R"({"id": 1, "circles": [[0, 0, 0, 0, 1]])"),
            "line 4: malformed JSON at column 39: syntax error while parsing object - unexpected end of input; "
            "expected '}'");
  EXPECT_EQ(refusal(R"({"id": 1, "circles": []} {"id": 2, "circles": []})"),
            "line 4: malformed JSON at column 26: syntax error while parsing value - unexpected '{'; expected end of "
            "input");
  EXPECT_EQ(refusal(" \t"),
            R"(line 4: empty line, expected an object {"id": N, "circles": [[px, py, vx, vy, r], ...]})");
}

}  // namespace
}  // namespace circles::formats
