// The exact numbers of the oracle: rationals Q, 2-vectors over Q, and the two exact bridges to binary64.
//
// The seed works over ℝ, but every quantity it ever computes from finite double inputs is rational:
// (3) compares a squared distance with a squared sum, (5) adds Δt·v with Δt = 1/60, and (6)-(9) only
// compare and copy. So Q loses nothing, and every decision the oracle makes is exact.
#pragma once

#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/gmp.hpp>
#include <Eigen/Core>

#include <string>

namespace circles::spec {

// Expression templates are off: Eigen's own expression templates already sit on top, and Boost's
// would hand Eigen unevaluated types it does not know.
using Q = boost::multiprecision::number<boost::multiprecision::gmp_rational, boost::multiprecision::et_off>;
using Z = boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

// A point or velocity of ℝ², held exactly.
using Vec2 = Eigen::Matrix<Q, 2, 1>;
// Eigen aligns a fixed-size matrix to as much as the instruction set's widest vector: 16 bytes for SSE, 32
// with AVX (-march=x86-64-v3, which the engines may be built with). A Vec2 is 64 bytes, so its alignment,
// and with it the layout of every Circle, would differ between a file built with AVX and one without, and a
// Circle passed between them would be read at the wrong offsets. circles::spec pins Eigen's alignment for
// every file that uses it (EIGEN_MAX_ALIGN_BYTES=16, spec/CMakeLists.txt); a file that includes this header
// without it, with AVX on, stops here instead of linking.
static_assert(alignof(Vec2) <= 16, "spec::Vec2's layout depends on the instruction set: build with "
                                   "EIGEN_MAX_ALIGN_BYTES=16, as the target circles::spec sets it");

// The exact value of a finite double. Every finite double is a dyadic rational, so this is exact.
// Throws std::domain_error for NaN and ±infinity, which have no value in Q.
Q exact(double x);

// RN(q): the double nearest to q, ties to even, as IEEE 754 round-to-nearest does.
// Magnitudes at or beyond 2^1024·(1 − 2^-54) round to ±infinity; results below the normal range are
// subnormals rounded at 2^-1074. An exact zero gives +0 (a rational has no sign of zero).
double nearest_double(const Q& q);

// "n/d" in lowest terms, or "n" when d = 1.
std::string to_string(const Q& q);

}  // namespace circles::spec
