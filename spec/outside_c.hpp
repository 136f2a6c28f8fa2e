// What makes five doubles an element of C, and the error for those that are not. Free of Eigen and GMP, so
// the engines validate their input with the oracle's own rules and error type.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::spec {

// The five coordinates in the protocol's order [px, py, vx, vy, r]; Field(k) is the coordinate at index k of
// a CircleDoubles. name(f) is its name in every message: "px", "py", "vx", "vy" or "r".
enum class Field { px, py, vx, vy, r };
const char* name(Field f);

// One circle as doubles, [px, py, vx, vy, r], and a world of them, circle k at index k: what the engines
// step, the step protocol and traces carry, and the oracle takes and rounds to (an exact circle is a Circle,
// spec/circle.hpp, and an exact world a Sequence, spec/oracle.hpp).
using CircleDoubles = std::array<double, 5>;
using Circles = std::vector<CircleDoubles>;

// An input that is not an element of C: NaN or infinity in any field, or a radius the profile refuses.
// `index` is the circle's position in the input, `field` the coordinate at fault.
class OutsideC : public std::invalid_argument {
 public:
  OutsideC(std::size_t index, Field field, const std::string& reason);
  std::size_t index;
  Field field;
};

// Which radii belong to C. The seed writes r ∈ ℝ⁺ in the definition of C but uses r ≥ 0 in the proof of
// Theorem 4 (spec-notes: "r-plus"); the literal profile takes the definition, the resolved one the proof.
enum class Radii { positive, non_negative };

// Throws OutsideC unless [px, py, vx, vy, r] is an element of C: the first NaN or infinite field, in field
// order, else a radius that `radii` refuses. `index` names the circle in the message.
void check_doubles(const CircleDoubles& fields, std::size_t index, Radii radii);

}  // namespace circles::spec
