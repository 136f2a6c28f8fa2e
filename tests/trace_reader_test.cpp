// The reader of traces (formats/trace_reader.hpp): each trace that is not one refused with its file, line and
// reason, never a crash, and the line of each world it returns.
#include "formats/trace_reader.hpp"

#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>

namespace circles::formats {
namespace {

using circles::testing::thrown;

// The reader's message for `text` read as the trace "t.jsonl".
std::string read_error(const std::string& text) {
  std::istringstream in(text);
  TraceReader reader(in, "t.jsonl");
  const auto e = thrown<TraceReadError>([&] {
    while (reader.next()) {
    }
  });
  return e ? e->what() : "";
}

TEST(trace_reader, names_the_line_and_reason_of_a_malformed_line) {
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[]}\n{\"step\":1,\"circles\":[]}\n{\"step\":2,\"circles\":[[0,0,0,0]]}\n"),
            "t.jsonl:3: circle 0: expected 5 numbers [px, py, vx, vy, r], found 4");
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[[0,0,0,0,-1]]}\n"),
            "t.jsonl:1: circle 0, field r: radius -1 is negative (r >= 0, the resolved profile) (not an element of C)");
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[[NaN,0,0,0,1]]}\n"),
            "t.jsonl:1: circle 0, field px: NaN is not finite: a request or trace holds finite numbers (only an answer "
            "to conform may hold NaN, Infinity or -Infinity)");
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[[1e309,0,0,0,1]]}\n"),
            "t.jsonl:1: circle 0, field px: 1e309 is beyond the double range");
  EXPECT_EQ(read_error("{\"id\":0,\"circles\":[]}\n"),
            "t.jsonl:1: unexpected key \"id\" (a line has exactly the keys \"step\" and \"circles\")");
}

TEST(trace_reader, names_a_truncated_last_line) {
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[]}\n{\"step\":1,\"circ"),
            "t.jsonl:2: malformed JSON at column 16: syntax error while parsing object key - invalid string: missing "
            "closing quote; last read: '\"circ'; expected string literal");
}

TEST(trace_reader, refuses_steps_that_are_not_consecutive) {
  EXPECT_EQ(read_error("{\"step\":3,\"circles\":[]}\n{\"step\":4,\"circles\":[]}\n{\"step\":6,\"circles\":[]}\n"),
            "t.jsonl:3: \"step\": expected 5, found 6 (the steps of a trace are consecutive)");
  EXPECT_EQ(read_error("{\"step\":3,\"circles\":[]}\n{\"step\":3,\"circles\":[]}\n"),
            "t.jsonl:2: \"step\": expected 4, found 3 (the steps of a trace are consecutive)");
  EXPECT_EQ(read_error("{\"step\":18446744073709551615,\"circles\":[]}\n{\"step\":0,\"circles\":[]}\n"),
            "t.jsonl:2: \"step\": found 0 after 18446744073709551615, the largest step a trace can hold");
  EXPECT_EQ(read_error("{\"step\":-1,\"circles\":[]}\n"),
            "t.jsonl:1: \"step\": expected an integer from 0 to 18446744073709551615, found -1");
}

TEST(trace_reader, refuses_worlds_of_another_length_than_the_first) {
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[[0,0,0,0,1]]}\n{\"step\":1,\"circles\":[]}\n"),
            "t.jsonl:2: 0 circles, but the first world has 1 (a step maps circle k to circle k)");
}

TEST(trace_reader, refuses_an_empty_line_between_worlds_and_before_the_first) {
  const std::string empty = "empty line, expected an object {\"step\": N, \"circles\": [[px, py, vx, vy, r], ...]}";
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[]}\n\n{\"step\":1,\"circles\":[]}\n"), "t.jsonl:2: " + empty);
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[]}\n\n"), "t.jsonl:2: " + empty);
  EXPECT_EQ(read_error("\n \n{\"step\":0,\"circles\":[]}\n"), "t.jsonl:1: " + empty);
}

TEST(trace_reader, refuses_a_nul_byte_and_invalid_utf8_as_escaped_bytes) {
  using namespace std::string_literals;
  // The NUL is byte 24, after the 23 bytes of the object.
  EXPECT_EQ(read_error("{\"step\":0,\"circles\":[]}\0\n"s),
            "t.jsonl:1: malformed JSON at column 24: a NUL byte, which JSON text cannot contain");
  // The invalid byte is quoted as \xC3, so the message stays one line of ASCII.
  EXPECT_EQ(read_error("{\"st\xC3\x28p\":0,\"circles\":[]}\n"),
            "t.jsonl:1: malformed JSON at column 6: syntax error while parsing object key - invalid string: ill-formed "
            "UTF-8 byte; last read: '\"st\\xC3('; expected string literal");
}

TEST(trace_reader, reports_the_line_of_each_world_it_returns) {
  std::istringstream in("{\"step\":0,\"circles\":[]}\n{\"step\":1,\"circles\":[]}\n");
  TraceReader reader(in, "t.jsonl");
  EXPECT_EQ(reader.line(), 0u);
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.line(), 1u);
  const std::optional<Line> second = reader.next();
  ASSERT_TRUE(second);
  EXPECT_EQ(second->number, 1u);
  EXPECT_EQ(reader.line(), 2u);
  EXPECT_FALSE(reader.next());
  EXPECT_FALSE(reader.next());
}

}  // namespace
}  // namespace circles::formats
