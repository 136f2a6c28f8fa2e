// The yardsticks of bench/baselines.hpp.
#include "bench/baselines.hpp"

#include "impl/arithmetic.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

namespace circles::bench {
namespace {

using Naive = impl::NaiveArithmetic;

// No contact: the circle keeps its own velocity.
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A dense grid beyond this many cells (1 GiB of offsets) is not a benchmark scene; refuse it.
constexpr std::size_t kMaxCells = std::size_t{1} << 28;

// Slot a precedes slot b: lexicographic on (px, py, vx, vy, r), −0 == +0, then by circle index.
bool precedes(const Arrays& w, std::uint32_t a, std::uint32_t b) {
  for (const std::vector<double>* key : {&w.px, &w.py, &w.vx, &w.vy, &w.r}) {
    if ((*key)[a] < (*key)[b]) return true;
    if ((*key)[b] < (*key)[a]) return false;
  }
  return w.id[a] < w.id[b];
}

// The naive test of (3) between slots a and b; symmetric, since dx and −dx have the same square.
bool touch(const Arrays& w, std::uint32_t a, std::uint32_t b) {
  return Naive::intersect(w.px[a], w.py[a], w.r[a], w.px[b], w.py[b], w.r[b]);
}

// Slot a's circle intersects slot b's: b becomes a's least contact if it precedes the current one.
void offer(const Arrays& w, std::vector<std::uint32_t>& least, std::uint32_t a, std::uint32_t b) {
  if (least[a] == kNone || precedes(w, b, least[a])) least[a] = b;
}

// The rest of the step once every slot's least contact is known: v ← v[least], then p ← p + v·RN(1/60).
void finish(Arrays& w, const std::vector<std::uint32_t>& least, std::vector<double>& vx, std::vector<double>& vy) {
  const std::size_t n = w.size();
  vx.resize(n);
  vy.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t s = least[k] == kNone ? k : least[k];
    vx[k] = w.vx[s];
    vy[k] = w.vy[s];
  }
  w.vx.swap(vx);
  w.vy.swap(vy);
  Naive::advance(std::span<double>(w.px), std::span<const double>(w.vx));
  Naive::advance(std::span<double>(w.py), std::span<const double>(w.vy));
}

}  // namespace

Arrays::Arrays(const Circles& circles) {
  if (circles.size() >= kNone) throw std::length_error("bench::Arrays: 2^32 - 1 circles or more");
  resize(circles.size());
  for (std::size_t k = 0; k < circles.size(); ++k) {
    px[k] = circles[k][0];
    py[k] = circles[k][1];
    vx[k] = circles[k][2];
    vy[k] = circles[k][3];
    r[k] = circles[k][4];
    id[k] = static_cast<std::uint32_t>(k);
  }
}

void Arrays::resize(std::size_t n) {
  for (std::vector<double>* a : {&px, &py, &vx, &vy, &r}) a->resize(n);
  id.resize(n);
}

Circles Arrays::circles() const {
  Circles out(size());
  for (std::size_t t = 0; t < size(); ++t) out[id[t]] = {px[t], py[t], vx[t], vy[t], r[t]};
  return out;
}

AllPairsNaive::AllPairsNaive(const Circles& circles) : w_(circles) {}

void AllPairsNaive::step() {
  const auto n = static_cast<std::uint32_t>(w_.size());
  least_.assign(n, kNone);
  // The test is symmetric, so each unordered pair is tested once for both sides' offers.
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (touch(w_, a, b)) {
        offer(w_, least_, a, b);
        offer(w_, least_, b, a);
      }
  finish(w_, least_, vx_, vy_);
}

UniformGrid::UniformGrid(const Circles& circles) : now_(circles) {}

void UniformGrid::sort_into_cells() {
  const std::size_t n = now_.size();
  double x_min = std::numeric_limits<double>::infinity(), y_min = x_min;
  double x_max = -x_min, y_max = -x_min, r_max = 0;
  for (std::size_t t = 0; t < n; ++t) {
    x_min = std::min(x_min, now_.px[t]);
    x_max = std::max(x_max, now_.px[t]);
    y_min = std::min(y_min, now_.py[t]);
    y_max = std::max(y_max, now_.py[t]);
    r_max = std::max(r_max, now_.r[t]);
  }
  // Side 2·r_max ≥ ra + rb: an intersecting pair is at most one cell apart on each axis. (Radii all 0: any
  // side works; 1 avoids dividing by 0.)
  const double inverse = r_max > 0 ? 1 / (2 * r_max) : 1;
  nx_ = n ? static_cast<std::size_t>((x_max - x_min) * inverse) + 1 : 1;
  ny_ = n ? static_cast<std::size_t>((y_max - y_min) * inverse) + 1 : 1;
  if (nx_ > kMaxCells / ny_)
    throw std::length_error("bench::UniformGrid: the centres' bounding box needs " + std::to_string(nx_) + " x " +
                            std::to_string(ny_) + " cells");
  const std::size_t cells = nx_ * ny_;

  cell_.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto cx = static_cast<std::size_t>((now_.px[t] - x_min) * inverse);
    const auto cy = static_cast<std::size_t>((now_.py[t] - y_min) * inverse);
    cell_[t] = static_cast<std::uint32_t>(cy * nx_ + cx);
  }
  // Counting sort, stable: counts land at begin_[c + 2], the prefix sums make begin_[c + 1] the start of c,
  // and placing each circle advances begin_[c + 1] to the start of c + 1.
  begin_.assign(cells + 2, 0);
  for (std::size_t t = 0; t < n; ++t) ++begin_[cell_[t] + 2];
  for (std::size_t c = 2; c < cells + 2; ++c) begin_[c] += begin_[c - 1];
  next_.resize(n);
  next_cell_.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const std::uint32_t s = begin_[cell_[t] + 1]++;
    next_.px[s] = now_.px[t];
    next_.py[s] = now_.py[t];
    next_.vx[s] = now_.vx[t];
    next_.vy[s] = now_.vy[t];
    next_.r[s] = now_.r[t];
    next_.id[s] = now_.id[t];
    next_cell_[s] = cell_[t];
  }
  std::swap(now_, next_);
  cell_.swap(next_cell_);
}

void UniformGrid::step() {
  sort_into_cells();
  const std::size_t n = now_.size();
  least_.assign(n, kNone);
  for (std::uint32_t a = 0; a < n; ++a) {
    const std::size_t cx = cell_[a] % nx_, cy = cell_[a] / nx_;
    const std::size_t x0 = cx ? cx - 1 : 0, x1 = std::min(cx + 1, nx_ - 1);
    const std::size_t y0 = cy ? cy - 1 : 0, y1 = std::min(cy + 1, ny_ - 1);
    // Cells x0..x1 of a row are consecutive, so their circles are one run of slots.
    for (std::size_t y = y0; y <= y1; ++y)
      for (std::uint32_t b = begin_[y * nx_ + x0]; b < begin_[y * nx_ + x1 + 1]; ++b)
        if (b != a && touch(now_, a, b)) offer(now_, least_, a, b);
  }
  finish(now_, least_, vx_, vy_);
}

StreamingFloor::StreamingFloor(const Circles& circles) : now_(circles), next_(circles) {}

void StreamingFloor::step() {
  const std::size_t n = now_.size();
  std::uint64_t radius_bits = 0;
  for (std::size_t k = 0; k < n; ++k) {
    next_.px[k] = now_.px[k] + now_.vx[k] * impl::rounding::kC;
    next_.py[k] = now_.py[k] + now_.vy[k] * impl::rounding::kC;
    next_.vx[k] = now_.vx[k];
    next_.vy[k] = now_.vy[k];
    radius_bits |= std::bit_cast<std::uint64_t>(now_.r[k]);
  }
  radius_bits_ = radius_bits;
  std::swap(now_.px, next_.px);
  std::swap(now_.py, next_.py);
  std::swap(now_.vx, next_.vx);
  std::swap(now_.vy, next_.vy);
}

}  // namespace circles::bench
