// Exact integer views of doubles, shared by the exact fallbacks of the engines' kernels (predicate.cpp,
// rounding.cpp). Internal: not part of circles::impl's API.
#pragma once

#include <gmp.h>

#include <bit>
#include <cstdint>

namespace circles::impl::detail {

// x = m·2^e exactly, with m odd and |m| < 2^53; x = ±0 gives m = 0 (and e = 0, which means nothing).
// Odd m makes e as large as it can be, so integers built by shifting to a common least exponent stay small.
struct Dyadic {
  std::int64_t m;
  int e;
};

inline Dyadic dyadic(double x) noexcept {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  // |x| = m·2^(max(biased, 1) − 1075): subnormals (biased 0) have no hidden bit and the exponent of biased 1.
  const std::uint64_t m = biased == 0 ? fraction : fraction | std::uint64_t{1} << 52;
  if (m == 0) return {0, 0};
  const int zeros = std::countr_zero(m);
  const auto odd = static_cast<std::int64_t>(m >> zeros);
  return {bits >> 63 ? -odd : odd, (biased == 0 ? 1 : biased) - 1075 + zeros};
}

// An owned GMP integer. Kernels keep them thread_local as scratch, so a call allocates nothing once the
// limbs have grown.
class Mpz {
 public:
  Mpz() { mpz_init(z_); }
  ~Mpz() { mpz_clear(z_); }
  Mpz(const Mpz&) = delete;
  Mpz& operator=(const Mpz&) = delete;
  mpz_ptr get() noexcept { return z_; }

 private:
  mpz_t z_;
};

}  // namespace circles::impl::detail
