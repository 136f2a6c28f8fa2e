#include "fuzz/step_input.hpp"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <utility>

namespace circles::fuzz {

namespace {

std::uint64_t read_u64(std::span<const std::uint8_t> bytes) {
  std::uint64_t x = 0;
  for (std::size_t i = 0; i < 8; ++i) x |= std::uint64_t{bytes[i]} << (8 * i);
  return x;
}

void write_u64(std::vector<std::uint8_t>& out, std::uint64_t x) {
  for (std::size_t i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(x >> (8 * i)));
}

// A field of C: finite, and a radius not negative.
double field_of_c(double x, std::size_t field) {
  if (!std::isfinite(x)) return 0.0;
  return field == 4 && x < 0 ? -x : x;  // −0 stays: a radius of C
}

void keep_in_c(Circles& w) {
  if (w.size() > kMaxCircles) w.resize(kMaxCircles);
  for (auto& c : w)
    for (std::size_t f = 0; f < 5; ++f) c[f] = field_of_c(c[f], f);
}

// SplitMix64: the mutations' draws, from libFuzzer's seed.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  }
  // 0 … n − 1, n > 0.
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
  bool coin() { return (next() & 1) != 0; }

 private:
  std::uint64_t state_;
};

// The values at the spec's edges that a field is set to: the signed zeros, the least subnormal and the
// largest, DBL_MIN, 1, 1 ± ulp, 60 (a velocity that moves one unit a step), 2^512 (squares overflow), 2^1023
// and DBL_MAX.
constexpr std::array kBoundaryValues = {0.0,     -0.0, 0x1p-1074, 0x0.fffffffffffffp-1022, DBL_MIN, 1.0,
                                        0x1.0000000000001p0, 0x1.fffffffffffffp-1, 60.0, 0x1p512, 0x1p1023,
                                        DBL_MAX};

double nudged(double x, int ulps) {
  const double toward = ulps > 0 ? INFINITY : -INFINITY;
  for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, toward);
  return x;
}

// The largest power of two at most |x|, or 1 for 0 and for values whose multiples below would overflow.
double power_below(double x) {
  x = std::fabs(x);
  if (x == 0 || x > 0x1p1000) return 1.0;
  int e = 0;
  std::frexp(x, &e);
  return std::ldexp(1.0, e - 1);
}

// Two circles of w drawn for a pair mutation, a copy of the first appended when the draw names one circle twice.
std::pair<std::size_t, std::size_t> drawn_pair(Circles& w, Draw& draw) {
  const std::size_t a = draw.below(w.size());
  std::size_t b = draw.below(w.size());
  if (a == b) {
    w.push_back(w[a]);
    b = w.size() - 1;
  }
  return {a, b};
}

void make_tangent(Circles& w, Draw& draw) {
  const auto [a, b] = drawn_pair(w, draw);
  // t a power of two near a's radius: 2t + 3t along an axis, or 2t + 3t at (3t, 4t); the offsets and radii
  // are exact, the positions exact unless a's position has bits below t's.
  const double t = power_below(w[a][4]);
  const bool axis = draw.coin();
  const double sx = draw.coin() ? 1.0 : -1.0, sy = draw.coin() ? 1.0 : -1.0;
  w[a][4] = 2 * t;
  w[b][4] = 3 * t;
  w[b][0] = w[a][0] + sx * (axis ? 5 * t : 3 * t);
  w[b][1] = w[a][1] + sy * (axis ? 0.0 : 4 * t);
}

// A pair at the boundary of (3), where a filter's error bound decides: b placed at distance r_a + r_b from a in
// a direction drawn at random, so that the offsets round and F = S² − X² − Y² is a few roundings from 0 (of
// either sign, |F| of the order of 2^-52·S²); half the time then b moved by ±1 … 64 ulps on one axis, which
// spans the sliver between the filters' bounds and bounds a few powers of two lower. The pair's scale is a's
// radius, or a power of two drawn from 2^-60 … 2^60, or one near the subnormal range.
void make_nearly_tangent(Circles& w, Draw& draw) {
  const auto [a, b] = drawn_pair(w, draw);
  const std::size_t scale_kind = draw.below(4);
  const double scale = scale_kind == 0   ? std::ldexp(1.0, static_cast<int>(draw.below(121)) - 60)
                       : scale_kind == 1 ? std::ldexp(1.0, -1020 - static_cast<int>(draw.below(40)))
                                         : (w[a][4] > 0 && w[a][4] < 0x1p1000 ? w[a][4] : 1.0);
  // r_b from r_a: equal, or a ratio up to 2^±8 with all its bits.
  const double ratio = draw.coin() ? 1.0 : std::ldexp(1.0 + static_cast<double>(draw.next() >> 12) * 0x1p-52,
                                                      static_cast<int>(draw.below(17)) - 8);
  w[a][4] = scale;
  w[b][4] = scale * ratio;
  const double s = w[a][4] + w[b][4];
  const double angle = static_cast<double>(draw.next() >> 11) * 0x1p-53 * 6.283185307179586;
  w[b][0] = w[a][0] + s * std::cos(angle);
  w[b][1] = w[a][1] + s * std::sin(angle);
  if (draw.coin()) {
    double& x = w[b][draw.below(2)];
    x = nudged(x, static_cast<int>(draw.below(64) + 1) * (draw.coin() ? 1 : -1));
  }
}

// A family's world: a big family's one draw in kBigFamilyDraws, a small family's otherwise. A big world costs as
// much to judge as a hundred small ones, and once in the corpus its children are big too; the small families'
// boundaries are where most decisions are close.
constexpr std::uint64_t kBigFamilyDraws = 8;
Circles drawn_family_world(Draw& draw) {
  std::vector<properties::Family> small, big;
  for (const properties::Family f : properties::families(properties::Profile::resolved))
    (properties::is_big(f) ? big : small).push_back(f);
  const std::vector<properties::Family>& from = draw.below(kBigFamilyDraws) == 0 ? big : small;
  return family_world(from[draw.below(from.size())], draw.next());
}

}  // namespace

Circles family_world(properties::Family family, std::uint64_t seed) {
  const rc::Random random(seed);
  Circles w = properties::is_big(family)
                  ? properties::gen::big_world(family, seed % 16, kBigCircles, random)
                  : properties::gen::boundary_world(family, properties::Profile::resolved)(random, 0).value();
  keep_in_c(w);
  return w;
}

StepInput decode(std::span<const std::uint8_t> bytes) {
  StepInput input;
  if (bytes.size() < kHeaderBytes) return input;
  input.steps = 1 + bytes[0] % kMaxSteps;
  if (bytes[1] != 0) {
    const auto all = properties::families(properties::Profile::resolved);
    input.circles = family_world(all[(bytes[1] - 1u) % all.size()], read_u64(bytes.subspan(2)));
  }
  for (std::size_t at = kHeaderBytes; at + kCircleBytes <= bytes.size() && input.circles.size() < kMaxCircles;
       at += kCircleBytes) {
    spec::CircleDoubles c{};
    for (std::size_t f = 0; f < 5; ++f) c[f] = std::bit_cast<double>(read_u64(bytes.subspan(at + 8 * f)));
    input.circles.push_back(c);
  }
  keep_in_c(input.circles);
  return input;
}

std::vector<std::uint8_t> encode(const StepInput& input) {
  std::vector<std::uint8_t> out;
  out.reserve(kHeaderBytes + kCircleBytes * input.circles.size());
  out.push_back(static_cast<std::uint8_t>((input.steps - 1) % kMaxSteps));
  out.push_back(0);
  write_u64(out, 0);
  for (const auto& c : input.circles)
    for (const double x : c) write_u64(out, std::bit_cast<std::uint64_t>(x));
  return out;
}

StepInput mutate(StepInput input, std::uint64_t seed) {
  Draw draw(seed);
  Circles& w = input.circles;
  // An empty world can only grow: draw a family's world or a circle at a boundary value.
  const std::size_t kind = w.empty() ? draw.below(2) : draw.below(13);
  switch (kind) {
    case 0:
      w = drawn_family_world(draw);
      break;
    case 1: {
      spec::CircleDoubles c{};
      for (double& x : c) x = kBoundaryValues[draw.below(kBoundaryValues.size())];
      w.push_back(c);
      break;
    }
    case 2: {  // a field nudged by ±1 … 3 ulps
      const int ulps = static_cast<int>(draw.below(3) + 1) * (draw.coin() ? 1 : -1);
      double& x = w[draw.below(w.size())][draw.below(5)];
      x = nudged(x, ulps);
      break;
    }
    case 3: {  // the world scaled by 2^e, positions, velocities and radii alike, unless a field would overflow
      const int e = draw.coin() ? static_cast<int>(draw.below(17)) - 8 : static_cast<int>(draw.below(2001)) - 1000;
      Circles scaled = w;
      bool finite = true;
      for (auto& c : scaled)
        for (double& x : c) finite = finite && std::isfinite(x = std::ldexp(x, e));
      if (finite) w = std::move(scaled);
      break;
    }
    case 4: {  // a copy of a circle, exact or with one field from another circle: equal keys and ties
      auto c = w[draw.below(w.size())];
      if (draw.coin()) {
        const std::size_t f = draw.below(5);
        c[f] = w[draw.below(w.size())][f];
      }
      w.insert(w.begin() + static_cast<std::ptrdiff_t>(draw.below(w.size() + 1)), c);
      break;
    }
    case 5:
      make_tangent(w, draw);
      break;
    case 6:
      w.erase(w.begin() + static_cast<std::ptrdiff_t>(draw.below(w.size())));
      break;
    case 7:
      std::swap(w[draw.below(w.size())], w[draw.below(w.size())]);
      break;
    case 8: {
      const double v = kBoundaryValues[draw.below(kBoundaryValues.size())];
      w[draw.below(w.size())][draw.below(5)] = draw.coin() ? v : -v;
      break;
    }
    case 9: {  // one field copied from another circle: a tie in that field
      const std::size_t f = draw.below(5);
      w[draw.below(w.size())][f] = w[draw.below(w.size())][f];
      break;
    }
    case 10:
      input.steps = 1 + draw.below(kMaxSteps);
      break;
    case 11:
      make_nearly_tangent(w, draw);
      break;
    default: {  // a family's world beside this one
      const Circles more = drawn_family_world(draw);
      w.insert(w.end(), more.begin(), more.end());
      break;
    }
  }
  keep_in_c(w);
  return input;
}

StepInput cross_over(const StepInput& a, const StepInput& b, std::uint64_t seed) {
  Draw draw(seed);
  StepInput child{a.steps, {}};
  const std::size_t from_a = draw.below(a.circles.size() + 1), from_b = draw.below(b.circles.size() + 1);
  child.circles.assign(a.circles.begin(), a.circles.begin() + static_cast<std::ptrdiff_t>(from_a));
  child.circles.insert(child.circles.end(), b.circles.end() - static_cast<std::ptrdiff_t>(from_b), b.circles.end());
  keep_in_c(child.circles);
  return child;
}

}  // namespace circles::fuzz
