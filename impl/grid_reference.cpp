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

#include "impl/predicate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <vector>

namespace circles::impl {
namespace {

struct Entry {  // circle k in cell (x, y)
  std::int64_t y, x;
  std::size_t k;
  auto key() const noexcept { return std::tie(y, x, k); }
};

}  // namespace

std::optional<double> grid_side(const World& w) {
  double radius = 0;
  for (const double r : w.r()) radius = std::max(radius, r);
  const double h = radius > 0 ? 4 * radius : 1;
  if (!std::isfinite(h)) return std::nullopt;
  for (const auto coordinates : {w.px(), w.py()})
    for (const double x : coordinates)
      if (!(std::fabs(x / h) <= kGridMaxCell)) return std::nullopt;
  return h;
}

World step_grid(const World& w) {
  const std::optional<double> side = grid_side(w);
  if (!side) return step_all_pairs(w);
  const double h = *side;
  const std::size_t n = w.size();
  std::vector<Entry> cells(n);
  const auto cell = [h](double x) { return static_cast<std::int64_t>(std::floor(x / h)); };
  for (std::size_t k = 0; k < n; ++k) cells[k] = {cell(w.py()[k]), cell(w.px()[k]), k};
  // Sorted by row, then column: the cells (x − 1 … x + 1, y') of one row y' are one run of the array.
  std::sort(cells.begin(), cells.end(), [](const Entry& a, const Entry& b) { return a.key() < b.key(); });
  std::vector<std::size_t> least(n);
  std::iota(least.begin(), least.end(), std::size_t{0});
  const auto px = w.px(), py = w.py(), r = w.r();
  for (const Entry& e : cells) {
    const std::size_t a = e.k;
    for (std::int64_t y = e.y - 1; y <= e.y + 1; ++y) {
      auto it = std::lower_bound(cells.begin(), cells.end(), Entry{y, e.x - 1, 0},
                                 [](const Entry& c, const Entry& v) { return c.key() < v.key(); });
      for (; it != cells.end() && it->y == y && it->x <= e.x + 1; ++it) {
        const std::size_t b = it->k;  // each pair once: from its lower index
        if (b > a && intersect_exact(px[a], py[a], r[a], px[b], py[b], r[b])) {
          offer_contact(w, least, a, b);
          offer_contact(w, least, b, a);
        }
      }
    }
  }
  return step_from_contacts(w, least);
}

}  // namespace circles::impl
