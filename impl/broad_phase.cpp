// The cell grid and the cell order; the conservativeness argument is in broad_phase.hpp.
#include "impl/broad_phase.hpp"

#include "impl/predicate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace circles::impl {

void CellGrid::plan(std::span<const double> px, std::span<const double> py, std::span<const double> r) {
  const std::size_t n = px.size();
  if (py.size() != n || r.size() != n) throw std::invalid_argument("CellGrid::plan: px, py and r differ in size");
  double xlo = std::numeric_limits<double>::infinity(), ylo = xlo, xhi = -xlo, yhi = -xlo;
  std::vector<double> widths;
  widths.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double a = outward_lower(px[k], r[k]), b = outward_upper(px[k], r[k]);
    const double c = outward_lower(py[k], r[k]), d = outward_upper(py[k], r[k]);
    if (std::isfinite(b - a)) widths.push_back(b - a);
    if (std::isfinite(a)) xlo = std::min(xlo, a);
    if (std::isfinite(b)) xhi = std::max(xhi, b);
    if (std::isfinite(c)) ylo = std::min(ylo, c);
    if (std::isfinite(d)) yhi = std::max(yhi, d);
  }
  // The base cell: the largest width within kWidthSpread medians (0 for an empty world).
  double base = 0;
  if (!widths.empty()) {
    const auto middle = widths.begin() + static_cast<std::ptrdiff_t>(widths.size() / 2);
    std::nth_element(widths.begin(), middle, widths.end());
    const double limit = kWidthSpread * *middle;
    for (const double w : widths)
      if (w <= limit) base = std::max(base, w);
    // A box's computed width depends on where the circle is (the roundings of x ± r): a circle that moves
    // can come out an ulp wider than it was planned with, miss level 0, and make every circle search the
    // level above. kBaseSlack keeps the widest planned box inside level 0 after such moves.
    base *= kBaseSlack;
  }
  // At least the extent over kPlannedCells, so the scene fits in the grid; halves keep the extent finite.
  const double extent = std::max(xhi / 2 - xlo / 2, yhi / 2 - ylo / 2);
  if (std::isfinite(extent)) base = std::max(base, extent / (kPlannedCells / 2));
  // Keep 1/base finite and base finite: 2^-1000 and 2^1000 are far outside any width that matters here.
  base_cell_ = std::clamp(std::isfinite(base) ? base : 0x1p1000, 0x1p-1000, 0x1p1000);
  const double centre_x = std::isfinite(extent) ? xlo / 2 + xhi / 2 : 0;
  const double centre_y = std::isfinite(extent) ? ylo / 2 + yhi / 2 : 0;
  origin_x_ = centre_x - static_cast<double>(kCells / 2) * base_cell_;
  origin_y_ = centre_y - static_cast<double>(kCells / 2) * base_cell_;
  // inv_L = 4^-L / base: exact powers of two apart (or 0 once they underflow, which keeps cell() monotone).
  for (unsigned level = 0; level < kLevels; ++level)
    inverse_[level] = std::ldexp(1 / base_cell_, -2 * static_cast<int>(level));
}

void CellGrid::keys(std::span<const double> px, std::span<const double> py, std::span<const double> r,
                    std::span<CellKey> out) const noexcept {
  // The first pass is the common case: level 0, where the box is no wider than the base cell and spans at
  // most two cells on each axis, branch-free (GCC 12 does not vectorize it yet; the branches it saves are the
  // gain); int32 suffices (cells < 2^27). At level 0, inv_0 ∈ [2^-1000, 2^1000]
  // and v − o is finite or ±∞, so the product is never NaN and the clamps can be branch-free ?: forms.
  // A misfit is marked by a key no circle has (real keys use the low 60 bits), then redone.
  constexpr CellKey kMisfit = ~CellKey{0};
  const std::size_t n = out.size();
  const double inv = inverse_[0], ox = origin_x_, oy = origin_y_;
  for (std::size_t t = 0; t < n; ++t) {
    const double x = px[t], y = py[t], radius = r[t];
    const double xlo = outward_lower(x, radius), xhi = outward_upper(x, radius);
    const double ylo = outward_lower(y, radius), yhi = outward_upper(y, radius);
    const auto at0 = [inv](double v, double origin) {
      double c = (v - origin) * inv;
      c = c > 0 ? c : 0;
      c = c < kLastCell ? c : kLastCell;
      return static_cast<std::int32_t>(c);
    };
    const std::int32_t cx = at0(xlo, ox), cy = at0(ylo, oy), cx1 = at0(xhi, ox), cy1 = at0(yhi, oy);
    const bool fits = ((xhi - xlo) * inv <= 1) & (cx1 - cx <= 1) & (cy1 - cy <= 1);
    const CellKey key = pack(0, static_cast<std::uint32_t>(cy), static_cast<std::uint32_t>(cx));
    out[t] = fits ? key : kMisfit;
  }
  for (std::size_t t = 0; t < n; ++t)
    if (out[t] == kMisfit) [[unlikely]]
      out[t] = key_at_any_level(outward_lower(px[t], r[t]), outward_upper(px[t], r[t]), outward_lower(py[t], r[t]),
                                outward_upper(py[t], r[t]));
}

CellKey CellGrid::key_at_any_level(double xlo, double xhi, double ylo, double yhi) const noexcept {
  // Start at the least level whose cell is at least the box's width in base cells, q = width·inv_0:
  // 4^L ≥ q for L = ⌈log4 q⌉ = ⌈(ilogb(q) + 1)/2⌉ (q < 2^(ilogb(q)+1)). Only a start: the span check decides.
  const double q = (xhi - xlo) * inverse_[0];
  unsigned level = 0;
  if (q > 1) level = static_cast<unsigned>(std::min((std::min(std::ilogb(q), 256) + 2) / 2, int{kGlobalLevel}));
  for (; level < kGlobalLevel; ++level) {
    const std::uint32_t cx = cell_of_x(xlo, level);
    if (cell_of_x(xhi, level) > cx + 1) continue;
    const std::uint32_t cy = cell_of_y(ylo, level);
    if (cell_of_y(yhi, level) > cy + 1) continue;
    return pack(level, cy, cx);
  }
  return pack(kGlobalLevel, 0, 0);
}

CellGrid::Range CellGrid::neighbourhood(double x, double y, double r, unsigned level) const noexcept {
  // Step 4 of the argument: [cell(xlo) − 1, cell(xhi)] × [cell(ylo) − 1, cell(yhi)], clamped at 0.
  const std::uint32_t x0 = cell_of_x(outward_lower(x, r), level), y0 = cell_of_y(outward_lower(y, r), level);
  return Range{x0 > 0 ? x0 - 1 : 0, cell_of_x(outward_upper(x, r), level), y0 > 0 ? y0 - 1 : 0,
               cell_of_y(outward_upper(y, r), level)};
}

bool CellOrder::sort(std::span<const CellKey> keys, std::span<const CellKey> previous,
                     std::vector<std::uint32_t>& order) {
  const std::size_t n = keys.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("CellOrder::sort: more than 2^32 - 1 slots");
  order.resize(n);
  // Already sorted (a quiet world, or one whose circles all kept their cells): the identity.
  if (std::is_sorted(keys.begin(), keys.end())) {
    for (std::size_t s = 0; s < n; ++s) order[s] = static_cast<std::uint32_t>(s);
    return true;
  }
  const auto before = [](const Entry& a, const Entry& b) { return a.key < b.key || (a.key == b.key && a.slot < b.slot); };
  // Split by how far each slot's band moved since `previous`, which was sorted: the slots that kept their band
  // are in band order, and within a band nearly in (column, row) order (a circle moves by one cell at most,
  // for most); so are those that moved one band up, and one band down. Each such list needs only local
  // repair.
  same_.clear();
  up_.clear();
  down_.clear();
  other_.clear();
  const bool guided = previous.size() == n;
  for (std::size_t s = 0; s < n; ++s) {
    const Entry e{keys[s], static_cast<std::uint32_t>(s)};
    if (guided) {
      // The band with the level above it: a change of level is never a neighbouring band.
      const CellKey now = CellGrid::band(keys[s]), then = CellGrid::band(previous[s]);
      if (now == then) {
        same_.push_back(e);
        continue;
      }
      if (now == then + 1 && CellGrid::level(keys[s]) == CellGrid::level(previous[s])) {
        up_.push_back(e);
        continue;
      }
      if (now + 1 == then && CellGrid::level(keys[s]) == CellGrid::level(previous[s])) {
        down_.push_back(e);
        continue;
      }
    }
    other_.push_back(e);
  }
  // Insertion sort with a budget of moves linear in the list; past it, std::sort.
  const auto repair = [&before](std::vector<Entry>& list) {
    std::size_t budget = 8 * list.size() + 64;
    for (std::size_t a = 1; a < list.size(); ++a) {
      const Entry e = list[a];
      std::size_t b = a;
      while (b > 0 && before(e, list[b - 1])) {
        list[b] = list[b - 1];
        --b;
        if (--budget == 0) {
          list[b] = e;
          std::sort(list.begin(), list.end(), before);
          return;
        }
      }
      list[b] = e;
    }
  };
  repair(same_);
  repair(up_);
  repair(down_);
  std::sort(other_.begin(), other_.end(), before);
  // Merge the small lists first, then the large one once. (key, slot) is a total order, so the result does
  // not depend on how the lists were formed.
  spare_.resize(up_.size() + down_.size());
  std::merge(up_.begin(), up_.end(), down_.begin(), down_.end(), spare_.begin(), before);
  merged_.resize(spare_.size() + other_.size());
  std::merge(spare_.begin(), spare_.end(), other_.begin(), other_.end(), merged_.begin(), before);
  std::size_t a = 0, b = 0, out = 0;
  while (a < same_.size() && b < merged_.size())
    order[out++] = before(merged_[b], same_[a]) ? merged_[b++].slot : same_[a++].slot;
  while (a < same_.size()) order[out++] = same_[a++].slot;
  while (b < merged_.size()) order[out++] = merged_[b++].slot;
  return false;
}

bool candidates_cover_all_intersecting_pairs(std::span<const double> px, std::span<const double> py,
                                             std::span<const double> r, std::span<const CandidatePair> candidates) {
  const std::size_t n = px.size();
  if (py.size() != n || r.size() != n)
    throw std::invalid_argument("candidates_cover_all_intersecting_pairs: px, py and r differ in size");
  std::vector<CandidatePair> have;
  have.reserve(candidates.size());
  for (const CandidatePair& c : candidates) have.push_back(c.i < c.j ? c : CandidatePair{c.j, c.i});
  std::sort(have.begin(), have.end());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (intersect_exact(px[i], py[i], r[i], px[j], py[j], r[j]) &&
          !std::binary_search(have.begin(), have.end(),
                              CandidatePair{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)}))
        return false;
  return true;
}

void index_levels(std::span<const CellKey> key, std::array<std::size_t, CellGrid::kLevels + 1>& level_begin,
                  std::vector<unsigned>& levels) {
  levels.clear();
  for (unsigned level = 0; level <= CellGrid::kLevels; ++level) {
    const CellKey first = level == CellGrid::kLevels ? std::numeric_limits<CellKey>::max() : CellGrid::pack(level, 0, 0);
    level_begin[level] = level == CellGrid::kLevels
                             ? key.size()
                             : static_cast<std::size_t>(std::lower_bound(key.begin(), key.end(), first) - key.begin());
  }
  for (unsigned level = 0; level < CellGrid::kGlobalLevel; ++level)
    if (level_begin[level] < level_begin[level + 1]) levels.push_back(level);
}

}  // namespace circles::impl
