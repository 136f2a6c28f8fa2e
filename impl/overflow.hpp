// A step whose next position is beyond the double range, as every stepper reports it: the engines and references
// of impl/, and the registry's steppers (engines::StepOverflow is this type); `circles serve` and `circles
// check-trace` name the circle and field with overflow_reason.
#pragma once

#include "spec/outside_c.hpp"  // spec::Field

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace circles::impl {

// "circle <index>, field <field>: the position p + v/60 overflows to infinity": the reason every overflow of a
// position is reported with.
inline std::string overflow_reason(std::size_t index, spec::Field field) {
  return "circle " + std::to_string(index) + ", field " + spec::name(field) +
         ": the position p + v/60 overflows to infinity";
}

// At step `step` (the step that would make world `step` from world `step` − 1), circle `index`'s coordinate
// `field` (px or py) would become ±infinity. The world is left as it was before that step. what(): "step 31, "
// and then overflow_reason, "circle 2, field px: the position p + v/60 overflows to infinity".
class PositionOverflow : public std::overflow_error {
 public:
  PositionOverflow(std::uint64_t s, std::size_t i, spec::Field f)
      : std::overflow_error("step " + std::to_string(s) + ", " + overflow_reason(i, f)), step(s), index(i), field(f) {}
  std::uint64_t step;
  std::size_t index;
  spec::Field field;
};

}  // namespace circles::impl
