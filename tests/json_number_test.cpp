// JSON numbers as doubles (formats/json_number.hpp): the shortest text that reads back as the double, always
// a float token; integers to their nearest double, ties to even; the tokens of the values JSON cannot write;
// and the exact forms messages name a double by.
#include "formats/json_number.hpp"

#include "tests/double_samples.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace circles::formats {
namespace {

using circles::testing::doubles_of_every_kind;
using circles::testing::thrown;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The plain rendering the writer must reproduce: to_chars' shortest round-trip text, then ".0" when that has
// neither a point nor an exponent.
std::string to_chars_rendering(double x) {
  char text[64];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  std::string s(text, end);
  if (s.find('.') == std::string::npos && s.find('e') == std::string::npos) s += ".0";
  return s;
}

std::string written_to_buffer(double x) {
  char text[json_number::kMaxChars];
  return std::string(text, json_number::write(text, x));
}

TEST(json_number, write_gives_the_bytes_of_a_plain_to_chars_rendering) {
  for (const double x : doubles_of_every_kind(200000)) {
    ASSERT_EQ(written_to_buffer(x), to_chars_rendering(x)) << json_number::hex(x);
    ASSERT_LE(written_to_buffer(x).size(), json_number::kMaxChars);
  }
  EXPECT_EQ(written_to_buffer(-0.0), "-0.0");
  EXPECT_EQ(written_to_buffer(1e22), "1e+22");
  EXPECT_EQ(written_to_buffer(123456789012345680000.0), "123456789012345683968.0");  // fixed form: all its digits
  EXPECT_EQ(written_to_buffer(-2.2250738585072014e-308), "-2.2250738585072014e-308");
}

TEST(json_number, append_appends_what_write_writes) {
  for (const double x : doubles_of_every_kind(1000)) {
    std::string out = "[";
    json_number::append(out, x);
    ASSERT_EQ(out, std::string("[").append(to_chars_rendering(x)));
  }
}

// Beyond 2^53 an integer is a tie or between two doubles: a truncating conversion (2^53 + 3 to 2^53 + 2,
// 2^64 − 1 to 2^64 − 2048) or one that rounds ties up (2^53 + 1 to 2^53 + 2) gives another double.
TEST(json_number, gives_an_integer_its_nearest_double_ties_to_even) {
  EXPECT_EQ(json_number::from_integer(std::int64_t{9007199254740993}), 0x1p53);      // 2^53 + 1: a tie, down
  EXPECT_EQ(json_number::from_integer(std::int64_t{9007199254740995}), 0x1p53 + 4);  // 2^53 + 3: a tie, up
  EXPECT_EQ(json_number::from_integer(std::int64_t{-9007199254740993}), -0x1p53);
  EXPECT_EQ(json_number::from_integer(std::numeric_limits<std::int64_t>::max()), 0x1p63);
  EXPECT_EQ(json_number::from_integer(std::numeric_limits<std::int64_t>::min()), -0x1p63);
  EXPECT_EQ(json_number::from_integer(std::numeric_limits<std::uint64_t>::max()), 0x1p64);
  EXPECT_EQ(json_number::from_integer(std::uint64_t{18446744073709550591u}), 0x1p64 - 2048);  // 2^64 − 1025: below the tie
  EXPECT_EQ(json_number::from_integer(std::uint64_t{18446744073709550592u}), 0x1p64);  // 2^64 − 1024: a tie, up to even
  EXPECT_EQ(json_number::from_integer(std::uint64_t{0}), 0.0);
  EXPECT_FALSE(std::signbit(json_number::from_integer(std::int64_t{0})));
}

TEST(json_number, append_refuses_nan_and_the_infinities_which_json_cannot_write) {
  for (const double x : {kNaN, kInf, -kInf}) {
    std::string out = "[";
    const auto e = thrown<std::domain_error>([&] { json_number::append(out, x); });
    ASSERT_TRUE(e);
    EXPECT_STREQ(e->what(), "a JSON number must be finite");
    EXPECT_EQ(out, "[") << "a refused number left text behind";
  }
}

// For answers and messages, the tokens of Python's json and JSON5; in a JSON document, the same as strings.
TEST(json_number, writes_nan_and_the_infinities_as_tokens_or_as_strings) {
  const auto any = [](double x) {
    std::string out;
    json_number::append_any(out, x);
    return out;
  };
  const auto or_string = [](double x) {
    std::string out;
    json_number::append_or_string(out, x);
    return out;
  };
  EXPECT_EQ(any(kNaN), "NaN");
  EXPECT_EQ(any(-kNaN), "NaN");
  EXPECT_EQ(any(kInf), "Infinity");
  EXPECT_EQ(any(-kInf), "-Infinity");
  EXPECT_EQ(any(-0.0), "-0.0");
  EXPECT_EQ(or_string(kNaN), "\"NaN\"");
  EXPECT_EQ(or_string(kInf), "\"Infinity\"");
  EXPECT_EQ(or_string(-kInf), "\"-Infinity\"");
  EXPECT_EQ(or_string(0.1), "0.1");
  EXPECT_EQ(or_string(1e300), "1e+300");
}

TEST(json_number, reads_back_only_the_three_tokens_it_writes) {
  ASSERT_TRUE(json_number::non_finite_token("NaN"));
  EXPECT_TRUE(std::isnan(*json_number::non_finite_token("NaN")));
  EXPECT_EQ(json_number::non_finite_token("Infinity").value_or(0), kInf);
  EXPECT_EQ(json_number::non_finite_token("-Infinity").value_or(0), -kInf);
  for (const char* other : {"nan", "inf", "-inf", "infinity", "+Infinity", "Infinity ", "-NaN", "", "1e999"})
    EXPECT_FALSE(json_number::non_finite_token(other)) << '"' << other << '"';
}

// C's "%a" names every double exactly, subnormals in the form 0x0.…p-1022.
TEST(json_number, names_a_double_by_its_shortest_decimal_and_its_hexadecimal_form) {
  EXPECT_EQ(json_number::hex(0.1), "0x1.999999999999ap-4");
  EXPECT_EQ(json_number::hex(-0.0), "-0x0p+0");
  EXPECT_EQ(json_number::hex(1.0), "0x1p+0");
  EXPECT_EQ(json_number::hex(5e-324), "0x0.0000000000001p-1022");
  EXPECT_EQ(json_number::hex(std::numeric_limits<double>::max()), "0x1.fffffffffffffp+1023");
  EXPECT_EQ(json_number::decimal_and_hex(0.1), "0.1 (0x1.999999999999ap-4)");
  EXPECT_EQ(json_number::decimal_and_hex(-1.0 / 60), "-0.016666666666666666 (-0x1.1111111111111p-6)");
  EXPECT_EQ(json_number::decimal_and_hex(100.0), "100.0 (0x1.9p+6)");
  EXPECT_EQ(json_number::decimal_and_hex(kNaN), "NaN");
  EXPECT_EQ(json_number::decimal_and_hex(-kInf), "-Infinity");
}

}  // namespace
}  // namespace circles::formats
