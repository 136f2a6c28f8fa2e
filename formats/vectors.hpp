// The text of golden test vectors (docs/vectors.md, "Format") and of exact worlds: a vector as one JSON line, and
// a world as rationals, as `circles vectors` writes its next exact worlds and `circles run --exact-trace` its lines.
//
// A vector is one world of doubles and its next world under the resolved step: exact, as rationals from the
// oracle (spec::resolved_step), and correctly rounded, as doubles in shortest decimal and in hexadecimal, with
// the canonical state hash (formats/state_hash.hpp) of the world and of its rounded next world. How the vectors are
// made is conform/vectors.hpp.
#pragma once

#include "formats/protocol.hpp"
#include "spec/oracle.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace circles::formats {

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

// Vector number `index` as one JSON line, without the newline (docs/vectors.md, "Format").
std::string format_vector(std::size_t index, const Vector& v);

// "n/d" in lowest terms, d >= 1, also for integers ("3/1", "0/1").
std::string fraction(const spec::Q& q);

// Appends [["px","py","vx","vy","r"], ...], each number its fraction() as a JSON string: a world as rationals,
// as a vector's next exact world and a line of `circles run --exact-trace` hold it.
void append_exact_world(std::string& out, const std::vector<spec::Circle>& w);

// {"step":t,"circles":[["px","py","vx","vy","r"],...]} without a newline, each number the exact "n/d" of
// fraction() (append_exact_world): a line of --exact-trace.
void append_exact_line(std::string& out, std::uint64_t step, const spec::Sequence& w);

}  // namespace circles::formats
