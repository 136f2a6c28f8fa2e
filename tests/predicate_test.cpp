// The exact intersect predicate (impl/predicate.hpp) against the oracle spec::intersect over exact rationals.
//
// Every case is checked the same way (Tally::check): intersect_exact and its mirror image (b, a) must equal
// the oracle; each tier must agree whenever it decides (Stage A, Stage A', Stage B always); the naive tier's
// mismatches and the deciding stage are counted and printed. Inputs come from a seeded std::mt19937_64.
#include "impl/predicate.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "spec/equations.hpp"

namespace circles::impl {
namespace {

using spec::Q;
using spec::Z;
using namespace impl::filter;  // the filter's bounds, by the names docs/predicate.md gives them

struct Input {
  double ax, ay, ar, bx, by, br;
};

std::string show(const Input& c) {
  std::ostringstream o;
  o.precision(17);
  o << "a = (" << c.ax << ", " << c.ay << ", r " << c.ar << "), b = (" << c.bx << ", " << c.by << ", r "
    << c.br << ")";
  return o.str();
}

bool oracle(const Input& c) {
  using spec::exact;
  return spec::intersect(spec::circle(exact(c.ax), exact(c.ay), 0, 0, exact(c.ar)),
                         spec::circle(exact(c.bx), exact(c.by), 0, 0, exact(c.br)));
}

// Counts for one family of cases; prints itself when the test ends.
struct Tally {
  long cases = 0, wrong = 0, tier_wrong = 0, naive_wrong = 0, oracle_true = 0;
  std::array<long, 3> stage{};  // by Stage

  void check(const Input& c) {
    const bool want = oracle(c);
    Stage by = Stage::gmp;
    const bool got = intersect_exact(c.ax, c.ay, c.ar, c.bx, c.by, c.br, by);
    const bool mirror = intersect_exact(c.bx, c.by, c.br, c.ax, c.ay, c.ar);
    ++cases;
    oracle_true += want;
    ++stage[static_cast<std::size_t>(by)];
    if (got != want || mirror != want) {
      if (++wrong <= 5) ADD_FAILURE() << "intersect_exact != oracle (" << want << ") at " << show(c);
    }
    const Decision a = intersect_filter(c.ax, c.ay, c.ar, c.bx, c.by, c.br);
    const Decision a2 = intersect_rescaled(c.ax, c.ay, c.ar, c.bx, c.by, c.br);
    const bool b = intersect_gmp(c.ax, c.ay, c.ar, c.bx, c.by, c.br);
    const auto disagrees = [want](Decision d) {
      return d != Decision::undecided && (d == Decision::intersect) != want;
    };
    if (disagrees(a) || disagrees(a2) || b != want) {
      if (++tier_wrong <= 5)
        ADD_FAILURE() << "a tier disagrees with the oracle (" << want << ") at " << show(c);
    }
    naive_wrong += intersect_naive(c.ax, c.ay, c.ar, c.bx, c.by, c.br) != want;
  }

  void print(const std::string& name) const {
    std::printf(
        "  %-34s %7ld cases (%3.0f%% intersect) | filter %7ld  rescaled %6ld  gmp %6ld | naive wrong %6ld\n",
        name.c_str(), cases,
        cases ? 100.0 * static_cast<double>(oracle_true) / static_cast<double>(cases) : 0.0, stage[0],
        stage[1], stage[2], naive_wrong);
  }
};

// Tallies by family name, printed and checked for zero mismatches at the end of the test.
struct Tallies {
  std::map<std::string, Tally> by_name;
  Tally& operator[](const std::string& name) { return by_name[name]; }
  ~Tallies() {
    for (const auto& [name, t] : by_name) {
      t.print(name);
      EXPECT_EQ(t.wrong, 0) << name;
      EXPECT_EQ(t.tier_wrong, 0) << name;
    }
  }
};

using Rng = std::mt19937_64;

long uniform(Rng& rng, long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }
bool coin(Rng& rng) { return uniform(rng, 0, 1) == 1; }

// n·2^q, exact: callers keep |n| < 2^53, q ≥ −1074 and the result ≤ DBL_MAX.
double scaled(long n, int q) { return std::ldexp(static_cast<double>(n), q); }

// ±m·2^e with a random 53-bit significand and e uniform in [lo, hi] (subnormal below −1022).
double wide(Rng& rng, int lo, int hi) {
  const long m = uniform(rng, 1L << 52, (1L << 53) - 1);
  const double x = std::ldexp(static_cast<double>(m), static_cast<int>(uniform(rng, lo, hi)) - 52);
  return coin(rng) ? -x : x;
}

// ── Tangency families ───────────────────────────────────────────────────────────────────────────────────

struct Triple {
  long a, b, c;
};

// Euclid's formula with 2^12 ≤ m < 2^13: legs and hypotenuse of 25 to 27 bits.
Triple large_triple(Rng& rng) {
  const long m = uniform(rng, 1L << 12, (1L << 13) - 1);
  const long n = uniform(rng, 1, m - 1);
  return {m * m - n * n, 2 * m * n, m * m + n * n};
}

int width(long n) { return static_cast<int>(std::bit_width(static_cast<unsigned long>(n))); }

// The binades a triple can be placed at: legs a·2^k with k from −1074 up to where half the hypotenuse
// still fits below 2^1024 (both radii, and both coordinates of a straddling pair, stay finite).
int lowest_k() { return -1074; }
int highest_k(const Triple& t) { return 1025 - width(t.c); }

// An exactly tangent pair with centres (a, b)·2^k apart and r_a + r_b = c·2^k. Every coordinate is an
// integer below 2^53 times the unit 2^q, q = k − j ≥ −1074, so it is exact; the translation is random
// (zero, any size up to 2^52 units, or straddling 0), the split of the radii random, the legs' signs and
// order random. In the top two binades (`beyond`: c·2^k near or past 2^1024) coordinates straddle 0 and
// radii are halves, each below 2^51 units with q ≤ 973, so they stay finite while the differences and
// the sum of the radii may overflow.
Input tangent(const Triple& t, int k, Rng& rng) {
  const bool beyond = k > 1023 - width(t.c);
  const int j = static_cast<int>(
      uniform(rng, std::max(0, k - (beyond ? 973 : 971)), std::min(52 - width(t.c), k + 1074)));
  const int q = k - j;
  long A = t.a << j, B = t.b << j;
  const long C = t.c << j;
  if (coin(rng)) std::swap(A, B);
  if (coin(rng)) A = -A;
  if (coin(rng)) B = -B;
  const auto start = [&rng, beyond](long leg) {
    switch (beyond ? 1 : uniform(rng, 0, 3)) {
      case 0:
        return 0L;
      case 1:
        return -leg / 2;
      default: {
        const long g = uniform(rng, 0, 52);
        return uniform(rng, -(1L << g) + 1, (1L << g) - 1) << (52 - g) >> uniform(rng, 0, 52 - g);
      }
    }
  };
  const long tx = start(A), ty = start(B);
  const long C1 = [&] {
    switch (beyond ? 2 : uniform(rng, 0, 4)) {
      case 0:
        return 0L;
      case 1:
        return C;
      case 2:
        return C / 2;
      default:
        return uniform(rng, 0, C);
    }
  }();
  return {scaled(tx, q),     scaled(ty, q),     scaled(C1, q),
          scaled(tx + A, q), scaled(ty + B, q), scaled(C - C1, q)};
}

// The regime a tangent case at 2^k falls in: r_a + r_b itself overflows (c·2^k ≥ 2^1024), squares that
// overflow (c·2^k ≥ 2^512), squares that underflow (c·2^k < 2^-511), or normal. c·2^(k−2) < 2^1024 here.
std::string regime(const Triple& t, int k) {
  const double quarter = std::ldexp(static_cast<double>(t.c), k - 2);
  return quarter >= 0x1p1022  ? "sum overflow"
         : quarter >= 0x1p510 ? "overflow"
         : quarter < 0x1p-513 ? "underflow"
                              : "normal";
}

double up(double x) { return std::nextafter(x, HUGE_VAL); }
double down(double x) { return std::nextafter(x, -HUGE_VAL); }

// Runs `each(family, input)` over every binade for (3,4,5), (5,12,13), (20,21,29) and a fresh large
// triple, with `per_binade` random placements each.
template <class Each>
void every_binade(Rng& rng, int per_binade, Each each) {
  const std::array<Triple, 3> small{{{3, 4, 5}, {5, 12, 13}, {20, 21, 29}}};
  for (int f = 0; f < 4; ++f) {
    for (int k = lowest_k(); k <= 1023; ++k) {
      for (int i = 0; i < per_binade; ++i) {
        const Triple t = f < 3 ? small[static_cast<std::size_t>(f)] : large_triple(rng);
        if (k > highest_k(t)) continue;
        each(regime(t, k), tangent(t, k, rng));
      }
    }
  }
}

TEST(intersect_exact, holds_at_exact_tangency_in_every_binade) {
  Rng rng(1);
  Tallies tallies;
  every_binade(rng, 2, [&](const std::string& regime, const Input& c) {
    ASSERT_TRUE(oracle(c)) << "not tangent: " << show(c);
    tallies["tangent, " + regime].check(c);
  });
}

TEST(intersect_exact, decides_one_ulp_nudges_on_both_sides_of_tangency) {
  Rng rng(2);
  Tallies tallies;
  every_binade(rng, 1, [&](const std::string& regime, const Input& c) {
    // Shrinking a radius by one ulp separates the circles (when it stays ≥ 0); growing one makes them
    // overlap; moving b's centre one ulp either way does either, and the oracle says which.
    if (c.ar > 0) tallies["radius - 1 ulp, " + regime].check({c.ax, c.ay, down(c.ar), c.bx, c.by, c.br});
    if (c.br > 0) tallies["radius - 1 ulp, " + regime].check({c.ax, c.ay, c.ar, c.bx, c.by, down(c.br)});
    if (c.ar < DBL_MAX) tallies["radius + 1 ulp, " + regime].check({c.ax, c.ay, up(c.ar), c.bx, c.by, c.br});
    if (c.br < DBL_MAX) tallies["radius + 1 ulp, " + regime].check({c.ax, c.ay, c.ar, c.bx, c.by, up(c.br)});
    for (const double bx : {down(c.bx), up(c.bx)})
      if (std::isfinite(bx)) tallies["centre +- 1 ulp, " + regime].check({c.ax, c.ay, c.ar, bx, c.by, c.br});
    for (const double by : {down(c.by), up(c.by)})
      if (std::isfinite(by)) tallies["centre +- 1 ulp, " + regime].check({c.ax, c.ay, c.ar, c.bx, by, c.br});
  });
  for (const auto& [name, t] : tallies.by_name) {
    if (name.starts_with("radius - 1 ulp")) {
      EXPECT_EQ(t.oracle_true, 0) << name;
    }
    if (name.starts_with("radius + 1 ulp")) {
      EXPECT_EQ(t.oracle_true, t.cases) << name;
    }
  }
}

TEST(intersect_exact, agrees_with_the_oracle_where_the_filters_are_at_their_threshold) {
  // From each tangency, grow or shrink the larger radius r ≥ S/2 by r·2^-e·t, e in [44, 58], t in [1, 2):
  // then |F| ≈ 2Sr·2^-e·t lies on both sides of the filters' bound 2^-50·M ≈ 2^-49·S², in every regime.
  // The filters decide about half of these, at the edge of what the proof allows.
  Rng rng(10);
  Tallies tallies;
  std::uniform_real_distribution<double> t(1, 2);
  every_binade(rng, 1, [&](const std::string& regime, Input c) {
    double& r = c.ar > c.br ? c.ar : c.br;
    for (int i = 0; i < 2; ++i) {
      const double step = std::ldexp(r * t(rng), -static_cast<int>(uniform(rng, 44, 58)));
      const double saved = r;
      r = coin(rng) ? r + step : std::max(0.0, r - step);
      if (std::isfinite(r)) tallies["filter threshold, " + regime].check(c);
      r = saved;
    }
  });
}

TEST(intersect_exact, decides_pairs_whose_differences_or_radius_sum_overflow) {
  // The top binades, where RN(bx − ax), RN(by − ay) or RN(ra + rb) may be infinite although every input
  // is finite: Stage A' recomputes from halved inputs. Tangent pairs and their nudges, then random pairs
  // straddling 0 near ±DBL_MAX, most of them far from tangency.
  Rng rng(9);
  Tallies tallies;
  const std::array<Triple, 3> small{{{3, 4, 5}, {5, 12, 13}, {20, 21, 29}}};
  for (int i = 0; i < 2000; ++i) {
    const Triple t = i % 4 < 3 ? small[static_cast<std::size_t>(i % 4)] : large_triple(rng);
    const int k = highest_k(t) - static_cast<int>(uniform(rng, 0, 2));
    const Input c = tangent(t, k, rng);
    tallies["top binades, tangent"].check(c);
    tallies["top binades, 1 ulp nudges"].check({c.ax, c.ay, c.ar, c.bx, c.by, down(c.br)});
    tallies["top binades, 1 ulp nudges"].check({c.ax, c.ay, up(c.ar), c.bx, c.by, c.br});
    tallies["top binades, 1 ulp nudges"].check(
        {c.ax, c.ay, c.ar, coin(rng) ? up(c.bx) : down(c.bx), c.by, c.br});
  }
  for (int i = 0; i < 10000; ++i) {
    const auto big = [&] { return std::fabs(wide(rng, 1019, 1023)); };
    tallies["straddling +-DBL_MAX"].check(
        {-big(), coin(rng) ? -big() : big(), big(), big(), wide(rng, 1019, 1023), big()});
  }
}

TEST(intersect_naive, is_wrong_on_one_ulp_disjoint_pairs_in_every_regime) {
  // The exact tier is needed: on pairs one ulp of radius past tangency, s = RN(ra + rb) rounds back onto
  // the tangent sum (normal range), inf <= inf holds (overflow), or the squares flush (underflow).
  Rng rng(3);
  std::map<std::string, std::array<long, 2>> naive;  // regime → {cases, naive says intersect}
  every_binade(rng, 1, [&](const std::string& regime, const Input& c) {
    if (c.br == 0) return;
    const Input d{c.ax, c.ay, c.ar, c.bx, c.by, down(c.br)};
    ASSERT_FALSE(oracle(d)) << show(d);
    ASSERT_FALSE(intersect_exact(d.ax, d.ay, d.ar, d.bx, d.by, d.br)) << show(d);
    ++naive[regime][0];
    naive[regime][1] += intersect_naive(d.ax, d.ay, d.ar, d.bx, d.by, d.br);
  });
  for (const auto& [regime, n] : naive) {
    std::printf("  naive on radius - 1 ulp, %-9s: %5ld false positives in %5ld\n", regime.c_str(), n[1],
                n[0]);
    EXPECT_GT(n[1], 0) << regime;
  }
}

// ── Random inputs ───────────────────────────────────────────────────────────────────────────────────────

TEST(intersect_exact, agrees_with_the_oracle_on_uniform_random_inputs) {
  Rng rng(4);
  std::uniform_real_distribution<double> position(-1000, 1000), radius(0, 100);
  Tallies tallies;
  for (int i = 0; i < 40000; ++i)
    tallies["uniform"].check(
        {position(rng), position(rng), radius(rng), position(rng), position(rng), radius(rng)});
  const Tally& t = tallies["uniform"];
  EXPECT_EQ(t.stage[static_cast<std::size_t>(Stage::gmp)], 0);
  EXPECT_EQ(t.stage[static_cast<std::size_t>(Stage::rescaled)], 0);
}

TEST(intersect_exact, agrees_with_the_oracle_on_wide_exponent_inputs) {
  Rng rng(5);
  Tallies tallies;
  // Independent exponents over the whole range.
  for (int i = 0; i < 20000; ++i)
    tallies["wide, independent"].check({wide(rng, -1074, 1023), wide(rng, -1074, 1023),
                                        std::fabs(wide(rng, -1074, 1023)), wide(rng, -1074, 1023),
                                        wide(rng, -1074, 1023), std::fabs(wide(rng, -1074, 1023))});
  // Related exponents: all within 2^±40 of a random binade, so that the terms compete.
  for (int i = 0; i < 20000; ++i) {
    const int e = static_cast<int>(uniform(rng, -1074, 1023));
    const auto near = [&] { return wide(rng, std::max(-1074, e - 40), std::min(1023, e + 40)); };
    tallies["wide, related"].check({near(), near(), std::fabs(near()), near(), near(), std::fabs(near())});
  }
}

TEST(intersect_exact, agrees_with_the_oracle_within_rounding_of_tangency) {
  // Not exactly representable tangencies: r_b = RN(hypot(dx, dy)) − r_a, in every regime, so that F is
  // within a few ulps of 0 and Stage A cannot decide; then a fraction of the cases nudged by one ulp.
  Rng rng(6);
  Tallies tallies;
  for (int i = 0; i < 30000; ++i) {
    const int e = static_cast<int>(uniform(rng, -1074, 1021));
    const auto near = [&] { return wide(rng, std::max(-1074, e - 30), e); };
    Input c{near(), near(), 0, near(), near(), 0};
    const double d = std::hypot(c.bx - c.ax, c.by - c.ay);
    if (!std::isfinite(d)) continue;
    c.ar = std::fabs(near()) / 4;
    c.br = std::max(0.0, d - c.ar);
    if (coin(rng)) c.br = coin(rng) ? up(c.br) : std::max(0.0, down(c.br));
    tallies[e > 511    ? "near tangent, overflow"
            : e < -511 ? "near tangent, underflow"
                       : "near tangent, normal"]
        .check(c);
  }
}

// ── Special values ──────────────────────────────────────────────────────────────────────────────────────

TEST(intersect_exact, agrees_with_the_oracle_on_signed_zeros_extremes_and_zero_radii) {
  // Every combination of these centres and radii: ±0, the least subnormal, 1, the least normal, ±DBL_MAX.
  const std::array<double, 7> centre{-0.0, 0.0, 0x1p-1074, 1.0, 0x1p-1022, DBL_MAX, -DBL_MAX};
  const std::array<double, 5> radius{-0.0, 0.0, 0x1p-1074, 1.0, DBL_MAX};
  Tallies tallies;
  for (double ax : centre)
    for (double ay : centre)
      for (double bx : centre)
        for (double by : centre)
          for (double ar : radius)
            for (double br : radius) tallies["extremes"].check({ax, ay, ar, bx, by, br});
}

TEST(intersect_exact, holds_for_coincident_centres_and_fails_for_distinct_points) {
  Rng rng(7);
  Tallies tallies;
  for (int i = 0; i < 10000; ++i) {
    const double x = wide(rng, -1074, 1023), y = wide(rng, -1074, 1023);
    const double ra = coin(rng) ? 0.0 : std::fabs(wide(rng, -1074, 1023));
    const double rb = coin(rng) ? (coin(rng) ? 0.0 : -0.0) : std::fabs(wide(rng, -1074, 1023));
    const Input same{x, y, ra, x, y, rb};
    ASSERT_TRUE(intersect_exact(same.ax, same.ay, same.ar, same.bx, same.by, same.br)) << show(same);
    tallies["coincident centres"].check(same);
    // Two points (r = 0) intersect only if they coincide; one ulp apart, they do not.
    const Input points{x, y, 0.0, coin(rng) ? up(x) : x, coin(rng) ? down(y) : y, -0.0};
    tallies["two points"].check(points);
  }
}

TEST(intersect_exact, agrees_with_the_oracle_on_negative_radii_outside_c) {
  // Outside C (r < 0) the oracle still answers: false when r_a + r_b < 0. So does intersect_exact.
  Rng rng(8);
  Tallies tallies;
  std::uniform_real_distribution<double> position(-10, 10), radius(-10, 10);
  for (int i = 0; i < 10000; ++i)
    tallies["negative radii"].check(
        {position(rng), position(rng), radius(rng), position(rng), position(rng), radius(rng)});
}

TEST(sign_filter, its_one_sided_forms_give_the_same_decisions_on_every_regime_and_at_the_threshold) {
  // certainly_disjoint_of_squares and certainly_intersecting_of_squares are the filter's two decided answers in
  // fewer operations (the pair lists' broad phase uses them). They must agree with sign_filter_of_squares
  // everywhere: far and near pairs, at the threshold itself (q chosen so that |p − q| is the bound, give or
  // take an ulp), zeros, subnormals, overflow to +∞, and both absolute terms.
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<int> exponent(-1074, 1023);
  const double specials[] = {0.0, 0x1p-1074, 0x1p-1022, 1.0, 0x1p511, 0x1.fffffffffffffp1023,
                             std::numeric_limits<double>::infinity()};
  std::vector<std::pair<double, double>> cases;  // (q, s)
  for (const double q : specials)
    for (const double s : specials) cases.emplace_back(q, s);
  int near_threshold = 0;
  for (int i = 0; i < 200000; ++i) {
    const double s = std::ldexp(unit(rng) + 0.5, i % 2 ? exponent(rng) / 2 : static_cast<int>(unit(rng) * 40) - 20);
    const double p = s * s;
    switch (i % 4) {
      case 0:  // anywhere
        cases.emplace_back(std::ldexp(unit(rng), exponent(rng)), s);
        break;
      case 1:  // within a few hundred ulps of tangency, either side
        cases.emplace_back(p * (1 + (unit(rng) - 0.5) * 0x1p-44), s);
        break;
      default: {  // q at the threshold p ∓ bound, nudged by up to two ulps
        const double bound = (p + p) * kRelative + kAbsolute;
        double q = i % 4 == 2 ? p + bound : p - bound;
        for (int k = static_cast<int>(unit(rng) * 5) - 2; k != 0; k += k > 0 ? -1 : 1)
          q = std::nextafter(q, k > 0 ? std::numeric_limits<double>::infinity() : 0.0);
        cases.emplace_back(q, s);
        ++near_threshold;
      }
    }
  }
  int disjoint = 0, intersecting = 0, undecided = 0;
  for (const auto& [q, s] : cases)
    for (const double absolute : {kAbsolute, kAbsoluteRescaled}) {
      const Decision d = sign_filter_of_squares(q, s, absolute);
      ASSERT_EQ(certainly_disjoint_of_squares(q, s, absolute), d == Decision::disjoint) << "q " << q << ", s " << s;
      ASSERT_EQ(certainly_intersecting_of_squares(q, s, absolute), d == Decision::intersect)
          << "q " << q << ", s " << s;
      disjoint += d == Decision::disjoint;
      intersecting += d == Decision::intersect;
      undecided += d == Decision::undecided;
    }
  // Every answer occurs often, so the agreement means something on each.
  EXPECT_GT(disjoint, 50000);
  EXPECT_GT(intersecting, 50000);
  EXPECT_GT(undecided, 1000);
  EXPECT_GT(near_threshold, 90000);
}

// ── The constants, recomputed from their derivations ────────────────────────────────────────────────────

Q pow2(long k) { return k >= 0 ? Q(Z(1) << k) : Q(Z(1), Z(1) << -k); }
Q power(const Q& x, int n) { return n == 0 ? Q(1) : x * power(x, n - 1); }
double to_double(const Q& q) { return static_cast<double>(q); }

const Q u = pow2(-53);
const Q eta = pow2(-1075);
// k: relative error of D per unit of M; γ: how the absolute errors of the squares reach D.
const Q k = (power(1 + u, 5) - 1) / power(1 - u, 5);
const Q gamma_ = 3 * k + 3 * power(1 + u, 3);
// The least absolute term c with (c − η)(1 − u) ≥ γ(b + η), for squares off by at most b.
Q least_absolute(const Q& b) { return eta + gamma_ * (b + eta) / (1 - u); }
// Stage A′: the per-coordinate absolute error after halving and scaling, the bound on an exact scaled coordinate
// (the computed one is < 4), and the resulting error of a square.
const Q rescaled_a = eta * (1 + pow2(-1020));
const Q rescaled_R = (4 + rescaled_a) / (1 - u);
const Q rescaled_b = 2 * rescaled_R * (1 + u) * rescaled_a + rescaled_a * rescaled_a;

// x ≥ 1 to 17 significant digits, rounded from its exact value (half up), as docs/predicate.md prints the
// constants. Printing through a double would round twice: k/u is 5.00000000000000388…, and %.17g of the double
// nearest to it gives 5.0000000000000036.
std::string decimal17(const Q& x) {
  const Z whole = numerator(x) / denominator(x);
  const std::size_t before_point = whole.str().size();
  Z scale = 1;
  for (std::size_t d = before_point; d < 17; ++d) scale *= 10;
  const Z digits = (2 * numerator(x) * scale + denominator(x)) / (2 * denominator(x));
  const std::string text = digits.str();
  return text.substr(0, before_point) + "." + text.substr(before_point);
}

TEST(error_bounds, relative_factor_2_pow_minus_50_covers_five_roundings_and_is_tight_within_1_6) {
  const Q c = spec::exact(kRelative);
  EXPECT_GE(c * (1 - u), k);
  EXPECT_LE(c / k, Q(8, 5));
  EXPECT_GT(k, 5 * u);                // five roundings, not fewer
  EXPECT_LT(k, Q(50001, 10000) * u);  // the 5.0001u of the design note
  std::printf("  k = %su; kRelative = %.17g k\n", decimal17(k / u).c_str(), to_double(c / k));
}

TEST(error_bounds, stage_a_absolute_term_covers_three_underflowing_squares_and_is_the_least_power_of_two) {
  const Q need = least_absolute(0);
  const Q c = spec::exact(kAbsolute);
  EXPECT_GE(c, need);
  EXPECT_LT(c / 2, need);
  EXPECT_LE(c / need, 2);
  std::printf("  c_min = %s eta; kAbsolute = %.17g c_min\n", decimal17(need / eta).c_str(), to_double(c / need));
}

TEST(error_bounds, rescaled_absolute_term_covers_scaling_and_halving_errors_and_is_the_least_power_of_two) {
  const Q need = least_absolute(rescaled_b);
  const Q c = spec::exact(kAbsoluteRescaled);
  EXPECT_GE(c, need);
  EXPECT_LT(c / 2, need);
  EXPECT_LE(c / need, Q(8, 7));  // 32η against 28η
  std::printf("  b = %s eta, c_min = %s eta; kAbsoluteRescaled = %.17g c_min\n", decimal17(rescaled_b / eta).c_str(),
              decimal17(need / eta).c_str(), to_double(c / need));
}

TEST(error_bounds, predicate_md_prints_each_constant_from_its_exact_value) {
  std::ifstream in(std::string(CIRCLES_SOURCE_DIR) + "/docs/predicate.md");
  const std::string doc{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_FALSE(doc.empty());
  EXPECT_EQ(decimal17(k / u), "5.0000000000000039");  // by hand: k/u = 5 + 35u + O(u²) = 5.00000000000000389
  for (const std::string& figure :
       {"k = " + decimal17(k / u) + "u", "c_{\\min} = " + decimal17(least_absolute(0) / eta) + "\\eta",
        "b = " + decimal17(rescaled_b / eta) + "\\eta", "c_{\\min} = " + decimal17(least_absolute(rescaled_b) / eta) + "\\eta"})
    EXPECT_NE(doc.find(figure), std::string::npos) << "docs/predicate.md does not print " << figure;
}

TEST(error_bounds, rescale_threshold_leaves_stage_a_absolute_term_negligible_above_it) {
  // Above kRescaleBelow the absolute term is at most 2^-122 of the relative one, so Stage A' could not
  // decide anything Stage A left open for lack of range.
  EXPECT_LE(spec::exact(kAbsolute), pow2(-122) * spec::exact(kRescaleBelow) * spec::exact(kRelative));
}

}  // namespace
}  // namespace circles::impl
