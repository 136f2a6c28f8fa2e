// The arithmetic of an engine: its intersect test and its position update, as a policy type.
//
//   ExactArithmetic  intersect_exact (exact for every pair of finite doubles) and advance_rounded
//                    (RN(p + v/60), correctly rounded): the resolved oracle step, bit for bit.
//   NaiveArithmetic  intersect_naive ((ra + rb)² ≥ dx² + dy² in doubles) and advance_naive (p + v·RN(1/60)):
//                    what a plain engine does; it differs from the oracle near tangency and in the last bits.
#pragma once

#include "impl/predicate.hpp"
#include "impl/rounding.hpp"

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

}  // namespace circles::impl
