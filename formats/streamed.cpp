#include "formats/streamed.hpp"

#include <simdjson.h>

#include <algorithm>
#include <cstring>
#include <string_view>

namespace circles::formats {

namespace {

// A piece of circles with no place to cut after this many pieces' worth of text is the exact reader's: a
// circle of the compact form is a few hundred bytes at most, unless its numbers have thousands of digits.
constexpr std::size_t kMaxPieces = 64;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::size_t skip_space(const std::string& text, std::size_t at) {
  while (at < text.size() && is_space(text[at])) ++at;
  return at;
}

// The document's bytes from the stream, to its end or to the line's '\n'.
class Source {
 public:
  Source(std::istream& in, bool line) : in_(in), line_(line) {}

  // Appends up to n more bytes of the document to `text` and keeps simdjson::SIMDJSON_PADDING bytes of capacity after
  // them; false when the document had ended before.
  bool more(std::string& text, std::size_t n) {
    if (done_) return false;
    const std::size_t old = text.size();
    text.resize(old + n);
    in_.read(text.data() + old, static_cast<std::streamsize>(n));
    std::size_t got = static_cast<std::size_t>(in_.gcount());
    if (got < n) done_ = true;  // the end of the stream, or a read error that the exact reader reports
    if (line_) {
      if (const void* eol = std::memchr(text.data() + old, '\n', got)) {
        got = static_cast<std::size_t>(static_cast<const char*>(eol) - (text.data() + old));
        done_ = true;
        ++bytes_;  // the '\n'
      }
    }
    bytes_ += got;
    text.resize(old + got);
    text.reserve(text.size() + simdjson::SIMDJSON_PADDING);
    return true;
  }

  bool done() const { return done_; }
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::istream& in_;
  bool line_;
  bool done_ = false;
  std::uint64_t bytes_ = 0;
};

// The '[' of the first `"circles"` followed by `:` and `[` (JSON whitespace between), or npos.
std::size_t circles_bracket(const std::string& text) {
  constexpr std::string_view key = "\"circles\"";
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
    std::size_t i = skip_space(text, at + key.size());
    if (i == text.size() || text[i] != ':') continue;
    i = skip_space(text, i + 1);
    if (i < text.size() && text[i] == '[') return i;
  }
  return std::string::npos;
}

// In text = "[c, c, ..., c" + more, the place to cut, at the last ']' after text[0] that is either
//   - the circles' own ']': the byte before it other than whitespace is a circle's ']' (`end` set); or
//   - a circle's ']' that a ',' follows: the place is the ','.
// npos if there is none. In the compact form a circle's ']' follows a number, so the two cannot be confused;
// anything else is found out when the piece or the rest of the document is read.
std::size_t cut_of(const std::string& text, bool& end) {
  for (std::size_t p = text.size(); p > 1;) {
    p = text.rfind(']', p - 1);
    if (p == std::string::npos || p == 0) break;
    std::size_t before = p - 1;
    while (before > 0 && is_space(text[before])) --before;
    if (text[before] == ']') {
      end = true;
      return p;
    }
    const std::size_t after = skip_space(text, p + 1);
    if (after < text.size() && text[after] == ',') return after;
  }
  return std::string::npos;
}

}  // namespace

std::string Streamed::with_one_circle() const {
  return outer.substr(0, junction) + "[0,0,0,0,0]" + outer.substr(junction);
}

std::optional<Streamed> stream_document(std::istream& in, bool line, PlainLineReader& reader, std::size_t piece,
                                        std::size_t expected) {
  piece = std::max<std::size_t>(piece, 1);
  Source source(in, line);
  std::string text;
  text.reserve(std::max(piece, kMaxOuter) * 2 + simdjson::SIMDJSON_PADDING);
  // The head, within the first kMaxOuter bytes.
  source.more(text, kMaxOuter);
  const std::size_t open = circles_bracket(text);
  if (open == std::string::npos || open >= kMaxOuter) return std::nullopt;
  Streamed s{text.substr(0, open + 1), open + 1, {}, 0};
  s.circles.reserve(expected);
  text.erase(0, open);  // text[0] is the circles' '['

  // The circles, a piece "[c, ..., c]" at a time: the ',' after the last circle of the piece becomes the
  // piece's ']' and then the next piece's '['.
  for (;;) {
    bool end = false;
    const std::size_t cut = cut_of(text, end);
    if (cut == std::string::npos) {
      if (text.size() > kMaxPieces * piece || !source.more(text, piece)) return std::nullopt;
      continue;
    }
    if (end) {
      if (!reader.append_circles(text.data(), cut + 1, text.capacity(), s.circles)) return std::nullopt;
      text.erase(0, cut);  // the tail, from the circles' ']'
      break;
    }
    text[cut] = ']';
    if (!reader.append_circles(text.data(), cut + 1, text.capacity(), s.circles)) return std::nullopt;
    text[cut] = '[';
    text.erase(0, cut);
    source.more(text, piece);
  }

  // The tail, to the end of the document.
  while (!source.done()) {
    if (text.size() > kMaxOuter) return std::nullopt;
    source.more(text, kMaxOuter);
  }
  if (in.bad() || text.size() > kMaxOuter) return std::nullopt;
  s.outer += text;
  s.bytes = source.bytes();
  return s;
}

}  // namespace circles::formats
