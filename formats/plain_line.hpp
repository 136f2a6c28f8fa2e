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

 private:
  struct Parser;
  std::unique_ptr<Parser> parser_;
};

}  // namespace circles::formats
