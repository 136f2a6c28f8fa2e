// Trace lines written a part at a time (formats/trace_writer.hpp): the same bytes as append_line, for every
// thread count, and nothing after a failure.
#include "formats/protocol.hpp"
#include "formats/trace_writer.hpp"

#include "tests/double_samples.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::formats {
namespace {

using circles::testing::thrown;

// n circles of random doubles of all kinds, each finite.
Circles world(std::size_t n) {
  const std::vector<double> xs = circles::testing::doubles_of_every_kind(n);
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
