// The swarm (swarm testing: Groce, Zhang, Eide, Chen and Regehr, ISSTA 2012): the worlds of a budget run's ladder
// (the sizes and big_chains families at a rung, properties/boundaries.hpp), each of which draws its own subset of
// features, so that a program's big-world path (its grid, filters, threads) meets combinations nobody listed:
//   - a radius law: equal; not powers of two; powers of two; spread over 2^±40; a few giants; about a typical
//     radius that is a power of two or not;
//   - a frame: unit scale; 2^±20 … 2^±40; near 2^1000 or near the subnormals (these two only in worlds of up to
//     kExtremeCircles circles, where conform's reference stays fast), or in the subnormals themselves (a ladder's
//     first stage has one world in them and one near 2^1000: Frame); offset by a value that is not dyadic, or
//     straddling zero;
//   - numbers with all 53 bits in use, or small dyadic ones;
//   - a layout: clusters, a lattice of tangent neighbours, a line, or sparse;
//   - tangent pairs whose contact sits on a multiple of a likely cell side (the largest diameter, twice it, the
//     power of two above it, 3 radii), negative multiples included, along an axis or along (±3, ±4) with
//     numbers of up to 50 bits (whose squares round, where a filter's error bound decides), exact or an ulp apart;
//   - pairs of the largest circles two cells apart for any cell side below their distance;
//   - speeds: fast (up to a diameter a step) or slow;
//   - duplicates and zero radii;
//   - and, among the thousands of circles, worlds of the small families (tangencies within an ulp, ties on each
//     key, subnormal gaps, cancellation, ...), each as its family draws it, at random places of the index order.
// Every number is finite, and so is every next position. kExtremeCircles (detail/boundaries.hpp) bounds the
// worlds at extreme frames.
#include "properties/detail/boundaries.hpp"
#include "properties/detail/draw.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace circles::properties::detail {
namespace {

using spec::CircleDoubles;

// A uniform double in [0, 1) with 53 random bits.
double unit(Draw& draw) { return std::ldexp(static_cast<double>(draw.bits() >> 11), -53); }

// The small families whose worlds the swarm embeds: every family but the big ones and random-doubles (whose
// numbers near DBL_MAX may take the next position out of the double range, which would make the whole world one
// that conform cannot ask).
std::vector<Family> small_families() {
  std::vector<Family> out;
  for (const FamilyRow& r : family_rows())
    if (!r.big && r.family != Family::random_doubles) out.push_back(r.family);
  return out;
}

// `w` times 2^j, every field: exact, and so every tangency, tie and ulp apart of it kept, as long as nothing
// leaves the normal range; no circles if something would (the world is then left out, rather than put in a
// binade of its own among the swarm's circles, where a grid would put every other circle in one cell).
Circles scaled(Circles w, int j) {
  for (const CircleDoubles& c : w)
    for (const double x : c)
      if (x != 0 && (std::ilogb(x) + j > 1000 || std::ilogb(x) + j < -1000)) return {};
  for (CircleDoubles& c : w)
    for (double& x : c) x = std::ldexp(x, j);
  return w;
}

}  // namespace

Circles swarm(std::size_t n, Draw& draw, Frame frame) {
  const auto coin = [&draw] { return draw.below(2) == 0; };
  // The frame: the typical radius r0 = m·2^e, m = 1 or (in half the worlds) 1 + j/8 for j = 1 … 7, so that the
  // largest radius is often not a power of two, as in most worlds people write (a grid's cell side is then no
  // power of two either), while a lattice of spacing 2·r0 stays exact.
  int e = static_cast<int>(draw.between(-6, 6));
  const bool extreme = n <= kExtremeCircles;
  switch (extreme && frame == Frame::huge ? 3 : extreme && frame == Frame::subnormal ? 5 : draw.below(extreme ? 5 : 3)) {
    case 1: e = static_cast<int>(draw.between(20, 40)) * (coin() ? 1 : -1); break;
    case 3: e = static_cast<int>(draw.between(960, 990)); break;       // near 2^1000
    case 4: e = static_cast<int>(draw.between(-1040, -1010)); break;  // near the subnormals
    // In them: for n <= kExtremeCircles every centre below is within 2^27·r0 of the origin (the non-dyadic
    // offset, at most 2^20 / 3 spans of 2^7·r0, is the farthest), and r0 < 2^(e+1) <= 2^-1049, so below
    // 2^-1022 = DBL_MIN, and so is nearly every next position (a step moves a circle at most 2·r0).
    case 5: e = static_cast<int>(draw.between(-1060, -1050)); break;
    default: break;
  }
  const double r0 = std::ldexp(coin() ? 1.0 : 1 + static_cast<double>(draw.between(1, 7)) / 8, e);
  const bool full_bits = coin();
  const auto bits = [&](double x) { return full_bits ? x * (1 + unit(draw) * 0x1p-8) : x; };
  // The radius law.
  const std::uint64_t law = draw.below(5);
  const auto radius = [&]() -> double {
    switch (law) {
      case 1: return bits(r0 * (1 + static_cast<double>(draw.between(1, 6)) / 7));
      case 2: return r0 * std::ldexp(1.0, -static_cast<int>(draw.below(7)));
      case 3: return bits(r0 * std::ldexp(1.0, -static_cast<int>(draw.below(std::min<std::uint64_t>(41, 1074 + e)))));
      case 4: return draw.below(200) == 0 ? r0 * 1024 : bits(r0);
      default: return r0;
    }
  };
  const double rmax = law == 4 ? r0 * 1024 : law == 1 ? r0 * 2 : r0;
  // The layout's extent: about 4 radii of room per circle.
  const double side = std::sqrt(static_cast<double>(n)) * 4 * r0;
  double ox = 0, oy = 0;
  switch (draw.below(3)) {
    case 1:  // not dyadic: a third of a random span
      ox = side * static_cast<double>(draw.between(1, 1 << 20)) / 3;
      oy = side * static_cast<double>(draw.between(-(1 << 20), 1 << 20)) / 3;
      break;
    case 2: ox = oy = -side / 2; break;  // straddling zero
    default: break;
  }
  const bool fast = coin();
  const auto speed = [&] {
    const double top = fast ? 120 * r0 : 4 * r0;  // 60·v per step: a diameter, or a sixteenth of a radius
    return bits(top * (2 * unit(draw) - 1));
  };
  const auto circle = [&](double x, double y, double r) { return CircleDoubles{x, y, speed(), speed(), r}; };
  Circles w;
  w.reserve(n);
  const std::uint64_t layout = draw.below(4);
  const std::size_t per_row = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::vector<std::array<double, 2>> centres;
  for (std::size_t k = 0; k < std::max<std::size_t>(1, n / 64); ++k)
    centres.push_back({ox + unit(draw) * side, oy + unit(draw) * side});
  for (std::size_t k = 0; k < n; ++k) {
    const double r = radius();
    double x = 0, y = 0;
    switch (layout) {
      case 0: {  // clusters
        const auto& c = centres[draw.below(centres.size())];
        x = c[0] + (unit(draw) + unit(draw) - 1) * 8 * r0;
        y = c[1] + (unit(draw) + unit(draw) - 1) * 8 * r0;
        break;
      }
      case 1:  // a lattice of spacing 2·r0: neighbours of radius r0 tangent
        x = ox + static_cast<double>(k % per_row) * 2 * r0;
        y = oy + static_cast<double>(k / per_row) * 2 * r0;
        break;
      case 2:  // a line along x, neighbours about touching
        x = ox + static_cast<double>(k) * bits(2 * r0);
        y = oy;
        break;
      default:  // sparse
        x = ox + bits(unit(draw) * side * 2);
        y = oy + bits(unit(draw) * side * 2);
        break;
    }
    w.push_back(circle(x, y, r));
  }
  // Tangent pairs whose contact point is on a multiple of a likely cell side, exact or an ulp apart.
  const std::array<double, 4> cells{2 * rmax, 4 * rmax, std::ldexp(1.0, std::ilogb(2 * rmax) + 1), 3 * rmax};
  for (std::size_t p = 0; p < n / 32 && n >= 2; ++p) {
    const double cell = cells[draw.below(cells.size())];
    const double m = std::round((ox + unit(draw) * side) / cell) + static_cast<double>(draw.between(-2, 2));
    const double at = m * cell, across = oy + unit(draw) * side;
    const double ra = radius(), rb = radius();
    CircleDoubles a = circle(at - ra, across, ra), b = circle(at + rb, across, rb);
    if (coin()) {
      // Along (±3, ±4) instead, exactly tangent: every coordinate a multiple of a grain that keeps the sums exact,
      // with up to 50 significant bits, so that |p_b − p_a|² and (r_a + r_b)² round in doubles, where a filter's
      // error bound decides.
      const double grain = std::ldexp(1.0, std::ilogb(4 * (std::fabs(at) + std::fabs(across) + 16 * rmax)) - 52);
      if (!std::isfinite(grain)) continue;
      const double k = std::max(1.0, std::round(rmax * (0.25 + unit(draw)) / grain));
      const double q = k * grain, r = grain * std::max(1.0, std::floor(5 * k * unit(draw)));
      const double sx = coin() ? 3 : -3, sy = coin() ? 4 : -4;
      a = circle(at, across, r);
      b = circle(at + sx * q, across + sy * q, 5 * q - r);
    }
    if (coin()) b[0] = std::nextafter(b[0], coin() ? -std::numeric_limits<double>::infinity()
                                                   : std::numeric_limits<double>::infinity());
    if (coin()) {  // along y instead
      std::swap(a[0], a[1]);
      std::swap(b[0], b[1]);
    }
    w[draw.below(n)] = a;
    w[draw.below(n)] = b;
  }
  if (coin())  // duplicates
    for (std::size_t k = 0; k < n / 64; ++k) w[draw.below(n)] = w[draw.below(n)];
  if (coin())  // zero radii
    for (std::size_t k = 0; k < n / 64; ++k) w[draw.below(n)][4] = 0;
  // The small families' worlds, among the others.
  if (draw.below(4) != 0) {
    static const std::vector<Family> smalls = small_families();
    for (std::uint64_t k = draw.between(1, 8); k > 0; --k) {
      const Family f = smalls[draw.below(smalls.size())];
      Circles small = gen::boundary_world(f, Profile::resolved)(rc::Random(draw.bits()), 50).value();
      // Scaled by a power of two to the swarm's radii, so that it sits among them rather than in a binade of
      // its own (where a grid would put every other circle in one cell).
      double biggest = 0;
      for (const CircleDoubles& c : small) biggest = std::max({biggest, std::fabs(c[0]), std::fabs(c[1]), c[4]});
      const int j = e - (biggest > 0 ? std::ilogb(biggest) : e) + static_cast<int>(draw.between(0, 6));
      small = scaled(std::move(small), j);
      const std::size_t at = draw.below(n - std::min(n, small.size()) + 1);
      for (std::size_t i = 0; i < small.size() && at + i < n; ++i) w[at + i] = small[i];
    }
  }
  // A circle that a frame near 2^1000 took past the double range, or whose next position would leave it, is
  // replaced by one at rest at the origin: the world stays one that conform can ask.
  const auto in_range = [](const CircleDoubles& c) {
    bool finite = true;
    for (const double x : c) finite = finite && std::isfinite(x);
    return finite && std::fabs(c[0]) + std::fabs(c[2]) < 0x1p1020 && std::fabs(c[1]) + std::fabs(c[3]) < 0x1p1020;
  };
  for (CircleDoubles& c : w)
    if (!in_range(c)) c = {0, 0, 0, 0, r0};
  // Last, pairs of the largest circles of the world as it now is, overlapping by 2^-20 of their distance, the
  // first centre just below a multiple of the largest diameter rounded down to a power of two: their centres
  // lie two cells apart for any cell side below their distance, where a grid that rounds its side down looks
  // one cell too near. Each replaces two smaller circles, so that the largest radius stays what it was.
  double largest = 0;
  for (const CircleDoubles& c : w) largest = std::max(largest, c[4]);
  const double cell = largest > 0 ? std::ldexp(1.0, std::ilogb(2 * largest)) : 0;
  for (std::size_t p = 0; p < n / 64 && cell > 0 && std::isfinite(2 * largest); ++p) {
    const double at = (std::round((ox + unit(draw) * side) / cell) + static_cast<double>(draw.between(-2, 2))) * cell;
    const double across = oy + unit(draw) * side;
    CircleDoubles a = circle(std::nextafter(at, -std::numeric_limits<double>::infinity()), across, largest);
    CircleDoubles b = circle(a[0] + 2 * largest * (1 - 0x1p-20), across, largest);
    if (coin()) {  // along y instead
      std::swap(a[0], a[1]);
      std::swap(b[0], b[1]);
    }
    const std::size_t i = draw.below(n), j = draw.below(n);
    if (i != j && w[i][4] < largest && w[j][4] < largest && in_range(a) && in_range(b)) {
      w[i] = a;
      w[j] = b;
    }
  }
  draw.shuffle(w);
  return w;
}

}  // namespace circles::properties::detail
