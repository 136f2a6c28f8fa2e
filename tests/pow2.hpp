// 2^k as an exact rational, for the tests that write binary64's boundaries by hand (tests/rational_test.cpp,
// tests/equations_test.cpp): built from shifts of an integer, never from a double.
#pragma once

#include "spec/rational.hpp"

namespace circles::testing {

inline spec::Q pow2(long k) {
  using spec::Q, spec::Z;
  return k >= 0 ? Q(Z(1) << k) : Q(Z(1), Z(1) << -k);
}

}  // namespace circles::testing
