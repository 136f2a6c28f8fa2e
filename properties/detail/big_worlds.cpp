// The big families' constructions (properties/boundaries.hpp, gen::big_world): worlds of hundreds to thousands
// of circles, each built around the place where one kind of optimized step goes wrong. docs/conform.md ("Big
// worlds") says which kind each family aims at and why it catches it.
//
// Every number is exact in doubles: centres are integers (or integers times a power of two), radii are halves,
// quarters or powers of two, velocities are quarters, so every tangency a family places is exact. The index
// order is part of each construction (where the least contact sits, which circles come last), so that, unlike
// the small families, a big world is not shuffled. Draws come from the case's own rc::Random, in statement
// order, so that a seed gives the same world on every compiler.
#include "properties/detail/boundaries.hpp"
#include "properties/detail/draw.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace circles::properties::detail {

using spec::CircleDoubles;

namespace {

// A circle whose vy differs from that of the 4094 circles made before and after it, and from those 2^8 and 2^16
// before and after it (the k-th circle made gets vy = (k mod 4095)/8 − 256 shifted by a per-world offset), so
// that taking any contact's velocity other than the right one changes the answer, at speeds below 6 units a step
// whatever the size of the world.
class Builder {
 public:
  explicit Builder(Draw& draw) : draw_(draw), offset_(static_cast<double>(draw.between(-64, 64))) {}
  CircleDoubles circle(double x, double y, double r) {
    const double vy = offset_ + static_cast<double>(made_++ % 4095) / 8 - 256;
    return {x, y, draw_.velocity(), vy, r};
  }

 private:
  Draw& draw_;
  double offset_;
  std::uint64_t made_ = 0;
};

// The values of `table` up to `max`, at least the first.
template <std::size_t N>
std::size_t levels_up_to(const std::array<std::size_t, N>& table, std::size_t max) {
  std::size_t n = 1;
  while (n < N && table[n] <= max) ++n;
  return n;
}

// n circles of radius 1, 1.5 or 2 at integer centres in a square of 16 units of area per circle, about two
// contacts each, in no order; the last three each placed tangent to an earlier circle, so that the end of the
// index order always has contacts. Shared by sizes and big_chains.
Circles random_world(std::size_t n, Draw& draw) {
  Builder make(draw);
  const I side = 4 * static_cast<I>(std::ceil(std::sqrt(static_cast<double>(n)))) + 4;
  Circles w;
  w.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double r = static_cast<double>(draw.between(2, 4)) / 2;
    if (k + 3 >= n && k > 0) {
      const CircleDoubles& a = w[draw.below(k)];
      w.push_back(make.circle(a[0] + a[4] + r, a[1], r));
      continue;
    }
    w.push_back(make.circle(static_cast<double>(draw.between(0, side)), static_cast<double>(draw.between(0, side)), r));
  }
  return w;
}

}  // namespace

// sizes: a world that crosses a power of two p: p + 1, p − 1 or p circles; above the largest p with p + 1 <= max,
// a last level of max circles itself when max is more, so that the limit is reached. On the ladder (a budget
// run), the swarm's world of max circles (detail/swarm.cpp), whose size is a rung: a power of two or the limit.
Circles sizes(std::uint64_t round, std::size_t max, Draw& draw) {
  std::size_t powers = 0;  // the powers of two p = 16 · 2^l with p + 1 <= max
  while ((std::size_t{16} << powers) + 1 <= max) ++powers;
  const bool limit = (std::size_t{16} << (powers - 1)) + 1 < max;
  const std::size_t l = draw.level(round, powers + limit);
  if (draw.largest()) return swarm(max, draw, round == 0 ? Frame::subnormal : Frame::drawn);  // a ladder's: the swarm's
  if (l == powers) return random_world(max, draw);
  const std::size_t p = std::size_t{16} << l;
  const std::size_t side = round < powers + limit ? 1 : static_cast<std::size_t>(round % 3);  // +1, then −1, 0, +1, …
  const std::size_t n = std::min(max, side == 1 ? p + 1 : side == 0 ? p - 1 : p);
  return random_world(n, draw);
}

// crowds: hubs, each touched by m circles (its only contacts) and nothing else, the least of them at a chosen
// rank of the hub's contacts in index order: the 9th (the first past an array of 8), the last, the first, and
// ranks spread over the rest.
Circles crowds(std::uint64_t round, std::size_t max, Draw& draw) {
  static constexpr std::array<std::size_t, 8> kContacts{9, 12, 17, 33, 65, 100, 129, 257};
  const std::size_t m = kContacts[draw.level(round, levels_up_to(kContacts, max / 3))];
  const std::size_t hubs = std::clamp<std::size_t>(std::min<std::size_t>(512, max) / (m + 1), 3, 16);
  // The contacts: distinct integer points of a k × k square around the hub's centre, radius 1/4, so that two
  // contacts (at least 1 apart) never touch; the hub's radius k + 1 reaches every one of them.
  const I k = static_cast<I>(std::ceil(std::sqrt(static_cast<double>(m)))) + 1;
  Builder make(draw);
  std::vector<Circles> blocks;
  for (std::size_t h = 0; h < hubs; ++h) {
    const double cx = static_cast<double>(static_cast<I>(h) * (4 * k + 8)), cy = static_cast<double>(draw.between(-k, k));
    std::vector<I> cells(static_cast<std::size_t>(k * k));
    std::iota(cells.begin(), cells.end(), 0);
    draw.shuffle(cells);
    cells.resize(m);
    Circles contacts;
    for (const I c : cells)
      contacts.push_back(make.circle(cx + static_cast<double>(c % k - k / 2), cy + static_cast<double>(c / k - k / 2), 0.25));
    // The least under (px, py, …) to rank `rank`, the others in random order.
    const auto least = std::min_element(contacts.begin(), contacts.end());
    std::iter_swap(contacts.begin(), least);
    Circles rest(contacts.begin() + 1, contacts.end());
    draw.shuffle(rest);
    const std::size_t rank = h == 0 ? 8 : h == 1 ? m - 1 : h == 2 ? 0 : static_cast<std::size_t>(draw.below(m));
    rest.insert(rest.begin() + static_cast<std::ptrdiff_t>(rank), contacts.front());
    // The hub anywhere among its contacts.
    const CircleDoubles hub = make.circle(cx, cy, static_cast<double>(k + 1));
    rest.insert(rest.begin() + static_cast<std::ptrdiff_t>(draw.below(m + 1)), hub);
    blocks.push_back(std::move(rest));
  }
  draw.shuffle(blocks);
  Circles w;
  for (const Circles& b : blocks) w.insert(w.end(), b.begin(), b.end());
  return w;
}

// cell_crowds: m centres inside one aligned square of side s = 2^e, on a lattice of spacing s / 2^b, with radii
// from s/2 (every grid whose cells are a diameter or more holds them all in one cell, and each overlaps
// dozens of the others) down to half the spacing (each touches its lattice neighbours, exactly tangent); beside
// it a cell of m/4 such centres, and scattered circles of the same radius elsewhere.
Circles cell_crowds(std::uint64_t round, std::size_t max, Draw& draw) {
  static constexpr std::array<std::size_t, 9> kCentres{5, 9, 17, 33, 65, 129, 257, 513, 1000};
  const std::size_t m = kCentres[draw.level(round, levels_up_to(kCentres, max / 2))];
  const int e = static_cast<int>(draw.between(-4, 8));
  const double s = std::ldexp(1.0, e);
  const I q = static_cast<I>(std::ceil(std::sqrt(static_cast<double>(m))));
  const int b = static_cast<int>(std::bit_width(static_cast<std::uint64_t>(q + 1)));  // 2^b > q + 1: q points fit
  const double d = std::ldexp(s, -b);
  const double r = round % 2 == 0 ? s / 2 : d / 2;
  Builder make(draw);
  Circles w;
  const I cx = draw.between(-1024, 1024), cy = draw.between(-1024, 1024);
  for (I cell = 0; cell < 2; ++cell)
    for (std::size_t k = 0; k < (cell == 0 ? m : std::max<std::size_t>(m / 4, 5)); ++k) {
      const I i = static_cast<I>(k) % q, j = static_cast<I>(k) / q;
      w.push_back(make.circle(static_cast<double>(cx + cell) * s + static_cast<double>(i + 1) * d,
                              static_cast<double>(cy) * s + static_cast<double>(j + 1) * d, r));
    }
  for (int k = 0; k < 32; ++k)
    w.push_back(make.circle(static_cast<double>(cx + draw.between(-64, 64)) * s,
                            static_cast<double>(cy + draw.between(2, 64)) * s, r));
  draw.shuffle(w);
  return w;
}

// radius_spread: small circles of radius 2^-12 … 1 at integer centres, then, last in the index order, big circles
// of radius 2^10 … 2^12 (over six decimal orders above the smallest) whose rims cross the small ones' quartile
// borders in x: a big circle reaching from the left over a border touches every small circle near it, whose
// least contact it then is (its px is far smaller); one reaching from the right touches a sliver.
Circles radius_spread(std::uint64_t round, std::size_t max, Draw& draw) {
  static constexpr std::array<std::size_t, 5> kCircles{64, 128, 256, 512, 1024};
  const std::size_t l = draw.level(round, levels_up_to(kCircles, max));
  const std::size_t n = kCircles[l], big = 2 + l;
  const I side = 4 * static_cast<I>(std::ceil(std::sqrt(static_cast<double>(n))));
  Builder make(draw);
  Circles w;
  for (std::size_t k = 0; k + big < n; ++k)
    w.push_back(make.circle(static_cast<double>(draw.between(0, side)), static_cast<double>(draw.between(0, side)),
                            std::ldexp(1.0, -static_cast<int>(draw.between(0, 12)))));
  std::vector<double> xs;
  for (const CircleDoubles& c : w) xs.push_back(c[0]);
  std::sort(xs.begin(), xs.end());
  for (std::size_t k = 0; k < big; ++k) {
    const double border = xs[xs.size() * (1 + k % 3) / 4];  // a quartile border of the small circles' x
    const double R = std::ldexp(1.0, static_cast<int>(draw.between(10, 12)));
    const double y = static_cast<double>(draw.between(0, side));
    const double reach = static_cast<double>(draw.between(0, 2));  // how far past the border its rim goes
    w.push_back(k % 2 == 0 ? make.circle(border - R + reach, y, R) : make.circle(border + R - reach, y, R));
  }
  return w;
}

// long_rows: one row of circles of diameter d = 2^e, tangent to their neighbours, up to 2048 wide, or two rows up
// to 1024 wide, far from the origin; or the same transposed, columns as tall. In no order.
Circles long_rows(std::uint64_t round, std::size_t max, Draw& draw) {
  static constexpr std::array<std::size_t, 5> kWidth{128, 256, 512, 1024, 2048};
  const std::size_t rows = 1 + round % 2;
  const std::size_t width = kWidth[draw.level(round, levels_up_to(kWidth, max / 2 / rows))];
  const bool transposed = (round / 2) % 2 == 1;
  const double d = std::ldexp(1.0, static_cast<int>(draw.between(-4, 4)));
  const double along = static_cast<double>(draw.between(-(I{1} << 20), I{1} << 20)) * d;
  const double across = static_cast<double>(draw.between(-(I{1} << 20), I{1} << 20)) * d;
  Builder make(draw);
  Circles w;
  for (std::size_t j = 0; j < rows; ++j)
    for (std::size_t i = 0; i < width; ++i) {
      const double a = along + static_cast<double>(i) * d, b = across + static_cast<double>(j) * d;
      w.push_back(transposed ? make.circle(b, a, d / 2) : make.circle(a, b, d / 2));
    }
  draw.shuffle(w);
  return w;
}

// index_bits: a world of 2^b + 16 to 2^b + 64 circles, b = 8 or, when the limit allows, 16, apart (sites 8 apart,
// radius 1) but for triples: circle c between circles i >= 2^b and j = i mod 2^b, which differ only in the bits
// from b up, touching both, with i its least contact (i is on its left). A step that keeps an index in b bits
// takes j's velocity for i's. The i include 2^b, 2^b + 1 and the last circle.
Circles index_bits(std::uint64_t round, std::size_t max, Draw& draw) {
  static constexpr std::array<std::size_t, 2> kBits{8, 16};
  std::size_t fits = 0;
  while (fits < kBits.size() && (std::size_t{1} << kBits[fits]) + 64 <= max) ++fits;
  const std::size_t bits = kBits[fits == 0 ? 0 : draw.level(round, fits)];
  const std::size_t low = std::size_t{1} << bits;
  const std::size_t n = std::min(max, low + 16 + static_cast<std::size_t>(draw.below(48)));
  const I columns = static_cast<I>(std::ceil(std::sqrt(static_cast<double>(n))));
  const auto site = [columns](std::size_t k) {
    return std::array<double, 2>{static_cast<double>(8 * (static_cast<I>(k) % columns)),
                                 static_cast<double>(8 * (static_cast<I>(k) / columns))};
  };
  Builder make(draw);
  Circles w;
  for (std::size_t k = 0; k < n; ++k) w.push_back(make.circle(site(k)[0], site(k)[1], 1));
  std::vector<std::size_t> is{low, low + 1, n - 1};
  for (int t = 0; t < 13; ++t) is.push_back(low + static_cast<std::size_t>(draw.below(n - low)));
  std::vector<bool> used(n, false);
  for (const std::size_t i : is) {
    const std::size_t j = i % low;
    std::size_t c = static_cast<std::size_t>(draw.below(n));
    if (used[i] || used[j]) continue;
    while (c == i || c == j || used[c]) c = static_cast<std::size_t>(draw.below(n));
    used[i] = used[j] = used[c] = true;
    const auto [x, y] = site(c);
    w[i][0] = x - 1.5, w[i][1] = y;
    w[j][0] = x + 1.5, w[j][1] = y;
  }
  return w;
}

// order_borders: a chain of circles of radius 5/2 along the direction (3, 4), each 5 or 10 from the next, so that
// neighbours touch (exactly tangent) or not and no others do; x and y grow with the chain, so its ranks are
// the x order and the y order. Every half, quarter and eighth border of those orders has a touching pair
// across it, and so has every such border of the index order (the pair's indices b − 1 and b), the other
// indices in no order.
Circles order_borders(std::uint64_t round, std::size_t max, Draw& draw) {
  static constexpr std::array<std::size_t, 5> kCircles{64, 128, 256, 512, 1024};
  const std::size_t n = kCircles[draw.level(round, levels_up_to(kCircles, max - 8))] + static_cast<std::size_t>(draw.below(8));
  std::vector<bool> touch(n - 1);
  for (std::size_t t = 0; t + 1 < n; ++t) touch[t] = draw.below(2) == 0;
  std::vector<std::size_t> borders;
  for (std::size_t f = 1; f < 8; ++f) borders.push_back(n * f / 8);
  for (const std::size_t b : borders) touch[b - 1] = true;
  // The index of the circle at each rank: for each index border b, a touching pair of ranks (t, t + 1), drawn
  // from the pairs not yet used, gets the indices b − 1 and b; the other ranks get the other indices in no order.
  std::vector<std::size_t> pairs;
  for (std::size_t t = 0; t + 1 < n; t += 2)
    if (touch[t]) pairs.push_back(t);
  draw.shuffle(pairs);
  std::vector<std::size_t> index(n, n);
  std::vector<bool> taken(n, false);
  for (std::size_t k = 0; k < borders.size() && k < pairs.size(); ++k) {
    index[pairs[k]] = borders[k] - 1, index[pairs[k] + 1] = borders[k];
    taken[borders[k] - 1] = taken[borders[k]] = true;
  }
  std::vector<std::size_t> rest;
  for (std::size_t k = 0; k < n; ++k)
    if (!taken[k]) rest.push_back(k);
  draw.shuffle(rest);
  for (std::size_t t = 0, next = 0; t < n; ++t)
    if (index[t] == n) index[t] = rest[next++];
  Builder make(draw);
  Circles w(n);
  I g = 0;
  for (std::size_t t = 0; t < n; ++t) {
    w[index[t]] = make.circle(static_cast<double>(3 * g), static_cast<double>(4 * g), 2.5);
    g += t + 1 < n && touch[t] ? 1 : 2;
  }
  return w;
}

// big_chains: random_world at 64 … 512 circles, moving up to one unit a step, chained 10 steps; on the ladder, the
// swarm's worlds, chained so.
Circles big_chains(std::uint64_t round, std::size_t max, Draw& draw) {
  if (draw.largest()) return swarm(max, draw, round == 0 ? Frame::huge : Frame::drawn);
  static constexpr std::array<std::size_t, 4> kCircles{64, 128, 256, 512};
  return random_world(kCircles[draw.level(round, levels_up_to(kCircles, max))], draw);
}

}  // namespace circles::properties::detail

namespace circles::properties::gen {

Circles big_world(Family family, std::uint64_t round, std::size_t max_circles, rc::Random random, bool largest) {
  if (!row(family).build_big) return {};
  detail::Draw draw(std::move(random), largest);
  return row(family).build_big(round, std::max(max_circles, kMinMaxCircles), draw);
}

}  // namespace circles::properties::gen
