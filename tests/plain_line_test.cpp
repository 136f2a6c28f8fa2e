// The trace reader's fast path (formats/plain_line.hpp) against parse_line: on every line it accepts, the same
// Line bit for bit; on lines parse_line refuses, or reads by a rule of its own, nothing, so that parse_line
// reads them and its messages stay the only ones.
#include "formats/plain_line.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace circles::formats {
namespace {

// Reads `text` both ways; expects the fast path to accept it (or not, with plain == false) and, if it does, to
// agree with parse_line to the bit.
void same_line(const std::string& text, bool plain = true) {
  PlainLineReader reader;
  std::string copy = text;
  const std::optional<Line> fast = reader.read(copy, kStep);
  EXPECT_EQ(copy, text) << "the fast path changed the line";
  EXPECT_EQ(fast.has_value(), plain) << text;
  if (!fast) return;
  const Line slow = parse_line(text, 1, kStep);
  EXPECT_EQ(fast->number, slow.number) << text;
  ASSERT_EQ(fast->circles.size(), slow.circles.size()) << text;
  for (std::size_t k = 0; k < slow.circles.size(); ++k)
    for (std::size_t f = 0; f < 5; ++f)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(fast->circles[k][f]), std::bit_cast<std::uint64_t>(slow.circles[k][f]))
          << text << ": circle " << k << " field " << f;
}

TEST(plain_line, reads_written_lines_of_random_doubles_of_every_exponent_as_parse_line_does) {
  std::mt19937_64 g(15);
  long fields = 0;
  for (int line = 0; line < 200; ++line) {
    Circles w(static_cast<std::size_t>(g() % 50));
    for (auto& c : w) {
      for (double& x : c) {
        x = std::bit_cast<double>(g());  // every exponent, subnormals included
        if (!std::isfinite(x)) x = 0;
        ++fields;
      }
      c[4] = std::fabs(c[4]);
    }
    same_line(format_line(kStep, g(), w));
  }
  EXPECT_GT(fields, 10000);
}

TEST(plain_line, reads_every_spelling_of_a_number_as_parse_line_does) {
  same_line(R"({"step":0,"circles":[]})");
  same_line(R"( { "circles" : [ [ 1 , -2 , 3e0 , 4E-1 , 0.5 ] ] , "step" : 18446744073709551615 } )");
  same_line(R"({"step":1,"circles":[[-0.0,-0,0e0,-0e-5,-0.0]]})");
  // Integer ties beyond 2^53, as from_integer rounds them, and the largest integers of 64 bits.
  same_line(R"({"step":2,"circles":[[9007199254740993,-9007199254740995,-9223372036854775808,9223372036854775807,18446744073709551615]]})");
  // Decimal ties and near-ties, 17 to 40 digits, subnormals, the least and largest doubles.
  same_line(R"({"step":3,"circles":[[0.1,2.2250738585072011e-308,4.9406564584124654e-324,1.7976931348623157e308,2.47032822920623272e-324]]})");
  same_line(R"({"step":4,"circles":[[9007199254740993.0,1.00000000000000011102230246251565404236316680908203125,1e-400,123456789012345678901234567890e-10,0.3]]})");
  same_line("{\"st\\u0065p\":5,\"circles\":[[1,2,3,4,5]]}\r");
}

TEST(plain_line, leaves_to_parse_line_every_line_it_does_not_plainly_accept) {
  same_line(R"({"step":1,"circles":[[1,2,3,4,-1]]})", false);                      // outside C
  same_line(R"({"step":1,"circles":[[1,2,3,4,1e400]]})", false);                   // beyond the double range
  same_line(R"({"step":1,"circles":[[1,2,3,4,18446744073709551616]]})", false);    // an integer beyond 64 bits
  same_line(R"({"step":1,"circles":[[1,2,3,4]]})", false);                         // four fields
  same_line(R"({"step":1,"circles":[[1,2,3,4,5,6]]})", false);                     // six
  same_line(R"({"step":1,"circles":[[1,2,3,4,5]],"step":2})", false);              // a key twice
  same_line(R"({"step":1,"circles":[[1,2,3,4,5]],"ms":2})", false);                // another key
  same_line(R"({"step":1})", false);                                                // no circles
  same_line(R"({"step":1.0,"circles":[]})", false);                                 // a counter not an integer
  same_line(R"({"step":-1,"circles":[]})", false);
  same_line(R"({"step":1,"circles":[[1,2,3,4,5]]} x)", false);                     // trailing text
  same_line(R"({"step":1,"circles":[[1,2,3,4,5]]}{})", false);
  same_line(R"({"step":1,"circles":[[1,2,3,4,[5]]]})", false);                     // nesting
  same_line(R"({"step":1,"circles":[[1,2,3,4,5])", false);                         // truncated
  same_line(R"({"step":1,"circles":[[01,2,3,4,5]]})", false);                      // not JSON
  same_line("", false);
  same_line(std::string(1000000, '['), false);                                       // deep nesting
  same_line(R"({"step":1,"circles":[[1,2,3,4,1)" + std::string(1000000, '0') + "]]}", false);  // 10^6 digits
}

}  // namespace
}  // namespace circles::formats
