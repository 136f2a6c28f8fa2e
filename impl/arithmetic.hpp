// The arithmetic of an engine: its intersect test and its position update, as a policy type.
//
//   ExactArithmetic  intersect_exact (exact for every pair of finite doubles) and advance_rounded
//                    (RN(p + v/60), correctly rounded): the resolved oracle step, bit for bit.
//   NaiveArithmetic  intersect_naive ((ra + rb)² ≥ dx² + dy² in doubles) and advance_naive (p + v·RN(1/60)):
//                    what a plain engine does; it differs from the oracle near tangency and in the last bits.
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

#include "impl/predicate.hpp"
#include "impl/rounding.hpp"

#include <cmath>
#include <cstddef>
#include <span>

namespace circles::impl {

struct ExactArithmetic {
  static constexpr const char* name = "exact";
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    return intersect_exact(ax, ay, ar, bx, by, br);
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_rounded(p, v); }
};

struct NaiveArithmetic {
  static constexpr const char* name = "naive";
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    return intersect_naive(ax, ay, ar, bx, by, br);
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_naive(p, v); }
};

struct NaiveSqrtArithmetic {
  static constexpr const char* name = "naive sqrt";
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    const double dx = bx - ax;
    const double dy = by - ay;
    return std::sqrt(dx * dx + dy * dy) <= ar + br;
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_naive(p, v); }
};

struct FloatNaiveArithmetic {
  static constexpr const char* name = "float naive";
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
  static constexpr const char* name = "exact decisions";
  static bool intersect(double ax, double ay, double ar, double bx, double by, double br) {
    return intersect_exact(ax, ay, ar, bx, by, br);
  }
  static void advance(std::span<double> p, std::span<const double> v) { advance_naive(p, v); }
};

}  // namespace circles::impl
