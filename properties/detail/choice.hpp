// Building blocks for the generators: uniform choices that ignore RapidCheck's size and shrink towards a
// chosen value. RapidCheck's own choices do not fit: rc::gen::inRange narrows its range with the size (at
// size 0 it only gives its lower bound), and rc::gen::weightedOneOf / rc::gen::element never shrink the
// choice itself, so a counterexample found in an exotic family stays exotic.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace circles::properties::detail {

// An integer uniform on [lo, hi] at every size, shrinking towards `target` (lo <= target <= hi).
template <class T>
rc::Gen<T> uniform(T lo, T hi, T target) {
  static_assert(std::is_integral_v<T> && sizeof(T) <= sizeof(std::uint64_t));
  return [=](const rc::Random& random, int /*size*/) {
    // Modular arithmetic on uint64 gives hi − lo exactly, for signed T too.
    const std::uint64_t width = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    std::uint64_t offset = rc::Random(random).next();
    if (width != UINT64_MAX) offset %= width + 1;
    const T value = static_cast<T>(static_cast<std::uint64_t>(lo) + offset);
    return rc::shrinkable::shrinkRecur(value, [target](T x) { return rc::shrink::towards<T>(x, target); });
  };
}

// false or true, each half the time; shrinks towards false.
inline rc::Gen<bool> coin() {
  return rc::gen::map(uniform<int>(0, 1, 0), [](int x) { return x == 1; });
}

// One of `choices`, picked with the given weights; the pick shrinks towards the first choice and then the
// value shrinks within its choice. So list the choices from the simplest to the most exotic.
template <class T>
rc::Gen<T> weighted_one_of(std::vector<std::pair<std::size_t, rc::Gen<T>>> choices) {
  std::vector<std::size_t> upper;  // upper[k]: the sum of the weights of choices 0..k
  std::vector<rc::Gen<T>> gens;
  std::size_t total = 0;
  for (auto& [weight, g] : choices) {
    total += weight;
    upper.push_back(total);
    gens.push_back(std::move(g));
  }
  rc::Gen<std::size_t> pick = [upper, total](const rc::Random& random, int /*size*/) {
    const std::size_t ticket = static_cast<std::size_t>(rc::Random(random).next() % total);
    const auto k = static_cast<std::size_t>(std::upper_bound(upper.begin(), upper.end(), ticket) - upper.begin());
    return rc::shrinkable::shrinkRecur(k, [](std::size_t x) { return rc::shrink::towards<std::size_t>(x, 0); });
  };
  return rc::gen::mapcat(pick, [gens](std::size_t k) { return gens[k]; });
}

// One of `values`, uniformly; shrinks towards values[0].
template <class T>
rc::Gen<T> element_of(std::vector<T> values) {
  return rc::gen::map(uniform<std::size_t>(0, values.size() - 1, 0), [values](std::size_t k) { return values[k]; });
}

// ±magnitude, each sign half the time; shrinks towards the positive sign (−0 towards +0).
template <class T>
rc::Gen<T> either_sign(rc::Gen<T> magnitude) {
  return rc::gen::apply([](bool negative, T x) { return negative ? T(-x) : x; }, coin(), std::move(magnitude));
}

}  // namespace circles::properties::detail
