// libFuzzer target for the protocol reader, formats::parse_line, with both counters ("id" for requests, "step"
// for trace lines): any bytes give a line of finite doubles with r >= 0 or a ProtocolError naming the line,
// never another exception or a crash. A line read, written (formats::format_line) and read again gives the same
// counter and the same doubles bit for bit: the writer keeps -0 as "-0.0", so no sign is lost after the first
// read (an integer token "-0" is read as +0 by the rule of docs/protocol.md, and that is what is compared).
// Read as a candidate's answer (Reading::answer: NaN and infinities as values, unknown keys ignored, the text
// blanked before nlohmann's parse), any bytes give a line or a ProtocolError of the same shape, and every line
// the strict reader takes reads the same, bit for bit. The trace reader's fast path (formats/plain_line.hpp)
// takes only lines parse_line takes, and reads them the same, bit for bit.
#include "formats/plain_line.hpp"
#include "formats/protocol.hpp"
#include "fuzz/check.hpp"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

using namespace circles;

namespace {

constexpr std::size_t kLine = 7;  // any line number: the check is that messages carry it

void require_message(const formats::ProtocolError& e) {
  const std::string_view message = e.what();
  fuzz::require(e.line == kLine, "the error carries the line number", message);
  fuzz::require(message == "line 7: " + e.reason, "the message is \"line L: reason\"", message);
  fuzz::require(fuzz::is_one_printable_line(message), "the message is one line of printable ASCII", message);
}

// The line as an answer, or nothing with the error checked.
std::optional<formats::Line> answer(std::string_view text) {
  try {
    return formats::parse_line(text, kLine, formats::kId, formats::Reading::answer);
  } catch (const formats::ProtocolError& e) {
    require_message(e);
    return std::nullopt;
  }
}

void check(std::string_view text, std::string_view counter) {
  static formats::PlainLineReader plain_reader;
  std::string copy(text);
  const std::optional<formats::Line> plain = plain_reader.read(copy, counter);
  fuzz::require(copy == text, "the fast path leaves the line as it was", std::string(text));
  formats::Line line;
  try {
    line = formats::parse_line(text, kLine, counter);
  } catch (const formats::ProtocolError& e) {
    require_message(e);
    fuzz::require(!plain, "the fast path takes only lines parse_line takes", std::string(text));
    return;
  }
  if (plain)
    fuzz::require(plain->number == line.number && fuzz::same_bits(plain->circles, line.circles),
                  "the fast path reads a line as parse_line does, bit for bit", std::string(text));
  if (counter == formats::kId) {
    const std::optional<formats::Line> as_answer = answer(text);
    fuzz::require(as_answer.has_value(), "a line read strictly reads as an answer", std::string(text));
    fuzz::require(as_answer->number == line.number && fuzz::same_bits(as_answer->circles, line.circles),
                  "read as an answer, a strict line is the same", std::string(text));
  }
  for (const auto& circle : line.circles) {
    for (const double x : circle) fuzz::require(std::isfinite(x), "every number is finite");
    fuzz::require(circle[4] >= 0, "every radius is >= 0");
  }
  const std::string written = formats::format_line(counter, line.number, line.circles);
  const formats::Line again = formats::parse_line(written, kLine, counter);
  fuzz::require(again.number == line.number, "the counter reads back", written);
  fuzz::require(fuzz::same_bits(again.circles, line.circles), "the doubles read back bit for bit", written);
  fuzz::require(formats::format_line(counter, again.number, again.circles) == written, "writing is a fixed point",
                written);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check(text, formats::kId);
  check(text, formats::kStep);
  answer(text);
  return 0;
}
