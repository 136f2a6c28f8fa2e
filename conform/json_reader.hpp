// The JSON documents conform writes, read back (corpus files, conform/corpus.hpp; the reports of `circles conform
// --report`, conform/report.hpp): each value as nlohmann parsed it, checked for the type it was written with, so
// that a file cut short or edited by hand is refused with the document's own error naming the place and why.
#pragma once

#include "formats/json_number.hpp"
#include "formats/json_world.hpp"  // Numbers
#include "formats/protocol.hpp"  // in_quotes
#include "spec/outside_c.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace circles::conform {

// A JSON number as the double nearest to it, by the rules of formats/json_number.hpp (the parser has refused values
// beyond the double range); nothing for any other value.
inline std::optional<double> to_double(const nlohmann::json& x) {
  if (x.is_number_float()) return x.get<double>();
  if (x.is_number_unsigned()) return formats::json_number::from_integer(x.get<std::uint64_t>());
  if (x.is_number_integer()) return formats::json_number::from_integer(x.get<std::int64_t>());
  return std::nullopt;
}

// Reads the values of the document `source` names in messages, and throws Error("SOURCE: key \"k\": expected a
// string, found number") for one of another type.
template <class Error>
class JsonReader {
 public:
  using Numbers = formats::Numbers;

  explicit JsonReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& reason) const { throw Error(source_ + ": " + reason); }

  std::string string(const nlohmann::json& x, std::string_view key) const {
    if (!x.is_string()) fail("key " + formats::in_quotes(key) + ": expected a string, found " + x.type_name());
    return x.get<std::string>();
  }

  std::uint64_t integer(const nlohmann::json& x, std::string_view key) const {
    if (!x.is_number_unsigned()) fail("key " + formats::in_quotes(key) + ": expected an integer >= 0, found " + x.dump());
    return x.get<std::uint64_t>();
  }

  // A number; with Numbers::any also the strings "NaN", "Infinity" and "-Infinity" (json_number::append_or_string).
  double number(const nlohmann::json& x, const std::string& where, Numbers numbers = Numbers::finite) const {
    std::optional<double> d = to_double(x);
    if (!d && numbers == Numbers::any && x.is_string()) d = formats::json_number::non_finite_token(x.get<std::string>());
    if (!d) fail(where + ": expected a number, found " + x.dump());
    return *d;
  }

  // A coordinate's name, "px", "py", "vx", "vy" or "r", the value of the key "field" of the object at `where`.
  spec::Field field(const nlohmann::json& x, const std::string& where) const {
    const std::string text = string(x, "field");
    for (std::size_t f = 0; f < 5; ++f)
      if (text == spec::name(spec::Field(f))) return spec::Field(f);
    fail(where + ": field " + x.dump() + " is not px, py, vx, vy or r");
  }

  // A world of the resolved profile's C: finite doubles, r >= 0; or an answer, any numbers.
  spec::Circles world(const nlohmann::json& x, std::string_view key, Numbers numbers = Numbers::finite) const {
    const std::string where = "key " + formats::in_quotes(key);
    if (!x.is_array()) fail(where + ": expected an array of circles [px, py, vx, vy, r], found " + x.type_name());
    spec::Circles w;
    for (std::size_t k = 0; k < x.size(); ++k) {
      const nlohmann::json& c = x[k];
      const std::string circle = where + ": circle " + std::to_string(k);
      if (!c.is_array() || c.size() != 5) fail(circle + ": expected 5 numbers [px, py, vx, vy, r]");
      spec::CircleDoubles fields{};
      for (std::size_t f = 0; f < 5; ++f)
        fields[f] = number(c[f], circle + ", field " + spec::name(spec::Field(f)), numbers);
      try {
        if (numbers == Numbers::finite) spec::check_doubles(fields, k, spec::Radii::non_negative);
      } catch (const spec::OutsideC& e) {
        fail(where + ": " + e.what());
      }
      w.push_back(fields);
    }
    return w;
  }

 private:
  std::string source_;
};

}  // namespace circles::conform
