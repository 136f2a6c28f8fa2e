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

// The table of families: one row each, in the order of Family. steps: 2 for tangent_after_step, whose circles
// become tangent in w_1, a tangency only the step from w_1 decides; 10 for big_chains, chained so that whatever a
// program keeps from one request to the next is used, long enough that slow circles drift past a pair list's
// skin; 1 for every other family, whose boundary is in w_0.
constexpr FamilyRow kRows[] = {
    {Family::lattice, "lattice", true, false, false, 1,
     "the property suite's exact worlds (gen::world), rounded: copies, ties, tangencies",
     detail::lattice, nullptr},
    {Family::random_doubles, "random-doubles", true, false, false, 1,
     "every field from gen::finite_double(): every binade, ±0, subnormals, near DBL_MAX",
     detail::random_doubles, nullptr},
    {Family::tangency, "tangency", true, false, false, 1,
     "exact tangency in every binade: a scaled Pythagorean triple, translated, r_a + r_b split",
     detail::tangency, nullptr},
    {Family::ulp_nudge, "ulp-nudge", true, false, false, 1,
     "a tangency with one coordinate moved by ±1 … 3 ulps: just inside or just outside",
     detail::ulp_nudge, nullptr},
    {Family::tie_px, "tie-px", true, false, false, 1,
     "two contacts of one circle with equal px",
     [](bool literal) { return detail::ties(1, literal); }, nullptr},
    {Family::tie_p, "tie-p", true, false, false, 1,
     "two contacts of one circle with equal p",
     [](bool literal) { return detail::ties(2, literal); }, nullptr},
    {Family::tie_p_vx, "tie-p-vx", true, false, false, 1,
     "two contacts of one circle with equal p and vx",
     [](bool literal) { return detail::ties(3, literal); }, nullptr},
    {Family::tie_p_v, "tie-p-v", true, false, false, 1,
     "two contacts of one circle with equal p and v, different r",
     [](bool literal) { return detail::ties(4, literal); }, nullptr},
    {Family::duplicates, "duplicates", false, false, false, 1,
     "two contacts of one circle exactly equal (resolved only: a set has no duplicates)",
     [](bool literal) { return detail::ties(5, literal); }, nullptr},
    {Family::incomparable, "incomparable", true, false, false, 1,
     "two contacts of one circle that the product order (6) does not order",
     detail::incomparable, nullptr},
    {Family::mutual_contacts, "mutual-contacts", true, false, false, 1,
     "three or more circles all touching each other (mutually tangent, or overlapping)",
     detail::mutual_contacts, nullptr},
    {Family::tangent_after_step, "tangent-after-step", true, false, false, 2,
     "v = 60·q: two circles apart in w_0 are exactly tangent in w_1",
     detail::tangent_after_step, nullptr},
    {Family::square_overflow, "square-overflow", true, false, false, 1,
     "magnitudes from 2^512 up, where |p_b − p_a|² and (r_a + r_b)² overflow doubles",
     detail::square_overflow, nullptr},
    {Family::subnormals, "subnormals", true, false, false, 1,
     "positions, radii and velocities below 2^-1022",
     detail::subnormals, nullptr},
    {Family::cancellation, "cancellation", true, false, false, 1,
     "p ≈ −v/60: the exact p + v/60 is tiny next to p, nudged by up to 3 ulps",
     detail::cancellation, nullptr},
    {Family::signed_zeros, "signed-zeros", true, false, false, 1,
     "+0 and −0 in every field, equal by value",
     detail::signed_zeros, nullptr},
    {Family::zero_radius, "zero-radius", false, false, false, 1,
     "r = 0: points on a circle's boundary, coincident points (resolved only)",
     detail::zero_radius, nullptr},
    {Family::wire, "wire", true, false, true, 1,
     "every spelling of a number a request may hold: 1e-400, -0, E, 5e-324, exact values, midpoints, 2^53 + 1",
     detail::wire, nullptr},
    {Family::sizes, "sizes", false, true, false, 1,
     "p − 1, p and p + 1 circles for every power of two p from 16 up to the limit, and the limit",
     nullptr, detail::sizes},
    {Family::crowds, "crowds", false, true, false, 1,
     "hubs touched by 9 … 257 circles each, the least contact at every rank of the index order",
     nullptr, detail::crowds},
    {Family::cell_crowds, "cell-crowds", false, true, false, 1,
     "5 … 1000 centres in one aligned square of side 2^e, for any e, dense or tangent",
     nullptr, detail::cell_crowds},
    {Family::radius_spread, "radius-spread", false, true, false, 1,
     "radii over seven decimal orders, the big ones last in the index order, across x quartiles",
     nullptr, detail::radius_spread},
    {Family::long_rows, "long-rows", false, true, false, 1,
     "one or two rows of tangent circles up to 2048 wide, far out, and their transpose",
     nullptr, detail::long_rows},
    {Family::index_bits, "index-bits", false, true, false, 1,
     "2^b + 16 … 2^b + 64 circles (b = 8, 16); the least contact i >= 2^b beside a wrong one, i mod 2^b",
     nullptr, detail::index_bits},
    {Family::order_borders, "order-borders", false, true, false, 1,
     "a contact across every half, quarter and eighth border of the index, x and y orders",
     nullptr, detail::order_borders},
    {Family::big_chains, "big-chains", false, true, false, 10,
     "random worlds of 64 … 512 moving circles, chained 10 steps",
     nullptr, detail::big_chains},
};

// Row k is the family k, so that row() is an index.
constexpr bool rows_in_order() {
  for (std::size_t k = 0; k < std::size(kRows); ++k)
    if (static_cast<std::size_t>(kRows[k].family) != k) return false;
  return true;
}
static_assert(rows_in_order(), "the rows of kRows are in the order of Family");

// The families of each profile, in the table's order.
std::vector<Family> profile_families(bool literal) {
  std::vector<Family> out;
  for (const FamilyRow& r : kRows)
    if (!literal || r.literal) out.push_back(r.family);
  return out;
}

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

std::span<const FamilyRow> family_rows() { return kRows; }

const FamilyRow& row(Family family) { return kRows[static_cast<std::size_t>(family)]; }

const char* name(Family family) { return row(family).name; }

void showValue(Family family, std::ostream& os) { os << name(family); }

std::span<const Family> families(Profile profile) {
  static const std::vector<Family> resolved = profile_families(false), literal = profile_families(true);
  return profile == Profile::literal ? literal : resolved;
}

bool is_big(Family family) { return row(family).big; }

std::uint64_t steps_to_decide(Family family) { return row(family).steps; }

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
    Circles w = *rc::gen::exec([family, profile] { return row(family).build_small(profile == Profile::literal); });
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
