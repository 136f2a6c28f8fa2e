#include "spec/rational.hpp"

#include <cmath>
#include <stdexcept>

namespace circles::spec {

Q exact(double x) {
  if (!std::isfinite(x)) throw std::domain_error("exact: " + std::to_string(x) + " is not a finite double");
  return Q(x);  // mpq_set_d: exact for every finite double
}

double nearest_double(const Q& q) {
  if (q == 0) return 0.0;
  const bool negative = q < 0;
  const Z n = abs(numerator(q));
  const Z d = denominator(q);

  // E = floor(log2(n/d)): first msb(n) − msb(d), then one lower if n/d < 2^E.
  long E = static_cast<long>(msb(n)) - static_cast<long>(msb(d));
  if ((E >= 0 ? n < (d << E) : (n << -E) < d)) --E;

  // binary64 keeps 53 significant bits: quantum 2^(E−52), but never below 2^-1074 (subnormals).
  if (E > 1023) return negative ? -HUGE_VAL : HUGE_VAL;
  const long s = std::max(E - 52, -1074L);

  // M = round(n / (d·2^s)) with ties to even; M ≤ 2^53, so it is exact as a double.
  const Z num = s < 0 ? Z(n << -s) : n;
  const Z den = s > 0 ? Z(d << s) : d;
  Z M, rem;
  divide_qr(num, den, M, rem);
  const int half = (rem * 2).compare(den);
  if (half > 0 || (half == 0 && bit_test(M, 0))) ++M;

  // ldexp is exact here, except that M·2^s ≥ 2^1024 (a carry out of the top binade) gives inf,
  // which is the correctly rounded result.
  const double magnitude = std::ldexp(M.convert_to<double>(), static_cast<int>(s));
  return negative ? -magnitude : magnitude;
}

std::string to_string(const Q& q) { return q.str(); }

}  // namespace circles::spec
