// `circles vectors --out DIR`: golden test vectors for implementations in other languages (docs/vectors.md).
//
// A vector is one world of doubles and its next world under the resolved step: exact, as rationals from the
// oracle (spec::resolved_step), and correctly rounded, as doubles in shortest decimal and in hexadecimal, with
// the canonical state hash (impl/state_hash.hpp) of the world and of its rounded next world. The cases are the
// first worlds of each bundled scene and conform's generated worlds (conform/conform.hpp, case_worlds), which are
// rich in contacts, exact tangencies, ties and copies. All of them go to one JSON Lines file, DIR/vectors.jsonl,
// one case per line, written beside its place and renamed into it, so DIR never holds a half-written file.
#pragma once

#include "formats/protocol.hpp"
#include "spec/oracle.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::cli {

// The program's layer names the libraries' types and functions unqualified.
using namespace circles::formats;

// The vectors cannot be made or written: what() names the file or directory and the reason.
class VectorsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct VectorsOptions {
  std::string out;                // the directory of vectors.jsonl, created if missing
  std::uint64_t cases = 200;      // generated cases: conform's cases 0 … cases − 1 of `seed`
  std::uint64_t seed = 1;
  std::string scenes = "scenes";  // every *.json file in it, in name order
  std::uint64_t scene_steps = 3;  // per scene, the worlds w_0 … w_{scene_steps − 1} of its run
};

// The file name of the vectors in the output directory.
inline constexpr const char* kVectorsFile = "vectors.jsonl";

// One vector.
struct Vector {
  // Where the world comes from: step `step` of scene file `scene` (its name in the scenes directory), or
  // case `case_index` of conform's seed `seed`.
  std::optional<std::string> scene;
  std::uint64_t step = 0;
  std::uint64_t seed = 0, case_index = 0;

  std::vector<std::string> features;  // what the world exercises: "contact", "tangency", "choice", ...
  Circles input;
  spec::Sequence next_exact;  // the oracle's resolved step of `input`, exact
  Circles next;               // next_exact, each coordinate the nearest double
};

// The vector of `input` (its source left empty), or nothing when a position of its next world rounds beyond
// the double range (there is no double to write).
std::optional<Vector> make_vector(const Circles& input);

// The names of what `w` exercises, in this order, each if it holds: "contact" (some pair intersects, (3)),
// "tangency" (some pair touches exactly), "choice" (some circle touches two or more others, so e (8)
// chooses), "tie" (two different circles share px or py), "duplicate" (one circle twice), "zero_radius".
std::vector<std::string> features_of(const Circles& w);

// Vector number `index` as one JSON line, without the newline (docs/vectors.md, "Format").
std::string format_vector(std::size_t index, const Vector& v);

// "n/d" in lowest terms, d >= 1, also for integers ("3/1", "0/1").
std::string fraction(const spec::Q& q);

// Appends [["px","py","vx","vy","r"], ...], each number its fraction() as a JSON string: a world as rationals,
// as a vector's next exact world and a line of `circles run --exact-trace` hold it.
void append_exact_world(std::string& out, const std::vector<spec::Circle>& w);


struct VectorsSummary {
  std::string file;                  // DIR/vectors.jsonl
  std::size_t written = 0;           // cases in the file
  std::size_t scenes = 0;            // scene files read
  std::size_t scene_cases = 0;       // cases from them
  std::size_t skipped = 0;           // worlds whose next world leaves the double range, not written
  std::map<std::string, std::size_t> features;  // feature → cases that exercise it
};

// Makes the vectors and writes them. Throws VectorsError when the scenes directory cannot be read or the file
// cannot be written (leaving no file behind), and SceneError for a scene that cannot be loaded.
VectorsSummary write_vectors(const VectorsOptions& options);

// The command: writes the vectors and a summary on `out`; 0 when written, 2 with the reason on `err`
// otherwise.
int vectors_command(const VectorsOptions& options, std::ostream& out, std::ostream& err);

}  // namespace circles::cli
