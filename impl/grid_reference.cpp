// The grid reference; its invariant is stated in grid_reference.hpp.
//
// Why the 3×3 neighbourhood finds every intersecting pair. Let R = max r and h = 4R (exact: ×4 is exact for
// every finite double whose product is finite). Circles a and b intersect by (3) iff |p_b − p_a| ≤ r_a + r_b on
// the exact values, so then |x_b − x_a| ≤ 2R = h/2 in each coordinate. A centre's cell is ⌊q⌋ with
// q = RN(x/h): |q − x/h| ≤ u·|x/h| ≤ 2^-53·2^40 = 2^-13 while |x/h| ≤ kGridMaxCell (a quotient that underflows
// errs by at most 2^-1075 instead). So |q_b − q_a| ≤ 1/2 + 2^-12 < 1, and the floors differ by at most 1: b's
// cell is one of the 3×3 around a's. With R = 0 any h > 0 serves (intersecting then means the same centre),
// and h = 1 is taken.
#include "impl/grid_reference.hpp"

#include <array>

namespace circles::impl {

std::optional<double> grid_side(const World& w) {
  double radius = 0;
  for (const double r : w.r()) radius = std::max(radius, r);
  return uniform_side(radius, w.size(), [&w](std::size_t k) { return std::array{w.px()[k], w.py()[k]}; });
}

World step_grid(const World& w) {
  const std::optional<double> h = grid_side(w);
  if (!h) return step_all_pairs(w);
  const auto px = w.px(), py = w.py();
  return step_over_pairs(w, [&](const auto& visit) {
    for_each_neighbour_pair(w.size(), *h, [&](std::size_t k) { return std::array{px[k], py[k]}; }, visit);
  });
}

}  // namespace circles::impl
