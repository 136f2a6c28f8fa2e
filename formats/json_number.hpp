// JSON numbers as doubles: one rule for scenes, protocol lines and traces, in both directions.
//
// Reading: every number token denotes its decimal value and means the double nearest to it, ties to even,
// whatever its form: "0.1", "1e300", "-0.0", and integers too, "9007199254740993" (2^53 + 1, a tie, so 2^53)
// as much as "4783255246441940000" (how JavaScript's JSON.stringify writes the double 4.78325524644194e18).
// This is what JavaScript's JSON.parse and C's strtod do, so a number any of them writes reads back as the
// double it wrote. A token is refused only when that double would be infinite (beyond the double range); the
// integer "-0" is zero, which only its sign distinguishes from -0.0 anyway.
//
// nlohmann's reader gives an integer token that fits in 64 bits as an int64 or uint64 (from_integer turns it
// into its nearest double), and any other token, an integer beyond 64 bits included, as the result of strtod
// on the token's text, which glibc rounds correctly (the nearest double, ties to even, in every case): that
// double is the token's value as it stands, with no further check.
//
// Writing: the shortest text that reads back as the same double, always with a fraction or an exponent, so
// -0 keeps its sign ("-0.0") and every reader, strict or not, takes it for a double.
//
// Non-finite values: JSON has no syntax for them, but Python's json, JavaScript's JSON5 and many other writers
// use the tokens NaN, Infinity and -Infinity. A candidate's answer may hold them (formats/protocol.hpp, reading
// an answer), and messages about an answer write them so (append_any, decimal_and_hex).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace circles::formats::json_number {

// The double nearest to n, ties to even: n itself for |n| <= 2^53.
double from_integer(std::int64_t n);
double from_integer(std::uint64_t n);

// The longest text write() and append() give a double: to_chars' shortest form is at most 24 characters,
// the scientific "-2.2250738585072014e-308" (sign, 17 digits, point, "e-308"; a fixed form is chosen only
// when it is no longer), and ".0" may follow it.
inline constexpr std::size_t kMaxChars = 24 + 2;

// Writes the shortest text that reads back as x, with ".0" added where it would read as an integer, at `out`,
// which has room for kMaxChars characters, and returns the end of the text. x must be finite (append checks).
char* write(char* out, double x) noexcept;

// Appends write()'s text. Throws std::domain_error for NaN and infinities, which JSON cannot write.
void append(std::string& out, double x);

// append for a finite x; the token NaN, Infinity or -Infinity otherwise. For messages and for answers, never
// for a line we send.
void append_any(std::string& out, double x);

// For a JSON document that records an answer (a corpus file, a report): append for a finite x; else its token
// as a JSON string, "NaN", "Infinity" or "-Infinity", which JSON can hold and non_finite_token reads back.
void append_or_string(std::string& out, double x);

// The value of the token "NaN", "Infinity" or "-Infinity"; nothing for any other text.
std::optional<double> non_finite_token(std::string_view token);

// x in C's hexadecimal form ("%a"), which names every double exactly: "0x1.999999999999ap-4".
std::string hex(double x);

// For messages and command lines: the shortest text that reads back as x, without the ".0" that marks an
// integer in JSON: "60", "0.5", "1e-05". x must be finite.
std::string plain(double x);

// For messages: the shortest decimal that reads back as x and its hexadecimal form, "0.1 (0x1.999999999999ap-4)";
// for a value that is not finite, its token alone: "Infinity".
std::string decimal_and_hex(double x);

}  // namespace circles::formats::json_number
