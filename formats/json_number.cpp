#include "formats/json_number.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace circles::formats::json_number {

// C++ leaves the direction of an inexact integer-to-double conversion to the implementation; GCC and Clang on
// x86-64 (cvtsi2sd, and for uint64 a halving that keeps the sticky bit) round in the current mode, which no
// code of ours changes from round to nearest, ties to even. tests/scene_test.cpp checks the ties.
double from_integer(std::int64_t n) { return static_cast<double>(n); }
double from_integer(std::uint64_t n) { return static_cast<double>(n); }

char* write(char* out, double x) noexcept {
  // to_chars writes the shortest round-trip digits, in fixed form only where that is no longer than the
  // scientific one; an integer's text gets ".0". The scan for '.' and 'e' reads what was just written.
  char* const end = std::to_chars(out, out + kMaxChars, x).ptr;
  for (const char* c = out; c != end; ++c)
    if (*c == '.' || *c == 'e') return end;
  end[0] = '.';
  end[1] = '0';
  return end + 2;
}

void append(std::string& out, double x) {
  if (!std::isfinite(x)) throw std::domain_error("a JSON number must be finite");
  std::array<char, kMaxChars> text{};
  out.append(text.data(), write(text.data(), x));
}

void append_any(std::string& out, double x) {
  if (std::isnan(x)) out += "NaN";
  else if (std::isinf(x)) out += x > 0 ? "Infinity" : "-Infinity";
  else append(out, x);
}

void append_or_string(std::string& out, double x) {
  if (std::isfinite(x)) return append(out, x);
  out += '"';
  append_any(out, x);
  out += '"';
}

std::optional<double> non_finite_token(std::string_view token) {
  if (token == "NaN") return std::numeric_limits<double>::quiet_NaN();
  if (token == "Infinity") return std::numeric_limits<double>::infinity();
  if (token == "-Infinity") return -std::numeric_limits<double>::infinity();
  return std::nullopt;
}

std::string hex(double x) {
  char text[32];  // "%a" of a double: at most "-0x1.fffffffffffffp-1022" (24 characters)
  std::snprintf(text, sizeof text, "%a", x);
  return text;
}

std::string plain(double x) {
  std::string text;
  append(text, x);
  if (text.ends_with(".0")) text.resize(text.size() - 2);
  return text;
}

std::string decimal_and_hex(double x) {
  std::string text;
  append_any(text, x);
  if (!std::isfinite(x)) return text;
  return text + " (" + hex(x) + ")";
}

}  // namespace circles::formats::json_number
