// The double engine's step; the invariant is stated in engine.hpp.
#include "impl/engine.hpp"

#include "impl/predicate.hpp"
#include "impl/rounding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circles::impl {
namespace {

// No contact: circle k keeps its own velocity.
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// Records that circle a intersects circle b: b becomes a's least contact if it precedes the current one.
void offer(const World& w, std::vector<std::size_t>& least, std::size_t a, std::size_t b) {
  if (least[a] == kNone || w.precedes(b, least[a])) least[a] = b;
}

// The rest of the step once every circle's least contact is known, all from the old world `w`:
// v_new[k] = v[least[k]] (or v[k]), p_new[k] = RN(p[k] + v_new[k]/60). Writes the next arrays and returns
// normally only if every new position is finite; otherwise throws PositionOverflow for the first circle
// (lowest index, px before py) at fault, before anything of `w` is changed.
void finish(const World& w, const std::vector<std::size_t>& least, std::vector<double>& vx, std::vector<double>& vy,
            std::vector<double>& px, std::vector<double>& py) {
  const std::size_t n = w.size();
  vx.resize(n);
  vy.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t s = least[k] == kNone ? k : least[k];
    vx[k] = w.vx()[s];
    vy[k] = w.vy()[s];
  }
  px.assign(w.px().begin(), w.px().end());
  py.assign(w.py().begin(), w.py().end());
  advance_rounded(std::span<double>(px), std::span<const double>(vx));
  advance_rounded(std::span<double>(py), std::span<const double>(vy));
  // Inputs are finite, so advance_rounded gives ±inf only on a correctly rounded overflow, never NaN.
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(px[k])) throw PositionOverflow(k, "px");
    if (!std::isfinite(py[k])) throw PositionOverflow(k, "py");
  }
}

}  // namespace

World::World(const std::vector<std::array<double, 5>>& circles) {
  const std::size_t n = circles.size();
  for (std::size_t k = 0; k < n; ++k) spec::check_doubles(circles[k], k, spec::Radii::non_negative);
  px_.resize(n);
  py_.resize(n);
  vx_.resize(n);
  vy_.resize(n);
  r_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    px_[k] = circles[k][0];
    py_[k] = circles[k][1];
    vx_[k] = circles[k][2];
    vy_[k] = circles[k][3];
    r_[k] = circles[k][4];
  }
}

std::vector<std::array<double, 5>> World::circles() const {
  std::vector<std::array<double, 5>> out(size());
  for (std::size_t k = 0; k < size(); ++k) out[k] = {px_[k], py_[k], vx_[k], vy_[k], r_[k]};
  return out;
}

bool World::precedes(std::size_t a, std::size_t b) const noexcept {
  // Each key is decided by exact comparisons of doubles; equal values (−0 and +0 included) pass to the next.
  for (const std::vector<double>* key : {&px_, &py_, &vx_, &vy_, &r_}) {
    const double x = (*key)[a];
    const double y = (*key)[b];
    if (x < y) return true;
    if (y < x) return false;
  }
  return a < b;
}

PositionOverflow::PositionOverflow(std::size_t i, const char* f)
    : std::overflow_error("circle " + std::to_string(i) + ", field " + f +
                          ": the position p + v/60 overflows to infinity"),
      index(i),
      field(f) {}

void Engine::step() {
  const World& w = world_;
  const std::size_t n = w.size();
  broad_.candidates(w.px(), w.py(), w.r(), pairs_);
  least_.assign(n, kNone);
  // Narrow phase: the broad phase lists each pair once and (3) is symmetric, so one exact test serves both
  // circles. The least contact does not depend on the order in which contacts are offered: precedes is a
  // strict total order.
  for (const CandidatePair& c : pairs_) {
    if (intersect_exact(w.px_[c.i], w.py_[c.i], w.r_[c.i], w.px_[c.j], w.py_[c.j], w.r_[c.j])) {
      offer(w, least_, c.i, c.j);
      offer(w, least_, c.j, c.i);
    }
  }
  finish(w, least_, next_vx_, next_vy_, next_px_, next_py_);
  // Commit: nothing of world_ changed before here, so a PositionOverflow leaves it as it was.
  std::swap(world_.px_, next_px_);
  std::swap(world_.py_, next_py_);
  std::swap(world_.vx_, next_vx_);
  std::swap(world_.vy_, next_vy_);
}

World step_all_pairs(const World& w) {
  const std::size_t n = w.size();
  std::vector<std::size_t> least(n, kNone);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (intersect_exact(w.px_[a], w.py_[a], w.r_[a], w.px_[b], w.py_[b], w.r_[b])) {
        offer(w, least, a, b);
        offer(w, least, b, a);
      }
  World next = w;
  finish(w, least, next.vx_, next.vy_, next.px_, next.py_);
  return next;
}

}  // namespace circles::impl
