#include "formats/json_world.hpp"

#include "formats/json_number.hpp"

#include <nlohmann/json.hpp>

namespace circles::formats {

std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void append_world(std::string& out, const Circles& w, Numbers numbers, JsonLayout layout) {
  append_rows(
      out, w,
      [numbers](std::string& text, const Circles::value_type& c, std::size_t j) {
        if (numbers == Numbers::any) json_number::append_or_string(text, c[j]);
        else json_number::append(text, c[j]);
      },
      layout);
}

}  // namespace circles::formats
