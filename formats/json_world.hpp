// JSON text the suite's documents share: a world as rows of five numbers, [[px, py, vx, vy, r], ...], written
// one way for every file that holds one (the reports of `circles conform`, corpus files, `circles vectors`), and
// a JSON string.
#pragma once

#include "formats/protocol.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace circles::formats {

// A JSON string: nlohmann escapes quotes and control characters; a byte that is not UTF-8 (a file name can hold
// one) becomes U+FFFD rather than an exception. The reports and `circles vectors` write names with it.
std::string json_string(const std::string& s);

// Where the white space of a world goes: `row` before each row (after the comma between rows), `field` between
// a row's numbers, and `close` before the world's closing bracket when it has rows. The default is compact,
// [[1.0,2.0,...],[...]].
struct JsonLayout {
  std::string_view row = "", field = ",", close = "";
};

// Appends [[a, b, c, d, e], ...] laid out by `layout`, each value written by write(out, rows[k], j).
template <class Rows, class Write>
void append_rows(std::string& out, const Rows& rows, Write write, JsonLayout layout = {}) {
  out += '[';
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (k) out += ',';
    out += layout.row;
    out += '[';
    for (std::size_t j = 0; j < 5; ++j) {
      if (j) out += layout.field;
      write(out, rows[k], j);
    }
    out += ']';
  }
  if (!rows.empty()) out += layout.close;
  out += ']';
}

// Which numbers a world holds: those of a world of C, finite (json_number::append), or any numbers, as an answer
// received can hold, those that are not finite as the strings "NaN", "Infinity", "-Infinity"
// (json_number::append_or_string).
enum class Numbers { finite, any };

// Appends the world `w` as rows of its numbers in shortest decimal (formats/json_number.hpp).
void append_world(std::string& out, const Circles& w, Numbers numbers, JsonLayout layout = {});

}  // namespace circles::formats
