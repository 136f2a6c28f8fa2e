// Every way a request may spell a number (docs/protocol.md, Numbers): the spellings conform's wire family sends,
// so that a program is checked on reading each form the grammar allows, not only the shortest one our writer
// gives (formats/json_number.hpp).
//
// Each spelling of a finite double x is a JSON number token whose decimal value rounds to x (nearest, ties to
// even): x's shortest digits in other forms (an upper-case E, a '+' or leading zeros in the exponent, the
// digits as an integer with an exponent, a fraction with trailing zeros), 17 significant digits, x's exact
// decimal value (up to 767 significant digits, a subnormal's), the exact midpoints to x's neighbours when they
// round to x (a tie whose even side is x), and numbers just inside those midpoints, which a reader that rounds
// twice or cuts the digits at 17 gets wrong; and, for zero, numbers that underflow to it (1e-400). Each is
// built exactly, with GMP, and tests/spelling_test.cpp reads each back exactly and through our reader.
#pragma once

#include "spec/outside_c.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace circles::formats {

// How a request's numbers are written: `shortest`, json_number::append's form, which is every line we write but
// the wire family's; `every_form`, each number in one of spellings(x), chosen by append_spelled_line.
enum class Spelling { shortest, every_form };

// The distinct spellings of x, the first json_number::append's. x must be finite (std::domain_error).
std::vector<std::string> spellings(double x);

// The longest spelling of any double: a sign, the 768 significant digits of a midpoint below 2^-1021 (an odd
// multiple of 2^-1075 above 10^-308: 1075 decimal places, the first 307 zeros; a double's own exact value has at
// most 767, and a larger double's midpoint has fewer places), four more digits, a point, and an exponent
// "e-308": 1 + 768 + 4 + 1 + 5 = 779; a fixed form is used only for decimal exponents within ±kFixedDigits,
// whose longest is shorter. tests/spelling_test.cpp recomputes it over the doubles whose spellings are longest.
inline constexpr std::size_t kMaxSpellingChars = 779;
// Decimal exponents (of the first significant digit) within ±kFixedDigits are also written without an exponent.
inline constexpr int kFixedDigits = 24;

// Appends {"<counter>":N,"circles":[[...],...]} as append_line does (formats/protocol.hpp), with the number of
// circle k, field j written as spellings(x)[(h + 5k + j) mod their count], h a hash of the world's bits, and
// (also by h) the two keys in either order and a space or a tab after some of the separators. The same world
// gives the same text, so a replayed case sends what its first run sent.
void append_spelled_line(std::string& out, std::string_view counter, std::uint64_t number,
                         const spec::Circles& circles);

}  // namespace circles::formats
