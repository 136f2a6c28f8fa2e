// The reader of traces: JSON Lines files of worlds, one line {"step": t, "circles": [...]} per world
// (docs/protocol.md, "Traces"), as `circles run --trace` writes them and any other implementation may.
//
// A trace is hostile input: the reader checks each line with the protocol's reader (cli::parse_line, counter
// "step") and the trace's own rules, and stops at the first fault with a TraceReadError naming the file, the
// line and the reason. The rules: at least one world; no empty line; each line one protocol line; step numbers
// consecutive (t, t + 1, t + 2, ... from any first t); every world as long as the first (a step maps circle k
// to circle k). Lines are read one at a time, so a trace longer than memory can still be read; and from a
// seekable stream (a file) a line of compact circles is read in pieces into its doubles (formats/streamed.hpp),
// so that a line of 10^7 circles, 1 GB of text, needs the 400 MB of its doubles and not its text too. A line the
// pieces do not take is read again whole, as before: every message is parse_line's.
#pragma once

#include "formats/plain_line.hpp"
#include "formats/protocol.hpp"
#include "formats/streamed.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace circles::formats {

// A trace that is not one. what() is "FILE:LINE: reason", or "FILE: reason" when no line is at fault (a file
// that cannot be opened, an empty file): "t.jsonl:4: "step": expected 3, found 5 (steps are consecutive)".
class TraceReadError : public std::runtime_error {
 public:
  TraceReadError(const std::string& source, std::size_t line, const std::string& reason);
  std::string source;
  std::size_t line;    // 1-based; 0 when the fault is the file's, not a line's
  std::string reason;  // what() without "FILE:LINE: "
};

class TraceReader {
 public:
  // Reads the file at `path`, or the standard input for "-" (named "<stdin>" in messages). Throws
  // TraceReadError when it is missing, a directory or cannot be opened.
  explicit TraceReader(const std::string& path);
  // Reads `in`, named `source` in messages (tests and the fuzzer read strings this way), `piece` bytes at a
  // time on the fast path.
  TraceReader(std::istream& in, std::string source, std::size_t piece = kStreamPiece);

  // The next world, or nothing at the end of the trace. Throws TraceReadError for the first line that breaks
  // a rule above, and for a trace that ends before its first world (an empty file).
  std::optional<Line> next();

  // The line of the last world next() returned (1-based; 0 before the first).
  std::size_t line() const noexcept { return line_; }
  const std::string& source() const noexcept { return source_; }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& reason) const;
  std::optional<Line> stream_line();

  std::unique_ptr<std::istream> owned_;  // the file, when the reader opened it
  std::istream* in_;
  std::string source_;
  std::size_t line_ = 0;         // lines read so far
  std::size_t first_blank_ = 0;  // the first blank line before the first world, 0 if none
  std::optional<std::uint64_t> last_step_;
  std::size_t circles_ = 0;  // the length of the first world
  std::size_t piece_ = kStreamPiece;
  std::string text_;         // the line being read, when the streamed path does not take it
  PlainLineReader plain_;    // the fast path for plain lines; parse_line reads the others
};

}  // namespace circles::formats
