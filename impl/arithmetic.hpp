// The arithmetic of an engine: its intersect test and its position update, as a policy type.
//
//   RoundedArithmetic  intersect_exact (exact for every pair of finite doubles) and advance_rounded
//                      (RN(p + v/60), correctly rounded): the resolved oracle step, bit for bit.
//   NaiveArithmetic    intersect_naive ((ra + rb)² ≥ dx² + dy² in doubles) and advance_naive (p + v·RN(1/60)):
//                      what a plain engine does; it differs from the oracle near tangency and in the last bits.
//
// Three more, for the accuracy benchmark only (bench/accuracy.cpp, docs/accuracy.md): the ways an engine is
// commonly written, run inside the same engine so that only the arithmetic differs. None is conformant.
//   NaiveSqrtArithmetic      √(dx² + dy²) ≤ ra + rb and p + v·RN(1/60), in doubles: the textbook step.
//   FloatNaiveArithmetic     the same in float. The engine's doubles hold floats: the caller rounds the input
//                            to float, each operation rounds to float, and a float converts to double exactly.
//   ExactDecisionArithmetic  intersect_exact and advance_naive: exact decisions on drifting positions.
// The broad phase is proven for the exact relation only (docs/engine.md): it offers the pairs in neighbouring
// cells, and a farther pair is never put to the test, even where a rounding test would call it touching.
#pragma once

#include "impl/pair_list.hpp"
#include "impl/predicate.hpp"
#include "impl/rounding.hpp"

#include <cmath>
#include <cstddef>
#include <span>

namespace circles::impl {

// Besides intersect and advance, each policy states two bounds for the pair list (impl/pair_list.hpp):
//   drift  per step, |advance(p, v) − p| ≤ |v|·kSpeedBound + |p′|·drift + kDriftAbsolute per coordinate, with
//          √2 folded in (the norm of the two coordinates' errors): √2·2^-53 rounded up for one double rounding
//          of the result (advance_naive's inexact 1/60 is below 1/60, so kSpeedBound covers it), √2·2^-24 for
//          a float rounding;
//   slack  how far beyond the exact relation, relative to the largest |coordinate| and radius, intersect may
//          call a pair touching: 0 for the exact test; for the naive tests a margin far above their few
//          roundings (2^-48 for doubles, 2^-20 for floats), so the list offers them every pair they would
//          test in a plain broad phase. Only the exact test is proven; the others are yardsticks.
struct RoundedArithmetic {
  static constexpr double drift = kDriftBound;
  static constexpr double slack = 0;
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    return intersect_exact(ax, ay, ar, bx, by, br);
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_rounded(p, v); }
};

struct NaiveArithmetic {
  static constexpr double drift = kDriftBound;
  static constexpr double slack = 0x1p-48;
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    return intersect_naive(ax, ay, ar, bx, by, br);
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_naive(p, v); }
};

struct NaiveSqrtArithmetic {
  static constexpr double drift = kDriftBound;
  static constexpr double slack = 0x1p-48;
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    const double dx = bx - ax;
    const double dy = by - ay;
    return std::sqrt(dx * dx + dy * dy) <= ar + br;
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_naive(p, v); }
};

struct FloatNaiveArithmetic {
  static constexpr double drift = 0x1.6a1p-24;
  static constexpr double slack = 0x1p-20;
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    const float dx = static_cast<float>(bx) - static_cast<float>(ax);
    const float dy = static_cast<float>(by) - static_cast<float>(ay);
    return std::sqrt(dx * dx + dy * dy) <= static_cast<float>(ar) + static_cast<float>(br);
  }
  // p + v·RN_float(1/60), two float roundings; an overflow gives ±inf, which the engine reports.
  static void advance(std::span<double> p, std::span<const double> v) {
    constexpr float dt = 1.0f / 60.0f;
    for (std::size_t i = 0; i < p.size(); ++i)
      p[i] = static_cast<double>(static_cast<float>(p[i]) + static_cast<float>(v[i]) * dt);
  }
};

struct ExactDecisionArithmetic {
  static constexpr double drift = kDriftBound;
  static constexpr double slack = 0;
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    return intersect_exact(ax, ay, ar, bx, by, br);
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_naive(p, v); }
};

}  // namespace circles::impl
