// Worlds of doubles that reach the spec's boundaries by construction, one generator per family, in two
// profiles: what `circles conform` and properties/conformance.hpp ask an implementation.
//
// A family is a kind of boundary a correct step must get right and a plausible wrong one gets wrong: an exact
// tangency (≤ against <, distances in doubles), a tie under the lexicographic key (which key, in which order),
// a subnormal (flushing), and so on. Each family builds its worlds from integers (a scale 2^k, offsets, a
// Pythagorean triple, a number of ulps) so that every world it draws has its boundary, whatever the seed, and
// shrinks through those integers towards the simplest world of the family (and by dropping circles).
// docs/properties.md lists the families and how each is built.
#pragma once

#include "spec/outside_c.hpp"

#include <rapidcheck.h>

#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace circles::properties {

// A world as the step protocol carries it (spec::Circles): [px, py, vx, vy, r] per circle, finite doubles,
// r >= 0.
using spec::Circles;

// resolved: worlds are sequences, circle k's image is circle k, e is the least contact in lexicographic
//           order; r >= 0 (docs/math.md). Every finite world with r >= 0 is in its domain.
// literal:  the seed to the letter, only inside its defined domain (see outside_literal_domain).
enum class Profile { resolved, literal };
const char* name(Profile profile);  // "resolved", "literal"
// "resolved" or "literal". Throws std::invalid_argument with a message for --profile.
Profile parse_profile(std::string_view text);

// Why w is outside the literal profile's domain, or nothing when it is inside: every radius is > 0, no two
// circles are equal (a world is a set), every circle's S = i(c, W) is empty or has a least element under the
// product order (6), so that e (8) is defined, and no two circles have equal images (none merge). Decided
// exactly on the doubles. The message names the circles: "circle 2: e(c, S) (8) has no least element: S
// holds circles 0 and 1, which (6) does not order".
std::optional<std::string> outside_literal_domain(const Circles& w);

enum class Family {
  lattice,             // the property suite's exact worlds (gen::world), rounded: copies, ties, tangencies
  random_doubles,      // every field from gen::finite_double(): every binade, ±0, subnormals, near DBL_MAX
  tangency,            // exact tangency in every binade: a scaled Pythagorean triple, translated, r_a + r_b split
  ulp_nudge,           // a tangency with one coordinate moved by ±1 … 3 ulps: just inside or just outside
  tie_px,              // two contacts of one circle with equal px
  tie_p,               // … with equal p
  tie_p_vx,            // … with equal p and vx
  tie_p_v,             // … with equal p and v, different r
  duplicates,          // … exactly equal (resolved only: a set has no duplicates)
  incomparable,        // two contacts of one circle that the product order (6) does not order
  mutual_contacts,     // three or more circles all touching each other (mutually tangent, or overlapping)
  tangent_after_step,  // v = 60·q: two circles apart in w_0 are exactly tangent in w_1
  square_overflow,     // magnitudes from 2^512 up, where |p_b − p_a|² and (r_a + r_b)² overflow doubles
  subnormals,          // positions, radii and velocities below 2^-1022
  cancellation,        // p ≈ −v/60: the exact p + v/60 is tiny next to p, nudged by up to 3 ulps
  signed_zeros,        // +0 and −0 in every field, equal by value
  zero_radius,         // r = 0: points on a circle's boundary, coincident points (resolved only)
  // The big families (resolved only): worlds of hundreds to thousands of circles, each built around the place
  // where one kind of optimized step (a broad phase, threads, fixed-size buffers, narrow indices) goes wrong.
  // docs/conform.md ("Big worlds") says which kind each aims at and why it catches it.
  sizes,               // p − 1, p and p + 1 circles for every power of two p from 16 up to the limit, and the limit
  crowds,              // hubs touched by 9 … 257 circles each, the least contact at every rank of the index order
  cell_crowds,         // 5 … 1000 centres in one aligned square of side 2^e, for any e, dense or tangent
  radius_spread,       // radii over seven decimal orders, the big ones last in the index order, across x quartiles
  long_rows,           // one or two rows of tangent circles up to 2048 wide, far out, and their transpose
  index_bits,          // 2^b + 16 … 2^b + 64 circles (b = 8, 16); the least contact i >= 2^b beside a wrong one, i mod 2^b
  order_borders,       // a contact across every half, quarter and eighth border of the index, x and y orders
  big_chains,          // random worlds of 64 … 512 moving circles, chained 3 steps
};

// A short name, for reports and RC_TAG: "tangency", "tie-p-vx", "square-overflow".
const char* name(Family family);
// How RapidCheck shows a family in a counterexample (a value of gen::boundary_case, say): by its name.
void showValue(Family family, std::ostream& os);

// The families a profile draws from, in the order above: all of them for resolved; literal leaves out
// duplicates and zero_radius, which are outside its domain.
std::span<const Family> families(Profile profile);

// Whether `family` is one of the big families (sizes … big_chains).
bool is_big(Family family);

// The most circles a big world has, unless told otherwise (`circles conform --max-circles`): 2^12 + 1, so that
// the sizes family crosses every power of two from 16 to 4096.
inline constexpr std::size_t kDefaultMaxCircles = 4097;
// The least the limit can be: 2^8 + 64, so that index_bits always crosses 2^8.
inline constexpr std::size_t kMinMaxCircles = 320;

// The steps a chain from a world of `family` needs to reach the family's boundary: 2 for tangent_after_step,
// whose circles become tangent in w_1, a tangency only the step from w_1 decides; 1 for every other family,
// whose boundary is in w_0. `circles conform` and step_conforms chain each case at least this far, whatever
// steps they are asked for, so that the default of one step decides every family's boundary. 3 for big_chains,
// whose worlds are chained so that whatever a program keeps from one request to the next is used.
std::uint64_t steps_to_decide(Family family);

namespace gen {

// A world of `family` in `profile`. A big family's: gen::big_world at a round drawn from 0 … 15 and at most
// 512 circles, which does not shrink. Any other family's: at most 8 circles, finite doubles, r >= 0 (r > 0 and inside
// outside_literal_domain's domain for literal: a drawn world that is not is cut down, circle by circle,
// until it is). Shrinks by dropping circles, then through the family's integers.
rc::Gen<Circles> boundary_world(Family family, Profile profile);

// The world of the big family's `round`-th case (its cases counted from 0), at most max(max_circles,
// kMinMaxCircles) circles, from `random`: the first rounds go up in size until the family's largest world, the
// rounds after come mostly small (docs/conform.md, "Big worlds"). Not shuffled: each family places its circles
// in the index order on purpose. properties/detail/big_worlds.cpp builds them.
Circles big_world(Family family, std::uint64_t round, std::size_t max_circles, rc::Random random);

// A family of `profile` (uniformly; shrinks towards lattice) and a world of it.
rc::Gen<std::pair<Family, Circles>> boundary_case(Profile profile);

}  // namespace gen
}  // namespace circles::properties
