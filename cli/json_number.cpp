#include "cli/json_number.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace circles::cli::json_number {
namespace {

// 2^63 and 2^64 as doubles: a double d in [-2^63, 2^63) converts to int64 without overflow, one in [0, 2^64)
// to uint64; beyond them no int64 / uint64 equals d, so the conversion must not even be tried.
constexpr double kTwo63 = 0x1p63;
constexpr double kTwo64 = 0x1p64;

}  // namespace

std::optional<double> from_integer(std::int64_t n) {
  const double d = static_cast<double>(n);
  // d is n rounded to nearest; it may round up to 2^63 exactly, which no int64 equals.
  if (d >= kTwo63 || static_cast<std::int64_t>(d) != n) return std::nullopt;
  return d;
}

std::optional<double> from_integer(std::uint64_t n) {
  const double d = static_cast<double>(n);
  if (d >= kTwo64 || static_cast<std::uint64_t>(d) != n) return std::nullopt;
  return d;
}

std::optional<double> from_float_token(double value, std::string_view token) {
  if (token.find_first_of(".eE") != std::string_view::npos) return value;
  // An integer token beyond 64 bits. Every double of that magnitude is an integer, and "%.0f" writes its
  // exact decimal value (glibc prints doubles exactly), which JSON's grammar (no leading zeros, no '+')
  // lets us compare with the token as text. 310 characters hold the 309 digits of DBL_MAX and a sign.
  std::array<char, 320> exact{};
  const int length = std::snprintf(exact.data(), exact.size(), "%.0f", value);
  if (length < 0 || std::string_view(exact.data(), static_cast<std::size_t>(length)) != token) return std::nullopt;
  return value;
}

std::string not_exact(std::string_view token) { return "integer " + std::string(token) + " is not exactly a double"; }

void append(std::string& out, double x) {
  if (!std::isfinite(x)) throw std::domain_error("a JSON number must be finite");
  // to_chars writes the shortest round-trip digits, in fixed form only where that is no longer than the
  // scientific one, which has at most 24 characters ("-2.2250738585072014e-308": sign, 17 digits, point,
  // "e-308"); with ".0" that is 26, so 32 always suffice.
  std::array<char, 32> text{};
  const auto end = std::to_chars(text.data(), text.data() + text.size(), x).ptr;
  const std::string_view written(text.data(), static_cast<std::size_t>(end - text.data()));
  out += written;
  if (written.find_first_of(".e") == std::string_view::npos) out += ".0";
}

}  // namespace circles::cli::json_number
