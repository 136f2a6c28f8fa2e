// The fast path of the trace reader: a line that parse_line would read strictly, read with simdjson's On-Demand
// parser, for the plain lines only.
//
//   Invariant: whenever read(text, counter) gives a Line, parse_line(text, n, counter) gives the same Line,
//              bit for bit. It gives nothing for every line it does not plainly accept (a fault, an unusual
//              key, an integer beyond 64 bits, a number beyond the double range, a negative radius, ...), and
//              the caller then reads that line with parse_line, whose message names the fault: every message
//              is parse_line's.
// tests/plain_line_test.cpp holds the two readers equal on well-formed lines of every spelling.
#pragma once

#include "formats/protocol.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace circles::formats {

class PlainLineReader {
 public:
  PlainLineReader();
  ~PlainLineReader();
  PlainLineReader(PlainLineReader&&) noexcept;
  PlainLineReader& operator=(PlainLineReader&&) noexcept;

  // The line {"<counter>": N, "circles": [[px, py, vx, vy, r], ...]} (keys in either order, JSON whitespace
  // anywhere), or nothing. `text` may gain capacity (simdjson reads a padding beyond its end) but keeps its
  // value.
  std::optional<Line> read(std::string& text, std::string_view counter);

  // The circles of the array text[0, size), [[px, py, vx, vy, r], ...] with at least one circle, each read as
  // read() reads a line's, appended to `circles`; false for anything else (`circles` may then hold some of
  // them). text[size, capacity) is padding that simdjson reads but does not change; capacity >= size +
  // SIMDJSON_PADDING. The pieces of a streamed document (formats/streamed.hpp) are read this way.
  bool append_circles(const char* text, std::size_t size, std::size_t capacity, Circles& circles);

 private:
  struct Parser;
  std::unique_ptr<Parser> parser_;
};

}  // namespace circles::formats
