// The laws: bodies of RapidCheck properties about the spec's equations, with the function under test as a
// parameter. The suite runs each law on the oracle (tests/spec_properties_test.cpp); the same law runs on
// an implementation, and on a deliberately wrong function to show that the law can fail at all.
//
// A law draws its inputs itself (from properties/generators.hpp), so call it inside a property:
//   RC_GTEST_PROP(intersect, is_symmetric, ()) { laws::intersect_is_symmetric(my_intersect, radii); }
//   bool held = rc::check("...", [] { laws::intersect_is_symmetric(my_intersect, radii); });
// Each law tags its cases (RC_TAG / RC_CLASSIFY) with the kinds of input it met, and draws its inputs
// without discarding any, so rc::check returning false always means a counterexample.
#pragma once

#include "spec/oracle.hpp"

#include <functional>
#include <optional>
#include <variant>
#include <vector>

namespace circles::properties::laws {

// The signatures of the functions under test.
using Intersect = std::function<bool(const spec::Circle&, const spec::Circle&)>;
using ResolvedStep = std::function<spec::Sequence(const spec::Sequence&)>;
// Builds a literal world from a list of circles (a set: repeats merge) and takes one step of (1).
using LiteralStep =
    std::function<std::variant<spec::LiteralWorld, spec::Undefined<spec::Circle>>(const std::vector<spec::Circle>&)>;
using LiteralE = std::function<std::optional<spec::Circle>(const spec::Circle&, const spec::LiteralWorld&)>;
using ResolvedE = std::function<std::optional<spec::Indexed>(const spec::Indexed&, const spec::World<spec::Indexed>&)>;
using M = std::function<spec::Circle(const spec::Circle&, const spec::Circle&)>;
using NearestDouble = std::function<double(const spec::Q&)>;

// (3), Theorem 4: every circle allowed by `radii` intersects itself. Fails for r = 0 if ≤ is taken as <.
void intersect_is_reflexive(const Intersect& intersect, spec::Radii radii);

// (3), Theorem 4: a intersect b exactly when b intersect a.
void intersect_is_symmetric(const Intersect& intersect, spec::Radii radii);

// Resolved profile: stepping a permuted sequence gives the step's result permuted the same way, for
// sequences with repeats, contacts and r = 0.
void resolved_step_commutes_with_permutations(const ResolvedStep& step);

// Literal profile: the order in which a list of circles is inserted into the world does not change the
// step: the same world, or the same circles c (each with the same S = i(c, W)) at which (8) is undefined.
void literal_step_ignores_insertion_order(const LiteralStep& step);

// For a set S of distinct circles (gen::set_for_e, so that many have a least element): where the literal
// e(c, S) is some x, the resolved e on S tagged with indices is x with its index; and the resolved e is
// always defined.
void resolved_e_equals_literal_e_where_defined(const ResolvedE& resolved_e, const LiteralE& literal_e);

// The claim that folding m (7) over S from the left and from the right agree. False under the product
// order (6): run it with rc::check and expect a counterexample. "Right to left" folds the reversed
// sequence with the accumulator first: m(m(s_n, s_{n-1}), …), so for S = {a, b} the two are m(a, b) and m(b, a).
void folding_m_left_to_right_equals_right_to_left(const M& m);

// Where e(c, S) (8) is defined, every fold of m over S, in every order of S (|S| ≤ 5) and with the
// accumulator on either side, gives e(c, S).
void every_fold_of_m_gives_e_where_e_is_defined(const M& m, const LiteralE& e);

// IEEE 754 arithmetic is correctly rounded, so RN(exact(a) op exact(b)) is a op b, bit for bit — except
// that an exact zero has no sign: nearest_double gives +0 where IEEE may give −0 (−0 + −0, −1 · 0), and
// there the law compares values and checks the +0. An overflow is checked too: nearest_double rounds
// beyond the largest double to ±infinity, as IEEE does. Cases with b = 0 for / have no exact quotient and
// pass. Needs SSE2 double arithmetic without flush-to-zero (the x86-64 default, and never -ffast-math).
enum class Op { add, subtract, multiply, divide };
void nearest_double_rounds_like_ieee(Op op, const NearestDouble& nearest);

// nearest_double(exact(x)) is x, bit for bit, for every finite x except −0, which comes back as +0.
void nearest_double_inverts_exact(const NearestDouble& nearest);

// On a set of distinct circles, some of which collide, where the literal step is defined and merges no
// circles, the resolved step gives the same circles.
void resolved_step_agrees_with_literal_where_defined(const ResolvedStep& resolved, const LiteralStep& literal);

}  // namespace circles::properties::laws
