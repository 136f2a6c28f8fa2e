// impl/rounding: RN(p + v/60) against the exact oracle, spec::nearest_double(exact(p) + exact(v)/60).
//
// Inputs come from the input classes of docs/rounding.md (random bits, related exponents,
// physics-like, close magnitudes, near midpoints, exact ties, p ≈ −v/60, subnormals, near DBL_MAX, zeros,
// small integers, exponent gaps), drawn from fixed-seed std::mt19937_64 streams and, where a class needs
// an exact property (a tie, a distance from a midpoint), constructed exactly with rationals.
#include "impl/rounding.hpp"
#include "spec/rational.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using circles::impl::advance_naive;
using circles::impl::advance_rounded;
using circles::impl::advance_rounded_traced;
using circles::impl::kRoundingPathCount;
using circles::impl::RoundingPath;
using circles::spec::exact;
using circles::spec::nearest_double;
using circles::spec::Q;
using circles::spec::Z;
namespace rounding = circles::impl::rounding;

using Rng = std::mt19937_64;
using Input = std::pair<double, double>;

constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kMin = std::numeric_limits<double>::min();
constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// 2^k as an exact rational, for any integer k.
Q pow2(long k) {
  Z one = 1;
  return k >= 0 ? Q(Z(one << static_cast<unsigned>(k))) : Q(Z(1), Z(one << static_cast<unsigned>(-k)));
}
const Q u = pow2(-53);
const Q eta = pow2(-1075);

// The oracle: RN of the exact x' = p + v/60.
double oracle(double p, double v) { return nearest_double(exact(p) + exact(v) / 60); }

// What advance_rounded promises: the oracle, except that (−0, −0) gives −0 (IEEE), where the oracle's
// rational zero gives +0.
bool is_negative_zero_pair(double p, double v) {
  return p == 0 && v == 0 && std::signbit(p) && std::signbit(v);
}
double expected(double p, double v) { return is_negative_zero_pair(p, v) ? -0.0 : oracle(p, v); }

// ── Random doubles ───────────────────────────────────────────────────────────────────────────────────

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
long integer(Rng& rng, long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }
bool coin(Rng& rng) { return (rng() & 1U) != 0; }
double sign(Rng& rng) { return coin(rng) ? -1.0 : 1.0; }

// Any finite double, every bit pattern equally likely.
double any_bits(Rng& rng) {
  for (;;) {
    const double x = std::bit_cast<double>(rng());
    if (std::isfinite(x)) return x;
  }
}

// ±m·2^e with m uniform over the 2^52 significands in [1, 2); below the normal range ldexp rounds it to a
// subnormal, which is still a double of about that size.
double with_exponent(Rng& rng, long e) {
  const double m = 1.0 + static_cast<double>(rng() >> 12) * 0x1p-52;
  return sign(rng) * std::ldexp(m, static_cast<int>(e));
}

// A random subnormal (exponent field 0, nonzero significand).
double subnormal(Rng& rng) {
  for (;;) {
    const double x = std::bit_cast<double>(rng() & 0x800f'ffff'ffff'ffffULL);
    if (x != 0) return x;
  }
}

// The exact midpoint between y and its neighbour toward +inf.
Q midpoint_above(double y) { return (exact(y) + exact(std::nextafter(y, kInf))) / 2; }

// |x − m|/gap for x = p + v/60 exactly, where m is the midpoint of the two doubles around x and gap their
// distance (for finite x within the double range).
Q midpoint_distance(double p, double v) {
  const Q x = exact(p) + exact(v) / 60;
  double y = nearest_double(x);  // then y: the double at or below x
  if (exact(y) > x) y = std::nextafter(y, -kInf);
  const Q gap = exact(std::nextafter(y, kInf)) - exact(y);
  return abs(x - midpoint_above(y)) / gap;
}

// ── The input classes ────────────────────────────────────────────────────────────────────────────────

struct InputClass {
  std::string name;
  int count;
  std::function<Input(Rng&)> draw;
};

std::vector<InputClass> input_classes() {
  return {
      {"R1 random bit patterns", 40000, [](Rng& rng) { return Input{any_bits(rng), any_bits(rng)}; }},
      {"R2 related exponents", 40000,
       [](Rng& rng) {
         const long e = integer(rng, -1074, 1023);
         return Input{with_exponent(rng, e), with_exponent(rng, std::min(1023L, e + integer(rng, -60, 66)))};
       }},
      {"R3 physics-like", 40000,
       [](Rng& rng) { return Input{uniform(rng, -1e3, 1e3), uniform(rng, -1e2, 1e2)}; }},
      {"R4 close magnitudes", 30000,
       [](Rng& rng) {
         const double p = with_exponent(rng, integer(rng, -100, 100));
         const double delta = uniform(rng, -1, 1) * std::ldexp(1.0, static_cast<int>(-integer(rng, 0, 30)));
         return Input{p, sign(rng) * 60 * std::fabs(p) * (1 + delta)};
       }},
      {"A1 within 2^-40..2^-60 ulp of a midpoint", 30000,
       [](Rng& rng) {
         for (;;) {
           const double y = with_exponent(rng, integer(rng, -900, 1000));  // p stays normal
           const Q mid = midpoint_above(y);
           const Q gap = exact(std::nextafter(y, kInf)) - exact(y);
           Input in;
           if (coin(rng)) {
             // p = y carries x and v/60 = gap·(1/2 ± i·2^-47/60): v = gap·(30·2^47 ± i)·2^-47 is a double, and
             // x lies exactly i·2^-47/60 ∈ [2^-53, 2^-40] gaps from the midpoint.
             const double i = std::round(std::exp2(uniform(rng, 0, std::log2(7680.0))));
             const double gap_d = std::nextafter(y, kInf) - y;
             in = Input{y, gap_d * ((0x1p47 * 30 + sign(rng) * i) * 0x1p-47)};
           } else {
             // v/60 carries x, p = RN(mid − v/60 + δ) with δ = ±2^-k gaps, k ∈ [40, 60]: x is within
             // |δ| + ulp(p)/2 ≤ |δ| + 2^-54 gaps of the midpoint (the test measures it exactly).
             const double v = nearest_double(mid * 60);
             const Q delta = gap * pow2(-integer(rng, 40, 60)) * (coin(rng) ? -1 : 1);
             in = Input{nearest_double(mid + delta - exact(v) / 60), v};
           }
           if (midpoint_distance(in.first, in.second) != 0) return in;  // not an exact tie
         }
       }},
      {"A2 exact ties", 20000,
       [](Rng& rng) {
         const long odd = 2 * integer(rng, 0, 1L << 19) + 1;
         switch (integer(rng, 0, 3)) {
           case 0: {  // p ± odd·ulp(p)/2
             const double p = with_exponent(rng, integer(rng, -1000, 1000));
             const double ulp = std::nextafter(std::fabs(p), kInf) - std::fabs(p);
             return Input{p, sign(rng) * 30 * static_cast<double>(odd) * ulp};
           }
           case 1: {  // 2^53 + odd, scaled: the 2^53 + 1 family
             const int j = static_cast<int>(integer(rng, -1000, 900));
             return Input{sign(rng) * std::ldexp(0x1p53, j), sign(rng) * std::ldexp(60.0 * static_cast<double>(odd), j)};
           }
           case 2: {  // subnormal ties: x = (2k ± odd)·2^-1075
             const double p = static_cast<double>(integer(rng, -1L << 20, 1L << 20)) * kDenormMin;
             return Input{p, sign(rng) * 15 * static_cast<double>(odd) * 0x1p-1073};
           }
           default: {  // the overflow tie 2^1024 − 2^970 and its neighbours
             const double p = sign(rng) * (kMax - static_cast<double>(integer(rng, 0, 4)) * 0x1p971);
             return Input{p, std::copysign(60.0 * static_cast<double>(integer(rng, 0, 4)) * 0x1p969, p)};
           }
         }
       }},
      {"A3 p close to -v/60", 30000,
       [](Rng& rng) {
         const double v = with_exponent(rng, integer(rng, -1000, 1020));
         if (integer(rng, 0, 9) == 0) {  // x = 0 exactly: v = 60w with w of at most 47 bits
           const double w = std::ldexp(std::round(std::ldexp(std::fabs(v), -1 - std::ilogb(v) + 47)),
                                       std::ilogb(v) - 53);
           return Input{-std::copysign(w, v), std::copysign(60 * w, v)};
         }
         double p = -v * rounding::kC;
         for (long k = integer(rng, -8, 8); k != 0; k += k < 0 ? 1 : -1)
           p = std::nextafter(p, k < 0 ? -kInf : kInf);
         return Input{p, v};
       }},
      {"A4 subnormal", 30000,
       [](Rng& rng) {
         const auto tiny = [&rng] {
           return coin(rng) ? subnormal(rng) : with_exponent(rng, integer(rng, -1022, -1000));
         };
         return Input{tiny(), tiny()};
       }},
      {"A5 near DBL_MAX and overflow", 20000,
       [](Rng& rng) {
         const double p = with_exponent(rng, 1023 - integer(rng, 0, 3));
         if (coin(rng)) return Input{p, sign(rng) * uniform(rng, 0.93, 1.0) * kMax};  // around the guard
         return Input{p, with_exponent(rng, 1023 - integer(rng, 0, 8))};
       }},
      {"A6 signed zeros", 10000,
       [](Rng& rng) {
         const double zero = coin(rng) ? -0.0 : 0.0;
         double other = 0;
         switch (integer(rng, 0, 3)) {
           case 0: other = any_bits(rng); break;
           case 1: other = subnormal(rng); break;
           case 2: other = coin(rng) ? -0.0 : 0.0; break;
           default: other = with_exponent(rng, integer(rng, -1074, 1023)); break;
         }
         return coin(rng) ? Input{zero, other} : Input{other, zero};
       }},
      {"A7 small integers", 20000,
       [](Rng& rng) {
         const double p = static_cast<double>(integer(rng, -1000, 1000));
         const long v = coin(rng) ? 60 * integer(rng, -200, 200) : integer(rng, -10000, 10000);
         return Input{p, static_cast<double>(v)};
       }},
      {"A8 exponent gaps 50..2100", 20000,
       [](Rng& rng) {
         const long gap = integer(rng, 50, 2100);
         const long lo = integer(rng, -1074, std::max(-1074L, 1023 - gap));
         const long hi = std::min(1023L, lo + gap);
         const double small = with_exponent(rng, lo);
         const double large = with_exponent(rng, hi);
         return coin(rng) ? Input{small, large} : Input{large, small};
       }},
  };
}

struct DrawnClass {
  std::string name;
  std::vector<Input> inputs;
  std::vector<double> expect;  // filled by oracle_classes() only
};

// Every class drawn once, shared by the tests below.
const std::vector<DrawnClass>& drawn_classes() {
  static const std::vector<DrawnClass> drawn = [] {
    std::vector<DrawnClass> out;
    std::uint64_t seed = 0x5eed'0060'c1c1'e500ULL;
    for (const InputClass& c : input_classes()) {
      Rng rng(seed++);
      DrawnClass d{c.name, {}, {}};
      for (int i = 0; i < c.count; ++i) d.inputs.push_back(c.draw(rng));
      out.push_back(std::move(d));
    }
    return out;
  }();
  return drawn;
}

// The same classes with the oracle's answers, the expensive part: computed once, for the tests that need it.
const std::vector<DrawnClass>& oracle_classes() {
  static const std::vector<DrawnClass> with_oracle = [] {
    std::vector<DrawnClass> out = drawn_classes();
    for (DrawnClass& d : out)
      for (const auto& [p, v] : d.inputs) d.expect.push_back(expected(p, v));
    return out;
  }();
  return with_oracle;
}

std::string describe(double p, double v) {
  std::ostringstream s;
  s << std::hexfloat << "p = " << p << ", v = " << v;
  return s.str();
}

// ── Constants ────────────────────────────────────────────────────────────────────────────────────────

TEST(rounding_constants, c_is_the_double_nearest_to_one_sixtieth_with_error_u_over_eight) {
  const Q sixtieth(1, 60);
  EXPECT_EQ(rounding::kC, nearest_double(sixtieth));
  EXPECT_EQ(rounding::kC, 1.0 / 60.0);
  const Q error = sixtieth - exact(rounding::kC);
  EXPECT_EQ(error, pow2(-58) / 15);              // = (16/15)·2^-62 ≈ 1.07·2^-62, and C < 1/60
  EXPECT_EQ(error / sixtieth, u / 8);            // relative error exactly 2^-56 = u/8
  EXPECT_EQ(rounding::kInverseDt, 60.0);
  EXPECT_EQ(rounding::kRemainderHigh - rounding::kRemainderLow, rounding::kInverseDt);
  EXPECT_EQ(rounding::kRemainderHigh, 0x1p6);
  EXPECT_EQ(rounding::kRemainderLow, 0x1p2);
}

TEST(rounding_constants, the_remainder_guard_keeps_sixty_four_q_finite) {
  const double g = rounding::kRemainderGuard;
  EXPECT_EQ(exact(g), nearest_double(exact(0.93) * exact(kMax)));
  // RN is monotone, so |v| ≤ g gives |q| ≤ RN(g·C), and 64 times that is a finite double.
  const double q_max = g * rounding::kC;
  EXPECT_LE(exact(q_max) * 64, exact(kMax));
  EXPECT_TRUE(std::isfinite(64 * q_max));
  // The exact threshold: 64·RN(v·C) first overflows near 0.9375·2^1024; the guard sits below it.
  EXPECT_LT(exact(g), pow2(1024) * Q(15, 16) * (1 - 2 * u));
}

TEST(rounding_constants, the_certificate_constants_are_eight_u_and_eight_eta) {
  EXPECT_EQ(exact(rounding::kBoundScale), 8 * u);
  EXPECT_EQ(rounding::kBoundOffset, kMin);  // the smallest normal: no subnormal operand in the bound
  EXPECT_EQ(exact(rounding::kBoundOffset) * exact(rounding::kBoundScale), 8 * eta);
  // The chain of the derivation: 8u(1 − u)² ≥ 7.9u and 8η(1 − u) − η ≥ 3η.
  EXPECT_GE(8 * u * (1 - u) * (1 - u), Q(79, 10) * u);
  EXPECT_GE(8 * eta * (1 - u) - eta, 3 * eta);
}

TEST(rounding_constants, the_cancellation_ratio_makes_sterbenz_apply_and_sixty_s_plus_r_fit) {
  const Q ratio = exact(rounding::kCancellationRatio);
  EXPECT_EQ(ratio, pow2(-8));
  // |p + q| ≤ ratio·|q|·(1 + u) puts p/(−q) within [1/2, 2].
  EXPECT_GE(1 - ratio * (1 + u), Q(1, 2));
  EXPECT_LE(1 + ratio * (1 + u), Q(2));
  // With |q| < 2^(k+1) and |r| < 2^7·ulp(q) = 2^(k−45): |60s + r| < 2^k, in units of 2^k.
  EXPECT_LT(60 * ratio * (1 + u) * 2 + pow2(-45), Q(1));
}

TEST(rounding_constants, the_tiny_limit_is_two_to_the_fifty_three_subnormal_quanta) {
  EXPECT_EQ(rounding::kTinyLimit, std::ldexp(kDenormMin, 53));
  EXPECT_EQ(rounding::kTinyLimit, 2 * kMin);
  // Every multiple of 2^-1074 below the limit is a double: the spacing there is 2^-1074.
  EXPECT_EQ(rounding::kTinyLimit - std::nextafter(rounding::kTinyLimit, 0.0), kDenormMin);
}

TEST(rounding_build, the_library_and_this_test_agree_on_fma) {
#if defined(__FMA__)
  constexpr bool test_has_fma = true;
#else
  constexpr bool test_has_fma = false;
#endif
  EXPECT_EQ(rounding::uses_fma(), test_has_fma);
  std::cout << "[          ] fast path built " << (rounding::uses_fma() ? "with" : "without") << " FMA\n";
}

// ── The pieces ───────────────────────────────────────────────────────────────────────────────────────

TEST(advance_rounded, the_remainder_v_minus_sixty_q_is_exact_on_every_class) {
  long checked = 0;
  for (const DrawnClass& c : drawn_classes())
    for (const auto& [p, v] : c.inputs) {
      if (!rounding::uses_fma() && !(std::fabs(v) <= rounding::kRemainderGuard)) continue;
      const double q = v * rounding::kC;
      const double r = rounding::exact_remainder(v, q);
      ASSERT_EQ(exact(r), exact(v) - 60 * exact(q)) << describe(p, v);
      // and |r| < 2^7·ulp(q) (or a small multiple of 2^-1074)
      const double ulp_q = std::nextafter(std::fabs(q), kInf) - std::fabs(q);
      ASSERT_LT(std::fabs(r), 128 * std::max(ulp_q, kDenormMin)) << describe(p, v);
      ++checked;
    }
  EXPECT_GT(checked, 300000);
}

TEST(advance_rounded, the_certificate_bound_covers_the_error_of_t_with_its_margin) {
  Rng rng(0xB0B0'0001ULL);
  long checked = 0;
  for (int i = 0; i < 50000; ++i) {
    // |e| and |c| across the whole range, including subnormals and zero.
    const auto draw = [&rng]() -> double {
      switch (integer(rng, 0, 3)) {
        case 0: return subnormal(rng);
        case 1: return 0.0;
        default: return with_exponent(rng, integer(rng, -1074, 1000));
      }
    };
    const double e = draw();
    const double c = draw();
    const Q a = abs(exact(e)) + abs(exact(c));
    const Q B = exact(rounding::certificate_bound(e, c));
    ASSERT_GE(B, Q(79, 10) * u * a + 3 * eta) << describe(e, c);
    ASSERT_GE(B, 3 * u * a + 2 * eta);
    ++checked;
  }
  EXPECT_EQ(checked, 50000);
}

TEST(advance_rounded, near_midpoint_inputs_lie_within_two_to_the_minus_forty_gaps_of_a_midpoint) {
  const DrawnClass& a1 = drawn_classes()[4];
  ASSERT_TRUE(a1.name.starts_with("A1"));
  long below_2_53 = 0;
  Q closest = 1;
  for (const auto& [p, v] : a1.inputs) {
    const Q distance = midpoint_distance(p, v);
    ASSERT_LE(distance, pow2(-40) + pow2(-54)) << describe(p, v);
    ASSERT_GT(distance, 0) << describe(p, v);
    if (distance < pow2(-53)) ++below_2_53;
    closest = std::min(closest, distance);
  }
  std::cout << "[          ] A1: " << below_2_53 << " inputs closer than 2^-53 gap to a midpoint; closest 2^"
            << std::log2(closest.convert_to<double>()) << "\n";
  EXPECT_GT(below_2_53, 1000);
}

// ── Correct rounding ─────────────────────────────────────────────────────────────────────────────────

TEST(advance_rounded, agrees_bitwise_with_the_oracle_on_every_input_class) {
  std::array<long, kRoundingPathCount> total{};
  long cases = 0;
  long mismatches = 0;
  std::cout << "[          ] " << std::left << std::setw(42) << "class" << std::right;
  for (int k = 0; k < kRoundingPathCount; ++k)
    std::cout << std::setw(14) << to_string(static_cast<RoundingPath>(k));
  std::cout << "\n";
  for (const DrawnClass& c : oracle_classes()) {
    std::array<long, kRoundingPathCount> count{};
    for (std::size_t i = 0; i < c.inputs.size(); ++i) {
      const auto [p, v] = c.inputs[i];
      RoundingPath path{};
      const double traced = advance_rounded_traced(p, v, path);
      const double x = advance_rounded(p, v);
      ++count[static_cast<std::size_t>(path)];
      ++cases;
      if (bits(x) != bits(c.expect[i]) || bits(traced) != bits(x)) {
        ++mismatches;
        ADD_FAILURE() << c.name << ": " << describe(p, v) << std::hexfloat << ": got " << x << " (traced "
                      << traced << ", " << to_string(path) << "), want " << c.expect[i];
      }
    }
    std::cout << "[          ] " << std::left << std::setw(42) << c.name << std::right;
    for (int k = 0; k < kRoundingPathCount; ++k) {
      std::cout << std::setw(14) << count[static_cast<std::size_t>(k)];
      total[static_cast<std::size_t>(k)] += count[static_cast<std::size_t>(k)];
    }
    std::cout << "\n";
  }
  std::cout << "[          ] " << std::left << std::setw(42) << "total" << std::right;
  for (int k = 0; k < kRoundingPathCount; ++k) std::cout << std::setw(14) << total[static_cast<std::size_t>(k)];
  std::cout << "\n[          ] " << cases << " cases, " << mismatches << " mismatches\n";
  EXPECT_EQ(mismatches, 0);
  // Every rung of the ladder was reached, so every one was checked above.
  for (int k = 0; k < kRoundingPathCount; ++k)
    if (static_cast<RoundingPath>(k) != RoundingPath::non_finite) {
      EXPECT_GT(total[static_cast<std::size_t>(k)], 0) << to_string(static_cast<RoundingPath>(k));
    }
}

TEST(advance_rounded, the_exact_integer_rung_alone_agrees_with_the_oracle) {
  long checked = 0;
  for (const DrawnClass& c : oracle_classes())
    for (std::size_t i = 0; i < c.inputs.size(); i += 7) {
      const auto [p, v] = c.inputs[i];
      if (is_negative_zero_pair(p, v)) continue;
      ASSERT_EQ(bits(rounding::exact_integer_round(p, v)), bits(c.expect[i])) << c.name << ": " << describe(p, v);
      ++checked;
    }
  EXPECT_GT(checked, 40000);
}

TEST(advance_rounded, exact_ties_round_to_even) {
  EXPECT_EQ(advance_rounded(0x1p53, 60), 0x1p53);             // 2^53 + 1 → 2^53
  EXPECT_EQ(advance_rounded(0x1p53, 180), 0x1p53 + 4);        // 2^53 + 3 → 2^53 + 4
  EXPECT_EQ(advance_rounded(-0x1p53, -60), -0x1p53);
  EXPECT_EQ(advance_rounded(1.0, 60 * 0x1p-53), 1.0);         // 1 + 2^-53 → 1
  EXPECT_EQ(advance_rounded(1.0, 180 * 0x1p-53), 1 + 0x1p-51);  // 1 + 3·2^-53 → 1 + 2^-51
  EXPECT_EQ(advance_rounded(0.0, 30 * kDenormMin), 0.0);      // 2^-1075 → 0 (even)
  EXPECT_EQ(advance_rounded(0.0, 90 * kDenormMin), 2 * kDenormMin);  // 3·2^-1075 → 2·2^-1074
  EXPECT_EQ(advance_rounded(kDenormMin, 30 * kDenormMin), 2 * kDenormMin);  // 3·2^-1075
  // docs/rounding.md, step 6: a tie is taken by the r = 0 rule, never by the certificate, whose |f| is at least
  // half a gap. At p = 2^53, v = 60: q = 1, r = 0, (s, e) = TwoSum(2^53, 1) = (2^53, 1), t = e, and
  // (y, f) = TwoSum(s, t) = (2^53, 1); the gap below y is G = 1, so |f| = G, twice H = G/2.
  RoundingPath path{};
  EXPECT_EQ(advance_rounded_traced(0x1p53, 60, path), 0x1p53);
  EXPECT_EQ(path, RoundingPath::exact_sum);
  const double q = 60 * rounding::kC;
  ASSERT_EQ(q, 1.0);
  ASSERT_EQ(rounding::exact_remainder(60, q), 0.0);
  const double y = 0x1p53 + q, f = (0x1p53 - y) + q;  // TwoSum(2^53, 1) with |2^53| ≥ |1|: Fast2Sum is exact
  const double G = y - std::nextafter(y, 0.0);
  EXPECT_EQ(y, 0x1p53);
  EXPECT_EQ(G, 1.0);
  EXPECT_EQ(std::fabs(f), G);
}

TEST(advance_rounded, zero_results_follow_the_sign_convention) {
  const auto is_pos_zero = [](double x) { return x == 0 && !std::signbit(x); };
  const auto is_neg_zero = [](double x) { return x == 0 && std::signbit(x); };
  // (−0, −0) → −0, as IEEE; every other exact zero → +0.
  EXPECT_TRUE(is_neg_zero(advance_rounded(-0.0, -0.0)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(-0.0, 0.0)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(0.0, -0.0)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(0.0, 0.0)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(1.0, -60.0)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(-1.0, 60.0)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(kDenormMin, -60 * kDenormMin)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(-0x1p1000, 60 * 0x1p1000)));
  // A nonzero x' that underflows keeps the sign of x'.
  EXPECT_TRUE(is_neg_zero(advance_rounded(0.0, -kDenormMin)));
  EXPECT_TRUE(is_neg_zero(advance_rounded(-0.0, -kDenormMin)));
  EXPECT_TRUE(is_pos_zero(advance_rounded(-0.0, kDenormMin)));
  EXPECT_TRUE(is_neg_zero(advance_rounded(-kDenormMin, 59 * kDenormMin)));
  // And by value, over every class: a zero result is a zero of the oracle, and its sign is the sign of the
  // exact x' when x' ≠ 0, + when x' = 0, − only for (−0, −0).
  long zeros = 0;
  for (const DrawnClass& c : drawn_classes())
    for (const auto& [p, v] : c.inputs) {
      const double x = advance_rounded(p, v);
      if (x != 0) continue;
      ++zeros;
      const Q exact_x = exact(p) + exact(v) / 60;
      ASSERT_EQ(nearest_double(exact_x), 0.0) << describe(p, v);
      const bool negative = exact_x < 0 || (exact_x == 0 && is_negative_zero_pair(p, v));
      ASSERT_EQ(std::signbit(x), negative) << describe(p, v);
    }
  EXPECT_GT(zeros, 1000);
}

TEST(advance_rounded, overflowing_results_are_infinite_with_the_sign_of_x) {
  EXPECT_EQ(advance_rounded(kMax, 60 * 0x1p970), kInf);    // the tie 2^1024 − 2^970 rounds up (to even)
  EXPECT_EQ(advance_rounded(kMax, 60 * 0x1p969), kMax);
  EXPECT_EQ(advance_rounded(-kMax, -60 * 0x1p970), -kInf);
  EXPECT_EQ(advance_rounded(-kMax, -kMax), -kInf);
  EXPECT_EQ(advance_rounded(kMax, kMax), kInf);
  EXPECT_EQ(advance_rounded(kMax, -kMax), nearest_double(exact(kMax) * Q(59, 60)));
  EXPECT_EQ(advance_rounded(0.0, kMax), nearest_double(exact(kMax) / 60));
}

TEST(advance_rounded, non_finite_inputs_give_what_ieee_p_plus_v_over_sixty_gives) {
  const double values[] = {kInf, -kInf, kNaN, 0.0, -0.0, 1.0, -kMax, kDenormMin};
  for (double p : values)
    for (double v : values) {
      if (std::isfinite(p) && std::isfinite(v)) continue;
      const double want = p + v / 60.0;
      const double got = advance_rounded(p, v);
      if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(got)) << describe(p, v);
      } else {
        EXPECT_EQ(bits(got), bits(want)) << describe(p, v);
      }
      // The ladder's first rung, except that a NaN p with v = ±0 (r = 0) is already exact in the fast path:
      // s = p + q is IEEE's NaN, and y = s.
      RoundingPath path{};
      advance_rounded_traced(p, v, path);
      if (std::isnan(p) && v == 0) {
        EXPECT_EQ(path, RoundingPath::exact_sum) << describe(p, v);
      } else {
        EXPECT_EQ(path, RoundingPath::non_finite) << describe(p, v);
      }
    }
}

// ── The batch form ───────────────────────────────────────────────────────────────────────────────────

TEST(advance_rounded, the_batch_form_matches_the_scalar_form_bit_for_bit) {
  std::vector<double> p;
  std::vector<double> v;
  for (const DrawnClass& c : drawn_classes())
    for (const auto& [pi, vi] : c.inputs) {
      p.push_back(pi);
      v.push_back(vi);
    }
  // Interleave classes so that blocks mix accepted and rejected elements.
  Rng rng(0xBA7C'0001ULL);
  for (std::size_t i = p.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng() % i);
    std::swap(p[i - 1], p[j]);
    std::swap(v[i - 1], v[j]);
  }
  p.push_back(kInf);
  v.push_back(1.0);
  p.push_back(-0.0);
  v.push_back(-0.0);
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{255}, std::size_t{256}, std::size_t{257},
                        std::size_t{1000}, p.size()}) {
    std::vector<double> batch(p.end() - static_cast<std::ptrdiff_t>(n), p.end());
    const std::span<const double> vs(v.data() + (v.size() - n), n);
    advance_rounded(std::span<double>(batch), vs);
    long mismatches = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double want = advance_rounded(p[p.size() - n + i], vs[i]);
      if (bits(batch[i]) != bits(want) && !(std::isnan(batch[i]) && std::isnan(want))) ++mismatches;
    }
    EXPECT_EQ(mismatches, 0) << "n = " << n;
  }
  std::vector<double> naive(p.begin(), p.begin() + 1000);
  advance_naive(std::span<double>(naive), std::span<const double>(v.data(), 1000));
  for (std::size_t i = 0; i < 1000; ++i) EXPECT_EQ(bits(naive[i]), bits(advance_naive(p[i], v[i])));
}

TEST(advance_rounded, the_batch_forms_reject_spans_of_different_sizes) {
  std::vector<double> p(3, 1.0);
  const std::vector<double> v(2, 1.0);
  EXPECT_THROW(advance_rounded(std::span<double>(p), std::span<const double>(v)), std::invalid_argument);
  EXPECT_THROW(advance_naive(std::span<double>(p), std::span<const double>(v)), std::invalid_argument);
}

// ── The naive tier ───────────────────────────────────────────────────────────────────────────────────

TEST(advance_naive, is_not_correctly_rounded) {
  long all_mismatches = 0;
  for (const DrawnClass& c : oracle_classes()) {
    long mismatches = 0;
    for (std::size_t i = 0; i < c.inputs.size(); ++i) {
      const auto [p, v] = c.inputs[i];
      if (bits(advance_naive(p, v)) != bits(c.expect[i])) ++mismatches;
    }
    std::cout << "[          ] naive p + v*(1/60), " << std::left << std::setw(42) << c.name << std::right
              << std::setw(7) << mismatches << " / " << c.inputs.size() << " wrong\n";
    if (c.name.starts_with("R3") || c.name.starts_with("R4") || c.name.starts_with("A1")) {
      EXPECT_GT(mismatches, 0) << c.name;
    }
    all_mismatches += mismatches;
  }
  EXPECT_GT(all_mismatches, 0);
  // A physics-sized case by hand: 0.1 + 3/60 is nearest to the double 0.15, but 3·RN(1/60) rounds to the
  // double 0.05 (0.05000000000000000277…), and 0.1 + 0.05 then rounds to 0.15000000000000002.
  EXPECT_EQ(advance_rounded(0.1, 3.0), 0.15);
  EXPECT_EQ(oracle(0.1, 3.0), 0.15);
  EXPECT_EQ(advance_naive(0.1, 3.0), std::nextafter(0.15, 1.0));
}

}  // namespace
