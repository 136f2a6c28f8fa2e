// RN(p + v/60) over binary64. The algorithm, its design and its proofs of every step are in docs/rounding.md,
// and the constants with their derivations in rounding.hpp and impl/double_bounds.hpp.
//
// Compiled with -ffp-contract=off: every + and * below is one IEEE operation, rounded once, and an FMA
// happens only where std::fma is written.
#include "impl/rounding.hpp"

#include "impl/detail/exact_int.hpp"
#include "impl/detail/steer.hpp"

#include <gmp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace circles::impl {

namespace {

using namespace rounding;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::uint64_t bits(double x) noexcept { return std::bit_cast<std::uint64_t>(x); }
double from_bits(std::uint64_t b) noexcept { return std::bit_cast<double>(b); }

// r = v − 60q, exact (docs/rounding.md, fast path step 1). The FMA-free form is exact only while 64q does
// not overflow; the fast path checks kRemainderGuard for that.
[[gnu::always_inline]] inline double remainder_of(double v, double q) noexcept {
#if defined(__FMA__)
  return std::fma(-q, kInverseDt, v);
#else
  return (v - kRemainderHigh * q) + kRemainderLow * q;
#endif
}

// B = RN(RN(a + 2^-1022)·2^-50) for a = RN(|e| + |c|). Written without a subnormal constant: an FMA or add
// with a subnormal operand takes a microcode assist on many x86 cores (measured here: an fma with addend
// 2^-1072 made the scalar fast path ~10x slower), while 2^-1022 is normal and the product is normal
// whenever a ≥ 2^-972.
[[gnu::always_inline]] inline double bound_of(double e, double c) noexcept {
  const double a = std::fabs(e) + std::fabs(c);
  return (a + kBoundOffset) * kBoundScale;
}

// What the fast path decided. y is the candidate; it is RN(x) when `certified` or `exact_sum` is 1.
// The flags are 0/1 integers of the width of a double, so that the batch loop keeps them in vector lanes.
struct Fast {
  double y;
  std::uint64_t certified;
  std::uint64_t exact_sum;
};

// The fast path, branch-free so that the batch loop vectorizes. Any overflow or NaN along the way makes f
// or y non-finite, and the certificate (an ordered compare) is then false; the r = 0 rule accepts only
// y = s, IEEE's own RN(p + q), which is then the answer (a NaN p with v = ±0 is the one non-finite case).
[[gnu::always_inline]] inline Fast fast_path(double p, double v) noexcept {
  const double q = v * kC;
  const double r = remainder_of(v, q);
#if defined(__FMA__)
  const bool remainder_ok = true;
#else
  const bool remainder_ok = std::fabs(v) <= kRemainderGuard;
#endif
  // TwoSum(p, q): s + e = p + q exactly.
  const double s = p + q;
  const double sp = s - p;
  const double e = (p - (s - sp)) + (q - sp);
  // t ≈ e + r/60 with |t − (e + r/60)| ≤ B.
  const double c = r * kC;
  const double t = e + c;
  const double B = bound_of(e, c);
  // TwoSum(s, t): y + f = s + t exactly, so |x − y| ≤ |f| + B.
  const double y = s + t;
  const double ys = y - s;
  const double f = (s - (y - ys)) + (t - ys);
  // G: the gap below |y| (the smaller of its two gaps), exact by Sterbenz; H = RN(G/2).
  // |y| = 0 gives G = NaN; |y| ≤ 2^-1021 gives H = 0; |y| = inf gives G = inf but then f is NaN.
  const double ay = std::fabs(y);
  const double G = ay - from_bits(bits(ay) - 1);
  const double H = 0.5 * G;
  detail::steer(std::fabs(f) + B, H);
  const bool certified = (std::fabs(f) + B < H) & remainder_ok;
  // r = 0: x = p + q, whose RN is s (ties, zero signs and overflow included); y = s unless s is inf.
  const bool exact_sum = (r == 0.0) & (bits(y) == bits(s)) & remainder_ok;
  return {y, std::uint64_t{certified}, std::uint64_t{exact_sum}};
}

// The fallback ladder, for inputs the fast path did not certify. Every rung is exact where it applies.
// std::fma is the correctly rounded libm fma when the build has no hardware FMA.
[[gnu::noinline]] double fallback(double p, double v, RoundingPath& path) noexcept {
  if (!std::isfinite(p) || !std::isfinite(v)) {
    path = RoundingPath::non_finite;
    return p + v / kInverseDt;
  }
  if (p == 0.0 && v == 0.0) {
    path = RoundingPath::zeros;
    return p + v;  // −0 only for (−0, −0)
  }
  const double q = v * kC;
  const double s = p + q;
  // |s| ≤ 2^-8|q|, decided exactly: dividing by 2^-8 is exact, or overflows to inf and fails.
  if (std::fabs(s) / kCancellationRatio <= std::fabs(q)) {
    path = RoundingPath::cancellation;
    const double r = std::fma(-q, kInverseDt, v);  // exact
    return std::fma(kInverseDt, s, r) / kInverseDt;  // the fma is exact; the division is the one rounding
  }
  const double g = std::fma(kInverseDt, p, v);
  if (std::fabs(g) < kTinyLimit) {
    path = RoundingPath::tiny;
    return g / kInverseDt;  // g = 60p + v exactly
  }
  path = RoundingPath::exact_integer;
  return exact_integer_round(p, v);
}

// binary64 format facts, from <limits>.
constexpr long kDigits = std::numeric_limits<double>::digits;                       // 53 significant bits
constexpr long kStoredBits = kDigits - 1;                                           // 52 of them stored
constexpr long kTopBinade = std::numeric_limits<double>::max_exponent - 1;          // 2^1023 ≤ DBL_MAX
constexpr long kQuantumExponent = std::numeric_limits<double>::min_exponent - kDigits;  // 2^-1074
static_assert(kStoredBits == 52 && kTopBinade == 1023 && kQuantumExponent == -1074);

// 60 = 2^2·15: the exact integer path shifts by the power of two and divides by the odd part, which has
// 4 bits (2^3 < 15 < 2^4).
constexpr long kInverseDtTwos = 2;
constexpr unsigned long kInverseDtOdd = 15;
constexpr long kInverseDtOddBits = 4;
static_assert((kInverseDtOdd << kInverseDtTwos) == 60 && kInverseDt == 60.0);
static_assert((1UL << (kInverseDtOddBits - 1)) < kInverseDtOdd && kInverseDtOdd < (1UL << kInverseDtOddBits));

// One full block of the batch form: a loop of constant trip count over restrict pointers with no FP-valued
// select (the result is chosen by integer masks on the bits), so GCC vectorizes it without versioning.
// A rejected element keeps its p and gets keep[j] = all ones. Returns the OR of the masks.
std::uint64_t fast_block(double* __restrict p, const double* __restrict v, std::uint64_t* __restrict keep) noexcept {
  std::uint64_t any = 0;
  for (std::size_t j = 0; j < kBatchBlock; ++j) {
    const Fast fast = fast_path(p[j], v[j]);
    const std::uint64_t mask = (fast.certified | fast.exact_sum) - 1;  // all ones when rejected
    p[j] = from_bits((bits(fast.y) & ~mask) | (bits(p[j]) & mask));
    keep[j] = mask;
    any |= mask;
  }
  return any;
}

}  // namespace

double advance_naive(double p, double v) noexcept { return p + v * kC; }

void advance_naive(std::span<double> p, std::span<const double> v) {
  if (p.size() != v.size()) throw std::invalid_argument("advance_naive: p and v differ in size");
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = p[i] + v[i] * kC;
}

double advance_rounded(double p, double v) noexcept {
  const Fast fast = fast_path(p, v);
  if ((fast.certified | fast.exact_sum) != 0) return fast.y;
  RoundingPath path;
  return fallback(p, v, path);
}

double advance_rounded_traced(double p, double v, RoundingPath& path) noexcept {
  const Fast fast = fast_path(p, v);
  if (fast.certified != 0) {
    path = RoundingPath::certified;
    return fast.y;
  }
  if (fast.exact_sum != 0) {
    path = RoundingPath::exact_sum;
    return fast.y;
  }
  return fallback(p, v, path);
}

void advance_rounded(std::span<double> p, std::span<const double> v) {
  if (p.size() != v.size()) throw std::invalid_argument("advance_rounded: p and v differ in size");
  const std::size_t n = p.size();
  const std::size_t whole = n - n % kBatchBlock;
  std::uint64_t keep[kBatchBlock];
  for (std::size_t base = 0; base < whole; base += kBatchBlock) {
    double* const pb = p.data() + base;
    const double* const vb = v.data() + base;
    if (fast_block(pb, vb, keep) != 0) {
      RoundingPath path;
      for (std::size_t j = 0; j < kBatchBlock; ++j)
        if (keep[j] != 0) pb[j] = fallback(pb[j], vb[j], path);
    }
  }
  for (std::size_t i = whole; i < n; ++i) p[i] = advance_rounded(p[i], v[i]);
}

std::string_view to_string(RoundingPath path) noexcept {
  switch (path) {
    case RoundingPath::certified: return "certified";
    case RoundingPath::exact_sum: return "exact_sum";
    case RoundingPath::non_finite: return "non_finite";
    case RoundingPath::zeros: return "zeros";
    case RoundingPath::cancellation: return "cancellation";
    case RoundingPath::tiny: return "tiny";
    case RoundingPath::exact_integer: return "exact_integer";
  }
  return "unknown";
}

namespace rounding {

bool uses_fma() noexcept {
#if defined(__FMA__)
  return true;
#else
  return false;
#endif
}

double exact_remainder(double v, double q) noexcept { return remainder_of(v, q); }

double certificate_bound(double e, double c) noexcept { return bound_of(e, c); }

// x = p + v/60 = N·2^E/60 = n·2^F/15 with n = |N|, F = E − 2 (60 = 2^2·15). Round n/15·2^F like a binary64
// operation: find k = ⌊log2 x⌋, the quantum 2^s with s = max(k − 52, −1074), then M = n·2^(F−s)/15 rounded
// to nearest-even by integer division with a remainder tie test; x' = ±M·2^s.
double exact_integer_round(double p, double v) noexcept {
  // A zero contributes nothing whatever its exponent, and every shift below stays non-negative.
  const detail::Dyadic a = detail::dyadic(p);
  const detail::Dyadic b = detail::dyadic(v);
  const long E = std::min(a.e, b.e);
  thread_local detail::Mpz n, t, d, quot, rem;  // per-thread scratch: reusing the limbs halves the cost of a call
  mpz_set_si(n.get(), a.m);
  mpz_mul_ui(n.get(), n.get(), kInverseDtOdd << kInverseDtTwos);
  mpz_mul_2exp(n.get(), n.get(), static_cast<mp_bitcnt_t>(a.e - E));
  mpz_set_si(t.get(), b.m);
  mpz_mul_2exp(t.get(), t.get(), static_cast<mp_bitcnt_t>(b.e - E));
  mpz_add(n.get(), n.get(), t.get());
  const int sign = mpz_sgn(n.get());
  if (sign == 0) return 0.0;
  mpz_abs(n.get(), n.get());
  const long F = E - kInverseDtTwos;

  // 2^(L−1) ≤ n < 2^L and 2^3 < 15 < 2^4, so 2^(L−5) < n/15 < 2^(L−3), and ⌊log2(n/15)⌋ is L − 4 exactly
  // when n·2^4 ≥ 15·2^L, else L − 5.
  const auto L = static_cast<long>(mpz_sizeinbase(n.get(), 2));
  mpz_mul_2exp(t.get(), n.get(), kInverseDtOddBits);
  mpz_set_ui(d.get(), kInverseDtOdd);
  mpz_mul_2exp(d.get(), d.get(), static_cast<mp_bitcnt_t>(L));
  const long k = F + L - kInverseDtOddBits - (mpz_cmp(t.get(), d.get()) >= 0 ? 0 : 1);
  if (k > kTopBinade) return sign < 0 ? -kInf : kInf;
  const long s = std::max(k - kStoredBits, kQuantumExponent);

  mpz_set_ui(d.get(), kInverseDtOdd);
  if (F >= s)
    mpz_mul_2exp(n.get(), n.get(), static_cast<mp_bitcnt_t>(F - s));
  else
    mpz_mul_2exp(d.get(), d.get(), static_cast<mp_bitcnt_t>(s - F));
  mpz_fdiv_qr(quot.get(), rem.get(), n.get(), d.get());
  mpz_mul_2exp(rem.get(), rem.get(), 1);
  const int half = mpz_cmp(rem.get(), d.get());
  if (half > 0 || (half == 0 && mpz_odd_p(quot.get()))) mpz_add_ui(quot.get(), quot.get(), 1);

  // M ≤ 2^53, so M is a double and M·2^s is exact, except that M·2^s = 2^1024 (a carry out of the top
  // binade) gives inf, the correctly rounded overflow. A zero M keeps the sign of x.
  const double M = static_cast<double>(mpz_get_ui(quot.get()));
  const double magnitude = std::ldexp(M, static_cast<int>(s));
  return sign < 0 ? -magnitude : magnitude;
}

}  // namespace rounding

}  // namespace circles::impl
