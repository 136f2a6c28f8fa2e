// The broad phase's walk and order (impl/broad_phase.hpp), checked directly against their definitions rather
// than only through the engines: every pair of neighbouring cells is visited exactly once, from the earlier
// slot, across band boundaries and levels, with narrow runs and with wide ones; and CellOrder's sorts, guided
// or by digits, equal a plain sort.
#include "impl/broad_phase.hpp"
#include "impl/contacts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace circles::impl {
namespace {

using G = CellGrid;

// Circles in cell order with everything a CellView needs.
struct Sorted {
  G grid;
  std::vector<CellKey> key;
  std::vector<double> px, py, r;
  std::vector<unsigned> levels;
  std::array<std::size_t, G::kLevels + 1> level_begin{};
  CellView view(bool wide_runs = false) const { return {key, px, py, r, levels, level_begin, wide_runs}; }
};

Sorted sorted(const std::vector<std::array<double, 3>>& circles) {
  Sorted s;
  std::vector<double> px, py, r;
  for (const auto& [x, y, radius] : circles) {
    px.push_back(x);
    py.push_back(y);
    r.push_back(radius);
  }
  s.grid.plan(px, py, r);
  std::vector<CellKey> keys(px.size());
  s.grid.keys(px, py, r, keys);
  Buffer<CellKey> in_order(keys.begin(), keys.end());
  Buffer<std::uint32_t> order;
  CellOrder().sort_in_place(in_order, {}, order);
  for (const std::uint32_t t : order) {
    s.key.push_back(keys[t]);
    s.px.push_back(px[t]);
    s.py.push_back(py[t]);
    s.r.push_back(r[t]);
  }
  index_levels(s.key, s.level_begin, s.levels);
  return s;
}

// The definition: a and b (non-global) are neighbours when, at the higher of their levels L, the cell of the
// one at L lies in the other's neighbourhood range at L (step 4); at one level that is cells at most one apart
// on each axis.
bool neighbours(const Sorted& s, std::size_t a, std::size_t b) {
  const unsigned la = G::level(s.key[a]), lb = G::level(s.key[b]);
  if (la == G::kGlobalLevel || lb == G::kGlobalLevel) return false;
  if (la == lb) {
    const auto apart = [](std::uint32_t u, std::uint32_t v) { return u > v ? u - v : v - u; };
    return apart(G::cell_x(s.key[a]), G::cell_x(s.key[b])) <= 1 && apart(G::cell_y(s.key[a]), G::cell_y(s.key[b])) <= 1;
  }
  const std::size_t low = la < lb ? a : b, high = la < lb ? b : a;
  const G::Range range = s.grid.neighbourhood(s.px[low], s.py[low], s.r[low], G::level(s.key[high]));
  const std::uint32_t x = G::cell_x(s.key[high]), y = G::cell_y(s.key[high]);
  return range.x0 <= x && x <= range.x1 && range.y0 <= y && y <= range.y1;
}

// A world of many circles per cell around band boundaries: cells of about 2 units, rows 0 to 40 (bands of 8
// rows), and a few circles a level or two up.
std::vector<std::array<double, 3>> busy_world(unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> at(0, 80), radius(0.5, 1), big(3, 12);
  std::vector<std::array<double, 3>> circles;
  for (int k = 0; k < 1500; ++k) circles.push_back({at(random), at(random), radius(random)});
  for (int k = 0; k < 12; ++k) circles.push_back({at(random), at(random), big(random)});
  return circles;
}

// The slots that a wide run may add to a's neighbours (visit_neighbourhood_runs): at a's level, in a's band,
// a's column above a or the next column; or, from its band's top row, the band above in columns cx − 1 … cx + 1.
bool in_wide_runs(const Sorted& s, std::size_t a, std::size_t b) {
  if (G::level(s.key[a]) != G::level(s.key[b])) return false;
  const std::uint32_t ax = G::cell_x(s.key[a]), ay = G::cell_y(s.key[a]);
  const std::uint32_t bx = G::cell_x(s.key[b]), by = G::cell_y(s.key[b]);
  const std::uint32_t band = ay / G::kBandRows;
  if (by / G::kBandRows == band) return bx == ax || bx == ax + 1;
  return ay % G::kBandRows == G::kBandRows - 1 && by / G::kBandRows == band + 1 && bx + 1 >= ax && bx <= ax + 1;
}

// Every pair of neighbouring cells visited exactly once from the earlier slot, and no other pair: with wide
// runs, other pairs at most once each, all of them of the shape the wide runs allow. Returns the pairs visited
// that are not neighbours.
std::size_t check_walk(const Sorted& s, bool wide_runs, unsigned seed) {
  const std::size_t n = s.key.size();
  std::map<std::pair<std::size_t, std::size_t>, int> visits;
  NeighbourCursor cursor;
  for (std::size_t a = 0; a < n; ++a)
    visit_neighbourhood(s.grid, s.view(wide_runs), a, cursor, [&](std::size_t b) {
      EXPECT_GT(b, a);
      ++visits[{a, b}];
    });
  std::size_t expected = 0, across_bands = 0, others = 0;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const bool want = neighbours(s, a, b);
      const auto found = visits.find({a, b});
      const int got = found == visits.end() ? 0 : found->second;
      const std::string where = "slots " + std::to_string(a) + " and " + std::to_string(b) + " (seed " +
                                std::to_string(seed) + (wide_runs ? ", wide runs)" : ")");
      if (want || !wide_runs) {
        EXPECT_EQ(got, want ? 1 : 0) << where;
      } else {
        EXPECT_LE(got, 1) << where;
        if (got > 0) {
          EXPECT_TRUE(in_wide_runs(s, a, b)) << where;
        }
        others += got;
      }
      expected += want;
      across_bands += want && G::level(s.key[a]) == G::level(s.key[b]) &&
                      G::cell_y(s.key[a]) / G::kBandRows != G::cell_y(s.key[b]) / G::kBandRows;
    }
  EXPECT_EQ(visits.size(), expected + others);
  EXPECT_GT(across_bands, 100u) << "the world must put many neighbours across a band boundary";
  return others;
}

TEST(broad_phase, the_walk_visits_every_pair_of_neighbouring_cells_once_from_the_earlier_slot) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Sorted s = sorted(busy_world(seed));
    ASSERT_GE(s.levels.size(), 2u) << "the world must use more than one level";
    EXPECT_EQ(check_walk(s, false, seed), 0u);
  }
}

TEST(broad_phase, wide_runs_visit_the_same_neighbours_once_and_other_slots_of_their_columns_at_most_once) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Sorted s = sorted(busy_world(seed));
    EXPECT_GT(check_walk(s, true, seed), 1000u) << "the wide runs must visit slots beyond the neighbours";
  }
}

TEST(broad_phase, the_walk_takes_wide_runs_where_the_cells_that_hold_slots_hold_one_and_a_half_or_fewer) {
  // Three cells holding 1, 1 and 2 slots: 4 slots ≤ 1.5 · 3 cells. One more slot in the last: 5 > 4.5.
  EXPECT_TRUE(few_per_cell(std::vector<CellKey>{1, 5, 9, 9}));
  EXPECT_FALSE(few_per_cell(std::vector<CellKey>{1, 5, 9, 9, 9}));
  EXPECT_TRUE(few_per_cell(std::vector<CellKey>{}));
  EXPECT_TRUE(few_per_cell(std::vector<CellKey>{7}));
  EXPECT_FALSE(few_per_cell(std::vector<CellKey>{7, 7}));
}

// A world at the subnormal scale gets cells of its own size: 40 × 40 circles of radius 3·2^-1074 on a lattice of
// pitch 16·2^-1074 (the whole world below 2^-1063) fall in as many cells as a world of the same shape at an
// ordinary scale, not in the one cell of a base clamped far above their size (which made a step quadratic).
TEST(broad_phase, a_world_at_the_subnormal_scale_gets_cells_of_its_own_size) {
  const auto distinct_keys = [](double unit) {
    std::vector<double> px, py, r;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j) {
        px.push_back(16 * i * unit);
        py.push_back(-16 * j * unit);
        r.push_back(3 * unit);
      }
    G grid;
    grid.plan(px, py, r);
    std::vector<CellKey> keys(px.size());
    grid.keys(px, py, r, keys);
    std::sort(keys.begin(), keys.end());
    for (const CellKey k : keys) EXPECT_EQ(G::level(k), 0u);
    return static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
  };
  const std::size_t ordinary = distinct_keys(1.0);
  EXPECT_GE(ordinary, 400u);  // at most four circles a cell
  EXPECT_EQ(distinct_keys(std::numeric_limits<double>::denorm_min()), ordinary);
  EXPECT_EQ(distinct_keys(0x1p-1040), ordinary);
}

// Four circles near ±1.5·10^308 among 40 × 40 ordinary ones: the grid is planned from the spread of the
// ordinary centres (the far ones clamp into its edge cells), so the ordinary circles fall in as many cells as
// without the far ones, not all in one cell of a base as wide as the double range.
TEST(broad_phase, a_few_far_outliers_do_not_widen_the_cells_of_the_rest) {
  std::vector<double> px, py, r;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      px.push_back(16.0 * i);
      py.push_back(16.0 * j);
      r.push_back(3);
    }
  const auto distinct_keys = [&](std::size_t outliers) {
    std::vector<double> x = px, y = py, radius = r;
    for (std::size_t k = 0; k < outliers; ++k) {
      x.push_back(k % 2 ? 1.5e308 : -1.5e308);
      y.push_back(k / 2 % 2 ? 1.5e308 : -1.5e308);
      radius.push_back(3);
    }
    G grid;
    grid.plan(x, y, radius);
    EXPECT_EQ(grid.trimmed(), outliers > 0);
    std::vector<CellKey> keys(x.size());
    grid.keys(x, y, radius, keys);
    keys.resize(px.size());  // the ordinary circles' keys
    std::sort(keys.begin(), keys.end());
    return static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
  };
  EXPECT_EQ(distinct_keys(4), distinct_keys(0));
  EXPECT_GE(distinct_keys(0), 400u);
}

TEST(broad_phase, keys_order_cells_by_level_band_column_then_row_within_the_band) {
  // Row 7 is the top of band 0, row 8 the bottom of band 1: column 5 of band 0 comes before column 0 of band 1,
  // and within a band a column's rows come before the next column.
  EXPECT_LT(G::pack(0, 7, 5), G::pack(0, 8, 0));
  EXPECT_LT(G::pack(0, 7, 5), G::pack(0, 0, 6));
  EXPECT_LT(G::pack(0, 3, 5), G::pack(0, 4, 5));
  EXPECT_LT(G::pack(0, G::kCells - 1, G::kCells - 1), G::pack(1, 0, 0));
  for (const std::uint32_t y : {0u, 7u, 8u, 12345u, G::kCells - 1})
    for (const std::uint32_t x : {0u, 1u, 999u, G::kCells - 1}) {
      const CellKey k = G::pack(3, y, x);
      EXPECT_EQ(G::level(k), 3u);
      EXPECT_EQ(G::cell_y(k), y);
      EXPECT_EQ(G::cell_x(k), x);
    }
}

// The slots of `keys` in (key, slot) order, by a plain stable sort: what CellOrder::sort_in_place must return.
Buffer<std::uint32_t> plainly_sorted(const std::vector<CellKey>& keys) {
  Buffer<std::uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  return order;
}

// A key far from every scene of these tests: with it among them, the keys' fields take 54 bits, too many to
// pack into the digits' entries, so the sort is the guided one.
constexpr CellKey kFarthest = G::pack(0, G::kCells - 1, G::kCells - 1);

// CellOrder::sort_in_place guided by `previous`: the keys must not pack, or the digits would sort them.
bool guided_sort(const std::vector<CellKey>& keys, std::span<const CellKey> previous, Buffer<std::uint32_t>& order,
                 unsigned threads = 1) {
  EXPECT_FALSE(CellOrder::by_digits(keys)) << "the keys pack: the sort would go by digits, not guided";
  Buffer<CellKey> copy(keys.begin(), keys.end());
  return CellOrder().sort_in_place(copy, previous, order, threads);
}

// CellOrder::sort_in_place on a copy of `keys`, which must come out as keys[order[t]] at t; `order` must be the
// plain sort's. Returns whether the sort went by digits.
bool sort_keys_in_place(const std::vector<CellKey>& keys, std::span<const CellKey> previous, unsigned threads,
                        const std::string& name) {
  Buffer<CellKey> sorted(keys.begin(), keys.end());
  Buffer<std::uint32_t> order;
  EXPECT_EQ(CellOrder().sort_in_place(sorted, previous, order, threads), std::is_sorted(keys.begin(), keys.end()))
      << name;
  EXPECT_EQ(order, plainly_sorted(keys)) << name;
  EXPECT_EQ(sorted.size(), keys.size()) << name;
  for (std::size_t t = 0; t < sorted.size() && t < order.size(); ++t)
    if (sorted[t] != keys[order[t]]) {
      ADD_FAILURE() << name << ": key at " << t << " is " << sorted[t] << ", not " << keys[order[t]];
      break;
    }
  return CellOrder::by_digits(keys);
}

TEST(broad_phase, the_guided_re_sort_equals_a_plain_sort_after_moves_within_and_across_bands) {
  const Sorted s = sorted(busy_world(7));
  const std::size_t n = s.key.size();
  std::mt19937_64 random(11);
  std::uniform_int_distribution<int> move(-12, 12), far(0, 19);
  // Each slot's cell moves by up to 12 rows and columns (many cross a band), one in twenty anywhere.
  std::vector<CellKey> moved(n);
  for (std::size_t t = 0; t < n; ++t) {
    const CellKey k = s.key[t];
    const auto shift = [&](std::uint32_t c) {
      if (far(random) == 0) return static_cast<std::uint32_t>(random() % 1000);
      return static_cast<std::uint32_t>(std::max(0, static_cast<int>(c) + move(random)));
    };
    moved[t] = G::pack(G::level(k), shift(G::cell_y(k)), shift(G::cell_x(k)));
  }
  moved[n / 2] = kFarthest;
  Buffer<std::uint32_t> guided;
  guided_sort(moved, s.key, guided);
  EXPECT_EQ(guided, plainly_sorted(moved));
}

TEST(broad_phase, the_sort_of_many_unguided_keys_equals_a_plain_sort_whichever_bits_they_differ_in) {
  // Past kRadixFrom (1,024) entries the sort goes by 11-bit digits from the lowest bit where keys differ,
  // skipping bits they all share. Each set has many repeated keys (their slot order must survive every pass)
  // and differs in other bits: a digit's edges (bits 10 and 11), two bits far apart (0 and 59, the level's
  // top), a whole digit (30 to 40), the last bits (a pass from 45 ends at 55, and 63 still needs a pass),
  // and the layout (row, column, band, level up to the global one).
  std::mt19937_64 random(21);
  const std::size_t n = 5000;
  const std::vector<std::pair<const char*, std::vector<CellKey>>> masks = {
      {"bits 10 and 11", {CellKey{1} << 10, CellKey{1} << 11}},
      {"bits 0 and 59", {CellKey{1}, CellKey{1} << 59}},
      {"bits 30 to 40", {CellKey{0x7ff} << 30}},
      {"bits 45 and 63", {CellKey{1} << 45, CellKey{1} << 63}},
      // The first layout packs the differing bits beside the slot when there are at most 32 of them.
      {"bits 0 to 15 and 40 to 55: 32 bits in two runs", {CellKey{0xffff}, CellKey{0xffff} << 40}},
      {"bits 0 to 32: 33 bits, too many to pack", {(CellKey{1} << 33) - 1}},
  };
  // The sort in place leaves the keys in their new order: unpacked from its entries where they pack (at most
  // 32 bits of fields that differ), else gathered; each must be keys[order[t]].
  const auto sort_with_keys = [](const std::vector<CellKey>& keys, const std::string& name, bool guided = false) {
    return sort_keys_in_place(keys, guided ? std::span<const CellKey>(keys) : std::span<const CellKey>(), 1, name);
  };
  for (const auto& [name, bits] : masks) {
    std::vector<CellKey> keys(n);
    for (CellKey& k : keys)
      for (const CellKey b : bits) k |= b & random();
    // Packed, each field takes the bits of its range: the fields of bits 0 to 15 and 40 to 55 take 42.
    const bool packs = std::string(name) != "bits 0 to 15 and 40 to 55: 32 bits in two runs" &&
                       std::string(name) != "bits 0 to 32: 33 bits, too many to pack";
    EXPECT_EQ(sort_with_keys(keys, name), packs) << name;
  }
  std::vector<CellKey> keys(n);
  for (CellKey& k : keys)
    k = random() % 50 == 0 ? G::pack(G::kGlobalLevel, 0, 0)
                           : G::pack(static_cast<unsigned>(random() % 3) * 7, static_cast<std::uint32_t>(random() % 300),
                                     static_cast<std::uint32_t>(random() % 40) + (std::uint32_t{1} << 20));
  EXPECT_FALSE(sort_with_keys(keys, "the layout")) << "the columns of the global circles and the rest take 21 bits";
  // A planned scene: cells around kCells / 2 on both axes (CellGrid::plan centres it there), so columns and
  // bands straddle a power of two and differ in every bit below it, on two levels.
  const std::uint32_t centre = G::kCells / 2;
  for (CellKey& k : keys) {
    const unsigned level = static_cast<unsigned>(random() % 2);
    k = G::pack(level, (centre >> (2 * level)) - 600 + static_cast<std::uint32_t>(random() % 1200),
                (centre >> (2 * level)) - 600 + static_cast<std::uint32_t>(random() % 1200));
  }
  EXPECT_FALSE(sort_with_keys(keys, "a planned scene")) << "level 1's columns are a quarter of level 0's";
  for (CellKey& k : keys)  // the same on level 0 alone: bands, rows and columns in 8 + 3 + 11 bits
    k = G::pack(0, centre - 600 + static_cast<std::uint32_t>(random() % 1200),
                centre - 600 + static_cast<std::uint32_t>(random() % 1200));
  EXPECT_TRUE(sort_with_keys(keys, "a planned scene on one level"));
  // Too few keys for the digits (std::sort).
  EXPECT_FALSE(sort_with_keys(std::vector<CellKey>(keys.begin(), keys.begin() + 1000), "1,000 keys"));
  // Keys that pack are sorted by digits whether or not their previous keys are given.
  EXPECT_TRUE(sort_with_keys(keys, "a planned scene on one level, guided", true));
}

TEST(broad_phase, the_sort_by_digits_in_parts_on_several_threads_equals_a_plain_sort) {
  // 40,000 slots, so that two and three threads split each pass into parts (kParallelFrom); the keys take
  // three digits (cells 0 to 2,999 on both axes), and many repeat, so the slot order of ties must survive
  // each pass's hand-over from part to part.
  std::mt19937_64 random(23);
  const std::size_t n = 40000;
  std::vector<CellKey> keys(n);
  for (CellKey& k : keys)
    k = G::pack(0, static_cast<std::uint32_t>(random() % 3000), static_cast<std::uint32_t>(random() % 3000 / 7));
  for (const unsigned threads : {1u, 2u, 3u}) {
    EXPECT_GT(chunk_count(n, threads), threads > 1 ? 1u : 0u);
    EXPECT_TRUE(sort_keys_in_place(keys, keys, threads, std::to_string(threads) + " threads"));
  }
}

TEST(broad_phase, the_guided_re_sort_equals_a_plain_sort_when_every_slot_changes_column_within_its_band) {
  // Every slot stays in its band, so the insertion sort of those slots runs out of its budget (8 moves a slot)
  // early and sorts the rest by digits, then merges it with the sorted front.
  std::mt19937_64 random(22);
  const std::size_t n = 20000;
  std::vector<CellKey> previous(n), moved(n);
  for (std::size_t t = 0; t < n; ++t)
    previous[t] = G::pack(0, static_cast<std::uint32_t>(t * 64 / n), static_cast<std::uint32_t>(t % 500));
  std::sort(previous.begin(), previous.end());
  for (std::size_t t = 0; t < n; ++t)
    moved[t] = G::pack(0, G::cell_y(previous[t]), static_cast<std::uint32_t>(random() % 500));
  moved[n - 1] = kFarthest;
  Buffer<std::uint32_t> guided;
  EXPECT_FALSE(guided_sort(moved, previous, guided));
  EXPECT_EQ(guided, plainly_sorted(moved));
}

TEST(broad_phase, the_re_sort_in_parts_on_several_threads_equals_a_plain_sort) {
  // 40,000 slots, so that two and three threads split them into chunks (kParallelFrom), whose parts are the
  // key ranges the previous keys held. Keys move within their band, across bands, far (some leave their part
  // for any other), and many repeat the key at a part's boundary, which must go to one part only.
  std::mt19937_64 random(12);
  const std::size_t n = 40000;
  std::vector<CellKey> previous(n);
  for (std::size_t t = 0; t < n; ++t)
    previous[t] = G::pack(0, static_cast<std::uint32_t>(random() % 400), static_cast<std::uint32_t>(random() % 400));
  std::sort(previous.begin(), previous.end());
  std::uniform_int_distribution<int> move(-12, 12), kind(0, 19);
  for (const unsigned threads : {1u, 2u, 3u}) {
    const std::size_t chunks = chunk_count(n, threads);
    std::vector<CellKey> moved(n);
    std::size_t crossed = 0;
    for (std::size_t t = 0; t < n; ++t) {
      const CellKey k = previous[t];
      const auto shift = [&](std::uint32_t c) {
        return static_cast<std::uint32_t>(std::max(0, static_cast<int>(c) + move(random)));
      };
      switch (kind(random)) {
        case 0:  // anywhere
          moved[t] = G::pack(0, static_cast<std::uint32_t>(random() % 400), static_cast<std::uint32_t>(random() % 400));
          break;
        case 1:  // onto the first key of a part
          moved[t] = previous[chunk_begin(n, chunks, random() % chunks)];
          break;
        default:
          moved[t] = G::pack(0, shift(G::cell_y(k)), shift(G::cell_x(k)));
      }
      // Its part: the chunk whose first previous key is the last one at or below it.
      std::size_t part = 0;
      while (part + 1 < chunks && previous[chunk_begin(n, chunks, part + 1)] <= moved[t]) ++part;
      crossed += part != t * chunks / n;
    }
    moved[n - 1] = kFarthest;
    Buffer<std::uint32_t> parted;
    CellOrder order;
    EXPECT_FALSE(CellOrder::by_digits(moved)) << "the keys pack: the sort would go by digits, not guided";
    Buffer<CellKey> in_order(moved.begin(), moved.end());
    EXPECT_FALSE(order.sort_in_place(in_order, previous, parted, threads));
    EXPECT_EQ(parted, plainly_sorted(moved)) << threads << " threads";
    // The guided sort gathers the keys into the new order.
    for (std::size_t t = 0; t < n; ++t) ASSERT_EQ(in_order[t], moved[parted[t]]) << threads << " threads, slot " << t;
    if (threads > 1) {
      EXPECT_GT(chunks, 1u);
      EXPECT_GT(crossed, n / 50) << threads << " threads: too few keys change part to test the hand-over";
    }
    // The same CellOrder again, on the result's own order: nothing left over from the last call.
    Buffer<std::uint32_t> identity;
    EXPECT_TRUE(order.sort_in_place(in_order, moved, identity, threads));
  }
}

}  // namespace
}  // namespace circles::impl

namespace circles::impl {
namespace {

TEST(threads, an_exception_in_a_chunk_reaches_the_caller_as_the_least_chunks_whatever_the_thread_count) {
  // An exception may not leave an OpenMP region (the program would terminate, as a failed allocation in a
  // parallel part once did): for_each_chunk rethrows the least failing chunk's after every chunk has run.
  for (const unsigned threads : {1u, 2u, 4u})
    for (const std::size_t chunks : {std::size_t{1}, std::size_t{8}}) {
      std::vector<int> ran(chunks, 0);
      try {
        for_each_chunk(chunks, threads, [&](std::size_t c) {
          ran[c] = 1;
          if (c % 3 == 2 || chunks == 1) throw std::runtime_error("chunk " + std::to_string(c));
        });
        ADD_FAILURE() << "nothing thrown";
      } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), chunks == 1 ? "chunk 0" : "chunk 2") << threads << " threads";
      }
      EXPECT_EQ(std::count(ran.begin(), ran.end(), 1), static_cast<long>(chunks)) << threads << " threads";
    }
}

}  // namespace
}  // namespace circles::impl
