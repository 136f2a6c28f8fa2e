// The step protocol (docs/protocol.md): JSON Lines, one world per line.
//   request   {"id": N, "circles": [[px, py, vx, vy, r], ...]}
//   response  the same shape, the same id; circle k is the image of circle k of the request
//   trace     {"step": t, "circles": [...]}, the world w_t of a run (`circles run --trace`)
// N and t are integers from 0 to 2^64 - 1; every coordinate is a finite double and r >= 0 (-0 allowed), read
// and written by the rules of formats/json_number.hpp.
#pragma once

#include "spec/outside_c.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace circles::formats {

// A world as the protocol carries it (spec::Circles): [px, py, vx, vy, r] per circle.
using spec::Circles;
inline constexpr std::size_t kFields = std::tuple_size_v<Circles::value_type>;  // px, py, vx, vy, r

// A line that is not a protocol line. what() is "line L: reason", the reason naming the key or the circle and
// field at fault: "line 3: circle 1, field r: radius -2 is negative (r >= 0, the resolved profile) (not an
// element of C)".
class ProtocolError : public std::runtime_error {
 public:
  ProtocolError(std::size_t line, const std::string& reason);
  std::size_t line;    // 1-based
  std::string reason;  // what() without "line L: "
};

// The key of a line's counter: the id of a request or response, or the step of a trace line.
inline constexpr std::string_view kId = "id";
inline constexpr std::string_view kStep = "step";

// One protocol line: its counter and its world.
struct Line {
  std::uint64_t number = 0;
  Circles circles;
};

// How parse_line reads a line.
//   strict  requests and traces: an object with exactly the keys `counter` and "circles"; each circle an
//           element of C in the resolved profile (finite numbers, r >= 0).
//   answer  a candidate's answer (docs/protocol.md): `counter` and "circles" still exactly once each, but any
//           other key is ignored, whatever its value (forward compatibility, as JSON-RPC and LSP readers do:
//           `"ms": 0.1` beside them is no fault). Each field is any double: the tokens NaN, Infinity and
//           -Infinity are the values they mean, a number beyond the double range is, like every number, its
//           nearest double (±infinity, round to nearest), and no field is checked against C, so that conform
//           judges each value against the expected one instead of refusing the line.
enum class Reading { strict, answer };

// Reads one line (without its newline; surrounding JSON whitespace is allowed): an object with the keys
// `counter` and "circles", each once, in either order (and, reading an answer, any others); the counter an
// integer in [0, 2^64 - 1]; each circle an array of 5 numbers, each read as its nearest double
// (formats/json_number.hpp), that form a circle of C in the resolved profile (finite, r >= 0) when reading
// strictly. Anything else, including trailing text and, reading strictly, any nesting beyond [[...]], throws
// ProtocolError; the reader stops at the first fault and keeps its nesting on the heap, so no input is too
// deep for it.
Line parse_line(std::string_view text, std::size_t line_number, std::string_view counter = kId,
                Reading reading = Reading::strict);

// Input bytes as they may appear in a message: printable ASCII as is, any other byte (a control character, a
// byte of a UTF-8 sequence, valid or not) as \xHH. A message naming what it read is then one line of ASCII,
// whatever the input held.
std::string printable(std::string_view bytes);

// A number token as messages show it: whole up to 64 characters; a longer one (a number of a million digits)
// as its first 21 and last 10 characters and its length, "100000000000000000000...0000000000 (1000000
// characters)", so that the message stays one readable line.
std::string shortened_token(std::string_view token);

// A key or name as messages show it: printable(bytes) between double quotes.
std::string in_quotes(std::string_view bytes);

// Appends {"<counter>":N,"circles":[[px,py,vx,vy,r],...]} without a newline, each number in the shortest
// form that reads back as the same double. Throws std::domain_error for a coordinate that is not finite.
void append_line(std::string& out, std::string_view counter, std::uint64_t number, const Circles& circles);
std::string format_line(std::string_view counter, std::uint64_t number, const Circles& circles);

// The 16 lowercase hexadecimal digits of a state hash (formats/state_hash.hpp), as golden vectors and check-trace
// write it.
std::string hash_text(std::uint64_t hash);

}  // namespace circles::formats
