// Strips, and sort and sweep on x within each; the conservativeness argument is in broad_phase.hpp.
#include "impl/broad_phase.hpp"

#include "impl/predicate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace circles::impl {

// RN(x − r) is one of the two doubles that bracket the exact x − r (or −∞ past the overflow threshold), so
// the next double below it is ≤ x − r: if RN(x − r) ≥ x − r, then the double below it is the lower bracket
// or lower still. The step costs a few ulps of width and needs no rounding-mode change. x, r finite: no NaN.
double outward_lower(double x, double r) noexcept {
  return std::nextafter(x - r, -std::numeric_limits<double>::infinity());
}

// The mirror image of outward_lower: the double above RN(x + r) is ≥ x + r.
double outward_upper(double x, double r) noexcept {
  return std::nextafter(x + r, std::numeric_limits<double>::infinity());
}

void BroadPhase::sort_members(std::size_t begin, std::size_t end) {
  // The keys (xlo, index) sit beside the members, so the sort reads contiguous memory.
  const auto before = [](const Member& a, const Member& b) { return a.xlo < b.xlo || (a.xlo == b.xlo && a.k < b.k); };
  // Insertion sort from the previous step's order, with a budget of moves linear in the segment; a segment
  // that moved far (or a first step) falls back to std::sort.
  std::size_t budget = 8 * (end - begin) + 64;
  for (std::size_t a = begin + 1; a < end; ++a) {
    const Member m = member_[a];
    std::size_t b = a;
    while (b > begin && before(m, member_[b - 1])) {
      member_[b] = member_[b - 1];
      --b;
      if (--budget == 0) {
        member_[b] = m;
        std::sort(member_.begin() + static_cast<std::ptrdiff_t>(begin),
                  member_.begin() + static_cast<std::ptrdiff_t>(end), before);
        return;
      }
    }
    member_[b] = m;
  }
}

std::size_t BroadPhase::strip_of(double y) const noexcept {
  // Monotone in y: y ↦ RN(y − y0) ↦ RN(·/h) are monotone (h > 0 finite, y0 finite, so no NaN), and so are the
  // clamp and the truncation. Accuracy does not matter, only monotonicity (broad_phase.hpp, step 4).
  const double t = (y - strip_origin_) / strip_height_;
  if (!(t > 0)) return 0;
  if (t >= static_cast<double>(strip_count_ - 1)) return strip_count_ - 1;
  return static_cast<std::size_t>(t);
}

void BroadPhase::choose_strips() {
  const std::size_t n = xlo_.size();
  strip_count_ = 1;
  strip_origin_ = 0;
  strip_height_ = 1;
  // The strip height: kStripDiameters times the median box width, so a strip holds a few circles' worth of
  // height; the count is capped at about n, which bounds memory for sparse worlds of huge extent.
  widths_.resize(n);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t k = 0; k < n; ++k) {
    widths_[k] = xhi_[k] - xlo_[k];
    if (std::isfinite(ylo_[k])) lo = std::min(lo, ylo_[k]);
    if (std::isfinite(yhi_[k])) hi = std::max(hi, yhi_[k]);
  }
  if (n < kStripsFrom || !(lo < hi)) return;
  std::nth_element(widths_.begin(), widths_.begin() + static_cast<std::ptrdiff_t>(n / 2), widths_.end());
  const double range = hi - lo;
  double height = kStripDiameters * widths_[n / 2];
  if (!std::isfinite(range) || !std::isfinite(height) || !(height > 0)) return;
  const double cap = static_cast<double>(n);
  if (range / height > cap) height = range / cap;
  if (!std::isfinite(height) || !(height > 0)) return;
  strip_origin_ = lo;
  strip_height_ = height;
  strip_count_ = static_cast<std::size_t>(std::min(cap, std::ceil(range / height))) + 1;
}

void BroadPhase::candidates(std::span<const double> px, std::span<const double> py, std::span<const double> r,
                            std::vector<CandidatePair>& out) {
  const std::size_t n = px.size();
  if (py.size() != n || r.size() != n)
    throw std::invalid_argument("BroadPhase::candidates: px, py and r differ in size");
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("BroadPhase::candidates: more than 2^32 - 1 circles");
  out.clear();

  // Step 2 of the argument: boxes that contain the exact ones.
  xlo_.resize(n);
  xhi_.resize(n);
  ylo_.resize(n);
  yhi_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    xlo_[k] = outward_lower(px[k], r[k]);
    xhi_[k] = outward_upper(px[k], r[k]);
    ylo_[k] = outward_lower(py[k], r[k]);
    yhi_[k] = outward_upper(py[k], r[k]);
  }

  choose_strips();

  // Step 4: circle k is a member of strips strip_of(ylo_k) … strip_of(yhi_k). A counting sort by strip,
  // filled in the previous step's order, then each strip sorted by (xlo, index): circles move little per
  // step, so each strip is nearly sorted already.
  if (order_.size() != n) {
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), std::uint32_t{0});
  }
  // A circle that would join more than kMaxSpan strips is wide: it joins none, and is paired below by a scan
  // of all circles, so memory stays linear when a few circles are far larger than the median.
  first_strip_.resize(n);
  last_strip_.resize(n);
  wide_.clear();
  is_wide_.assign(n, 0);
  strip_start_.assign(strip_count_ + 1, 0);
  for (std::size_t k = 0; k < n; ++k) {
    first_strip_[k] = strip_of(ylo_[k]);
    last_strip_[k] = strip_of(yhi_[k]);
    if (last_strip_[k] - first_strip_[k] >= kMaxSpan) {
      wide_.push_back(static_cast<std::uint32_t>(k));
      is_wide_[k] = 1;
      continue;
    }
    for (std::size_t s = first_strip_[k]; s <= last_strip_[k]; ++s) ++strip_start_[s + 1];
  }
  for (std::size_t s = 0; s < strip_count_; ++s) strip_start_[s + 1] += strip_start_[s];
  const std::size_t members = strip_start_[strip_count_];
  member_.resize(members);
  fill_.assign(strip_start_.begin(), strip_start_.end() - 1);
  for (const std::uint32_t k : order_)
    if (!is_wide_[k])
      for (std::size_t s = first_strip_[k]; s <= last_strip_[k]; ++s) member_[fill_[s]++] = Member{xlo_[k], k};
  for (std::size_t s = 0; s < strip_count_; ++s) sort_members(strip_start_[s], strip_start_[s + 1]);
  sorted_xlo_.resize(members);
  sorted_xhi_.resize(members);
  sorted_ylo_.resize(members);
  sorted_yhi_.resize(members);
  sorted_first_.resize(members);
  order_.clear();
  for (std::size_t s = 0; s < strip_count_; ++s) {
    for (std::size_t a = strip_start_[s]; a < strip_start_[s + 1]; ++a) {
      const std::uint32_t k = member_[a].k;
      sorted_xlo_[a] = xlo_[k];
      sorted_xhi_[a] = xhi_[k];
      sorted_ylo_[a] = ylo_[k];
      sorted_yhi_[a] = yhi_[k];
      sorted_first_[a] = first_strip_[k];
      // The next step's fill order: each circle once, at its first strip, in (strip, xlo, index) order.
      if (first_strip_[k] == s) order_.push_back(k);
    }
  }
  order_.insert(order_.end(), wide_.begin(), wide_.end());

  // Step 3 within each strip: its members are sorted by xlo, so every member whose x interval meets a's and
  // that follows a lies in one run after a, ended by the first xlo beyond xhi_a. Comparisons are exact and
  // ±∞ compare as ordered numbers, so an overflowed bound only widens the run. Step 4's rule keeps the pair
  // in one strip only: the strip of max(ylo_i, ylo_j), which is max(first strip of i, first strip of j).
  for (std::size_t s = 0; s < strip_count_; ++s) {
    const std::size_t end = strip_start_[s + 1];
    for (std::size_t a = strip_start_[s]; a < end; ++a) {
      const double xhi = sorted_xhi_[a];
      const double ylo = sorted_ylo_[a];
      const double yhi = sorted_yhi_[a];
      const std::size_t first = sorted_first_[a];
      for (std::size_t b = a + 1; b < end && sorted_xlo_[b] <= xhi; ++b) {
        if (sorted_ylo_[b] <= yhi && ylo <= sorted_yhi_[b] && std::max(first, sorted_first_[b]) == s) {
          const std::uint32_t i = member_[a].k;
          const std::uint32_t j = member_[b].k;
          out.push_back(i < j ? CandidatePair{i, j} : CandidatePair{j, i});
        }
      }
    }
  }

  // Wide circles, by steps 1 and 2 alone: each is box-tested against every other circle. A pair of two wide
  // circles is reported by the one with the lower index; a wide circle is in no strip, so no pair is reported
  // twice. Cost n per wide circle.
  for (const std::uint32_t w : wide_) {
    for (std::size_t k = 0; k < n; ++k) {
      if (k == w || (is_wide_[k] && k < w)) continue;
      if (xlo_[k] <= xhi_[w] && xlo_[w] <= xhi_[k] && ylo_[k] <= yhi_[w] && ylo_[w] <= yhi_[k]) {
        const auto j = static_cast<std::uint32_t>(k);
        out.push_back(w < j ? CandidatePair{w, j} : CandidatePair{j, w});
      }
    }
  }
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

}  // namespace circles::impl
