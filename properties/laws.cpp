#include "properties/laws.hpp"

#include "properties/features.hpp"
#include "properties/generators.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <string>

namespace circles::properties::laws {

using spec::Circle;
using spec::Indexed;
using spec::LiteralWorld;
using spec::Q;
using spec::Radii;
using spec::Sequence;
using spec::Undefined;

namespace {

// The tags most laws about worlds report: what the world held.
void classify_world(const std::vector<Circle>& w) {
  const Features f = features(w);
  RC_CLASSIFY(f.contact, "contact");
  RC_CLASSIFY(f.tangency, "tangency");
  RC_CLASSIFY(f.duplicate, "equal circles");
  RC_CLASSIFY(f.zero_radius, "r = 0");
}

// A double as "-0x1.8p+1 (-3)": the hexadecimal form is exact, the decimal one readable.
std::string show_double(double x) {
  std::ostringstream os;
  os << std::hexfloat << x << std::defaultfloat << std::setprecision(17) << " (" << x << ")";
  return os.str();
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// The circles at which a literal step was undefined, each with its S, in the storage order of the circles:
// a form of Undefined that does not depend on the order the step visited them in.
std::vector<std::pair<Circle, LiteralWorld>> canonical(const Undefined<Circle>& u) {
  std::vector<std::pair<Circle, LiteralWorld>> at;
  for (const auto& meeting : u.at) at.emplace_back(meeting.c, meeting.S);
  std::sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return spec::Storage{}(a.first, b.first); });
  return at;
}

Circle fold_left(const M& m, const std::vector<Circle>& s) {
  Circle acc = s.front();
  for (std::size_t k = 1; k < s.size(); ++k) acc = m(acc, s[k]);
  return acc;
}

// m(s_0, m(s_1, … m(s_{n-2}, s_{n-1}))): the accumulator second.
Circle fold_right(const M& m, const std::vector<Circle>& s) {
  Circle acc = s.back();
  for (std::size_t k = s.size() - 1; k-- > 0;) acc = m(s[k], acc);
  return acc;
}

}  // namespace

void intersect_is_reflexive(const Intersect& intersect, Radii radii) {
  const Circle c = *gen::circle(radii);
  RC_TAG(c.r == 0 ? "r = 0" : "r > 0");
  RC_ASSERT(intersect(c, c));
}

void intersect_is_symmetric(const Intersect& intersect, Radii radii) {
  // Two circles of a world rather than two independent circles: half the time the second relates to the
  // first (touches it, copies it), so that tangent pairs, where a slip in (3) shows first, are common.
  const std::vector<Circle> w = *rc::gen::suchThat(gen::world(radii, 2), [](const auto& x) { return x.size() == 2; });
  const Circle& a = w[0];
  const Circle& b = w[1];
  const Features f = features(w);
  RC_TAG(f.tangency ? "tangent" : f.contact ? "overlapping" : "apart");
  RC_ASSERT(intersect(a, b) == intersect(b, a));
}

void resolved_step_commutes_with_permutations(const ResolvedStep& step) {
  const std::vector<Circle> w = *gen::world(Radii::non_negative);
  const std::vector<std::size_t> perm = *gen::permutation(w.size());
  classify_world(w);
  RC_ASSERT(step(permute(w, perm)) == permute(step(w), perm));
}

void literal_step_ignores_insertion_order(const LiteralStep& step) {
  const std::vector<Circle> list = *gen::world(Radii::positive);
  const std::vector<std::size_t> perm = *gen::permutation(list.size());
  const auto one = step(list);
  const auto other = step(permute(list, perm));
  classify_world(list);
  RC_TAG(std::holds_alternative<LiteralWorld>(one) ? "defined" : "undefined");
  RC_ASSERT(one.index() == other.index());
  if (const auto* w = std::get_if<LiteralWorld>(&one)) {
    const LiteralWorld& w_other = std::get<LiteralWorld>(other);
    RC_ASSERT(std::vector<Circle>(w->begin(), w->end()) == std::vector<Circle>(w_other.begin(), w_other.end()));
  } else {
    const auto at = canonical(std::get<Undefined<Circle>>(one));
    const auto at_other = canonical(std::get<Undefined<Circle>>(other));
    RC_ASSERT(at.size() == at_other.size());
    for (std::size_t k = 0; k < at.size(); ++k) {
      RC_ASSERT(at[k].first == at_other[k].first);
      RC_ASSERT(at[k].second == at_other[k].second);
    }
  }
}

void resolved_e_equals_literal_e_where_defined(const ResolvedE& resolved_e, const LiteralE& literal_e) {
  const std::vector<Circle> s = *rc::gen::nonEmpty(gen::set_for_e(Radii::positive, 5));
  // e ignores c; it is drawn anyway, so that an e which reads c is not excused.
  const Circle c = *gen::circle(Radii::positive);
  spec::World<Indexed> tagged;
  for (std::size_t k = 0; k < s.size(); ++k) tagged.insert(Indexed{k, s[k]});

  const std::optional<Circle> x = literal_e(c, spec::literal_world(s));
  const std::optional<Indexed> y = resolved_e(Indexed{s.size(), c}, tagged);
  RC_TAG(!x ? "literal e undefined" : s.size() == 1 ? "literal e defined, |S| = 1" : "literal e defined, |S| >= 2");
  RC_ASSERT(y.has_value());
  RC_ASSERT(y->k < s.size());
  RC_ASSERT(y->c == s[y->k]);
  if (x) RC_ASSERT(y->c == *x);
}

void folding_m_left_to_right_equals_right_to_left(const M& m) {
  const std::vector<Circle> s = *rc::gen::nonEmpty(gen::distinct_world(Radii::positive));
  std::vector<Circle> reversed(s.rbegin(), s.rend());
  RC_ASSERT(fold_left(m, s) == fold_left(m, reversed));
}

void every_fold_of_m_gives_e_where_e_is_defined(const M& m, const LiteralE& e) {
  const std::vector<Circle> s = *rc::gen::nonEmpty(gen::set_for_e(Radii::positive, 5));
  const Circle c = *gen::circle(Radii::positive);
  const std::optional<Circle> x = e(c, spec::literal_world(s));
  RC_TAG(!x ? "e undefined" : s.size() == 1 ? "e defined, |S| = 1" : "e defined, |S| >= 2");
  if (!x) return;
  std::vector<std::size_t> order(s.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  do {  // every order of S: at most 5! = 120
    const std::vector<Circle> t = permute(s, order);
    RC_ASSERT(fold_left(m, t) == *x);
    RC_ASSERT(fold_right(m, t) == *x);
  } while (std::next_permutation(order.begin(), order.end()));
}

void nearest_double_rounds_like_ieee(Op op, const NearestDouble& nearest) {
  const double a = *gen::finite_double();
  const double b = *gen::finite_double();
  if (op == Op::divide && b == 0) {
    RC_TAG("b = 0: no exact quotient");
    return;
  }
  const Q qa = spec::exact(a);
  const Q qb = spec::exact(b);
  const double ieee = op == Op::add ? a + b : op == Op::subtract ? a - b : op == Op::multiply ? a * b : a / b;
  const Q q = op == Op::add ? qa + qb : op == Op::subtract ? qa - qb : op == Op::multiply ? qa * qb : qa / qb;
  RC_TAG(q == 0 ? "exact zero" : std::isinf(ieee) ? "overflow to infinity" : family(ieee));
  const double got = nearest(q);
  RC_LOG() << "a = " << show_double(a) << "\nb = " << show_double(b) << "\nIEEE:           " << show_double(ieee)
           << "\nnearest_double: " << show_double(got) << "\n";
  if (q == 0) {
    RC_ASSERT(ieee == 0);
    RC_ASSERT(bits(got) == bits(0.0));
  } else {
    RC_ASSERT(bits(got) == bits(ieee));
  }
}

void nearest_double_inverts_exact(const NearestDouble& nearest) {
  const double x = *gen::finite_double();
  RC_TAG(family(x));
  const double got = nearest(spec::exact(x));
  RC_LOG() << "x = " << show_double(x) << "\nnearest_double(exact(x)) = " << show_double(got) << "\n";
  RC_ASSERT(bits(got) == bits(x == 0 ? 0.0 : x));
}

void resolved_step_agrees_with_literal_where_defined(const ResolvedStep& resolved, const LiteralStep& literal) {
  // Only the worlds the law speaks of, and among them only those where some circles collide (about one
  // in six of distinct_world): the filter is in the generator, so no case is discarded, and shrinking
  // stays inside the filter. The filter keeps a copy of `literal`: RapidCheck shrinks after this returns.
  const std::vector<Circle> s =
      *rc::gen::suchThat(gen::distinct_world(Radii::positive), [literal](const std::vector<Circle>& w) {
        const auto next = literal(w);
        const LiteralWorld* defined = std::get_if<LiteralWorld>(&next);
        return defined && defined->size() == w.size() && features(w).contact;
      });
  const LiteralWorld w_literal = std::get<LiteralWorld>(literal(s));
  const Features f = features(s);
  RC_TAG(f.tangency ? "with a tangency" : "with overlaps only");
  const Sequence w_resolved = resolved(s);
  RC_ASSERT(w_resolved.size() == s.size());
  const LiteralWorld as_set(w_resolved.begin(), w_resolved.end());
  RC_ASSERT(std::vector<Circle>(as_set.begin(), as_set.end()) ==
            std::vector<Circle>(w_literal.begin(), w_literal.end()));
}

}  // namespace circles::properties::laws
