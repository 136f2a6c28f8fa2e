// JSON numbers as doubles: one rule for scenes, protocol lines and traces, in both directions.
//
// Reading: a number written with a fraction or an exponent means the double nearest to it, as in every JSON
// reader; an integer (no fraction, no exponent) must be exactly a double, because a writer that meant "the
// nearest double" would have written one of those. Writing: the shortest text that reads back as the same
// double, always with a fraction or an exponent, so -0 keeps its sign ("-0.0") and every reader, strict or
// not, takes it for a double.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace circles::cli::json_number {

// The double whose value is exactly n, if there is one (always for |n| <= 2^53).
std::optional<double> from_integer(std::int64_t n);
std::optional<double> from_integer(std::uint64_t n);

// A number token that the JSON reader has already turned into `value`, the nearest double: `value`, unless
// `token` is an integer (an integer too large for 64 bits reaches here) that `value` is not exactly.
std::optional<double> from_float_token(double value, std::string_view token);

// The reason to give when an integer token is not exactly a double: "integer 9007199254740993 is not
// exactly a double".
std::string not_exact(std::string_view token);

// Appends the shortest text that reads back as x, with ".0" added where it would read as an integer. Throws
// std::domain_error for NaN and infinities, which JSON cannot write.
void append(std::string& out, double x);

}  // namespace circles::cli::json_number
