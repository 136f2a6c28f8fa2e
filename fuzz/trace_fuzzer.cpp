// libFuzzer target for the trace reader, formats::TraceReader (what `circles check-trace` reads): any bytes give a
// sequence of worlds or a TraceReadError naming the source, never another exception or a crash. The worlds
// read keep the trace's rules: finite doubles with r >= 0, consecutive steps, one length. A failure after some
// worlds names a line after theirs; and the worlds read, written again as a trace (formats::format_line) and read
// back, are the same bit for bit. And the reader of a file, which reads a line of compact circles in pieces
// (formats/streamed.hpp) cut here every 7 bytes, gives what the reader of a pipe gives, which reads each line
// whole: the same worlds bit for bit and the same message.
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

// A stream that cannot seek, as a pipe: the reader reads its lines whole.
class Pipe : public std::stringbuf {
 public:
  using std::stringbuf::stringbuf;

 protected:
  pos_type seekoff(off_type, std::ios_base::seekdir, std::ios_base::openmode) override { return pos_type(-1); }
  pos_type seekpos(pos_type, std::ios_base::openmode) override { return pos_type(-1); }
};

// Reads `text` to its end or to its first fault: the worlds read, and the error if there was one. From a
// seekable stream in pieces of `piece` bytes, or with piece == 0 from a pipe.
std::vector<formats::Line> read(const std::string& text, std::optional<formats::TraceReadError>& error,
                                std::vector<std::size_t>& lines, std::size_t piece = 7) {
  Pipe pipe(text);
  std::istringstream file(text);
  std::istream pipe_stream(&pipe);
  formats::TraceReader reader(piece ? static_cast<std::istream&>(file) : pipe_stream, kSource,
                              piece ? piece : formats::kStreamPiece);
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

  // The same from a pipe, each line read whole.
  std::optional<formats::TraceReadError> whole_error;
  std::vector<std::size_t> whole_lines;
  const std::vector<formats::Line> whole = read(text, whole_error, whole_lines, 0);
  fuzz::require(whole_error.has_value() == error.has_value() &&
                    (!error || std::string_view(error->what()) == whole_error->what()),
                "in pieces, the same message", error ? error->what() : "");
  fuzz::require(whole.size() == worlds.size() && whole_lines == lines, "in pieces, as many worlds on the same lines");
  for (std::size_t t = 0; t < worlds.size(); ++t)
    fuzz::require(whole[t].number == worlds[t].number && fuzz::same_bits(whole[t].circles, worlds[t].circles),
                  "in pieces, the same worlds bit for bit");

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
