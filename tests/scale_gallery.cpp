#include "tests/scale_gallery.hpp"

#include "impl/predicate.hpp"
#include "impl/rounding.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace circles::testing {
namespace {

using spec::CircleDoubles;
// For each circle, the circles it tests for contact (directed: circle i finds its own contacts among looks[i]).
using Looks = std::vector<std::vector<std::size_t>>;

// Up to this many circles every pair is tested, as fast steps do below some count: every entry is exact there.
constexpr std::size_t kAllPairsUpTo = 64;
// Cells a little over a diameter wide: two circles that touch are at most a diameter of the largest apart, so
// their cells are the same or adjacent even after x/h is rounded: a quotient |x/h| <= kMaxCell = 2^30 is within
// 2^30 · 2^-53 = 2^-23 of a cell of its exact value, far inside the margin of 2^-20 of a cell.
constexpr double kCellMargin = 1 + 0x1p-20;
constexpr double kMaxCell = 0x1p30;
// The least cell side: 2^-960, so that a margin of 2^-20 of a cell is a normal number and every rounding error
// in placing a centre is relative. A world of subnormal scale then sits in one cell, tested pair by pair.
constexpr double kLeastCell = 0x1p-960;

Looks all_pairs(std::size_t n) {
  Looks looks(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j) looks[i].push_back(j);
  return looks;
}

// The largest |coordinate| of a centre.
double extent(const Circles& w) {
  double e = 0;
  for (const CircleDoubles& c : w) e = std::max({e, std::fabs(c[0]), std::fabs(c[1])});
  return e;
}

// A uniform grid: each circle in the cell of its centre (a cell keeps its first `capacity` circles, 0: all),
// each circle looking at the 3 × 3 cells around its own. Cells of side 2·kCellMargin·(the largest radius of the
// first `sample` circles, 0: of all), widened where needed so that every cell coordinate is within ±kMaxCell.
Looks grid(const Circles& w, std::size_t sample, std::size_t capacity, bool pow2_cell) {
  const std::size_t n = w.size();
  double largest = 0;
  for (std::size_t k = 0; k < (sample ? std::min(sample, n) : n); ++k) largest = std::max(largest, w[k][4]);
  double h = 2 * kCellMargin * largest;
  if (pow2_cell && h > 0) h = std::ldexp(1.0, std::ilogb(h));
  h = std::max({h, extent(w) / kMaxCell, kLeastCell});
  if (!std::isfinite(h)) return all_pairs(n);
  std::vector<std::pair<std::int64_t, std::int64_t>> cell(n);
  for (std::size_t k = 0; k < n; ++k)
    cell[k] = {static_cast<std::int64_t>(std::floor(w[k][0] / h)), static_cast<std::int64_t>(std::floor(w[k][1] / h))};
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> cells;
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<std::size_t>& in = cells[cell[k]];
    if (capacity == 0 || in.size() < capacity) in.push_back(k);
  }
  Looks looks(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        if (const auto at = cells.find({cell[i].first + dx, cell[i].second + dy}); at != cells.end())
          for (const std::size_t j : at->second)
            if (j != i) looks[i].push_back(j);
  return looks;
}

// A grid per size class, as fast steps do when radii spread (a hierarchical grid): class k holds the circles of
// radius in [2^k, 2^(k+1)), radius 0 a class below every other, in cells of side 2·kCellMargin·(the class's largest
// radius), widened where needed so that every cell coordinate is within ±kMaxCell. Each circle looks into its own
// class and every larger one, over the cells that its box of half-side r + (the class's largest radius), widened
// by 2^-20 of a cell, meets; each pair so found is looked at from both sides. A few giants then fill their own
// class's cells only, not every circle's.
Looks size_classes(const Circles& w) {
  const std::size_t n = w.size();
  const double far = extent(w);
  using Cell = std::pair<std::int64_t, std::int64_t>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(c.first) * 0x9E3779B97F4A7C15u ^
                                        static_cast<std::uint64_t>(c.second));
    }
  };
  struct Class {
    double largest = 0, side = 0;
    std::unordered_map<Cell, std::vector<std::size_t>, CellHash> cells;
  };
  const auto class_of = [](double r) { return r > 0 ? std::ilogb(r) : std::numeric_limits<int>::min(); };
  std::map<int, Class> classes;
  for (const CircleDoubles& c : w) {
    Class& k = classes[class_of(c[4])];
    k.largest = std::max(k.largest, c[4]);
  }
  for (auto& [_, k] : classes) {
    k.side = std::max({2 * kCellMargin * k.largest, far / kMaxCell, kLeastCell});
    if (!std::isfinite(k.side)) return all_pairs(n);
  }
  for (std::size_t j = 0; j < n; ++j) {
    Class& k = classes[class_of(w[j][4])];
    k.cells[{static_cast<std::int64_t>(std::floor(w[j][0] / k.side)), static_cast<std::int64_t>(std::floor(w[j][1] / k.side))}]
        .push_back(j);
  }
  Looks looks(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int own = class_of(w[i][4]);
    for (auto at = classes.find(own); at != classes.end(); ++at) {
      const Class& k = at->second;
      const double reach = (w[i][4] + k.largest) + k.side * 0x1p-20;
      const double x0 = std::floor((w[i][0] - reach) / k.side), x1 = std::floor((w[i][0] + reach) / k.side);
      const double y0 = std::floor((w[i][1] - reach) / k.side), y1 = std::floor((w[i][1] + reach) / k.side);
      if (!std::isfinite(x0 + x1 + y0 + y1)) return all_pairs(n);
      for (auto x = static_cast<std::int64_t>(x0); x <= static_cast<std::int64_t>(x1); ++x)
        for (auto y = static_cast<std::int64_t>(y0); y <= static_cast<std::int64_t>(y1); ++y)
          if (const auto cell = k.cells.find({x, y}); cell != k.cells.end())
            for (const std::size_t j : cell->second)
              if (at->first != own || j > i) {
                looks[i].push_back(j);
                looks[j].push_back(i);
              }
    }
  }
  return looks;
}

// Sort and sweep along x: the intervals [x − r, x + r], widened outward by an ulp so that they hold the exact
// ones, sorted by their left ends (in blocks of `block` circles, 0: all at once), each compared with the ones
// after it while they start before it ends (at most `window` ahead, 0: no limit). All pairs if an end overflows.
Looks sweep(const Circles& w, std::size_t block, std::size_t window) {
  const std::size_t n = w.size();
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<double> left(n), right(n);
  for (std::size_t k = 0; k < n; ++k) {
    left[k] = std::nextafter(w[k][0] - w[k][4], -inf);
    right[k] = std::nextafter(w[k][0] + w[k][4], inf);
    if (!std::isfinite(left[k]) || !std::isfinite(right[k])) return all_pairs(n);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const std::size_t run = block ? block : n;
  for (std::size_t from = 0; from < n; from += run) {
    const auto first = order.begin() + static_cast<std::ptrdiff_t>(from);
    const auto last = order.begin() + static_cast<std::ptrdiff_t>(std::min(n, from + run));
    std::stable_sort(first, last, [&](std::size_t a, std::size_t b) { return left[a] < left[b]; });
  }
  Looks looks(n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n && (window == 0 || b - a <= window) && left[order[b]] <= right[order[a]]; ++b) {
      looks[order[a]].push_back(order[b]);
      looks[order[b]].push_back(order[a]);
    }
  return looks;
}

// Strips of equal counts along x; a circle of strip s looks at every circle whose x is within twice the largest
// radius of strip s (the right reach is its own radius plus the largest of all).
Looks strips(const Circles& w, std::size_t count) {
  const std::size_t n = w.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return w[a][0] < w[b][0]; });
  Looks looks(n);
  for (std::size_t s = 0; s < count; ++s) {
    const std::size_t from = n * s / count, to = n * (s + 1) / count;
    double reach = 0;
    for (std::size_t t = from; t < to; ++t) reach = std::max(reach, 2 * kCellMargin * w[order[t]][4]);
    for (std::size_t t = from; t < to; ++t) {
      const std::size_t i = order[t];
      for (const std::size_t j : order)
        if (j != i && std::fabs(w[j][0] - w[i][0]) <= reach) looks[i].push_back(j);
    }
  }
  return looks;
}

// Whether circle a precedes circle b: lexicographic on (px, py, vx, vy, r), exactly (−0 == +0), then by index
// (on (px, py) only with `position`).
bool precedes(const Circles& w, std::size_t a, std::size_t b, bool position = false) {
  for (std::size_t f = 0; f < (position ? 2 : 5); ++f) {
    if (w[a][f] < w[b][f]) return true;
    if (w[b][f] < w[a][f]) return false;
  }
  return a < b;
}

// Whether circles a and b touch, as the step with `bugs` decides it: exactly (impl::intersect_exact), unless a
// bug decides first.
bool touches(const CircleDoubles& a, const CircleDoubles& b, const ScaleBugs& bugs) {
  if (bugs.skip_zero_radius && (a[4] == 0 || b[4] == 0)) return false;
  if (bugs.skip_same_centre && a[0] == b[0] && a[1] == b[1]) return false;
  const double dx = b[0] - a[0], dy = b[1] - a[1], s = a[4] + b[4];
  const double d2 = dx * dx + dy * dy, s2 = s * s;
  if (bugs.approx_tangent && std::isfinite(d2) && std::isfinite(s2)) return d2 <= s2 * (1 + 0x1p-50);
  if (bugs.float32_filter) {
    const float fx = static_cast<float>(b[0]) - static_cast<float>(a[0]);
    const float fy = static_cast<float>(b[1]) - static_cast<float>(a[1]);
    const float fs = static_cast<float>(a[4]) + static_cast<float>(b[4]);
    if (std::isfinite(fx * fx + fy * fy) && fx * fx + fy * fy > fs * fs) return false;
  }
  if (bugs.filter_bound > 0 && std::isfinite(d2) && std::isfinite(s2) && std::isnormal(s2)) {
    const double bound = bugs.filter_bound * (d2 + s2);
    if (d2 - s2 > bound) return false;
    if (s2 - d2 > bound) return true;
  }
  return impl::intersect_exact(a[0], a[1], a[4], b[0], b[1], b[4]);
}

// Circle i's image: the velocity of its least contact among looks (the first `slots` contacts in index order,
// 0: all; the least kept in `bits` bits, 0: in full), then the correctly rounded move.
CircleDoubles image(const Circles& w, std::size_t i, std::vector<std::size_t> looks, const ScaleBugs& bugs) {
  std::sort(looks.begin(), looks.end());
  looks.erase(std::unique(looks.begin(), looks.end()), looks.end());
  std::vector<std::size_t> contacts;
  for (const std::size_t j : looks)
    if (touches(w[i], w[j], bugs)) contacts.push_back(j);
  if (bugs.contact_slots && contacts.size() > bugs.contact_slots) contacts.resize(bugs.contact_slots);
  const std::size_t mask = bugs.index_bits ? (std::size_t{1} << bugs.index_bits) - 1 : ~std::size_t{0};
  std::size_t least = i;
  bool any = false;
  for (const std::size_t j : contacts)
    if (!any || precedes(w, j, least, bugs.position_order)) {
      least = j & mask;
      any = true;
    }
  const double vx = w[least][2], vy = w[least][3];
  CircleDoubles out{impl::advance_rounded(w[i][0], vx), impl::advance_rounded(w[i][1], vy), vx, vy, w[i][4]};
  if (bugs.flush_subnormal)
    for (const std::size_t f : {0, 1})
      if (std::fabs(out[f]) < std::numeric_limits<double>::min()) out[f] = 0;
  return out;
}

// Whether no circle of `w` has moved `skin` or more from where it was in `before` (a world of as many circles).
bool within_skin(const Circles& w, const Circles& before, double skin) {
  for (std::size_t i = 0; i < w.size(); ++i)
    if (!(std::fabs(w[i][0] - before[i][0]) < skin && std::fabs(w[i][1] - before[i][1]) < skin)) return false;
  return true;
}

// The circles of `w` with each radius grown by `skin`: the pairs a grid finds among them are those within
// r_a + r_b + 2·skin.
Circles grown(Circles w, double skin) {
  for (CircleDoubles& c : w) c[4] += skin;
  return w;
}

// The candidate pairs a step kept from an earlier request, as looks over n circles.
Looks kept_looks(const ScaleState& state, std::size_t n) {
  Looks looks(n);
  for (const auto& [i, j] : state.pairs) looks[i].push_back(j);
  return looks;
}

// Keeps `looks`, the candidate pairs of a world of their count of circles, for a later request.
void keep_looks(ScaleState& state, const Looks& looks) {
  state.circles = looks.size();
  state.pairs.clear();
  for (std::size_t i = 0; i < looks.size(); ++i)
    for (const std::size_t j : looks[i]) state.pairs.emplace_back(i, j);
}

Looks candidates(const Circles& w, const ScaleBugs& bugs, ScaleState& state) {
  if (bugs.keeps_pairs && state.circles == w.size() && !state.pairs.empty()) return kept_looks(state, w.size());
  if (bugs.verlet_skin > 0) {
    double largest = 0;
    for (const CircleDoubles& c : w) largest = std::max(largest, c[4]);
    const double skin = bugs.verlet_skin * largest;
    const bool keep = state.circles == w.size() && within_skin(w, state.last, skin);
    state.last = w;
    if (keep) return kept_looks(state, w.size());
    Looks looks = size_classes(grown(w, skin));
    keep_looks(state, looks);
    return looks;
  }
  Looks looks = bugs.strips ? strips(w, bugs.strips)
                : bugs.broad == ScaleBugs::Broad::sweep ? sweep(w, bugs.sort_block, bugs.sweep_window)
                : bugs.radius_sample || bugs.cell_capacity || bugs.pow2_cell
                    ? grid(w, bugs.radius_sample, bugs.cell_capacity, bugs.pow2_cell)
                    : size_classes(w);
  if (bugs.simd_width)
    for (std::size_t i = w.size() - w.size() % bugs.simd_width; i < w.size(); ++i) looks[i].clear();
  // Two threads, each its half of the circles (by index, or by y about the median), whose contacts across the
  // halves are never merged.
  if ((bugs.index_halves && w.size() > bugs.index_halves) || (bugs.space_halves && w.size() > bugs.space_halves)) {
    std::vector<bool> upper(w.size());
    if (bugs.index_halves) {
      for (std::size_t i = 0; i < w.size(); ++i) upper[i] = i >= w.size() / 2;
    } else {
      std::vector<double> ys;
      for (const CircleDoubles& c : w) ys.push_back(c[1]);
      std::nth_element(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(ys.size() / 2), ys.end());
      for (std::size_t i = 0; i < w.size(); ++i) upper[i] = w[i][1] >= ys[ys.size() / 2];
    }
    for (std::size_t i = 0; i < w.size(); ++i) std::erase_if(looks[i], [&](std::size_t j) { return upper[j] != upper[i]; });
  }
  if (bugs.keeps_pairs) keep_looks(state, looks);
  return looks;
}

}  // namespace

Circles optimized_step(const Circles& w, const ScaleBugs& bugs, ScaleState& state) {
  const std::size_t n = w.size();
  Circles out(n);
  if (n <= kAllPairsUpTo) {
    const Looks looks = all_pairs(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = image(w, i, looks[i], ScaleBugs{.contact_slots = bugs.contact_slots});
    return out;
  }
  const Looks looks = candidates(w, bugs, state);
  if (bugs.barrier_free) {
    // Each chunk decides its contacts on the world as the chunks before it left it.
    Circles now = w;
    for (std::size_t c = 0; c < bugs.barrier_free; ++c) {
      const std::size_t from = n * c / bugs.barrier_free, to = n * (c + 1) / bugs.barrier_free;
      for (std::size_t i = from; i < to; ++i) out[i] = image(now, i, looks[i], bugs);
      std::copy(out.begin() + static_cast<std::ptrdiff_t>(from), out.begin() + static_cast<std::ptrdiff_t>(to),
                now.begin() + static_cast<std::ptrdiff_t>(from));
    }
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = image(w, i, looks[i], bugs);
  return out;
}

const std::vector<ScaleEntry>& scale_gallery() {
  using Broad = ScaleBugs::Broad;
  static const std::vector<ScaleEntry> entries{
      {"contact-slots", "keeps the first 8 contacts of a circle, in index order", {.contact_slots = 8}, 10},
      {"radius-sample", "sizes its grid's cells from the radii of the first 64 circles", {.radius_sample = 64}, 65},
      {"strip-reach", "looks as far as its own strip's largest diameter, of 4 strips along x", {.strips = 4}, 65},
      {"barrier-free", "updates 4 chunks of the index order in place, one after another", {.barrier_free = 4}, 65},
      {"cell-capacity", "holds at most 16 circles in a grid cell", {.cell_capacity = 16}, 65},
      {"index-bits", "keeps the least contact's index in 8 bits", {.index_bits = 8}, 257},
      {"block-sort", "sorts along x in blocks of 256 circles, never merged",
       {.broad = Broad::sweep, .sort_block = 256}, 257},
      {"sweep-window", "looks at most 32 circles ahead in x order", {.broad = Broad::sweep, .sweep_window = 32}, 65},
      {"simd-remainder", "skips the contacts of the last circles, past the last whole block of 8",
       {.simd_width = 8}, 65},
      {"kept-pairs", "keeps the last request's candidate pairs when the count matches", {.keeps_pairs = true}, 65},
  };
  return entries;
}

const std::vector<ScaleEntry>& swarm_gallery() {
  static const std::vector<ScaleEntry> entries{
      {"pow2-cell", "rounds its grid's cell side down to a power of two", {.pow2_cell = true}, 65},
      {"tight-filter", "decides a pair in doubles unless within 10^-18 of tangency, 100 times too tight",
       {.filter_bound = 1e-18}, 65},
      {"approx-tangent", "takes d^2 <= (r_a + r_b)^2 (1 + 2^-50), in doubles, for touching", {.approx_tangent = true}, 65},
      {"float32-filter", "drops a pair that float32 arithmetic puts apart", {.float32_filter = true}, 65},
      {"zero-radius-skip", "leaves circles of radius 0 out of its broad phase", {.skip_zero_radius = true}, 65},
      {"same-centre-skip", "takes a circle at the same centre for the circle itself", {.skip_same_centre = true}, 65},
      {"position-order", "orders contacts by position alone, not velocity and radius", {.position_order = true}, 65},
      {"flush-subnormal", "writes a next position below DBL_MIN as 0", {.flush_subnormal = true}, 65},
      {"index-halves", "above 20,000 circles, two threads by index never merged", {.index_halves = 20000}, 20001},
      {"space-halves", "above 30,000 circles, two threads by y never merged", {.space_halves = 30000}, 30001},
      {"verlet-skin", "keeps its pairs within a skin of half the largest radius while no circle moved that far "
       "since the last request, not since the list was built", {.verlet_skin = 0.5}, 65},
  };
  return entries;
}

const ScaleEntry* find_scale_entry(std::string_view name) {
  static const ScaleEntry optimized{"optimized", "the correct optimized step", {}, 0};
  if (name == optimized.name) return &optimized;
  for (const auto* gallery : {&scale_gallery(), &swarm_gallery()})
    for (const ScaleEntry& e : *gallery)
      if (e.name == name) return &e;
  return nullptr;
}

}  // namespace circles::testing
