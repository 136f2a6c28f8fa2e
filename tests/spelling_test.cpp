// The spellings of the wire family (formats/spelling.hpp): each is a JSON number token of docs/protocol.md's
// grammar whose exact decimal value rounds to the double it spells, read exactly here (GMP) and by our reader
// (formats::parse_line); every form the docs name is among them; the lines that carry them read back as their
// worlds. tests/spelling_python_test.py reads the same spellings with Python's float().
#include "formats/spelling.hpp"

#include "formats/json_number.hpp"
#include "formats/protocol.hpp"
#include "spec/rational.hpp"
#include "tests/double_samples.hpp"
#include "tests/repository.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <regex>
#include <string>
#include <vector>

namespace circles::formats {
namespace {

using spec::Q;
using spec::Z;

// docs/protocol.md, The grammar of a number: the expression in the code block after its marker.
std::string request_number_in_protocol_md() {
  const std::vector<std::string> lines = testing::lines_of("docs/protocol.md");
  const auto marker = std::find(lines.begin(), lines.end(), "<!-- request-number -->");
  if (marker == lines.end() || lines.end() - marker < 3 || marker[1] != "```") return "no expression";
  return marker[2];
}
const std::regex kRequestNumber(request_number_in_protocol_md());

// The exact value of a token of that grammar.
Q exact_value(const std::string& token) {
  std::smatch m;
  EXPECT_TRUE(std::regex_match(token, m, kRequestNumber)) << token;
  const std::string fraction = m[2].matched ? m[2].str().substr(1) : "";
  const std::string all = m[1].str() + fraction;  // without leading zeros, which Z would read as octal
  const Z digits(all.find_first_not_of('0') == std::string::npos ? "0" : all.substr(all.find_first_not_of('0')));
  long exponent = m[3].matched ? std::stol(m[3].str().substr(1)) : 0;
  exponent -= static_cast<long>(fraction.size());
  const Q scale = Q(boost::multiprecision::pow(Z(10), static_cast<unsigned>(std::abs(exponent))));
  const Q value = exponent >= 0 ? Q(digits) * scale : Q(digits) / scale;
  return token[0] == '-' ? Q(-value) : value;
}

// The doubles of every kind, and the ones whose spellings are the edge cases: zeros, the least and largest
// subnormals, DBL_MIN, DBL_MAX, powers of two (whose inner neighbour is half as far), 2^53.
std::vector<double> samples() {
  std::vector<double> xs = testing::doubles_of_every_kind(200);
  for (const double x : {std::nextafter(DBL_MIN, 0.0), 0x1p53, 0x1p-1022, 0x1p-1073, 3 * 0x1p-1074, 0x1p1023, 1e300})
    xs.insert(xs.end(), {x, -x});
  return xs;
}

TEST(spelling, every_spelling_is_a_request_number_whose_exact_value_rounds_to_the_double_and_our_reader_agrees) {
  for (const double x : samples()) {
    const std::vector<std::string> forms = spellings(x);
    ASSERT_GE(forms.size(), 7u) << x;  // 5e-324's shortest digits are its integer mantissa too
    std::string first;
    json_number::append(first, x);
    EXPECT_EQ(forms.front(), first);
    for (const std::string& s : forms) {
      ASSERT_TRUE(std::regex_match(s, kRequestNumber)) << s;
      const double exact = spec::nearest_double(exact_value(s));
      EXPECT_EQ(exact, x) << s << " spells " << json_number::hex(x) << " but rounds to " << json_number::hex(exact);
      EXPECT_LE(s.size(), kMaxSpellingChars) << s;
      const Line line = parse_line("{\"id\": 1, \"circles\": [[" + s + ", 0, 0, 0, 1]]}", 1);
      EXPECT_EQ(line.circles.at(0)[0], x) << s << " read as " << json_number::hex(line.circles[0][0]);
      EXPECT_EQ(std::strtod(s.c_str(), nullptr), x) << s;
    }
  }
}

// Our reader follows the grammar: it reads a token the expression matches, and refuses each token the page names
// as not a number, and one beyond the range.
TEST(spelling, our_reader_reads_the_tokens_of_the_grammar_of_protocol_md_and_refuses_the_others) {
  EXPECT_EQ(request_number_in_protocol_md(), R"(-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  const auto reads = [](const std::string& token) {
    try {
      parse_line("{\"id\": 1, \"circles\": [[" + token + ", 0, 0, 0, 1]]}", 1);
      return true;
    } catch (const ProtocolError&) {
      return false;
    }
  };
  for (const std::string token : {"0", "-0", "0.0", "1E+0007", "1e-400", "-1e-400", "0e999999", "9007199254740993",
                                  "18446744073709551617", "1.7976931348623157e308", "123456789012345678901234567890e-300"}) {
    EXPECT_TRUE(std::regex_match(token, kRequestNumber)) << token;
    EXPECT_TRUE(reads(token)) << token;
  }
  for (const std::string token : {"+1", "01", "-01", ".5", "1.", "1e", "1e+", "0x10", "NaN", "Infinity", "-Infinity",
                                  "nan", "inf", "--1", "1e1.5"}) {
    EXPECT_FALSE(std::regex_match(token, kRequestNumber)) << token;
    EXPECT_FALSE(reads(token)) << token;
  }
  EXPECT_TRUE(std::regex_match(std::string("1e309"), kRequestNumber));
  EXPECT_FALSE(reads("1e309"));  // a number, but beyond the double range
}

// Each form docs/protocol.md names is spelled: an exponent with E and with e+, leading zeros in it, an integer
// mantissa, more than 17 digits (the exact value, and just inside a midpoint), a tie, an underflow to zero.
TEST(spelling, spells_each_form_the_protocol_names) {
  const auto has = [](double x, const std::string& s) {
    const std::vector<std::string> forms = spellings(x);
    return std::find(forms.begin(), forms.end(), s) != forms.end();
  };
  EXPECT_TRUE(has(0.0, "1e-400"));
  EXPECT_TRUE(has(-0.0, "-1e-400"));
  EXPECT_TRUE(has(-0.0, "-0"));
  EXPECT_TRUE(has(0.0, "0E+5"));
  EXPECT_TRUE(has(5e-324, "5E-324"));
  EXPECT_TRUE(has(5e-324, "4.9406564584124654e-324"));
  EXPECT_TRUE(has(60.0, "60.000"));
  EXPECT_TRUE(has(60.0, "6e1"));
  EXPECT_TRUE(has(60.0, "0.6E+0002"));
  EXPECT_TRUE(has(0x1p53, "9007199254740992"));
  EXPECT_TRUE(has(0x1p53, "9007199254740993"));       // the outer midpoint, a tie that goes to the even 2^53
  EXPECT_TRUE(has(0x1p53, "9007199254740991.50001"));  // just above the inner midpoint
  EXPECT_TRUE(has(0.1, "0.1000000000000000055511151231257827021181583404541015625"));
  EXPECT_TRUE(has(0.1, "1.0000000000000001e-01"));
  EXPECT_TRUE(has(DBL_MAX, "1.797693134862315807937289714053034150799341327100378269361737789804449682927647509466490"
                           "179775872070963302864166928879109465555478519404026306574886715058206819089020007083836"
                           "762738548458177115317644757302700698555713669596228429148198608349364752927190741684443"
                           "655107043427115596995080930428801779041744977919999e308"));
}

// kMaxSpellingChars: the longest spelling of the doubles whose exact values and midpoints have the most digits,
// the subnormals with the most significant bits and their negatives.
TEST(spelling, the_longest_spelling_is_kMaxSpellingChars) {
  std::size_t longest = 0;
  for (const double a : {std::nextafter(DBL_MIN, 0.0), std::nextafter(std::nextafter(DBL_MIN, 0.0), 0.0), DBL_MIN,
                         std::nextafter(DBL_MIN, 1.0)})
    for (const double x : {a, -a})
      for (const std::string& s : spellings(x)) longest = std::max(longest, s.size());
  EXPECT_EQ(longest, kMaxSpellingChars);
}

// A spelled line reads back as its world, with both key orders and some whitespace among the lines written, and
// the same world gives the same text (a replay sends what the first run sent).
TEST(spelling, a_spelled_line_reads_back_as_its_world) {
  const std::vector<double> xs = samples();
  bool circles_first = false, spaced = false;
  for (std::size_t i = 0; i + 15 <= xs.size(); i += 15) {
    spec::Circles w;
    for (std::size_t k = 0; k < 3; ++k)
      w.push_back({xs[i + 5 * k], xs[i + 5 * k + 1], xs[i + 5 * k + 2], xs[i + 5 * k + 3], std::fabs(xs[i + 5 * k + 4])});
    std::string text, again;
    append_spelled_line(text, kId, 7 + i, w);
    append_spelled_line(again, kId, 7 + i, w);
    EXPECT_EQ(text, again);
    const Line line = parse_line(text, 1);
    EXPECT_EQ(line.number, 7 + i);
    EXPECT_EQ(line.circles, w) << text;
    circles_first |= text.starts_with("{\"circles\"");
    spaced |= text.find_first_of(" \t") != std::string::npos;
  }
  EXPECT_TRUE(circles_first);
  EXPECT_TRUE(spaced);
}

}  // namespace
}  // namespace circles::formats
