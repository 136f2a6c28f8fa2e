// The exact grid reference; its invariant is stated in exact_grid_reference.hpp.
//
// Why the 3×3 neighbourhood of the rounded centres finds every intersecting pair. The cells are those of
// step_grid (grid_reference.cpp), taken over x̃ = RN(x), the nearest double of each exact coordinate x, and
// with ρ = RN(r) for each radius. Every x̃ and ρ is finite (the constructor refuses an infinite one and a step
// that would make one throws), so x̃ lies within half an ulp of its binade of x:
//   |x̃ − x| ≤ 2^-53·|x̃| + 2^-1075,   r ≤ ρ·(1 + 2^-53) + 2^-1075   (2^-1075: half the subnormal spacing).
// Let P = max ρ and h = 4P (h = 1 when P = 0), used only when finite, h ≥ kExactGridMinSide = 2^-1000 and each
// RN(|x̃|/h) ≤ kGridMaxCell = 2^40 (so |x̃| ≤ 2^41·h). If circles a and b intersect by (3), then in each
// coordinate |x_b − x_a| ≤ r_a + r_b ≤ 2P·(1 + 2^-53) + 2^-1074, which is h/2·(1 + 2^-53) + 2^-1074 when
// P > 0, and at most 2^-1074 ≤ h/2 when P = 0 (every r ≤ 2^-1075). Then
//   |x̃_b − x̃_a| ≤ |x_b − x_a| + |x̃_a − x_a| + |x̃_b − x_b|
//              ≤ h·(1/2 + 2^-54) + 2^-1074 + 2·(2^-53·2^41·h + 2^-1075) = h·(1/2 + 2^-54 + 2^-11) + 2^-1073,
// and with h ≥ 2^-1000, |x̃_b − x̃_a|/h ≤ 1/2 + 2^-54 + 2^-11 + 2^-73 < 1/2 + 2^-10. A cell is ⌊q⌋ with
// q = RN(x̃/h), within u·2^41 = 2^-12 of x̃/h (or 2^-1075 when the quotient underflows), so
// |q_b − q_a| < 1/2 + 2^-10 + 2^-11 < 1: the floors differ by at most 1, and b's cell is one of the 3×3 around
// a's. Below 2^-1000 the term 2^-1073/h is no longer negligible, and every pair is asked instead.
#include "impl/exact_grid_reference.hpp"

#include "impl/grid_reference.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

namespace circles::impl {
namespace {

using exact::raw;
using exact::Wide;
using spec::Circles;

}  // namespace

std::optional<double> exact_grid_side(const Circles& rounded) {
  double radius = 0;
  for (const auto& c : rounded) radius = std::max(radius, c[4]);
  const auto centre = [&rounded](std::size_t k) { return std::array{rounded[k][0], rounded[k][1]}; };
  const std::optional<double> h = uniform_side(radius, rounded.size(), centre);
  if (!h || !(*h >= kExactGridMinSide)) return std::nullopt;
  return h;
}

ExactGrid::ExactGrid(const Circles& w0) : ExactGrid(spec::from_doubles(w0, spec::Radii::non_negative)) {}

ExactGrid::ExactGrid(const spec::Sequence& w0) {
  const std::size_t n = w0.size();
  exact::Scaled scaled = exact::scale(w0);
  rounded_ = std::move(scaled.rounded);
  den_ = std::move(scaled.den);
  den_v_ = std::move(scaled.den_v);
  std::vector<Wide>* columns[5] = {&x_, &y_, &vx_, &vy_, &r_};
  for (std::size_t f = 0; f < 5; ++f) columns[f]->swap(scaled.columns[f]);
  for (auto* field : {&next_x_, &next_y_, &next_vx_, &next_vy_}) field->resize(n);
  next_rounded_.resize(n);
  error_.resize(n);
}

// Inlined into the grid's walk, the filter decides all but near-tangent pairs in a few operations.
[[gnu::always_inline]] inline bool ExactGrid::intersect(std::size_t a, std::size_t b) {
  const auto& p = rounded_[a];
  const auto& q = rounded_[b];
  const Decision filtered = exact::intersect_approximate(p[0], p[1], p[4], error_[a], q[0], q[1], q[4], error_[b]);
  if (filtered != Decision::undecided) return filtered == Decision::intersect;
  return intersect_exactly(a, b);
}

bool ExactGrid::intersect_exactly(std::size_t a, std::size_t b) {
  mpz_add(raw(sum_), raw(r_[a]), raw(r_[b]));
  mpz_sub(raw(dx_), raw(x_[b]), raw(x_[a]));
  mpz_sub(raw(dy_), raw(y_[b]), raw(y_[a]));
  return exact::intersect_scaled(sum_, dx_, dy_);
}

bool ExactGrid::precedes(std::size_t a, std::size_t b) const noexcept {
  for (const auto* field : {&x_, &y_, &vx_, &vy_, &r_})
    if (const int s = mpz_cmp(raw((*field)[a]), raw((*field)[b]))) return s < 0;
  return a < b;
}

void ExactGrid::step() {
  const std::size_t n = size();
  // Each circle's least contact, itself while it has none: u(h(c, c)) = u(c) is then f's second case.
  std::vector<std::size_t> least(n);
  std::iota(least.begin(), least.end(), std::size_t{0});
  const auto offer = [&](std::size_t a, std::size_t b) {
    if (intersect(a, b)) {
      if (least[a] == a || precedes(b, least[a])) least[a] = b;
      if (least[b] == b || precedes(a, least[b])) least[b] = a;
    }
  };
  for (std::size_t k = 0; k < n; ++k) {
    const auto& c = rounded_[k];
    error_[k] = std::max(std::max(std::fabs(c[0]), std::fabs(c[1])), c[4]) * kNearestRelative;
    error_[k] = std::max(error_[k], kNearestFloor);
  }
  if (const std::optional<double> h = exact_grid_side(rounded_)) {
    for_each_neighbour_pair(n, *h, [this](std::size_t k) { return std::array{rounded_[k][0], rounded_[k][1]}; },
                            offer);
  } else {
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) offer(a, b);
  }
  // f(c, W) = u(h(c, e)): X ← X + V_e, V ← V_e; the radius stays.
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t e = least[k];
    mpz_add(raw(next_x_[k]), raw(x_[k]), raw(vx_[e]));
    mpz_add(raw(next_y_[k]), raw(y_[k]), raw(vy_[e]));
    mpz_set(raw(next_vx_[k]), raw(vx_[e]));
    mpz_set(raw(next_vy_[k]), raw(vy_[e]));
    const double px = exact::round_quotient(next_x_[k], den_), py = exact::round_quotient(next_y_[k], den_);
    if (std::isinf(px)) throw PositionOverflow(steps_ + 1, k, spec::Field::px);
    if (std::isinf(py)) throw PositionOverflow(steps_ + 1, k, spec::Field::py);
    // v_e's nearest double is e's, since the velocity is a copy.
    next_rounded_[k] = {px, py, rounded_[e][2], rounded_[e][3], rounded_[k][4]};
  }
  std::swap(x_, next_x_);
  std::swap(y_, next_y_);
  std::swap(vx_, next_vx_);
  std::swap(vy_, next_vy_);
  std::swap(rounded_, next_rounded_);
  ++steps_;
}

spec::Sequence ExactGrid::exact() const {
  spec::Sequence out;
  out.reserve(size());
  const spec::Q d(den_), l(den_v_);
  for (std::size_t k = 0; k < size(); ++k)
    out.push_back(spec::circle(spec::Q(x_[k]) / d, spec::Q(y_[k]) / d, spec::Q(vx_[k]) / l, spec::Q(vy_[k]) / l,
                               spec::Q(r_[k]) / d));
  return out;
}

spec::Sequence step_grid(const spec::Sequence& w) {
  ExactGrid grid(w);
  grid.step();
  return grid.exact();
}

}  // namespace circles::impl
