#include "formats/trace_reader.hpp"

#include "formats/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace circles::formats {
namespace {

// "FILE:LINE: WHY", or "FILE: WHY" for line 0 (the file as a whole); appended, not added to a literal, for the
// reason cmake/flags.cmake gives (GCC 12's false -Wrestrict).
std::string located(const std::string& file, std::size_t line, const std::string& why) {
  std::string text = file;
  if (line) text.append(":").append(std::to_string(line));
  return text.append(": ").append(why);
}

}  // namespace

TraceReadError::TraceReadError(const std::string& file, std::size_t line_number, const std::string& why)
    : std::runtime_error(located(file, line_number, why)),
      source(file),
      line(line_number),
      reason(why) {}

TraceReader::TraceReader(const std::string& path) : source_(input_name(path)) {
  try {
    owned_ = open_input(path);
  } catch (const InputError& e) {
    fail(0, e.what());
  }
  in_ = owned_.get();
}

TraceReader::TraceReader(std::istream& in, std::string source, std::size_t piece)
    : in_(&in), source_(std::move(source)), piece_(piece) {}

void TraceReader::fail(std::size_t line, const std::string& reason) const { throw TraceReadError(source_, line, reason); }

// The next line by the fast path, with the stream moved past it; or nothing, with the stream where it was.
std::optional<Line> TraceReader::stream_line() {
  const std::streampos start = in_->tellg();
  if (start == std::streampos(-1)) return std::nullopt;  // a pipe: getline alone
  std::optional<Streamed> streamed;
  try {
    streamed = stream_document(*in_, true, plain_, piece_, circles_);
  } catch (const std::bad_alloc&) {
    fail(line_ + 1, "the world is too large to hold in memory");
  }
  std::optional<Line> world;
  if (streamed) {
    // The rest of the line, read by parse_line, with no circle and with one (formats/streamed.hpp).
    try {
      Line outer = parse_line(streamed->outer, line_ + 1, kStep);
      if (outer.circles.empty() && parse_line(streamed->with_one_circle(), line_ + 1, kStep).circles.size() == 1)
        world = Line{outer.number, std::move(streamed->circles)};
    } catch (const ProtocolError&) {
    }
  }
  in_->clear();
  in_->seekg(world ? start + static_cast<std::streamoff>(streamed->bytes) : start);
  return world;
}

std::optional<Line> TraceReader::next() {
  for (;;) {
    std::optional<Line> streamed = stream_line();
    errno = 0;
    if (!streamed && !std::getline(*in_, text_)) break;
    ++line_;
    const bool blank = !streamed && text_.find_first_not_of(" \t\r\n") == std::string::npos;
    // Blank lines before the first world: an empty file if nothing follows, an empty line if something does.
    if (blank && !last_step_) {
      if (!first_blank_) first_blank_ = line_;
      continue;
    }
    Line world;
    try {
      // parse_line refuses a blank line with the protocol's own message; so is the first blank line before
      // a world reported.
      if (first_blank_) parse_line("", first_blank_, kStep);
      if (streamed) world = std::move(*streamed);
      else if (std::optional<Line> plain = plain_.read(text_, kStep)) world = std::move(*plain);
      else world = parse_line(text_, line_, kStep);
    } catch (const ProtocolError& e) {
      fail(e.line, e.reason);
    } catch (const std::bad_alloc&) {
      fail(line_, "the world is too large to hold in memory");
    }
    if (last_step_) {
      if (*last_step_ == std::numeric_limits<std::uint64_t>::max())
        fail(line_, "\"step\": found " + std::to_string(world.number) + " after " + std::to_string(*last_step_) +
                        ", the largest step a trace can hold");
      if (world.number != *last_step_ + 1)
        fail(line_, "\"step\": expected " + std::to_string(*last_step_ + 1) + ", found " +
                        std::to_string(world.number) + " (the steps of a trace are consecutive)");
      if (world.circles.size() != circles_)
        fail(line_, std::to_string(world.circles.size()) + " circles, but the first world has " +
                        std::to_string(circles_) + " (a step maps circle k to circle k)");
    } else {
      circles_ = world.circles.size();
    }
    last_step_ = world.number;
    return world;
  }
  // getline turns every failure into badbit, a line longer than memory too (std::bad_alloc, errno ENOMEM).
  if (in_->bad())
    fail(line_ + 1, std::string("cannot read the line: ") + (errno ? std::strerror(errno) : "read error"));
  if (!last_step_)
    fail(0, "empty file, expected one world per line {\"step\": t, \"circles\": [[px, py, vx, vy, r], ...]}");
  return std::nullopt;
}

}  // namespace circles::formats
