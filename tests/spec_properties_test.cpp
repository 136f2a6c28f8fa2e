// Properties of the oracle (spec/), checked with RapidCheck on the generators of properties/.
//
// Each RC_GTEST_PROP runs a law of properties/laws.hpp on the oracle. Each law is also run, through
// rc::check, on a deliberately wrong function, and that run must find a counterexample: a law that no
// wrong function can fail checks nothing. rc::check prints the counterexample it found to stderr.
#include "properties/features.hpp"
#include "properties/generators.hpp"
#include "properties/laws.hpp"
#include "spec/oracle.hpp"

#include <gmp.h>
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace {

namespace gen = circles::properties::gen;
namespace laws = circles::properties::laws;
namespace spec = circles::spec;
using spec::Circle;
using spec::Indexed;
using spec::LiteralWorld;
using spec::Q;
using spec::Radii;
using spec::Sequence;

// ── The oracle's functions, in the shapes the laws take ──────────────────────────────────────────────

bool oracle_intersect(const Circle& a, const Circle& b) { return spec::intersect(a, b); }
Sequence oracle_resolved_step(const Sequence& w) { return spec::resolved_step(w); }
std::variant<LiteralWorld, spec::Undefined<Circle>> oracle_literal_step(const std::vector<Circle>& list) {
  return spec::literal_step(spec::literal_world(list));
}
std::optional<Circle> oracle_literal_e(const Circle& c, const LiteralWorld& s) { return spec::e(c, s); }
std::optional<Indexed> oracle_resolved_e(const Indexed& c, const spec::World<Indexed>& s) { return spec::e(c, s); }
Circle oracle_m(const Circle& a, const Circle& b) { return spec::m(a, b); }
double oracle_nearest_double(const Q& q) { return spec::nearest_double(q); }

// ── Deliberately wrong versions: plausible slips in transcribing the seed ────────────────────────────

// (3) with < for ≤: a circle of radius 0 no longer intersects itself.
bool intersect_strictly(const Circle& a, const Circle& b) {
  const Q s = a.r + b.r;
  return s > 0 && (b.p - a.p).squaredNorm() < s * s;
}

// (3) with r_a + r_a for r_a + r_b.
bool intersect_with_own_radius_twice(const Circle& a, const Circle& b) {
  const Q s = a.r + a.r;
  return (b.p - a.p).squaredNorm() <= s * s;
}

// (1) updated in place: circle k meets circles 0 … k-1 already moved, instead of all of w_{n-1}.
Sequence step_in_place(const Sequence& w) {
  Sequence next = w;
  for (std::size_t k = 0; k < next.size(); ++k) {
    const spec::World<Indexed> current = spec::resolved_world(next);
    next[k] = spec::f(Indexed{k, next[k]}, current)->c;
  }
  return next;
}

// (8) as "the least circle of S", found by folding m over S in insertion order: always defined, and the
// answer depends on the order (the fold law below shows why).
std::variant<LiteralWorld, spec::Undefined<Circle>> literal_step_folding_m(const std::vector<Circle>& list) {
  std::vector<Circle> w;  // the set, in insertion order
  for (const Circle& c : list)
    if (std::find(w.begin(), w.end(), c) == w.end()) w.push_back(c);
  LiteralWorld next;
  for (const Circle& c : w) {
    std::optional<Circle> least;
    for (const Circle& x : w)
      if (!(x == c) && spec::intersect(c, x)) least = least ? spec::m(*least, x) : x;
    next.insert(least ? spec::u(spec::h(c, *least)) : spec::u(c));
  }
  return next;
}

// The resolved e as "the first circle of S": the one with the least index, as an engine that takes the first
// colliding circle in array order would. Always defined, but not the least circle under (7).
std::optional<Indexed> resolved_e_first_in_array_order(const Indexed& /*c*/, const spec::World<Indexed>& s) {
  if (s.empty()) return std::nullopt;
  return *std::min_element(s.begin(), s.end(), [](const Indexed& a, const Indexed& b) { return a.k < b.k; });
}

// (6) with < for ≤: circles that tie in a coordinate are no longer comparable, so m(x, a) can be a even
// when x is the least circle.
Circle m_strictly(const Circle& a, const Circle& b) {
  const bool less = a.p.x() < b.p.x() && a.p.y() < b.p.y() && a.v.x() < b.v.x() && a.v.y() < b.v.y() && a.r < b.r;
  return less ? a : b;
}

// GMP's own conversion, mpq_get_d, which truncates towards zero instead of rounding to nearest.
double nearest_double_by_mpq_get_d(const Q& q) { return mpq_get_d(q.backend().data()); }

// Rounds numerator and denominator separately, then divides. For the exact value of a double the
// denominator is a power of two and the numerator has at most 53 bits, so this is right unless the
// denominator passes 2^1023: for a subnormal x, d = 2^1074 rounds to infinity and x comes back as 0.
// rc::gen::arbitrary<double> makes no subnormals, so only a generator that does catches it.
double nearest_double_by_parts(const Q& q) {
  return numerator(q).convert_to<double>() / denominator(q).convert_to<double>();
}

// rc::check(description, testable) returns true when the property held and false when it found a
// counterexample (or gave up, which the laws never do: they discard nothing); it prints the shrunk
// counterexample to stderr. RapidCheck then also prints "Some of your RapidCheck properties had failures"
// with a reproduction string when the binary exits: those are these expected failures.
template <class Law>
bool holds(const std::string& description, Law law) {
  return rc::check(description, law);
}

}  // namespace

// ── (a) intersect (3) is reflexive for r ≥ 0 and symmetric: Theorem 4 ──────────────────────────────────

RC_GTEST_PROP(intersect, is_reflexive_for_every_radius_at_least_0, ()) {
  laws::intersect_is_reflexive(oracle_intersect, Radii::non_negative);
}

RC_GTEST_PROP(intersect, is_symmetric, ()) { laws::intersect_is_symmetric(oracle_intersect, Radii::non_negative); }

TEST(intersect, the_reflexivity_property_catches_a_strict_inequality) {
  EXPECT_FALSE(holds("intersect with < is reflexive",
                     [] { laws::intersect_is_reflexive(intersect_strictly, Radii::non_negative); }));
}

TEST(intersect, the_symmetry_property_catches_an_asymmetric_intersect) {
  EXPECT_FALSE(holds("intersect with r_a + r_a is symmetric",
                     [] { laws::intersect_is_symmetric(intersect_with_own_radius_twice, Radii::non_negative); }));
}

// ── (b) the resolved step commutes with permutations ──────────────────────────────────────────────────

RC_GTEST_PROP(resolved_step, permutes_its_result_as_its_input_is_permuted, ()) {
  laws::resolved_step_commutes_with_permutations(oracle_resolved_step);
}

TEST(resolved_step, the_permutation_property_catches_an_in_place_update) {
  EXPECT_FALSE(holds("an in-place step commutes with permutations",
                     [] { laws::resolved_step_commutes_with_permutations(step_in_place); }));
}

// ── (c) the literal step does not depend on the order the world was built in ─────────────────────────

RC_GTEST_PROP(literal_step, does_not_depend_on_insertion_order, ()) {
  laws::literal_step_ignores_insertion_order(oracle_literal_step);
}

TEST(literal_step, the_insertion_order_property_catches_a_step_that_folds_m) {
  EXPECT_FALSE(holds("a literal step folding m ignores insertion order",
                     [] { laws::literal_step_ignores_insertion_order(literal_step_folding_m); }));
}

// ── (d) the resolved e is the literal e wherever the literal e is defined ────────────────────────────

RC_GTEST_PROP(resolved_e, equals_the_literal_e_wherever_that_is_defined, ()) {
  laws::resolved_e_equals_literal_e_where_defined(oracle_resolved_e, oracle_literal_e);
}

TEST(resolved_e, the_agreement_property_catches_an_e_that_takes_the_first_circle_in_array_order) {
  EXPECT_FALSE(holds("the first circle of S equals the literal e", [] {
    laws::resolved_e_equals_literal_e_where_defined(resolved_e_first_in_array_order, oracle_literal_e);
  }));
}

// ── (e) folding m: order matters in general, not where e is defined ──────────────────────────────────

// The seed's m (7) is not commutative on circles that (6) does not compare: m(a, b) = b but m(b, a) = a.
// So "fold m over S" is no way to compute (8); this run must find such an S.
TEST(literal_m, folds_differently_left_to_right_and_right_to_left) {
  EXPECT_FALSE(holds("folding m left to right equals folding right to left",
                     [] { laws::folding_m_left_to_right_equals_right_to_left(oracle_m); }));
}

RC_GTEST_PROP(literal_m, folds_to_e_in_every_order_wherever_e_is_defined, ()) {
  laws::every_fold_of_m_gives_e_where_e_is_defined(oracle_m, oracle_literal_e);
}

TEST(literal_m, the_fold_property_catches_an_m_with_strict_inequalities) {
  EXPECT_FALSE(holds("every fold of m with < gives e",
                     [] { laws::every_fold_of_m_gives_e_where_e_is_defined(m_strictly, oracle_literal_e); }));
}

// ── (f) nearest_double is round to nearest, ties to even ─────────────────────────────────────────────

RC_GTEST_PROP(nearest_double, of_an_exact_sum_is_the_ieee_sum, ()) {
  laws::nearest_double_rounds_like_ieee(laws::Op::add, oracle_nearest_double);
}

RC_GTEST_PROP(nearest_double, of_an_exact_difference_is_the_ieee_difference, ()) {
  laws::nearest_double_rounds_like_ieee(laws::Op::subtract, oracle_nearest_double);
}

RC_GTEST_PROP(nearest_double, of_an_exact_product_is_the_ieee_product, ()) {
  laws::nearest_double_rounds_like_ieee(laws::Op::multiply, oracle_nearest_double);
}

RC_GTEST_PROP(nearest_double, of_an_exact_quotient_is_the_ieee_quotient, ()) {
  laws::nearest_double_rounds_like_ieee(laws::Op::divide, oracle_nearest_double);
}

RC_GTEST_PROP(nearest_double, of_exact_x_is_x_for_every_finite_x_but_minus_0, ()) {
  laws::nearest_double_inverts_exact(oracle_nearest_double);
}

TEST(nearest_double, the_rounding_property_catches_mpq_get_d_which_truncates) {
  EXPECT_FALSE(holds("mpq_get_d of an exact product is the IEEE product",
                     [] { laws::nearest_double_rounds_like_ieee(laws::Op::multiply, nearest_double_by_mpq_get_d); }));
}

TEST(nearest_double, the_inversion_property_catches_rounding_numerator_and_denominator_apart) {
  EXPECT_FALSE(holds("rounding n and d apart inverts exact",
                     [] { laws::nearest_double_inverts_exact(nearest_double_by_parts); }));
}

// ── (g) the resolved step is the literal step wherever that is defined and merges nothing ─────────────

RC_GTEST_PROP(resolved_step, agrees_with_the_literal_step_where_that_is_defined_and_merges_nothing, ()) {
  laws::resolved_step_agrees_with_literal_where_defined(oracle_resolved_step, oracle_literal_step);
}

TEST(resolved_step, the_agreement_property_catches_an_in_place_update) {
  EXPECT_FALSE(holds("an in-place step agrees with the literal step", [] {
    laws::resolved_step_agrees_with_literal_where_defined(step_in_place, oracle_literal_step);
  }));
}

// ── The generators reach what they promise ─────────────────────────────────────────────────────────

namespace {

// n values of `g`, each from its own random stream, at RapidCheck's largest default size.
template <class T>
std::vector<T> sample(const rc::Gen<T>& g, int n) {
  rc::Random random(20261122);
  std::vector<T> out;
  for (int k = 0; k < n; ++k) out.push_back(g(random.split(), 100).value());
  return out;
}

// The end of the shrinking path that always takes the first shrink offered.
template <class T>
T first_shrinks_to(rc::Shrinkable<T> s) {
  for (;;) {
    auto next = s.shrinks().next();
    if (!next) return s.value();
    s = std::move(*next);
  }
}

}  // namespace

TEST(finite_double, reaches_every_family_and_the_named_boundaries) {
  const std::vector<double> xs = sample(gen::finite_double(), 4000);
  std::map<std::string, int> families;
  std::set<std::uint64_t> seen;
  for (double x : xs) {
    ASSERT_TRUE(std::isfinite(x)) << x;
    ++families[circles::properties::family(x)];
    seen.insert(std::bit_cast<std::uint64_t>(x));
  }
  for (const char* f : {"+0", "-0", "subnormal", "DBL_MIN", "top binade", "small integer", "dyadic", "|x| <= 1000",
                        "tiny normal", "huge", "other normal"})
    EXPECT_GE(families[f], 10) << f;
  const double denorm_min = std::numeric_limits<double>::denorm_min();
  for (double x : {denorm_min, DBL_MIN - denorm_min, DBL_MIN, DBL_MAX, -DBL_MAX})
    EXPECT_TRUE(seen.count(std::bit_cast<std::uint64_t>(x))) << std::hexfloat << x;
}

TEST(finite_double, shrinks_every_value_to_plus_0) {
  rc::Random random(7);
  for (int k = 0; k < 200; ++k) {
    const double end = first_shrinks_to(gen::finite_double()(random.split(), 100));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(end), std::bit_cast<std::uint64_t>(0.0)) << end;
  }
}

TEST(rational, reaches_dyadic_and_non_dyadic_values) {
  int dyadic = 0;
  int non_dyadic = 0;
  for (const Q& q : sample(gen::rational(), 1000)) {
    const spec::Z d = denominator(q);
    ++((d & (d - 1)) == 0 ? dyadic : non_dyadic);  // d is a power of two
  }
  EXPECT_GE(non_dyadic, 100);
  EXPECT_GE(dyadic, 100);
}

TEST(world, makes_contacts_tangencies_ties_and_equal_circles_likely) {
  for (Radii radii : {Radii::positive, Radii::non_negative}) {
    int contact = 0;
    int tangency = 0;
    int duplicate = 0;
    int tie = 0;
    int zero_radius = 0;
    const auto worlds = sample(gen::world(radii), 1000);
    for (const auto& w : worlds) {
      ASSERT_LE(w.size(), 8u);
      for (const Circle& c : w) ASSERT_TRUE(radii == Radii::positive ? c.r > 0 : c.r >= 0) << spec::to_string(c);
      const circles::properties::Features f = circles::properties::features(w);
      contact += f.contact;
      tangency += f.tangency;
      duplicate += f.duplicate;
      tie += f.tie;
      zero_radius += f.zero_radius;
    }
    EXPECT_GE(contact, 300);
    EXPECT_GE(tangency, 150);
    EXPECT_GE(duplicate, 150);
    EXPECT_GE(tie, 300);
    EXPECT_EQ(zero_radius == 0, radii == Radii::positive);
  }
}

TEST(permutation, is_a_permutation_and_shrinks_to_the_identity) {
  rc::Random random(11);
  for (std::size_t n = 0; n <= 8; ++n) {
    const rc::Shrinkable<std::vector<std::size_t>> p = gen::permutation(n)(random.split(), 100);
    std::vector<std::size_t> sorted = p.value();
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> identity(n);
    std::iota(identity.begin(), identity.end(), std::size_t{0});
    EXPECT_EQ(sorted, identity);
    EXPECT_EQ(first_shrinks_to(p), identity);
  }
}
