// The step fuzzer's inputs (docs/hardening.md, "The step fuzzer"): bytes decoded into a world and a number of
// chained steps, through the boundary families' own constructions (properties/boundaries.hpp), and the
// mutations that keep a world meaningful: a field nudged by ulps, a world scaled by a power of two, a circle
// copied, two circles made tangent, a family's world drawn afresh.
//
// The bytes: a 10-byte header, then circles of 40 bytes each (five little-endian doubles px, py, vx, vy, r).
//   byte 0       the steps K = 1 + (byte mod kMaxSteps)
//   byte 1       0: no family; f >= 1: the world starts with a world of family (f − 1) mod F of the resolved
//                profile (F families, properties::families), drawn from the seed: gen::boundary_world for a
//                small family, gen::big_world (round seed mod 16, kBigCircles circles at most) for a big one
//   bytes 2..9   the seed, a little-endian 64-bit integer
//   then         explicit circles, appended after the family's (a trailing part of a circle is ignored; at
//                most kMaxCircles circles in all)
// A field that is not finite decodes as +0, and a radius as its magnitude, so every input is a world of C.
// encode writes the world it is given explicitly (no family): decode(encode(x)) is x, bit for bit.
#pragma once

#include "properties/boundaries.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace circles::fuzz {

using spec::Circles;

inline constexpr std::uint64_t kMaxSteps = 16;
inline constexpr std::size_t kHeaderBytes = 10;
inline constexpr std::size_t kCircleBytes = 40;
// The most circles of an input: a big family's world at its least limit (properties::kMinMaxCircles) and a few
// more. Larger worlds make each input slow without reaching other branches: the broad phase's levels and the
// pair lists' buckets are all reached by a few hundred circles.
inline constexpr std::size_t kBigCircles = properties::kMinMaxCircles;
inline constexpr std::size_t kMaxCircles = kBigCircles + 64;

struct StepInput {
  std::uint64_t steps = 1;  // 1 … kMaxSteps
  Circles circles;
  friend bool operator==(const StepInput&, const StepInput&) = default;
};

StepInput decode(std::span<const std::uint8_t> bytes);
std::vector<std::uint8_t> encode(const StepInput& input);

// A world of family `family` of the resolved profile from `seed` (bytes 1..9 above).
Circles family_world(properties::Family family, std::uint64_t seed);

// One mutation of `input`, chosen and drawn from `seed`: nudge a field by 1 … 3 ulps, scale the world by 2^e,
// copy a circle (exactly or with one field changed), make two circles tangent (along an axis or a (3, 4, 5)
// direction, exactly where the sums are exact), make two circles nearly tangent (in a direction drawn at
// random, F a few roundings from 0, then maybe b moved by up to 64 ulps), remove or swap circles, set a field to a boundary value (±0,
// 2^-1074, DBL_MIN, DBL_MAX, ...), copy a field from another circle (a tie), change K, or draw a family's
// world (replacing or appended). The result is a world of C with at most kMaxCircles circles.
StepInput mutate(StepInput input, std::uint64_t seed);
// A child of two inputs: a's first circles, then b's last ones, a's steps.
StepInput cross_over(const StepInput& a, const StepInput& b, std::uint64_t seed);

}  // namespace circles::fuzz
