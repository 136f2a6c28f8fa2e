// `circles serve`: an engine behind the step protocol (formats/protocol.hpp, docs/protocol.md), so that any
// checker can test it: one request per line on the input, one flushed response line each.
#pragma once

#include "engines/registry.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>

namespace circles::conform {

using spec::Circles;
using formats::ProtocolError;
using formats::Line;
using formats::parse_line;
using formats::format_line;
using formats::kId;

// A request whose image has a position beyond the double range, so that no response can be written.
// what(): "line 4 (id 7): circle 2, field px: the position p + v/60 overflows to infinity".
class RequestOverflow : public std::overflow_error {
 public:
  RequestOverflow(std::size_t line, std::uint64_t id, std::size_t index, spec::Field field);
  std::size_t line;
  std::uint64_t id;
  std::size_t index;
  spec::Field field;
};

// The step behind the protocol: w_1 for the w_0 of a request. Throws StepOverflow (step 1) for a position
// beyond the double range. Any step function can be served so, not only an engine (the gallery of wrong
// implementations does, tests/gallery_candidate.cpp).
using StepFunction = std::function<Circles(const Circles&)>;

// The response line (without its newline) to one request line, number `line_number`: what serve writes for
// it. Throws ProtocolError for a malformed request and RequestOverflow.
std::string answer(const StepFunction& step, std::string_view request, std::size_t line_number);
std::string answer(const engines::EngineEntry& engine, unsigned threads, std::string_view request, std::size_t line_number);

// Answers every line of `in` on `out`, flushing each response, until the end of `in`. Returns the exit code:
// 0 at the end of the input, 2 after a malformed request or an overflow, which it names on `err` (nothing is
// written to `out` for that line, and the lines after it are not read).
int serve(const StepFunction& step, std::istream& in, std::ostream& out, std::ostream& err);
int serve(const engines::EngineEntry& engine, unsigned threads, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace circles::conform
