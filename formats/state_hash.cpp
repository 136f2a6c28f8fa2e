#include "formats/state_hash.hpp"

#include <bit>

namespace circles::formats {

void StateHash::add(std::span<const spec::CircleDoubles> world) noexcept {
  for (const spec::CircleDoubles& circle : world)
    for (const double field : circle) {
      // x + 0.0 is +0 for x = ±0 and x for every other finite x (round to nearest): the ±0 policy.
      const std::uint64_t bits = std::bit_cast<std::uint64_t>(field + 0.0);
      for (int byte = 0; byte < 8; ++byte) {  // least significant byte first, whatever the host's order
        h_ ^= (bits >> (8 * byte)) & 0xff;
        h_ *= kFnvPrime;
      }
    }
}

std::uint64_t state_hash(std::span<const spec::CircleDoubles> world) noexcept {
  StateHash h;
  h.add(world);
  return h.value();
}

}  // namespace circles::formats
