// A second reference step for checking big worlds: step_all_pairs with a uniform grid in front of it.
//
//   Invariant: step_grid(w) == step_all_pairs(w), bit for bit, for every World w (the same world, or the same
//              PositionOverflow: step, circle and field), which tests/grid_reference_test.cpp holds it to.
//
// It is deliberately not the engine it judges (impl/engine.hpp: levelled cells, inflated radii, pair lists over
// many steps, threads). One level of square cells of side h ≥ twice the largest diameter, each circle in the
// cell of its centre, and every pair of circles in the same or adjacent cells (3×3) tested with intersect_exact;
// each circle's least contact by World::precedes and the update advance_rounded, both shared with
// step_all_pairs (step_from_contacts). Where the grid's proof does not hold (no positive finite h, or a centre
// too far out in cells) it is step_all_pairs itself.
#pragma once

#include "impl/engine.hpp"

#include <optional>

namespace circles::impl {

// Cells per axis, either side of 0, within which the grid is used: |x/h| ≤ 2^40 for every coordinate x. The
// proof of the 3×3 neighbourhood (grid_reference.cpp) needs RN(x/h) within 2^-13 of x/h, which u·2^40 = 2^-13
// gives; a floor of at most 2^40 also fits in int64_t.
inline constexpr double kGridMaxCell = 0x1p40;

// The side h of step_grid's cells for w, or nothing when the grid's proof does not hold for w and step_grid is
// step_all_pairs: 4·max r (1 if every radius is 0) when that is finite and every |x/h| ≤ kGridMaxCell.
std::optional<double> grid_side(const World& w);

// The exact step (intersect_exact, World::precedes, advance_rounded) with pairs from a uniform grid: in
// O(n log n + tested pairs) when the radii are alike, and step_all_pairs when the grid cannot be proven.
// Throws PositionOverflow (step 1) like step_all_pairs.
World step_grid(const World& w);

}  // namespace circles::impl
