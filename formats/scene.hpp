// Scenes for the `circles` command (docs/scenes.md, with its JSON Schema docs/scene.schema.json): one JSON object
//   {"name": "...", "steps": N, "circles": [C, ...]}            "name" and "steps" optional
// where each circle C is the protocol's compact array [px, py, vx, vy, r] or the object
//   {"p": [px, py], "v": [vx, vy], "r": r, "name": "..."}         "name" optional
// so the protocol's compact form {"circles": [[px, py, vx, vy, r], ...]} is a scene. Any other key, at the top
// or in a circle, is refused with its place: a misspelt "raduis" or "step" must not pass as a scene without
// it. The one exception is "$schema" at the top, a string that editors read to check the file and we ignore.
#pragma once

#include "spec/circle.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace circles::formats {

// Any scene that cannot be used: the message names the source, the place and the reason.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The largest "steps" of a scene: the largest `circles run --steps`, 2^63 - 1, which every tool can count to
// in a signed 64-bit integer.
inline constexpr std::uint64_t kMaxSceneSteps = std::numeric_limits<std::int64_t>::max();

// A scene read: w_0 and what the file says about it.
struct Scene {
  std::optional<std::string> name;
  std::optional<std::uint64_t> steps;  // the default step count of `circles run` and `circles oracle`
  std::vector<spec::Circle> circles;   // w_0, circle k the k-th of the file
  std::vector<std::optional<std::string>> circle_names;  // the "name" of circle k, if it has one; as many as circles

  friend bool operator==(const Scene&, const Scene&) = default;
};

// Reads a scene. Each number means the double nearest to it (formats/json_number.hpp) and the circle holds its
// exact value. `source` names the text in messages (a file name, or "<embedded default scene>"). Throws
// SceneError, naming the place ("circle 3, field vx", "\"steps\"", a byte and JSON pointer) and the reason, for:
// empty text, malformed JSON (NaN, Infinity, invalid UTF-8, a NUL byte, truncation), a number beyond the
// double range, a key twice in one object, an unknown key, a missing "circles", "p", "v" or "r", a value of
// the wrong type or arity, "steps" not an integer in [0, kMaxSceneSteps], and a circle outside C in the
// resolved profile (r < 0). Nesting of any depth is read without recursion.
Scene parse_scene(std::string_view text, const std::string& source);

// The same, from a file, or from the standard input for "-" (named "<stdin>" in messages); a missing file, a
// directory or a read error is a SceneError too. A file whose circles
// are all in the compact form is read in pieces (formats/streamed.hpp), any other by parse_scene whole: the
// scene and every message are parse_scene's either way.
Scene load_scene(const std::string& path);

// A scene as the engines take it, doubles, for `circles run`: its circles as doubles_of gives them (a -0 as
// +0), with none of the exact circles of a Scene or its circles' names.
struct SceneWorld {
  std::optional<std::string> name;
  std::optional<std::uint64_t> steps;
  spec::Circles circles;

  friend bool operator==(const SceneWorld&, const SceneWorld&) = default;
};

// The same as doubles_of(load_scene(path)) with the scene's name and steps, and the same messages; a file of
// compact circles is read in pieces into doubles and holds, beyond them, one piece of text (1 MiB).
SceneWorld load_scene_world(const std::string& path);

// The readers above on a stream, reading `piece` bytes at a time; tests and the fuzzer read strings this way.
// The fast path needs a stream that can seek back to its start (a text it does not take is read again): one
// that cannot, a pipe, is read whole by parse_scene.
Scene read_scene(std::istream& in, const std::string& source, std::size_t piece);
SceneWorld read_scene_world(std::istream& in, const std::string& source, std::size_t piece);

// The embedded default scene (scenes/default.json, built into the binary).
Scene default_scene();

// The doubles of a scene: every coordinate of a loaded scene is the exact value of a double, so this gives
// those doubles back (a -0 as +0: a rational has no sign, and no step can tell them apart).
spec::Circles doubles_of(const std::vector<spec::Circle>& scene);
spec::Circles doubles_of(const Scene& scene);

// A world too large for this machine: "world too large for memory: 1000000000 circles need 320000000000 bytes,
// more than the 25000000000 bytes of memory of this machine".
class WorldTooLarge : public SceneError {
 public:
  WorldTooLarge(std::size_t circles, std::size_t bytes, std::size_t memory);
};

// The physical memory of this machine in bytes (sysconf: pages times page size).
std::size_t physical_memory();

// Bytes per circle that `circles oracle` holds at its peak, for the check of random_world: the oracle's report
// holds both profiles' worlds as rationals. Measured (4250 bytes, 4000 circles, 1 step; 3500 for the scene
// alone) with 20% to spare, as each engine's figure is (engines/registry.cpp, EngineEntry::bytes_per_circle).
inline constexpr std::size_t kOracleBytesPerCircle = 5120;

// The benchmarks' random scene (formats/random_scene.hpp: r in [2, 6], |v| <= 100, `coverage` of a square), as
// doubles [px, py, vx, vy, r]. Throws WorldTooLarge, before allocating anything, when n circles at
// `bytes_per_circle` each need more than physical_memory(), and SceneError for n = 0 or a coverage outside
// (0, 1] or too small for a finite square.
spec::Circles random_world(std::size_t n, double coverage, std::uint64_t seed, std::size_t bytes_per_circle);

// The same as a Scene of exact circles, named by random_scene_name.
Scene random_scene(std::size_t n, double coverage, std::uint64_t seed, std::size_t bytes_per_circle);

// "a random scene of 1000 circles (coverage 0.1, seed 1)".
std::string random_scene_name(std::size_t n, double coverage, std::uint64_t seed);

}  // namespace circles::formats
