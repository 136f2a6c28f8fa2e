#include "formats/scene.hpp"

#include "formats/input_file.hpp"
#include "formats/json_number.hpp"
#include "formats/plain_line.hpp"
#include "formats/protocol.hpp"  // printable
#include "formats/streamed.hpp"
#include "formats/random_scene.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace circles::formats {

extern const char* const default_scene_json;  // generated from scenes/default.json (formats/embedded.cpp.in)

namespace {

// The keys of the two kinds of object a scene has; every other key is refused where it is read.
constexpr std::array<std::string_view, 4> kSceneKeys = {"name", "steps", "circles", "$schema"};
constexpr std::array<std::string_view, 4> kCircleKeys = {"p", "v", "r", "name"};

template <std::size_t N>
bool is_one_of(const std::string& key, const std::array<std::string_view, N>& keys) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}


// What a value is, for messages: a number as JSON writes it ("found -1"), anything else by its type ("found
// string").
std::string found(const nlohmann::json& x) {
  return "found " + (x.is_number() ? x.dump() : std::string(x.type_name()));
}

// A JSON number as the double nearest to it (formats/json_number.hpp). A float in the DOM is already that double:
// the parser's strtod of the token, finite (the reader refuses overflow, Builder::parse_error); this includes
// integer tokens beyond 64 bits.
double to_double(const nlohmann::json& x, const std::string& where) {
  if (x.is_number_float()) return x.get<double>();
  if (x.is_number_unsigned()) return json_number::from_integer(x.get<std::uint64_t>());
  if (x.is_number_integer()) return json_number::from_integer(x.get<std::int64_t>());
  throw SceneError(where + ": expected a number, " + found(x));
}

// The SAX events of nlohmann::json::sax_parse, built into a DOM as nlohmann::json::parse would, except that
//   - a key twice in one object is refused (parse would keep the last value silently);
//   - a key that a scene or a circle object does not have is refused where it is read, so the first in the
//     file is named, however many follow;
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
    if (open_.size() == 1 && !is_one_of(k, kSceneKeys))
      throw SceneError(source_ + ": unknown key " + in_quotes(k) +
                       " in the top-level object (a scene has the keys \"circles\", \"name\", \"steps\" and "
                       "\"$schema\")");
    if (open_.size() == 3 && in_circle() && !is_one_of(k, kCircleKeys))
      throw SceneError(source_ + ": " + circle() + ": unknown key " + in_quotes(k) +
                       " (a circle object has the keys \"p\", \"v\", \"r\" and \"name\")");
    Open& object = open_.back();
    if (object.json->contains(k))
      throw SceneError(source_ + ": duplicate key " + in_quotes(k) + " in " +
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
    if (e.id == 406)
      throw SceneError(source_ + ": " + place(byte) + ": " + shortened_token(token) + " is beyond the double range");
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

  // True when the open containers begin as a scene's do: the top-level object at its "circles", that array,
  // and one of its circles, open_[2], which is the last element of the array while it is open.
  bool in_circle() const {
    return open_.size() >= 3 && open_[0].json->is_object() && open_[0].key == "circles" && open_[1].json->is_array();
  }
  std::string circle() const { return "circle " + std::to_string(open_[1].json->size() - 1); }

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

  // The place of the next value in the scene's terms where it is a number of the scene: "circle 1, field vx"
  // (the compact form, or "p", "v" and "r" of a circle object), "\"steps\""; by its byte otherwise.
  std::string place(std::size_t byte) const {
    const auto field = [&](std::size_t f) { return circle() + ", field " + spec::name(spec::Field(f)); };
    if (open_.size() == 1 && open_[0].json->is_object() && open_[0].key == "steps") return "\"steps\"";
    if (open_.size() == 3 && in_circle()) {
      const Open& c = open_[2];
      if (c.json->is_array() && c.json->size() < 5) return field(c.json->size());
      if (c.json->is_object() && c.key == "r") return field(4);
    }
    if (open_.size() == 4 && in_circle() && open_[2].json->is_object() && open_[3].json->is_array() &&
        open_[3].json->size() < 2 && (open_[2].key == "p" || open_[2].key == "v"))
      return field((open_[2].key == "p" ? 0 : 2) + open_[3].json->size());
    return "byte " + std::to_string(byte) + " (at " + pointer(open_.size()) + ")";
  }

  const std::string& source_;
  std::vector<Open> open_;
};

// "steps": an integer in [0, kMaxSceneSteps]. A float token counts when its value is such an integer ("1e3"),
// as JSON Schema's "integer" has it.
std::uint64_t steps_of(const nlohmann::json& x, const std::string& source) {
  if (x.is_number_unsigned() && x.get<std::uint64_t>() <= kMaxSceneSteps) return x.get<std::uint64_t>();
  if (x.is_number_integer() && !x.is_number_unsigned() && x.get<std::int64_t>() >= 0)
    return static_cast<std::uint64_t>(x.get<std::int64_t>());
  // 2^63 = kMaxSceneSteps + 1 is a double; every double below it and >= 0 that is an integer converts exactly.
  if (x.is_number_float()) {
    const double d = x.get<double>();
    if (d >= 0 && d < 0x1p63 && std::floor(d) == d) return static_cast<std::uint64_t>(d);
  }
  throw SceneError(source + ": \"steps\": expected an integer from 0 to " + std::to_string(kMaxSceneSteps) + ", " +
                   found(x));
}

std::string string_of(const nlohmann::json& x, const std::string& where) {
  if (!x.is_string()) throw SceneError(where + ": expected a string, " + found(x));
  return x.get<std::string>();
}

// [px, py] or [vx, vy] of a circle object into fields[first], fields[first + 1].
void pair_of(const nlohmann::json& x, const std::string& where, const char* shape, spec::CircleDoubles& fields,
             std::size_t first) {
  if (!x.is_array()) throw SceneError(where + ": expected " + shape + ", " + found(x));
  if (x.size() != 2)
    throw SceneError(where + ": expected 2 numbers " + shape + ", found " + std::to_string(x.size()));
  for (std::size_t j = 0; j < 2; ++j) fields[first + j] = to_double(x[j], where + std::string(1, "xy"[j]));
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw SceneError(source + ": empty file, expected an object {\"circles\": [[px, py, vx, vy, r], ...]}");
  // nlohmann's lexer reads a NUL byte as the end of the input, so "{...}\0anything" would pass as "{...}".
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    throw SceneError(source + ": malformed JSON at byte " + std::to_string(nul + 1) +
                     ": a NUL byte, which JSON text cannot contain");
  Builder builder(source);
  nlohmann::json::sax_parse(text, &builder);
  const nlohmann::json& doc = builder.root;
  if (!doc.is_object()) throw SceneError(source + ": expected an object with a \"circles\" array");

  Scene scene;
  if (doc.contains("$schema")) string_of(doc["$schema"], source + ": \"$schema\"");
  if (doc.contains("name")) scene.name = string_of(doc["name"], source + ": \"name\"");
  if (doc.contains("steps")) scene.steps = steps_of(doc["steps"], source);
  if (!doc.contains("circles")) throw SceneError(source + ": missing key \"circles\"");
  const nlohmann::json& list = doc["circles"];
  if (!list.is_array()) throw SceneError(source + ": \"circles\" must be an array");

  scene.circles.reserve(list.size());
  scene.circle_names.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string where = source + ": circle " + std::to_string(k);
    const auto field = [&](std::size_t f) { return where + ", field " + spec::name(spec::Field(f)); };
    const nlohmann::json& c = list[k];
    spec::CircleDoubles fields{};
    std::optional<std::string> name;
    if (c.is_array()) {
      if (c.size() != 5)
        throw SceneError(where + ": expected 5 numbers [px, py, vx, vy, r], found " + std::to_string(c.size()));
      for (std::size_t j = 0; j < 5; ++j) fields[j] = to_double(c[j], field(j));
    } else if (c.is_object()) {
      for (const char* key : {"p", "v", "r"})  // the keys are known (Builder::key): only a missing one is left
        if (!c.contains(key)) throw SceneError(where + ": missing key \"" + key + "\"");
      pair_of(c["p"], where + ", field p", "[px, py]", fields, 0);
      pair_of(c["v"], where + ", field v", "[vx, vy]", fields, 2);
      fields[4] = to_double(c["r"], field(4));
      if (c.contains("name")) name = string_of(c["name"], where + ", field name");
    } else {
      throw SceneError(where + ": expected [px, py, vx, vy, r] or {\"p\": [px, py], \"v\": [vx, vy], \"r\": r}, " +
                       found(c));
    }
    try {
      scene.circles.push_back(spec::from_doubles(fields, k, spec::Radii::non_negative));
    } catch (const spec::OutsideC& e) {
      throw SceneError(source + ": " + e.what());
    }
    scene.circle_names.push_back(std::move(name));
  }
  return scene;
}

namespace {

// The doubles of a scene whose circles are all compact, read in pieces, with its name and steps (Streamed's
// checks: the rest of the scene read by parse_scene, with no circle and with one); or nothing, for
// parse_scene to read. A -0 stays -0 here.
std::optional<SceneWorld> streamed_scene(std::istream& in, const std::string& source, std::size_t piece) {
  if (in.tellg() != std::streampos(0)) return std::nullopt;  // a pipe, which cannot be read again from its start
  PlainLineReader reader;
  std::optional<Streamed> s = stream_document(in, false, reader, piece);
  if (!s) return std::nullopt;
  try {
    Scene outer = parse_scene(s->outer, source);
    if (!outer.circles.empty() || parse_scene(s->with_one_circle(), source).circles.size() != 1) return std::nullopt;
    return SceneWorld{std::move(outer.name), outer.steps, std::move(s->circles)};
  } catch (const SceneError&) {
    return std::nullopt;
  }
}

// The text of `in` from its start, for parse_scene.
std::string whole_text(std::istream& in, const std::string& source) {
  in.clear();
  in.seekg(0);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(source + ": read error");
  return text.str();
}

std::unique_ptr<std::istream> open_scene(const std::string& path) {
  try {
    return open_input(path);
  } catch (const InputError& e) {
    throw SceneError(input_name(path) + ": " + e.what());
  }
}

}  // namespace

Scene read_scene(std::istream& in, const std::string& source, std::size_t piece) {
  std::optional<SceneWorld> world = streamed_scene(in, source, piece);
  if (!world) return parse_scene(whole_text(in, source), source);
  // The circles parse_scene would make of the same doubles: the fast path refused every r < 0.
  Scene scene{std::move(world->name), world->steps, {}, {}};
  scene.circles.reserve(world->circles.size());
  for (std::size_t k = 0; k < world->circles.size(); ++k)
    scene.circles.push_back(spec::from_doubles(world->circles[k], k, spec::Radii::non_negative));
  scene.circle_names.resize(scene.circles.size());
  return scene;
}

SceneWorld read_scene_world(std::istream& in, const std::string& source, std::size_t piece) {
  std::optional<SceneWorld> world = streamed_scene(in, source, piece);
  if (!world) {
    Scene scene = parse_scene(whole_text(in, source), source);
    return SceneWorld{std::move(scene.name), scene.steps, doubles_of(scene)};
  }
  for (auto& circle : world->circles)
    for (double& x : circle)
      if (x == 0) x = 0;  // -0 as +0, as doubles_of gives it
  return std::move(*world);
}

Scene load_scene(const std::string& path) { return read_scene(*open_scene(path), input_name(path), kStreamPiece); }

SceneWorld load_scene_world(const std::string& path) {
  return read_scene_world(*open_scene(path), input_name(path), kStreamPiece);
}

Scene default_scene() { return parse_scene(default_scene_json, "<embedded default scene>"); }

Circles doubles_of(const std::vector<spec::Circle>& scene) {
  Circles w;
  w.reserve(scene.size());
  for (const spec::Circle& c : scene) w.push_back(spec::nearest_doubles(c));
  return w;
}

Circles doubles_of(const Scene& scene) { return doubles_of(scene.circles); }

WorldTooLarge::WorldTooLarge(std::size_t circles, std::size_t bytes, std::size_t memory)
    : SceneError("world too large for memory: " + std::to_string(circles) + " circles need " + std::to_string(bytes) +
                 " bytes, more than the " + std::to_string(memory) + " bytes of memory of this machine") {}

std::size_t physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return std::numeric_limits<std::size_t>::max();  // unknown: let allocation decide
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page);
}

Circles random_world(std::size_t n, double coverage, std::uint64_t seed, std::size_t bytes_per_circle) {
  const std::size_t memory = physical_memory();
  // n * bytes_per_circle > memory, without the product's overflow.
  if (bytes_per_circle > 0 && n > memory / bytes_per_circle) {
    const bool overflows = n > std::numeric_limits<std::size_t>::max() / bytes_per_circle;
    throw WorldTooLarge(n, overflows ? std::numeric_limits<std::size_t>::max() : n * bytes_per_circle, memory);
  }
  try {
    return formats::random_scene(n, coverage, seed);
  } catch (const std::invalid_argument& e) {
    std::string why = e.what();  // "random_scene: coverage 0 is not in (0, 1] (...)"
    if (why.starts_with("random_scene: ")) why.erase(0, std::string_view("random_scene: ").size());
    throw SceneError("random scene: " + why);
  }
}

Scene random_scene(std::size_t n, double coverage, std::uint64_t seed, std::size_t bytes_per_circle) {
  const auto world = random_world(n, coverage, seed, bytes_per_circle);
  Scene scene;
  scene.name = random_scene_name(n, coverage, seed);
  scene.circles.reserve(world.size());
  for (std::size_t k = 0; k < world.size(); ++k)
    scene.circles.push_back(spec::from_doubles(world[k], k, spec::Radii::non_negative));
  scene.circle_names.resize(world.size());
  return scene;
}

std::string random_scene_name(std::size_t n, double coverage, std::uint64_t seed) {
  std::string c;
  if (std::isfinite(coverage)) json_number::append(c, coverage);
  else c = std::to_string(coverage);  // "nan", "inf": a coverage random_world refuses
  return "a random scene of " + std::to_string(n) + " circles (coverage " + c + ", seed " + std::to_string(seed) + ")";
}

}  // namespace circles::formats
