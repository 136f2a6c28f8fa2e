#include "properties/boundaries.hpp"

#include "impl/predicate.hpp"
#include "properties/detail/boundaries.hpp"
#include "properties/detail/choice.hpp"
#include "properties/generators.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace circles::properties {
namespace {

using spec::CircleDoubles;

constexpr Family kAll[] = {
    Family::lattice,      Family::random_doubles,  Family::tangency,           Family::ulp_nudge,
    Family::tie_px,       Family::tie_p,           Family::tie_p_vx,           Family::tie_p_v,
    Family::duplicates,   Family::incomparable,    Family::mutual_contacts,    Family::tangent_after_step,
    Family::square_overflow, Family::subnormals,   Family::cancellation,       Family::signed_zeros,
    Family::zero_radius,  Family::sizes,           Family::crowds,             Family::cell_crowds,
    Family::radius_spread, Family::long_rows,      Family::index_bits,         Family::order_borders,
    Family::big_chains,
};
constexpr Family kLiteral[] = {
    Family::lattice,      Family::random_doubles,  Family::tangency,           Family::ulp_nudge,
    Family::tie_px,       Family::tie_p,           Family::tie_p_vx,           Family::tie_p_v,
    Family::incomparable, Family::mutual_contacts, Family::tangent_after_step, Family::square_overflow,
    Family::subnormals,   Family::cancellation,    Family::signed_zeros,
};

// (6) and (7) on all five fields: a <= b in px, py, vx, vy and r. Comparisons of doubles are exact, and
// −0 == +0 as for the exact values.
bool product_leq(const CircleDoubles& a, const CircleDoubles& b) {
  for (std::size_t f = 0; f < 5; ++f)
    if (!(a[f] <= b[f])) return false;
  return true;
}

bool equal(const CircleDoubles& a, const CircleDoubles& b) {
  for (std::size_t f = 0; f < 5; ++f)
    if (!(a[f] == b[f])) return false;
  return true;
}

// The first reason w is outside the literal domain, with a circle whose removal may bring it back: the later
// of two equal or merging circles, the last-placed circle of a set without a least element.
struct Violation {
  std::size_t drop;
  std::string reason;
};

std::optional<Violation> first_violation(const Circles& w) {
  const std::size_t n = w.size();
  const auto circle = [](std::size_t k) { return "circle " + std::to_string(k); };
  for (std::size_t k = 0; k < n; ++k)
    if (!(w[k][4] > 0)) return Violation{k, circle(k) + ": r is not > 0 (the literal profile's C has r in R+)"};
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (equal(w[a], w[b]))
        return Violation{b, "circles " + std::to_string(a) + " and " + std::to_string(b) +
                                " are one circle (a world is a set)"};
  std::vector<std::vector<std::size_t>> S(n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (impl::intersect_exact(w[a][0], w[a][1], w[a][4], w[b][0], w[b][1], w[b][4])) {
        S[a].push_back(b);
        S[b].push_back(a);
      }
  std::vector<std::size_t> takes(n);  // whose velocity circle k takes: e(c, S), or itself
  for (std::size_t k = 0; k < n; ++k) {
    takes[k] = k;
    if (S[k].empty()) continue;
    const auto least = std::find_if(S[k].begin(), S[k].end(), [&](std::size_t x) {
      return std::all_of(S[k].begin(), S[k].end(), [&](std::size_t a) { return product_leq(w[x], w[a]); });
    });
    if (least != S[k].end()) {
      takes[k] = *least;
      continue;
    }
    // No least element of a finite set: it has two minimal elements, which (6) does not order.
    std::vector<std::size_t> minimal;
    for (const std::size_t x : S[k])
      if (std::none_of(S[k].begin(), S[k].end(),
                       [&](std::size_t a) { return a != x && product_leq(w[a], w[x]); }))
        minimal.push_back(x);
    const std::size_t last = std::max(k, *std::max_element(S[k].begin(), S[k].end()));
    return Violation{last, circle(k) + ": e(c, S) (8) has no least element: S holds circles " +
                               std::to_string(minimal.at(0)) + " and " + std::to_string(minimal.at(1)) +
                               ", which (6) does not order"};
  }
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      // Images (p + v'/60, v', r) are equal exactly when p, r and the velocities taken are.
      if (w[a][0] == w[b][0] && w[a][1] == w[b][1] && w[a][4] == w[b][4] &&
          w[takes[a]][2] == w[takes[b]][2] && w[takes[a]][3] == w[takes[b]][3])
        return Violation{b, "circles " + std::to_string(a) + " and " + std::to_string(b) +
                                " merge: their images under (4) are equal"};
  return std::nullopt;
}

// Removes circles until w is inside the literal domain.
void cut_to_literal_domain(Circles& w) {
  while (const auto v = first_violation(w)) w.erase(w.begin() + static_cast<std::ptrdiff_t>(v->drop));
}

// The world `inner` gives with the circles at `dropped` removed in turn (an index past the end is ignored),
// cut to the literal domain if need be. Its shrinks drop one more circle first (each in turn), then shrink
// `inner` with the same circles dropped: so a counterexample loses its circles before its numbers shrink.
rc::Shrinkable<Circles> dropping(rc::Shrinkable<Circles> inner, std::vector<std::size_t> dropped, Profile profile) {
  const auto value = [inner, dropped, profile] {
    Circles w = inner.value();
    for (const std::size_t k : dropped)
      if (k < w.size()) w.erase(w.begin() + static_cast<std::ptrdiff_t>(k));
    if (profile == Profile::literal) cut_to_literal_domain(w);
    return w;
  };
  return rc::shrinkable::lambda(value, [inner, dropped, profile, value] {
    const std::size_t n = value().size();
    auto drop_one = rc::seq::map(rc::seq::range<std::size_t>(0, n), [inner, dropped, profile](std::size_t k) {
      std::vector<std::size_t> more = dropped;
      more.push_back(k);
      return dropping(inner, std::move(more), profile);
    });
    auto deeper = rc::seq::map(inner.shrinks(), [dropped, profile](rc::Shrinkable<Circles>&& s) {
      return dropping(std::move(s), dropped, profile);
    });
    return rc::seq::concat(std::move(drop_one), std::move(deeper));
  });
}

}  // namespace

const char* name(Profile profile) { return profile == Profile::literal ? "literal" : "resolved"; }

Profile parse_profile(std::string_view text) {
  if (text == "resolved") return Profile::resolved;
  if (text == "literal") return Profile::literal;
  throw std::invalid_argument("--profile: \"" + std::string(text) + "\" is not resolved or literal");
}

const char* name(Family family) {
  switch (family) {
    case Family::lattice: return "lattice";
    case Family::random_doubles: return "random-doubles";
    case Family::tangency: return "tangency";
    case Family::ulp_nudge: return "ulp-nudge";
    case Family::tie_px: return "tie-px";
    case Family::tie_p: return "tie-p";
    case Family::tie_p_vx: return "tie-p-vx";
    case Family::tie_p_v: return "tie-p-v";
    case Family::duplicates: return "duplicates";
    case Family::incomparable: return "incomparable";
    case Family::mutual_contacts: return "mutual-contacts";
    case Family::tangent_after_step: return "tangent-after-step";
    case Family::square_overflow: return "square-overflow";
    case Family::subnormals: return "subnormals";
    case Family::cancellation: return "cancellation";
    case Family::signed_zeros: return "signed-zeros";
    case Family::zero_radius: return "zero-radius";
    case Family::sizes: return "sizes";
    case Family::crowds: return "crowds";
    case Family::cell_crowds: return "cell-crowds";
    case Family::radius_spread: return "radius-spread";
    case Family::long_rows: return "long-rows";
    case Family::index_bits: return "index-bits";
    case Family::order_borders: return "order-borders";
    case Family::big_chains: return "big-chains";
  }
  return "?";
}

void showValue(Family family, std::ostream& os) { os << name(family); }

std::span<const Family> families(Profile profile) {
  if (profile == Profile::literal) return kLiteral;
  return kAll;
}

bool is_big(Family family) { return family >= Family::sizes; }

std::uint64_t steps_to_decide(Family family) {
  if (family == Family::big_chains) return 3;
  return family == Family::tangent_after_step ? 2 : 1;
}

std::optional<std::string> outside_literal_domain(const Circles& w) {
  if (auto v = first_violation(w)) return std::move(v->reason);
  return std::nullopt;
}

namespace gen {

rc::Gen<Circles> boundary_world(Family family, Profile profile) {
  if (is_big(family))
    return rc::gen::noShrink(rc::gen::exec([family] {
      const auto round = *rc::gen::inRange<std::uint64_t>(0, 16);
      return big_world(family, round, 512, rc::Random(*rc::gen::arbitrary<std::uint64_t>()));
    }));
  // The family's circles, cut to the literal domain (before shuffling, so that bystanders, placed last, go
  // first), then shuffled: the order of a world must not matter to a step, and a shuffle shrinks to none.
  const rc::Gen<Circles> shuffled = rc::gen::exec([family, profile] {
    Circles w = *detail::family_world(family, profile);
    if (profile == Profile::literal) cut_to_literal_domain(w);
    return permute(w, *permutation(w.size()));
  });
  return [shuffled, profile](const rc::Random& random, int size) {
    return dropping(shuffled(random, size), {}, profile);
  };
}

rc::Gen<std::pair<Family, Circles>> boundary_case(Profile profile) {
  const std::span<const Family> all = families(profile);
  return rc::gen::mapcat(detail::element_of<Family>({all.begin(), all.end()}), [profile](Family f) {
    return rc::gen::map(boundary_world(f, profile), [f](Circles w) { return std::pair<Family, Circles>{f, std::move(w)}; });
  });
}

}  // namespace gen
}  // namespace circles::properties
