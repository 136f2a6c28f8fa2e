// Doubles of every kind, for the tests of the number text (tests/json_number_test.cpp) and of the trace lines
// written with it (tests/trace_writer_test.cpp).
#pragma once

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace circles::testing {

// Random bit patterns (every exponent), random values of a trace's magnitudes, and the edges: zeros,
// subnormals, the extremes, integers on both sides of where to_chars switches to the exponent. `random` of
// each random kind, always the same ones.
inline std::vector<double> doubles_of_every_kind(std::size_t random) {
  std::vector<double> xs = {0.0,  -0.0,  1.0,   -1.0,  0.1,     1e15,     1e16,    1e21, 1e22, 1e23,
                            123456789012345680000.0, 9007199254740993.0, 0.000001, 1e-7, 5e-324, -5e-324,
                            DBL_MIN, -DBL_MIN, DBL_MAX, -DBL_MAX, 2.2250738585072009e-308, 100.0, 60.0, 1.0 / 60};
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> trace(-10000, 10000);
  for (std::size_t i = 0; i < random; ++i) {
    const double x = std::bit_cast<double>(rng());
    if (std::isfinite(x)) xs.push_back(x);
    xs.push_back(trace(rng));
    xs.push_back(std::round(trace(rng)) * std::ldexp(1.0, static_cast<int>(rng() % 80)));  // integers
  }
  return xs;
}

}  // namespace circles::testing
