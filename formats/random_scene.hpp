// The benchmark scenes: n circles with radii uniform in [2, 6], velocities uniform in the disc
// |v| ≤ 100, and centres uniform in a square whose side makes the circles' areas sum to `coverage` of it
// (overlaps allowed, so the covered fraction of the plane is somewhat less).
//
// The same seed gives the same doubles on every platform: the generator is std::mt19937_64, whose output
// sequence the standard fixes, and the mapping to doubles is written here in IEEE operations (the standard's
// distributions, std::uniform_real_distribution included, are left to each library and differ between them).
//
// Draws, in this order: for each circle k = 0 … n−1, r then (vx, vy), redrawing the pair until it lies in the
// disc; then, once the side is known, px then py of each circle k = 0 … n−1. A uniform u ∈ [0, 1) is
// (x >> 11)·2^−53 of one 64-bit output x: exact, the top 53 bits.
#pragma once

#include "spec/outside_c.hpp"

#include <cstddef>
#include <cstdint>

namespace circles::formats {

inline constexpr double kSceneMinRadius = 2;
inline constexpr double kSceneMaxRadius = 6;
inline constexpr double kSceneMaxSpeed = 100;

// n circles as [px, py, vx, vy, r], every one in C of both profiles (r > 0, all finite):
//   r = 2 + 4u; (vx, vy) = (100·(2u − 1), 100·(2u' − 1)) redrawn until vx² + vy² ≤ 100² (in double arithmetic);
//   side = √(Σ π r² / coverage); (px, py) = (side·u, side·u'), so 0 ≤ px, py ≤ side.
// Throws std::invalid_argument, naming the argument, when n is 0, when coverage is not in (0, 1] (NaN
// included), or when coverage is so small that the side overflows to infinity.
spec::Circles random_scene(std::size_t n, double coverage, std::uint64_t seed);

}  // namespace circles::formats
