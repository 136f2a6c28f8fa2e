// The families' constructions behind gen::boundary_world and gen::big_world (properties/boundaries.hpp), one a
// family; the table of families (properties/boundaries.cpp) names each family's construction.
#pragma once

#include "properties/boundaries.hpp"

#include <cstddef>
#include <cstdint>

namespace circles::properties::detail {

// ── The small families (detail/boundaries.cpp) ────────────────────────────────────────────────────────
// The circles of one world of the family, drawn inside rc::gen::exec, before properties/boundaries.cpp finishes
// it (cuts it down to the literal domain, shuffles it, drops circles while shrinking): the family's own circles
// first, then up to two bystanders near them. Every number is a finite double built exactly from integers;
// r >= 0, and r > 0 when `literal`, whose worlds are also ordered so that each circle's contacts have a least
// element. `tie` is the number of keys two contacts share (1 px … 4 the whole p and v, 5 every field).
Circles lattice(bool literal);
Circles random_doubles(bool literal);
Circles tangency(bool literal);
Circles ulp_nudge(bool literal);
Circles ties(int tie, bool literal);
Circles incomparable(bool literal);
Circles mutual_contacts(bool literal);
Circles tangent_after_step(bool literal);
Circles square_overflow(bool literal);
Circles subnormals(bool literal);
Circles cancellation(bool literal);
Circles signed_zeros(bool literal);
Circles zero_radius(bool literal);  // resolved only: `literal` is never true
Circles wire(bool literal);

// ── The big families (detail/big_worlds.cpp) ───────────────────────────────────────────────────────────
// The world of the family's round-th case, at most `max` circles, from the case's random stream `draw`.
class Draw;
Circles sizes(std::uint64_t round, std::size_t max, Draw& draw);
Circles crowds(std::uint64_t round, std::size_t max, Draw& draw);
Circles cell_crowds(std::uint64_t round, std::size_t max, Draw& draw);
Circles radius_spread(std::uint64_t round, std::size_t max, Draw& draw);
Circles long_rows(std::uint64_t round, std::size_t max, Draw& draw);
Circles index_bits(std::uint64_t round, std::size_t max, Draw& draw);
Circles order_borders(std::uint64_t round, std::size_t max, Draw& draw);
Circles big_chains(std::uint64_t round, std::size_t max, Draw& draw);

// ── The swarm (detail/swarm.cpp): a ladder's world of n circles with its own random subset of features ──────
// Its frame (the scale of its radii): drawn, or one of the extremes: the subnormals themselves (centres and next
// positions below DBL_MIN) or near 2^1000. A ladder's first stage, which every budget run asks, holds one world
// of each extreme (sizes's and big_chains's), so that no seed misses the ends of the double range.
enum class Frame { drawn, subnormal, huge };
Circles swarm(std::size_t n, Draw& draw, Frame frame = Frame::drawn);
// The most circles of a swarm world in a frame near 2^1000 or near the subnormals: the double engine, conform's
// reference for big worlds, slows down by orders of magnitude at those scales (over 600 s for 10^5 circles near
// 2^-1060, 2 to 4 s for 4096 swarm circles near 2^-1030 here), so the swarm keeps them to sizes it steps in a
// fraction of a second.
inline constexpr std::size_t kExtremeCircles = 1024;

}  // namespace circles::properties::detail
