// The invariant is stated in plain_line.hpp. Numbers follow formats/json_number.hpp: an integer token that fits
// in 64 bits is json_number::from_integer of it, as nlohmann's reader gives it; a token with a fraction or an
// exponent is simdjson's get_double, the nearest double (simdjson parses floating-point numbers correctly
// rounded, as glibc's strtod does). Anything else (an integer beyond 64 bits, a number beyond the double range)
// is left to parse_line.
#include "formats/plain_line.hpp"

#include "formats/json_number.hpp"

#include <simdjson.h>

#include <array>
#include <cstdint>
#include <tuple>

namespace circles::formats {

struct PlainLineReader::Parser {
  simdjson::ondemand::parser parser;
};

PlainLineReader::PlainLineReader() : parser_(std::make_unique<Parser>()) {}
PlainLineReader::~PlainLineReader() = default;
PlainLineReader::PlainLineReader(PlainLineReader&&) noexcept = default;
PlainLineReader& PlainLineReader::operator=(PlainLineReader&&) noexcept = default;

namespace {

using namespace simdjson;

// One field of a circle, or nothing.
std::optional<double> number(ondemand::value value) {
  ondemand::number_type type;
  if (value.get_number_type().get(type)) return std::nullopt;
  switch (type) {
    case ondemand::number_type::signed_integer: {
      std::int64_t n;
      if (value.get_int64().get(n)) return std::nullopt;
      return json_number::from_integer(n);
    }
    case ondemand::number_type::unsigned_integer: {
      std::uint64_t n;
      if (value.get_uint64().get(n)) return std::nullopt;
      return json_number::from_integer(n);
    }
    case ondemand::number_type::floating_point_number: {
      // Only a token with a fraction or an exponent: an integer beyond 64 bits is parse_line's.
      const std::string_view token = value.raw_json_token();
      if (token.find_first_of(".eE") == std::string_view::npos) return std::nullopt;
      double x;
      if (value.get_double().get(x)) return std::nullopt;
      return x;
    }
  }
  return std::nullopt;
}

bool read_circles(ondemand::array array, Circles& circles) {
  for (auto element : array) {
    ondemand::array fields;
    if (element.get_array().get(fields)) return false;
    spec::CircleDoubles circle{};
    std::size_t j = 0;
    for (auto field : fields) {
      ondemand::value v;
      if (j == kFields || field.get(v)) return false;
      const std::optional<double> x = number(v);
      if (!x) return false;
      circle[j++] = *x;
    }
    // Finite by construction; a negative radius is outside C, for parse_line to name.
    if (j != kFields || !(circle[4] >= 0)) return false;
    circles.push_back(circle);
  }
  return true;
}

}  // namespace

std::optional<Line> PlainLineReader::read(std::string& text, std::string_view counter) {
  const std::size_t size = text.size();
  text.reserve(size + SIMDJSON_PADDING);
  ondemand::document document;
  if (parser_->parser.iterate(padded_string_view(text.data(), size, text.capacity())).get(document))
    return std::nullopt;
  ondemand::object object;
  if (document.get_object().get(object)) return std::nullopt;
  Line line;
  bool number_seen = false, circles_seen = false;
  for (auto field : object) {
    std::string_view key;
    ondemand::value value;
    if (field.unescaped_key().get(key) || field.value().get(value)) return std::nullopt;
    if (key == counter && !number_seen) {
      if (value.get_uint64().get(line.number)) return std::nullopt;
      number_seen = true;
    } else if (key == "circles" && !circles_seen) {
      ondemand::array array;
      if (value.get_array().get(array) || !read_circles(array, line.circles)) return std::nullopt;
      circles_seen = true;
    } else {
      return std::nullopt;  // another key, or one seen twice
    }
  }
  // Nothing after the object: the document's location is then out of bounds.
  const char* rest = nullptr;
  if (!number_seen || !circles_seen || document.current_location().get(rest) != OUT_OF_BOUNDS) return std::nullopt;
  return line;
}

bool PlainLineReader::append_circles(const char* text, std::size_t size, std::size_t capacity, Circles& circles) {
  ondemand::document document;
  ondemand::array array;
  if (parser_->parser.iterate(padded_string_view(text, size, capacity)).get(document) ||
      document.get_array().get(array))
    return false;
  const std::size_t before = circles.size();
  if (!read_circles(array, circles) || circles.size() == before) return false;
  // Nothing after the array, as after a line's object.
  const char* rest = nullptr;
  return document.current_location().get(rest) == OUT_OF_BOUNDS;
}

}  // namespace circles::formats
