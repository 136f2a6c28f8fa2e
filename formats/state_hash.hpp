// The canonical state hash: a cheap way for any language to compare worlds and trajectories bit for bit
// (docs/vectors.md, "The state hash", defines it for other languages; `circles vectors` and
// `circles check-trace` print it as 16 lowercase hexadecimal digits).
//
//   bytes(world)  for each circle in index order, for each field px, py, vx, vy, r in that order: the field's
//                 IEEE 754 binary64 encoding as 8 bytes, least significant byte first, with −0 written as +0
//                 (the oracle compares by value, so −0 and +0 are the same state).
//   state_hash    FNV-1a, 64 bits, of bytes(world): offset basis 0xcbf29ce484222325, prime 0x100000001b3.
//   trajectory    FNV-1a, 64 bits, of bytes(world 0) bytes(world 1) … bytes(world N), one running hash.
//   The empty world has no bytes: its hash is the offset basis.
#pragma once

#include "spec/outside_c.hpp"

#include <cstdint>
#include <span>

namespace circles::formats {

inline constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325;  // FNV-1a 64-bit parameters
inline constexpr std::uint64_t kFnvPrime = 0x100000001b3;

// A running FNV-1a hash over canonical world bytes.
class StateHash {
 public:
  // Adds bytes(world).
  void add(std::span<const spec::CircleDoubles> world) noexcept;
  std::uint64_t value() const noexcept { return h_; }

 private:
  std::uint64_t h_ = kFnvOffsetBasis;
};

// state_hash(world) = FNV-1a of bytes(world).
std::uint64_t state_hash(std::span<const spec::CircleDoubles> world) noexcept;

}  // namespace circles::formats
