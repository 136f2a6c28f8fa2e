#include "formats/protocol.hpp"

#include "formats/json_number.hpp"
#include "spec/outside_c.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <utility>

namespace circles::formats {

ProtocolError::ProtocolError(std::size_t line_number, const std::string& why)
    : std::runtime_error("line " + std::to_string(line_number) + ": " + why), line(line_number), reason(why) {}

namespace {

// What a strict line's message says after a field's token NaN, Infinity or -Infinity.
constexpr const char* kNotFinite =
    " is not finite: a request or trace holds finite numbers (only an answer to conform may hold NaN, Infinity or "
    "-Infinity)";

// {"id": N, "circles": [[px, py, vx, vy, r], ...]}, for messages.
std::string line_shape(std::string_view counter) {
  return "{\"" + std::string(counter) + "\": N, \"circles\": [[px, py, vx, vy, r], ...]}";
}

// Reading an answer: the number tokens nlohmann's reader refuses, which an answer may hold (Reading::answer):
// NaN, Infinity, -Infinity, and numbers beyond the double range (its error 406, which ends the parse). Each is
// blanked in the text to "0" and spaces, the same length, so columns in messages stay those of the line, and
// remembered by its ordinal among the number events the parser will give, with its value and its text.
//
// Why ordinals are sound: outside strings, a run of the characters [A-Za-z0-9+.-] is, in valid JSON, exactly
// one token, a number if it starts with '-' or a digit, else true, false or null. nlohmann gives at most one
// number event per run that starts with '-' or a digit (for a run that is more than one number token, the
// parse fails right after its first), and none for any other run. So counting those runs, and the blanked
// tokens, numbers the events of every line that parses, in order.
struct Blanked {
  std::size_t ordinal;
  double value;
  std::string token;
};

bool json_number_token(std::string_view s) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i > from;
  };
  if (i < s.size() && s[i] == '-') ++i;
  if (i < s.size() && s[i] == '0') ++i;
  else if (!digits()) return false;
  if (i < s.size() && s[i] == '.' && (++i, !digits())) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (!digits()) return false;
  }
  return i == s.size();
}

// Which tokens blank_non_finite blanks: every non-finite one (reading an answer), or only NaN, Infinity and
// -Infinity (naming them in a strict line's message; a number beyond the range has its own, the parser's 406).
enum class Blank { all, named_tokens };

std::vector<Blanked> blank_non_finite(std::string& text, Blank which = Blank::all) {
  const auto in_run = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '-' ||
           c == '.';
  };
  std::vector<Blanked> blanked;
  std::size_t ordinal = 0;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '"') {  // a string: up to its closing quote, past escapes
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
      ++i;
      continue;
    }
    if (!in_run(text[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && in_run(text[end])) ++end;
    const std::string run = text.substr(i, end - i);
    const bool number_like = run[0] == '-' || (run[0] >= '0' && run[0] <= '9');
    std::optional<double> value = json_number::non_finite_token(run);
    if (!value && which == Blank::all && json_number_token(run)) {
      // glibc's strtod: the nearest double, ±HUGE_VAL (infinity) beyond the range, as nlohmann's reader uses it.
      if (const double x = std::strtod(run.c_str(), nullptr); std::isinf(x)) value = x;
    }
    if (value) {
      blanked.push_back(Blanked{ordinal, *value, run});
      text.replace(i, run.size(), "0" + std::string(run.size() - 1, ' '));
    }
    ordinal += number_like || value;
    i = end;
  }
  return blanked;
}

// The SAX events of nlohmann::json::sax_parse, checked against the grammar of a line as they come:
//   line   = { counter : integer, "circles" : [ circle, ... ] }    (keys in either order)
//   circle = [ number, number, number, number, number ]
// The first event out of place stops the parse with its reason, so a deeply nested input is refused at its
// fourth '[' rather than built; nlohmann's SAX parser keeps its own nesting on the heap, not the stack.
class Reader {
 public:
  Reader(std::string_view counter, Reading reading, std::vector<Blanked> blanked = {})
      : counter_(counter), reading_(reading), blanked_(std::move(blanked)) {}

  Line line;
  std::optional<std::string> error;  // the reason, once an event was refused

  bool null() { return skipped() || unexpected("null"); }
  bool boolean(bool b) { return skipped() || unexpected(b ? "true" : "false"); }
  bool string(std::string&) { return skipped() || unexpected("a string"); }
  bool binary(nlohmann::json::binary_t&) { return skipped() || unexpected("binary data"); }

  bool number_integer(std::int64_t n) {
    if (const Blanked* b = next_number()) return non_finite(*b);
    if (skipped()) return true;
    if (state_ == State::counter && n >= 0) return counter(static_cast<std::uint64_t>(n));  // "-0" is 0
    return integer_field(n);
  }
  bool number_unsigned(std::uint64_t n) {
    if (const Blanked* b = next_number()) return non_finite(*b);
    if (skipped()) return true;
    if (state_ == State::counter) return counter(n);
    return integer_field(n);
  }
  bool number_float(double x, const std::string& token) {
    if (const Blanked* b = next_number()) return non_finite(*b);
    if (skipped()) return true;
    if (state_ != State::circle || field_ == kFields) return unexpected(token);
    return field(x);  // the nearest double, finite (formats/json_number.hpp): the parser refuses overflow (406)
  }

  bool start_object(std::size_t) {
    if (state_ == State::skip) return ++depth_, true;
    if (state_ != State::top) return unexpected("an object");
    state_ = State::object;
    return true;
  }
  bool key(std::string& k) {
    if (state_ == State::skip) return true;  // a key inside an ignored value
    bool* seen = k == counter_ ? &seen_counter_ : k == "circles" ? &seen_circles_ : nullptr;
    if (!seen && reading_ == Reading::answer) {  // ignored, with its value
      state_ = State::skip;
      depth_ = 0;
      return true;
    }
    if (!seen) return fail("unexpected key \"" + printable(k) + "\" (a line has exactly the keys " + keys() + ")");
    if (*seen) return fail("duplicate key \"" + k + "\"");
    *seen = true;
    state_ = k == counter_ ? State::counter : State::circles;
    return true;
  }
  bool end_object() {
    if (state_ == State::skip) return close_skipped();
    state_ = State::done;
    if (!seen_counter_) return fail("missing key " + in_quotes(counter_));
    if (!seen_circles_) return fail("missing key \"circles\"");
    return true;
  }

  bool start_array(std::size_t) {
    if (state_ == State::skip) return ++depth_, true;
    if (state_ == State::circles) {
      state_ = State::list;
      return true;
    }
    if (state_ == State::list) {
      state_ = State::circle;
      field_ = 0;
      return true;
    }
    return unexpected("an array");
  }
  bool end_array() {
    if (state_ == State::skip) return close_skipped();
    if (state_ == State::list) {  // the end of "circles"
      state_ = State::object;
      return true;
    }
    // The end of a circle: only circle and list states have open arrays.
    if (field_ != kFields)
      return fail(circle_name() + ": expected 5 numbers [px, py, vx, vy, r], found " + std::to_string(field_));
    try {
      if (reading_ == Reading::strict) spec::check_doubles(fields_, line.circles.size(), spec::Radii::non_negative);
    } catch (const spec::OutsideC& e) {
      return fail(e.what());
    }
    line.circles.push_back(fields_);
    state_ = State::list;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& token, const nlohmann::json::exception& e) {
    // 406 is the one out_of_range error of the parser: a number token beyond the double range.
    if (e.id == 406) return fail(expectation().first + shortened_token(token) + " is beyond the double range");
    return fail("malformed JSON at column " + std::to_string(position) + ": " + parser_reason(e.what()));
  }

 private:
  // skip: inside the value of an ignored key, `depth_` arrays and objects deep.
  enum class State { top, object, counter, circles, list, circle, done, skip };

  // The blanked token that the number event now being given stands for, if any; counts the event.
  const Blanked* next_number() {
    const std::size_t ordinal = numbers_++;
    if (next_blanked_ < blanked_.size() && blanked_[next_blanked_].ordinal == ordinal) return &blanked_[next_blanked_++];
    return nullptr;
  }
  bool non_finite(const Blanked& b) {
    if (skipped()) return true;
    if (state_ != State::circle || field_ == kFields) return unexpected(b.token);
    if (reading_ == Reading::strict)
      return fail(field_name() + ": " + b.token + kNotFinite);
    return field(b.value);
  }

  // Whether the value now given is inside an ignored one (and, if it closes it, back to the object's keys).
  bool skipped() {
    if (state_ != State::skip) return false;
    if (depth_ == 0) state_ = State::object;
    return true;
  }
  bool close_skipped() {
    if (--depth_ == 0) state_ = State::object;
    return true;
  }

  bool counter(std::uint64_t n) {
    line.number = n;
    state_ = State::object;
    return true;
  }

  template <class Integer>
  bool integer_field(Integer n) {
    if (state_ != State::circle || field_ == kFields) return unexpected(std::to_string(n));
    return field(json_number::from_integer(n));
  }

  bool field(double x) {
    fields_[field_++] = x;
    return true;
  }

  // Where the parser is, as a message prefix ("circle 2, field vx: "), and what it expects there.
  std::pair<std::string, std::string> expectation() const {
    switch (state_) {
      case State::top: return {"", "an object " + shape()};
      case State::counter: return {in_quotes(counter_) + ": ", "an integer from 0 to 18446744073709551615"};
      case State::circles: return {"\"circles\": ", "an array of circles [px, py, vx, vy, r]"};
      case State::list: return {circle_name() + ": ", "an array [px, py, vx, vy, r]"};
      case State::circle:
        if (field_ == kFields) return {circle_name() + ": ", "5 numbers [px, py, vx, vy, r]"};
        return {field_name() + ": ", "a number"};
      case State::object:
      case State::done:
      case State::skip:
        break;  // the parser reports only keys and the closing brace here, never a value
    }
    return {"", "a key or '}'"};
  }

  // Refuses a value where the state expects something else: "circle 2, field vx: expected a number, found
  // a string". A value after the fifth of a circle is "found more".
  bool unexpected(const std::string& found) {
    const auto [where, expected] = expectation();
    const bool extra = state_ == State::circle && field_ == kFields;
    return fail(where + "expected " + expected + ", found " + (extra ? "more" : found));
  }

  bool fail(const std::string& reason) {
    error = reason;
    return false;
  }

  std::string keys() const { return in_quotes(counter_) + " and \"circles\""; }
  std::string shape() const { return line_shape(counter_); }
  std::string circle_name() const { return "circle " + std::to_string(line.circles.size()); }
  std::string field_name() const { return circle_name() + ", field " + spec::name(spec::Field(field_)); }

  // nlohmann's message without its own prefix "[json.exception.parse_error.101] parse error at line 1,
  // column 29: ", whose position we give ourselves (the line is the protocol's, not nlohmann's).
  static std::string parser_reason(const std::string& what) {
    const std::size_t column = what.find("column ");
    const std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
    return printable(colon == std::string::npos ? what : what.substr(colon + 2));
  }

  std::string_view counter_;
  Reading reading_;
  std::vector<Blanked> blanked_;
  std::size_t numbers_ = 0, next_blanked_ = 0;  // number events given, and blanked tokens met
  std::size_t depth_ = 0;
  State state_ = State::top;
  bool seen_counter_ = false, seen_circles_ = false;
  spec::CircleDoubles fields_{};
  std::size_t field_ = 0;
};

}  // namespace

Line parse_line(std::string_view text, std::size_t line_number, std::string_view counter, Reading reading) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw ProtocolError(line_number, "empty line, expected an object " + line_shape(counter));
  // nlohmann's lexer reads a NUL byte as the end of the input, so "{...}\0anything" would pass as "{...}".
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    throw ProtocolError(line_number, "malformed JSON at column " + std::to_string(nul + 1) +
                                         ": a NUL byte, which JSON text cannot contain");
  std::string blanked_text;
  std::vector<Blanked> blanked;
  if (reading == Reading::answer) {
    blanked_text = text;
    blanked = blank_non_finite(blanked_text);
    text = blanked_text;
  }
  Reader reader(counter, reading, std::move(blanked));
  if (nlohmann::json::sax_parse(text, &reader)) return std::move(reader.line);
  // Read strictly, a token NaN, Infinity or -Infinity is a syntax error to the JSON parser, whose message names
  // neither the token nor its field ("invalid literal; last read: '[[N'"). Only on that failure path, so at no
  // cost to a line that reads: read again with those tokens blanked, so that the first is named where it stands
  // (Reader::non_finite), unless a fault before it comes first, which is then reported as before.
  if (reading == Reading::strict) {
    std::string again(text);
    if (std::vector<Blanked> tokens = blank_non_finite(again, Blank::named_tokens); !tokens.empty()) {
      Reader named(counter, reading, std::move(tokens));
      if (!nlohmann::json::sax_parse(again, &named)) throw ProtocolError(line_number, named.error.value_or("unreadable"));
    }
  }
  throw ProtocolError(line_number, reader.error.value_or("unreadable"));
}

std::string shortened_token(std::string_view token) {
  constexpr std::size_t kWhole = 64, kHead = 21, kTail = 10;
  if (token.size() <= kWhole) return std::string(token);
  return std::string(token.substr(0, kHead)) + "..." + std::string(token.substr(token.size() - kTail)) + " (" +
         std::to_string(token.size()) + " characters)";
}

std::string printable(std::string_view bytes) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(bytes.size());
  for (const char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    if (b >= 0x20 && b < 0x7F) {  // printable ASCII: space to '~'
      out += c;
    } else {
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 0xF];
    }
  }
  return out;
}

std::string in_quotes(std::string_view bytes) {
  std::string out = "\"";
  out += printable(bytes);
  out += '"';
  return out;
}

void append_line(std::string& out, std::string_view counter, std::uint64_t number, const Circles& circles) {
  out += "{\"";
  out += counter;
  out += "\":";
  out += std::to_string(number);
  out += ",\"circles\":[";
  for (std::size_t k = 0; k < circles.size(); ++k) {
    out += k ? ",[" : "[";
    for (std::size_t j = 0; j < kFields; ++j) {
      if (j) out += ',';
      json_number::append(out, circles[k][j]);
    }
    out += ']';
  }
  out += "]}";
}

std::string hash_text(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

std::string format_line(std::string_view counter, std::uint64_t number, const Circles& circles) {
  std::string out;
  append_line(out, counter, number, circles);
  return out;
}

}  // namespace circles::formats
