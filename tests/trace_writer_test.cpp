// Trace lines written a part at a time (formats/trace_writer.hpp) and the number text they use
// (json_number::write): the same bytes as a plain std::to_chars rendering and as append_line, for every thread
// count, and nothing after a failure.
#include "formats/json_number.hpp"
#include "formats/protocol.hpp"
#include "formats/trace_writer.hpp"

#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::formats {
namespace {

using circles::testing::thrown;

// The plain rendering the writer must reproduce: to_chars' shortest round-trip text, then ".0" when that has
// neither a point nor an exponent.
std::string plain(double x) {
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

// Doubles of every kind: random bit patterns (every exponent), random values of a trace's magnitudes, and the
// edges: zeros, subnormals, the extremes, integers on both sides of where to_chars switches to the exponent.
std::vector<double> doubles(std::size_t random) {
  std::vector<double> xs = {0.0,  -0.0,  1.0,   -1.0,  0.1,     1e15,     1e16,    1e21, 1e22, 1e23,
                            123456789012345680000.0, 9007199254740993.0, 0.000001, 1e-7, 5e-324, -5e-324,
                            DBL_MIN, -DBL_MIN, DBL_MAX, -DBL_MAX, 2.2250738585072009e-308, 100.0, 60.0, 1.0 / 60};
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> trace(-10000, 10000);
  for (std::size_t i = 0; i < random; ++i) {
    const double x = std::bit_cast<double>(rng());
    if (std::isfinite(x)) xs.push_back(x);
    xs.push_back(trace(rng));
    xs.push_back(std::round(trace(rng)) * std::ldexp(1.0, static_cast<int>(rng() % 80)));  // integers
  }
  return xs;
}

TEST(json_number, write_gives_the_bytes_of_a_plain_to_chars_rendering) {
  for (const double x : doubles(200000)) {
    ASSERT_EQ(written_to_buffer(x), plain(x)) << json_number::hex(x);
    ASSERT_LE(written_to_buffer(x).size(), json_number::kMaxChars);
  }
  EXPECT_EQ(written_to_buffer(-0.0), "-0.0");
  EXPECT_EQ(written_to_buffer(1e22), "1e+22");
  EXPECT_EQ(written_to_buffer(123456789012345680000.0), "123456789012345683968.0");  // fixed form: all its digits
  EXPECT_EQ(written_to_buffer(-2.2250738585072014e-308), "-2.2250738585072014e-308");
}

TEST(json_number, append_appends_what_write_writes) {
  for (const double x : doubles(1000)) {
    std::string out = "[";
    json_number::append(out, x);
    ASSERT_EQ(out, std::string("[").append(plain(x)));
  }
}

// n circles of random doubles of all kinds, each finite.
Circles world(std::size_t n) {
  const std::vector<double> xs = doubles(n);
  Circles w(n);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < 5; ++j) w[k][j] = xs[(5 * k + j) % xs.size()];
  return w;
}

struct Written {
  std::string text;
  std::size_t pieces = 0;
  std::uint64_t bytes = 0;
};

Written write_line(LineWriter& writer, const Circles& w, std::uint64_t number = 7) {
  Written out;
  out.bytes = writer.write(
      [&](std::string_view text) {
        out.text += text;
        ++out.pieces;
      },
      kStep, number, w.size(), source_of(w));
  return out;
}

// Sizes around the parts' edges, and a line of several parts with a short last one.
TEST(LineWriter, writes_the_bytes_of_append_line_for_every_thread_count) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, kPartCircles - 1, kPartCircles, kPartCircles + 1,
                              3 * kPartCircles + 5}) {
    const Circles w = world(n);
    const std::string want = format_line(kStep, 7, w) + "\n";
    for (const unsigned threads : {1u, 2u, 3u}) {
      LineWriter writer(threads);
      const Written got = write_line(writer, w);
      ASSERT_EQ(got.text, want) << n << " circles, " << threads << " threads";
      EXPECT_EQ(got.bytes, want.size());
      // The header, one piece per part, the closing "]}\n".
      EXPECT_EQ(got.pieces, 2 + (n + kPartCircles - 1) / kPartCircles);
    }
  }
}

TEST(LineWriter, gives_the_same_bytes_on_one_thread_and_two_line_after_line) {
  const Circles a = world(2 * kPartCircles + 100), b = world(kPartCircles / 2);
  LineWriter one(1), two(2);
  for (const Circles* w : {&a, &b, &a}) {  // buffers reused from line to line, a shorter line between
    const std::string want = format_line(kStep, 3, *w) + "\n";
    EXPECT_EQ(write_line(one, *w, 3).text, want);
    EXPECT_EQ(write_line(two, *w, 3).text, want);
  }
}

// A number that is not finite in the third part: the header and the first two parts reach the sink, nothing
// after them, and the error is append_line's.
TEST(LineWriter, stops_at_the_part_of_a_number_that_is_not_finite) {
  Circles w = world(4 * kPartCircles);
  w[2 * kPartCircles + 17][3] = std::numeric_limits<double>::infinity();
  const std::string whole = format_line(kStep, 1, world(4 * kPartCircles));
  for (const unsigned threads : {1u, 2u}) {
    LineWriter writer(threads);
    std::string got;
    const auto e = thrown<std::domain_error>(
        [&] { writer.write([&](std::string_view text) { got += text; }, kStep, 1, w.size(), source_of(w)); });
    ASSERT_TRUE(e);
    EXPECT_EQ(std::string(e->what()), "a JSON number must be finite");
    const std::string prefix = format_line(kStep, 1, Circles(w.begin(), w.begin() + 2 * kPartCircles));
    EXPECT_EQ(got, prefix.substr(0, prefix.size() - 2)) << threads << " threads";  // without its "]}"
  }
}

// A sink that fails on its third piece (the second part): that error leaves write, on any thread count, and
// no piece is offered after it.
TEST(LineWriter, passes_on_the_sinks_error_and_offers_nothing_after_it) {
  const Circles w = world(5 * kPartCircles);
  for (const unsigned threads : {1u, 2u}) {
    LineWriter writer(threads);
    std::size_t pieces = 0;
    const auto e = thrown<std::runtime_error>([&] {
      writer.write(
          [&](std::string_view) {
            if (++pieces == 3) throw std::runtime_error("disk full");
          },
          kStep, 1, w.size(), source_of(w));
    });
    ASSERT_TRUE(e);
    EXPECT_EQ(std::string(e->what()), "disk full");
    EXPECT_EQ(pieces, 3u) << threads << " threads";
  }
}

}  // namespace
}  // namespace circles::formats
