// A big world's random stream (properties/detail/big_worlds.cpp, detail/swarm.cpp).
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace circles::properties::detail {

using I = std::int64_t;

// The case's random stream, and whether its world is the family's largest (a ladder's world).
class Draw {
 public:
  // Whether the world is a ladder's: the family's largest under the limit.
  bool largest() const { return largest_; }
  // 64 random bits.
  std::uint64_t bits() { return random_.next(); }
  Draw(rc::Random random, bool largest) : random_(std::move(random)), largest_(largest) {}
  // Uniform in [0, n), n > 0 (the modulo's bias, below 2^-40 for n < 2^24, does not matter here).
  std::uint64_t below(std::uint64_t n) { return random_.next() % n; }
  I between(I lo, I hi) { return lo + static_cast<I>(below(static_cast<std::uint64_t>(hi - lo + 1))); }
  // A quarter in [-60, 60]: up to one unit of movement per step.
  double velocity() { return static_cast<double>(between(-240, 240)) / 4; }
  template <class T>
  void shuffle(std::vector<T>& items) {
    for (std::size_t k = items.size(); k > 1; --k) std::swap(items[k - 1], items[below(k)]);
  }
  // The round-th case's level among `levels` (0 … levels − 1): the largest for a ladder's world; else the first
  // `levels` rounds go up one level each, so that a run of that many rounds has reached the largest; after them
  // the ruler sequence 0, 1, 0, 2, 0, 1, 0, 3, … (the number of trailing zero bits of the round counted from
  // there), so that a level's worlds come half as often as the level below's, and a long run's time stays
  // dominated by its first cases.
  std::size_t level(std::uint64_t round, std::size_t levels) const {
    if (levels == 0) return 0;
    if (largest_) return levels - 1;
    if (round < levels) return static_cast<std::size_t>(round);
    return std::min<std::size_t>(levels - 1, static_cast<std::size_t>(std::countr_zero(round - levels + 1)));
  }

 private:
  rc::Random random_;
  bool largest_;
};

}  // namespace circles::properties::detail
