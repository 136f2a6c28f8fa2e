#include "cli/scene.hpp"

#include "cli/json_number.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <fstream>
#include <sstream>

namespace circles::cli {

extern const char* const default_scene_json;  // generated from scenes/default.json (cli/embedded.cpp.in)

namespace {

// A JSON number as a double by the rule of cli/json_number.hpp. The DOM keeps no token text, so an integer
// token beyond 64 bits, which nlohmann stores as the nearest double, is taken as that double.
double to_double(const nlohmann::json& x, const std::string& where) {
  if (x.is_number_float()) return x.get<double>();  // finite: the parser rejects overflow (out_of_range.406)
  if (x.is_number_integer()) {
    const auto d = x.is_number_unsigned() ? json_number::from_integer(x.get<std::uint64_t>())
                                          : json_number::from_integer(x.get<std::int64_t>());
    if (!d) throw SceneError(where + ": " + json_number::not_exact(x.dump()));
    return *d;
  }
  throw SceneError(where + ": expected a number, found " + std::string(x.type_name()));
}

}  // namespace

std::vector<spec::Circle> parse_scene(std::string_view text, const std::string& source) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError(source + ": malformed JSON at byte " + std::to_string(e.byte) + ": " + e.what());
  } catch (const nlohmann::json::exception& e) {  // out_of_range: a number beyond the double range
    throw SceneError(source + ": unreadable JSON: " + e.what());
  }
  if (!doc.is_object() || !doc.contains("circles"))
    throw SceneError(source + ": expected an object with a \"circles\" array");
  const nlohmann::json& list = doc.at("circles");
  if (!list.is_array()) throw SceneError(source + ": \"circles\" must be an array");

  std::vector<spec::Circle> circles;
  circles.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string where = source + ": circle " + std::to_string(k);
    const nlohmann::json& c = list[k];
    if (!c.is_array() || c.size() != 5) throw SceneError(where + ": expected [px, py, vx, vy, r]");
    std::array<double, 5> fields{};
    for (std::size_t j = 0; j < 5; ++j) fields[j] = to_double(c[j], where + ", field " + spec::name(spec::Field(j)));
    try {
      circles.push_back(spec::from_doubles(fields, k, spec::Radii::non_negative));
    } catch (const spec::OutsideC& e) {
      throw SceneError(source + ": " + e.what());
    }
  }
  return circles;
}

std::vector<spec::Circle> load_scene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(path + ": read error");
  return parse_scene(text.str(), path);
}

std::vector<spec::Circle> default_scene() { return parse_scene(default_scene_json, "<embedded default scene>"); }

}  // namespace circles::cli
