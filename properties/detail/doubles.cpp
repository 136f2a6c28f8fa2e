// The double families. Each builds its values from integers (bit patterns, numerators, exponents) so that
// it shrinks through those integers, towards the simplest member, instead of through rc::shrink::real.
#include "properties/detail/choice.hpp"
#include "properties/detail/families.hpp"

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>

namespace circles::properties::detail {

namespace {

constexpr std::uint64_t significand_mask = (std::uint64_t{1} << 52) - 1;

double from_bits(std::uint64_t bits) { return std::bit_cast<double>(bits); }

}  // namespace

rc::Gen<double> zero() { return either_sign(rc::gen::just(0.0)); }

rc::Gen<double> small_integer() {
  return either_sign(rc::gen::map(uniform<int>(0, 16, 0), [](int n) { return double(n); }));
}

rc::Gen<double> dyadic() {
  return either_sign(rc::gen::apply([](int n, int k) { return std::ldexp(double(n), -k); }, uniform<int>(1, 4096, 1),
                                    uniform<int>(1, 24, 1)));
}

rc::Gen<double> decimal() {
  return either_sign(rc::gen::apply(
      [](std::int64_t k, int d) {
        constexpr std::int64_t powers_of_ten[] = {1, 10, 100, 1000};
        const std::int64_t scale = powers_of_ten[d];
        // One correctly rounded division: the double nearest to k' / 10^d, k' = k mod (1000·10^d + 1) ≤ 1000·10^d.
        return double(k % (1000 * scale + 1)) / double(scale);
      },
      uniform<std::int64_t>(0, 1'000'000, 0), uniform<int>(0, 3, 0)));
}

rc::Gen<double> physics() {
  return either_sign(rc::gen::map(uniform<std::uint64_t>(0, std::uint64_t{1} << 53, 0), [](std::uint64_t u) {
    return std::ldexp(double(u), -53) * 1000.0;  // u ≤ 2^53 is exact as a double; one rounding, in the product
  }));
}

rc::Gen<double> edge() {
  // In increasing magnitude, so that a value shrinks towards the smaller boundaries.
  const double min_normal = DBL_MIN;
  const double denorm_min = std::numeric_limits<double>::denorm_min();
  return either_sign(element_of<double>({
      denorm_min,                       // 2^-1074, the least positive double
      2 * denorm_min,                   // 2^-1073
      min_normal - denorm_min,          // the largest subnormal
      min_normal,                       // DBL_MIN = 2^-1022, the least normal
      std::nextafter(min_normal, 1.0),  // the least normal but one
      DBL_EPSILON,                      // 2^-52
      1.0 / 60.0,                       // the double nearest Δt
      0.1,
      0.5,
      std::nextafter(1.0, 0.0),  // 1 − 2^-53
      1.0,
      std::nextafter(1.0, 2.0),  // 1 + 2^-52
      60.0,
      std::ldexp(1.0, 52),      // from here on every double is an integer
      std::ldexp(1.0, 53) - 1,  // the largest odd integer that is a double
      std::ldexp(1.0, 53),      // 2^53 + 1 is the first integer that is not
      std::ldexp(1.0, 53) + 2,
      std::nextafter(DBL_MAX, 0.0),
      DBL_MAX,
  }));
}

rc::Gen<double> subnormal() {
  return either_sign(rc::gen::map(uniform<std::uint64_t>(1, significand_mask, 1), from_bits));
}

rc::Gen<double> binade() {
  return either_sign(rc::gen::apply(
      [](int e, std::uint64_t m) {
        if (e >= -1022) return from_bits(std::uint64_t(e + 1023) << 52 | m);  // normal: 2^e · 1.m
        // Subnormal binade [2^e, 2^(e+1)): the significand has e + 1074 bits below its leading one.
        const int s = e + 1074;
        return from_bits(std::uint64_t{1} << s | (m & ((std::uint64_t{1} << s) - 1)));
      },
      uniform<int>(-1074, 1023, 0), uniform<std::uint64_t>(0, significand_mask, 0)));
}

rc::Gen<double> bit_pattern() {
  // Bit patterns of non-negative doubles are ordered as their values, so shrinking the pattern shrinks the value.
  return either_sign(rc::gen::map(uniform<std::uint64_t>(0, std::bit_cast<std::uint64_t>(DBL_MAX), 0), from_bits));
}

rc::Gen<double> near_max() {
  return either_sign(rc::gen::map(uniform<std::uint64_t>(0, std::uint64_t{1} << 20, 0), [](std::uint64_t k) {
    return from_bits(std::bit_cast<std::uint64_t>(DBL_MAX) - k);
  }));
}

}  // namespace circles::properties::detail
