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

// The families, in the order a round checks them; what each aims at is its row's (FamilyRow::aim, below).
enum class Family {
  lattice,
  random_doubles,
  tangency,
  ulp_nudge,
  tie_px,
  tie_p,
  tie_p_vx,
  tie_p_v,
  duplicates,
  incomparable,
  mutual_contacts,
  tangent_after_step,
  square_overflow,
  subnormals,
  cancellation,
  signed_zeros,
  zero_radius,
  wire,
  sizes,
  crowds,
  cell_crowds,
  radius_spread,
  long_rows,
  index_bits,
  order_borders,
  big_chains,
};

namespace detail {
class Draw;  // a big world's random stream (properties/detail/big_worlds.cpp)
}

// A family's row in the table of families: everything conform, the properties, the CLI, the tests and the docs
// know of it. A new family is a row, its construction (properties/detail/) and its test.
struct FamilyRow {
  Family family;
  const char* name;     // a short name, for reports and RC_TAG: "tangency", "tie-p-vx", "square-overflow"
  bool literal;         // drawn in the literal profile too (false: resolved only, outside the seed's domain)
  bool big;             // worlds of hundreds to thousands of circles (gen::big_world), resolved only
  bool spelled;         // its requests spell each number in one of the forms the protocol allows, not only the
                        // shortest (formats/spelling.hpp): the wire family
  std::uint64_t steps;  // steps_to_decide
  const char* aim;      // what it aims at, in a line: the boundary it reaches, the wrong step it catches
  // Its construction: a small family's world, drawn inside rc::gen::exec (`literal`: for the literal profile);
  // a big family's world of the `round`-th case, at most `max` circles.
  Circles (*build_small)(bool literal);
  Circles (*build_big)(std::uint64_t round, std::size_t max, detail::Draw& draw);
};

// Every family's row, in the order of Family (the order a round checks them).
std::span<const FamilyRow> family_rows();
const FamilyRow& row(Family family);

// A short name, for reports and RC_TAG: "tangency", "tie-p-vx", "square-overflow" (row(family).name).
const char* name(Family family);
// How RapidCheck shows a family in a counterexample (a value of gen::boundary_case, say): by its name.
void showValue(Family family, std::ostream& os);

// The families a profile draws from, in the order above: all of them for resolved; literal leaves out
// those whose row is not `literal` (duplicates and zero_radius, outside its domain, and the big families).
std::span<const Family> families(Profile profile);

// Whether `family` is one of the big families (row(family).big).
bool is_big(Family family);

// The most circles a big world has, unless told otherwise (`circles conform --max-circles`): 2^12 + 1, so that
// the sizes family crosses every power of two from 16 to 4096.
inline constexpr std::size_t kDefaultMaxCircles = 4097;
// The least the limit can be: 2^8 + 64, so that index_bits always crosses 2^8.
inline constexpr std::size_t kMinMaxCircles = 320;

// The steps a chain from a world of `family` needs (row(family).steps) to reach the family's boundary: 2 for tangent_after_step,
// whose circles become tangent in w_1, a tangency only the step from w_1 decides; 1 for every other family,
// whose boundary is in w_0. `circles conform` and step_conforms chain each case at least this far, whatever
// steps they are asked for, so that the default of one step decides every family's boundary. 10 for big_chains,
// whose worlds are chained so that whatever a program keeps from one request to the next is used, and long
// enough that slow circles drift past a pair list's skin.
std::uint64_t steps_to_decide(Family family);

namespace gen {

// A world of `family` in `profile`. A big family's: gen::big_world at a round drawn from 0 … 15 and at most
// 512 circles, which does not shrink. Any other family's: at most 8 circles, finite doubles, r >= 0 (r > 0 and inside
// outside_literal_domain's domain for literal: a drawn world that is not is cut down, circle by circle,
// until it is). Shrinks by dropping circles, then through the family's integers.
rc::Gen<Circles> boundary_world(Family family, Profile profile);

// The world of the big family's `round`-th case (its cases counted from 0), at most max(max_circles,
// kMinMaxCircles) circles, from `random`: the first rounds go up in size until the family's largest world, the
// rounds after come mostly small (docs/conform.md, "Big worlds"); with `largest`, every round's world is of the
// family's largest size under the limit (a step of conform's ladder of sizes). Not shuffled: each family places
// its circles in the index order on purpose. properties/detail/big_worlds.cpp builds them. A small family's is
// empty.
Circles big_world(Family family, std::uint64_t round, std::size_t max_circles, rc::Random random,
                  bool largest = false);

// A family of `profile` (uniformly; shrinks towards lattice) and a world of it.
rc::Gen<std::pair<Family, Circles>> boundary_case(Profile profile);

}  // namespace gen
}  // namespace circles::properties
