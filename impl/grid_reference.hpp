// A second reference step for checking big worlds: step_all_pairs with a uniform grid in front of it.
//
//   Invariant: step_grid(w) == step_all_pairs(w), bit for bit, for every World w (the same world, or the same
//              PositionOverflow: step, circle and field), which tests/grid_reference_test.cpp holds it to.
//
// It is deliberately not the engine it judges (impl/engine.hpp: levelled cells, inflated radii, pair lists over
// many steps, threads). One level of square cells of side h ≥ twice the largest diameter, each circle in the
// cell of its centre, and every pair of circles in the same or adjacent cells (3×3); the pair test
// intersect_exact, each circle's least contact by World::precedes and the update advance_rounded are
// step_all_pairs' own (step_over_pairs). Where the grid's proof does not hold (no positive finite h, or a centre
// too far out in cells) it is step_all_pairs itself.
//
// The grid itself (uniform_side, for_each_neighbour_pair) is generic over where the centres come from, so that
// the exact reference (impl/exact_grid_reference.hpp) walks the same cells over its centres' nearest doubles.
#pragma once

#include "impl/engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

namespace circles::impl {

// Cells per axis, either side of 0, within which the grid is used: |x/h| ≤ 2^40 for every coordinate x. The
// proof of the 3×3 neighbourhood (grid_reference.cpp) needs RN(x/h) within 2^-13 of x/h, which u·2^40 = 2^-13
// gives; a floor of at most 2^40 also fits in int64_t.
inline constexpr double kGridMaxCell = 0x1p40;

// The side of a uniform grid for circles of radius at most `radius` (≥ 0) whose centres centre(k), k < n, are
// pairs of doubles: 4·radius (1 if radius is 0) when that is finite and every |x/h| ≤ kGridMaxCell; else
// nothing. `Centre` is any callable std::size_t → std::array<double, 2>.
template <class Centre>
std::optional<double> uniform_side(double radius, std::size_t n, Centre centre) {
  const double h = radius > 0 ? 4 * radius : 1;
  if (!std::isfinite(h)) return std::nullopt;
  for (std::size_t k = 0; k < n; ++k)
    for (const double x : centre(k))
      if (!(std::fabs(x / h) <= kGridMaxCell)) return std::nullopt;
  return h;
}

// Calls visit(a, b) once for every pair a < b of the n circles whose cells (⌊x/h⌋, ⌊y/h⌋) of centre(k) = (x, y)
// are the same or adjacent (the 3×3 around either), and for no other pair. Requires h from uniform_side for
// the same centres (so every floor fits in int64_t). O(n log n + visited pairs).
template <class Centre, class Visit>
void for_each_neighbour_pair(std::size_t n, double h, Centre centre, Visit visit) {
  struct Entry {  // circle k in cell (x, y)
    std::int64_t y, x;
    std::size_t k;
    auto key() const noexcept { return std::tie(y, x, k); }
  };
  const auto cell = [h](double x) { return static_cast<std::int64_t>(std::floor(x / h)); };
  std::vector<Entry> cells(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto [x, y] = centre(k);
    cells[k] = {cell(y), cell(x), k};
  }
  const auto before = [](const Entry& a, const Entry& b) { return a.key() < b.key(); };
  // Sorted by row, then column: the cells (x − 1 … x + 1, y') of one row y' are one run of the array.
  std::sort(cells.begin(), cells.end(), before);
  for (const Entry& e : cells)
    for (std::int64_t y = e.y - 1; y <= e.y + 1; ++y)
      for (auto it = std::lower_bound(cells.begin(), cells.end(), Entry{y, e.x - 1, 0}, before);
           it != cells.end() && it->y == y && it->x <= e.x + 1; ++it)
        if (it->k > e.k) visit(e.k, it->k);  // each pair once: from its lower index
}

// The side h of step_grid's cells for w, or nothing when the grid's proof does not hold for w and step_grid is
// step_all_pairs: uniform_side of the largest radius and the centres.
std::optional<double> grid_side(const World& w);

// The exact step (intersect_exact, World::precedes, advance_rounded) with pairs from a uniform grid: in
// O(n log n + tested pairs) when the radii are alike, and step_all_pairs when the grid cannot be proven.
// Throws PositionOverflow (step 1) like step_all_pairs.
World step_grid(const World& w);

}  // namespace circles::impl
