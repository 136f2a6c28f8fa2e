// libFuzzer target for the trace reader, formats::TraceReader (what `circles check-trace` reads): any bytes give a
// sequence of worlds or a TraceReadError naming the source, never another exception or a crash. The worlds
// read keep the trace's rules: finite doubles with r >= 0, consecutive steps, one length. A failure after some
// worlds names a line after theirs; and the worlds read, written again as a trace (formats::format_line) and read
// back, are the same bit for bit.
#include "formats/protocol.hpp"
#include "formats/trace_reader.hpp"
#include "fuzz/check.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace circles;

namespace {

const std::string kSource = "fuzz.jsonl";

// Reads `text` to its end or to its first fault: the worlds read, and the error if there was one.
std::vector<formats::Line> read(const std::string& text, std::optional<formats::TraceReadError>& error,
                            std::vector<std::size_t>& lines) {
  std::istringstream in(text);
  formats::TraceReader reader(in, kSource);
  std::vector<formats::Line> worlds;
  try {
    while (std::optional<formats::Line> w = reader.next()) {
      worlds.push_back(std::move(*w));
      lines.push_back(reader.line());
    }
  } catch (const formats::TraceReadError& e) {
    error = e;
  }
  return worlds;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<formats::TraceReadError> error;
  std::vector<std::size_t> lines;
  const std::vector<formats::Line> worlds = read(text, error, lines);

  if (error) {
    const std::string_view message = error->what();
    fuzz::require(message.starts_with(kSource + ":"), "the message names the source", message);
    fuzz::require(fuzz::is_one_printable_line(message), "the message is one line of printable ASCII", message);
    fuzz::require(error->line > 0 || worlds.empty(), "only a fault before the first world has no line", message);
    fuzz::require(worlds.empty() || error->line > lines.back(), "the fault is after the worlds read", message);
  } else {
    fuzz::require(!worlds.empty(), "a trace read whole holds a world");
  }
  for (std::size_t t = 0; t < worlds.size(); ++t) {
    for (const auto& circle : worlds[t].circles) {
      for (const double x : circle) fuzz::require(std::isfinite(x), "every number is finite");
      fuzz::require(circle[4] >= 0, "every radius is >= 0");
    }
    if (t == 0) continue;
    fuzz::require(worlds[t - 1].number < std::numeric_limits<std::uint64_t>::max() &&
                      worlds[t].number == worlds[t - 1].number + 1,
                  "the steps are consecutive");
    fuzz::require(worlds[t].circles.size() == worlds[0].circles.size(), "every world has the first's length");
  }

  // The worlds written as a trace read back the same, line after line, with no fault.
  if (worlds.empty()) return 0;
  std::string written;
  for (const formats::Line& w : worlds) written += formats::format_line(formats::kStep, w.number, w.circles) + "\n";
  std::optional<formats::TraceReadError> again_error;
  std::vector<std::size_t> again_lines;
  const std::vector<formats::Line> again = read(written, again_error, again_lines);
  fuzz::require(!again_error, "the worlds written as a trace read back", again_error ? again_error->what() : "");
  fuzz::require(again.size() == worlds.size(), "as many worlds read back", written);
  for (std::size_t t = 0; t < worlds.size(); ++t) {
    fuzz::require(again[t].number == worlds[t].number, "the steps read back", written);
    fuzz::require(fuzz::same_bits(again[t].circles, worlds[t].circles), "the doubles read back bit for bit", written);
    fuzz::require(again_lines[t] == t + 1, "world t is on line t + 1 of a written trace", written);
  }
  return 0;
}
