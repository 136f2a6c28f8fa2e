#include "cli/scene.hpp"

#include "cli/json_number.hpp"
#include "cli/protocol.hpp"  // printable

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace circles::cli {

extern const char* const default_scene_json;  // generated from scenes/default.json (cli/embedded.cpp.in)

namespace {

// A JSON number as a double by the rule of cli/json_number.hpp. The DOM keeps no token text, so an integer
// token beyond 64 bits, which nlohmann stores as the nearest double, is taken as that double.
double to_double(const nlohmann::json& x, const std::string& where) {
  if (x.is_number_float()) return x.get<double>();  // finite: the reader refuses overflow (Builder::parse_error)
  if (x.is_number_integer()) {
    const auto d = x.is_number_unsigned() ? json_number::from_integer(x.get<std::uint64_t>())
                                          : json_number::from_integer(x.get<std::int64_t>());
    if (!d) throw SceneError(where + ": " + json_number::not_exact(x.dump()));
    return *d;
  }
  throw SceneError(where + ": expected a number, found " + std::string(x.type_name()));
}

// The SAX events of nlohmann::json::sax_parse, built into a DOM as nlohmann::json::parse would, except that
//   - a key twice in one object is refused (parse would keep the last value silently);
//   - a number beyond the double range is reported with its place (parse says only "number overflow");
//   - the open containers are a vector, not the call stack, so no nesting is too deep to read.
// A container stays at its address while it is open: its parent receives nothing until it closes.
class Builder {
 public:
  explicit Builder(const std::string& source) : source_(source) {}

  nlohmann::json root;

  bool null() { return value(nullptr); }
  bool boolean(bool b) { return value(b); }
  bool number_integer(std::int64_t n) { return value(n); }
  bool number_unsigned(std::uint64_t n) { return value(n); }
  bool number_float(double x, const std::string&) { return value(x); }
  bool string(std::string& s) { return value(std::move(s)); }
  bool binary(nlohmann::json::binary_t& b) { return value(nlohmann::json::binary(std::move(b))); }

  bool start_object(std::size_t) {
    open_.push_back({&add(nlohmann::json::object()), {}});
    return true;
  }
  bool key(std::string& k) {
    Open& object = open_.back();
    if (object.json->contains(k))
      throw SceneError(source_ + ": duplicate key " + quoted(k) + " in " +
                       (open_.size() == 1 ? "the top-level object" : "the object at " + pointer(open_.size() - 1)));
    object.key = std::move(k);
    return true;
  }
  bool end_object() {
    open_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    open_.push_back({&add(nlohmann::json::array()), {}});
    return true;
  }
  bool end_array() {
    open_.pop_back();
    return true;
  }

  bool parse_error(std::size_t byte, const std::string& token, const nlohmann::json::exception& e) {
    // 406 is the one out_of_range error of the parser: a number token beyond the double range.
    if (e.id == 406) throw SceneError(source_ + ": " + place(byte) + ": " + token + " is beyond the double range");
    throw SceneError(source_ + ": malformed JSON at byte " + std::to_string(byte) + ": " + printable(e.what()));
  }

 private:
  struct Open {
    nlohmann::json* json;
    std::string key;  // an object's latest key
  };

  template <class Value>
  bool value(Value&& v) {
    add(nlohmann::json(std::forward<Value>(v)));
    return true;
  }

  nlohmann::json& add(nlohmann::json v) {
    if (open_.empty()) return root = std::move(v);
    Open& parent = open_.back();
    if (parent.json->is_array()) {
      parent.json->push_back(std::move(v));
      return parent.json->back();
    }
    return (*parent.json)[parent.key] = std::move(v);
  }

  // The JSON pointer ("/circles/1/2") of the container open_[depth], or with depth == open_.size() of the next
  // value. An open container is the last element of its parent; the next value goes after it.
  std::string pointer(std::size_t depth) const {
    std::string out;
    for (std::size_t i = 0; i < depth; ++i) {
      const Open& o = open_[i];
      const std::size_t next = i + 1 == open_.size() ? 0 : 1;  // an open child is already in its parent
      out += "/" + (o.json->is_array() ? std::to_string(o.json->size() - next) : printable(o.key));
    }
    return out;
  }

  // The place of the next value in the scene's terms, "circle 1, field vx", where it is one of the five
  // numbers of a circle, and by its byte otherwise.
  std::string place(std::size_t byte) const {
    if (open_.size() == 3 && open_[0].json->is_object() && open_[0].key == "circles" && open_[1].json->is_array() &&
        open_[2].json->is_array() && open_[2].json->size() < 5)
      return "circle " + std::to_string(open_[1].json->size() - 1) + ", field " +
             spec::name(spec::Field(open_[2].json->size()));
    return "byte " + std::to_string(byte) + " (at " + pointer(open_.size()) + ")";
  }

  static std::string quoted(const std::string& key) { return "\"" + printable(key) + "\""; }

  const std::string& source_;
  std::vector<Open> open_;
};

}  // namespace

std::vector<spec::Circle> parse_scene(std::string_view text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw SceneError(source + ": empty file, expected an object {\"circles\": [[px, py, vx, vy, r], ...]}");
  // nlohmann's lexer reads a NUL byte as the end of the input, so "{...}\0anything" would pass as "{...}".
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    throw SceneError(source + ": malformed JSON at byte " + std::to_string(nul + 1) +
                     ": a NUL byte, which JSON text cannot contain");
  Builder builder(source);
  nlohmann::json::sax_parse(text, &builder);
  const nlohmann::json& doc = builder.root;
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
  // A directory opens as a stream on Linux and reads as empty, which would be reported as an empty file.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw SceneError(path + ": cannot read the file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(path + ": read error");
  return parse_scene(text.str(), path);
}

std::vector<spec::Circle> default_scene() { return parse_scene(default_scene_json, "<embedded default scene>"); }

}  // namespace circles::cli
