// The scale gallery: deliberately wrong optimized steps, each exact on every world of the small families (at most
// 8 circles; all but contact-slots on every world of at most 64, where they test every pair, as fast steps do
// below some count) and wrong on some bigger world, in the way a broad phase, threads, a fixed-size buffer or a
// narrow index goes wrong. `circles conform` with its default
// options must reject each one (tests/scale_gallery_test.cpp), through its big families (properties/boundaries.hpp);
// the small families, of at most 8 circles, cannot.
//
// One optimized step with a knob per bug, so that each entry differs from the correct optimized step (every knob
// off, which conforms) in exactly one way. Above 64 circles it finds candidate pairs with a grid per size class
// of radius (cells a diameter of the class wide), a uniform grid, or a sort and sweep along x, then decides each
// pair exactly (impl::intersect_exact),
// takes each circle's least contact, and moves it by impl::advance_rounded.
#pragma once

#include "formats/protocol.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace circles::testing {

using spec::Circles;

struct ScaleBugs {
  enum class Broad { grid, sweep } broad = Broad::grid;
  std::size_t contact_slots = 0;   // each circle keeps its first N contacts, in index order, and drops the rest
  std::size_t radius_sample = 0;   // the grid's cell is sized from the radii of the first N circles only
  std::size_t strips = 0;          // N strips by x; each looks for contacts as far as its own largest diameter
  std::size_t barrier_free = 0;    // N chunks by index, each updated in place before the next decides its contacts
  std::size_t cell_capacity = 0;   // a grid cell holds its first N circles; later ones are left out of it
  unsigned index_bits = 0;         // the least contact's index is kept in N bits
  std::size_t sort_block = 0;      // the sweep's sort is done per block of N circles, never merged
  std::size_t sweep_window = 0;    // the sweep looks at most N circles ahead in x order
  std::size_t simd_width = 0;      // circles go in blocks of N; the last, partial block looks for no contact
  bool keeps_pairs = false;        // the candidate pairs of the last request are kept when the count matches
  // Kinds of bug that no named big family aims at, which the swarm's worlds must catch (swarm_gallery):
  bool pow2_cell = false;          // the grid's cell side rounded down to a power of two
  double filter_bound = 0;         // d² − (r_a + r_b)² in doubles decides a pair unless within this relative bound
  bool approx_tangent = false;     // a pair touches when d² <= (r_a + r_b)²·(1 + 2^-50), in doubles, no exact test
  bool float32_filter = false;     // a pair is dropped when float32 arithmetic says it is apart
  bool skip_zero_radius = false;   // circles of radius 0 are left out of the broad phase
  bool skip_same_centre = false;   // a circle at the same centre is taken for the circle itself
  bool position_order = false;     // the least contact by (px, py) and index only, not by velocity and radius
  bool flush_subnormal = false;    // a next position below DBL_MIN is written 0
  std::size_t index_halves = 0;    // above N circles, two threads by index whose contacts are never merged
  std::size_t space_halves = 0;    // above N circles, two threads by y (below and above the median), never merged
  // A pair list with a skin (a Verlet list): the pairs within r_a + r_b + 2·s (s this share of the largest
  // radius), kept while no circle has moved s since the last request, where it must be since the list was built.
  double verlet_skin = 0;
};

// What a step over the protocol keeps from one request to the next (ScaleBugs::keeps_pairs, verlet_skin).
struct ScaleState {
  std::size_t circles = 0;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  Circles last;  // verlet_skin: the world of the last request
};

// The optimized step with the bugs `bugs`; with none, the correct step (rounded to nearest). `state` carries
// what it keeps between calls (needed only by keeps_pairs).
Circles optimized_step(const Circles& input, const ScaleBugs& bugs, ScaleState& state);

struct ScaleEntry {
  std::string name;         // "contact-slots": scale_gallery_candidate's argument, and its ctest's name
  std::string description;  // "keeps 8 contacts per circle": what the bug is, in reports
  ScaleBugs bugs;
  // The fewest circles of a world on which the bug can show: what a shrunk counterexample should come near.
  std::size_t needs;
};

// Every wrong optimized step whose kind a named big family aims at.
const std::vector<ScaleEntry>& scale_gallery();

// Wrong optimized steps of kinds no named family aims at: the swarm's worlds (properties/detail/swarm.cpp) on a
// budget run's ladder must catch each (tests/scale_gallery_test.cpp).
const std::vector<ScaleEntry>& swarm_gallery();

// The entry called `name` of either gallery, or the correct optimized step for "optimized"; nullptr for any other
// name.
const ScaleEntry* find_scale_entry(std::string_view name);

}  // namespace circles::testing
