// Golden test vectors for implementations in other languages, as `circles vectors --out DIR` writes them
// (docs/vectors.md); a vector and its text are formats/vectors.hpp.
//
// The cases are the first worlds of each bundled scene and conform's generated worlds (conform/conform.hpp,
// case_worlds), which are rich in contacts, exact tangencies, ties and copies. All of them go to one JSON Lines
// file, DIR/vectors.jsonl, one case per line, written beside its place and renamed into it, so DIR never holds a
// half-written file.
#pragma once

#include "formats/protocol.hpp"
#include "formats/vectors.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::conform {

using spec::Circles;
using formats::Vector;

// The vectors cannot be made or written: what() names the file or directory and the reason.
class VectorsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct VectorsOptions {
  std::string out;                // the directory of vectors.jsonl, created if missing; "-": the vectors on stdout
  std::uint64_t cases = 200;      // generated cases: conform's cases 0 … cases − 1 of `seed`
  std::uint64_t seed = 1;
  std::string scenes = "scenes";  // every *.json file in it, in name order
  std::uint64_t scene_steps = 3;  // per scene, the worlds w_0 … w_{scene_steps − 1} of its run
};

// The file name of the vectors in the output directory.
inline constexpr const char* kVectorsFile = "vectors.jsonl";

// The vector of `input` (its source left empty), or nothing when a position of its next world rounds beyond
// the double range (there is no double to write).
std::optional<Vector> make_vector(const Circles& input);

// The names of what `w` exercises, in this order, each if it holds: "contact" (some pair intersects, (3)),
// "tangency" (some pair touches exactly), "choice" (some circle touches two or more others, so e (8)
// chooses), "tie" (two different circles share px or py), "duplicate" (one circle twice), "zero_radius".
std::vector<std::string> features_of(const Circles& w);

struct VectorsSummary {
  std::string file;                  // DIR/vectors.jsonl, or "-"
  std::size_t written = 0;           // cases in the file
  std::size_t scenes = 0;            // scene files read
  std::size_t scene_cases = 0;       // cases from them
  std::size_t skipped = 0;           // worlds whose next world leaves the double range, not written
  std::size_t big = 0;               // generated cases of the big families, left out (conform checks them)
  std::map<std::string, std::size_t> features;  // feature → cases that exercise it
};

// Makes the vectors and writes them. Throws VectorsError when the scenes directory cannot be read or the file
// cannot be written (leaving no file behind), and SceneError for a scene that cannot be loaded.
VectorsSummary write_vectors(const VectorsOptions& options);

}  // namespace circles::conform
