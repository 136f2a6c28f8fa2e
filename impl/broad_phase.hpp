// The broad phase of the engines: a hierarchy of uniform grids over circles kept in cell order.
//
//   Invariant (conservative): for finite px, py and r ≥ 0, every pair {a, b}, a ≠ b, that intersects exactly
//   by (3) is visited: a's neighbourhood (CellGrid::neighbourhood) holds b's cell, or b's holds a's, or one of
//   them is global. The narrow phase decides the pairs it is given; pairs that do not intersect cost a test,
//   never a wrong answer.
//
// The grid. Level L has square cells of side s·4^L (s, the base cell, chosen from the radii by plan()); cell
// indices along an axis are cell(x, L) = clamp(⌊RN(RN(x − o)·inv_L)⌋, 0, kCells − 1), inv_L = 4^−L/s, for an
// origin o. Circle c has the box [xlo, xhi] × [ylo, yhi] that holds its exact box [px − r, px + r] × … (the
// outward bounds below). Its level is the first L, from the least whose cell is as wide as the box, at which
// the box spans at most two cells on each axis, cell(xhi, L) ≤ cell(xlo, L) + 1 and the same in y, and its cell
// there is (cell(xlo, L), cell(ylo, L)): the cell of the box's lower corner. A box that spans more at every level below kGlobalLevel (only for extents near the
// double range) is global and is tested against every circle.
//
// Why no exactly intersecting pair is missed (broad_phase.cpp repeats it at the code):
//   1. a intersect b gives |X| ≤ |p_b − p_a| ≤ r_a + r_b exactly, so the exact boxes overlap: b_x − r_b ≤ a_x + r_a
//      and a_x − r_a ≤ b_x + r_b, and the same in y.
//   2. The computed bounds contain the exact ones, so the computed boxes overlap: xlo_b ≤ xhi_a, xlo_a ≤ xhi_b.
//   3. cell(·, L) is monotone (non-decreasing) in x at every level: RN is monotone, inv_L ≥ 0, and floor and
//      clamp are monotone. Rounding moves cell boundaries, never the order.
//   4. Take L = level(b) ≥ level(a). By 2 and 3, cell(xlo_b) ≤ cell(xhi_a); by b's span and 3,
//      cell(xlo_b) ≥ cell(xhi_b) − 1 ≥ cell(xlo_a) − 1. So b's cell lies in
//      [cell(xlo_a) − 1, cell(xhi_a)] × [cell(ylo_a) − 1, cell(yhi_a)] at level L: a's neighbourhood at L.
//   No step relies on the accuracy of a rounded value; only the monotonicity of 3 and the spans, which are
//   checked per circle, carry the argument.
//
// The layout. The engines keep their circles sorted by key, and the key orders cells in bands of kBandRows
// rows: by level, band, column, then row within the band (a column of kBandRows cells is one run of slots).
// So a cell's neighbours in its band are a few cells away in memory, not a whole row of the grid, and the
// pair tests read partners that are still in the first-level cache; only a band's top row looks into the
// next band. A neighbourhood is then at most five runs of consecutive slots. Circles move little per step,
// so the order of one step is nearly the order of the next: CellOrder re-sorts in linear time when each
// circle stays in its band or moves to the next one (the common case) and sorts the others by digits (a
// radix sort, linear too).
#pragma once

#include "impl/double_bounds.hpp"

#include "impl/buffers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace circles::impl {

// ── Outward bounds ────────────────────────────────────────────────────────────────────────────────────
// kOutwardRelative and kOutwardAbsolute, with the proof that RN(t ∓ e) is outward, are in impl/double_bounds.hpp.

// A double ≤ the exact x − r, for finite x and r ≥ 0 (−∞ when x − r is below −DBL_MAX's reach).
inline double outward_lower(double x, double r) noexcept {
  const double t = x - r;
  return t - (std::fabs(t) * kOutwardRelative + kOutwardAbsolute);
}
// A double ≥ the exact x + r, for finite x and r ≥ 0 (+∞ when x + r is beyond DBL_MAX's reach).
inline double outward_upper(double x, double r) noexcept {
  const double t = x + r;
  return t + (std::fabs(t) * kOutwardRelative + kOutwardAbsolute);
}

// ── The grid ──────────────────────────────────────────────────────────────────────────────────────────

// A key: level (6 bits) · band (cell y / kBandRows, 24 bits) · cell x (27 bits) · cell y mod kBandRows
// (3 bits). Keys order circles by level, band, column, and row within the band.
using CellKey = std::uint64_t;

class CellGrid {
 public:
  static constexpr int kCellBits = 27;
  static constexpr std::uint32_t kCells = std::uint32_t{1} << kCellBits;  // cells per axis
  static constexpr unsigned kLevels = 64;
  static constexpr unsigned kGlobalLevel = kLevels - 1;  // the level of global circles
  // plan() puts the circles' extent within kCells / 4 base cells, centred, so circles can drift that far
  // before their cells clamp (clamping is correct, only slower).
  static constexpr double kPlannedCells = static_cast<double>(kCells) / 4;

  // Rows per band: 8 keeps a band's columns within a few dozen slots at the densities that matter (a cell
  // holds about two circles at 10% coverage), while only one row in 8 looks into the next band.
  static constexpr int kBandBits = 3;
  static constexpr std::uint32_t kBandRows = std::uint32_t{1} << kBandBits;

  static constexpr CellKey pack(unsigned level, std::uint32_t y, std::uint32_t x) noexcept {
    return (CellKey{level} << (2 * kCellBits)) | (CellKey{y >> kBandBits} << (kCellBits + kBandBits)) |
           (CellKey{x} << kBandBits) | (y & (kBandRows - 1));
  }
  static constexpr unsigned level(CellKey k) noexcept { return static_cast<unsigned>(k >> (2 * kCellBits)); }
  static constexpr std::uint32_t cell_y(CellKey k) noexcept {
    const auto band = static_cast<std::uint32_t>(k >> (kCellBits + kBandBits)) & ((kCells >> kBandBits) - 1);
    return (band << kBandBits) | (static_cast<std::uint32_t>(k) & (kBandRows - 1));
  }
  static constexpr std::uint32_t cell_x(CellKey k) noexcept {
    return static_cast<std::uint32_t>(k >> kBandBits) & (kCells - 1);
  }
  // The level and band of a key: the keys of one band at one level are one run in cell order.
  static constexpr CellKey band(CellKey k) noexcept { return k >> (kCellBits + kBandBits); }

  // Chooses the base cell and the origin for circles (px, py, r): the base cell is the largest box width
  // that is at most kWidthSpread times the median width (so one huge circle does not coarsen the grid for all
  // the others; it takes a higher level), and at least the extent / kPlannedCells. The median is that of at
  // most kMedianSample boxes, every (n / kMedianSample)-th slot's. Any finite choice is correct (see above);
  // this one is for speed. Spans must have equal sizes.
  void plan(std::span<const double> px, std::span<const double> py, std::span<const double> r);

  // The cell index of x along one axis at a level: monotone in x. `origin` is the axis's origin.
  std::uint32_t cell(double x, double origin, unsigned level) const noexcept {
    const double t = (x - origin) * scale_ * inverse_[level];
    if (!(t > 0)) return 0;
    if (t >= kLastCell) return kCells - 1;
    return static_cast<std::uint32_t>(t);
  }
  std::uint32_t cell_of_x(double x, unsigned level) const noexcept { return cell(x, origin_x_, level); }
  std::uint32_t cell_of_y(double y, unsigned level) const noexcept { return cell(y, origin_y_, level); }

  // The key of the circle (x, y, r): its level and the cell of its box's lower corner there.
  CellKey key(double x, double y, double r) const noexcept {
    CellKey k;
    keys(std::span<const double>(&x, 1), std::span<const double>(&y, 1), std::span<const double>(&r, 1),
         std::span<CellKey>(&k, 1));
    return k;
  }
  // out[t] = key(px[t], py[t], r[t]) for every t, in two passes: a branch-free one for the common case,
  // then key_at_any_level for the rest. Spans of equal size.
  void keys(std::span<const double> px, std::span<const double> py, std::span<const double> r,
            std::span<CellKey> out) const noexcept;
  // The key from the box: its level is the first from the least whose cell is as wide as the box, at which
  // the box spans at most two cells on each axis.
  CellKey key_at_any_level(double xlo, double xhi, double ylo, double yhi) const noexcept;

  // A's neighbourhood at level L ≥ level(a): cells [x0, x1] × [y0, y1] (step 4 above).
  struct Range {
    std::uint32_t x0, x1, y0, y1;
  };
  Range neighbourhood(double x, double y, double r, unsigned level) const noexcept;

  // True when plan() left circles beyond the cover of the grid (a few far outliers), to clamp into its edge cells:
  // a plan from the same world would leave them out again.
  bool trimmed() const noexcept { return trimmed_; }

  // True when the rectangle's corners fall strictly inside the grid at level 0: no cell there is clamped.
  bool covers(double xlo, double xhi, double ylo, double yhi) const noexcept {
    const auto inside = [](std::uint32_t c) { return c > 0 && c < kCells - 1; };
    return inside(cell_of_x(xlo, 0)) && inside(cell_of_x(xhi, 0)) && inside(cell_of_y(ylo, 0)) &&
           inside(cell_of_y(yhi, 0));
  }

 private:
  static constexpr double kLastCell = static_cast<double>(kCells - 1);
  static constexpr double kWidthSpread = 4.0;
  static constexpr std::size_t kMedianSample = 4096;
  static constexpr double kBaseSlack = 1 + 0x1p-10;  // plan(): the base cell a little wider than the widest box
  // plan(): the outliers' trim, a speed choice. Extents up to 2^20 times the spread of the centres between
  // their 1/64 and 63/64 quantiles are planned whole (uniform, clustered and sparse worlds: the grid holds 2^27
  // cells a side); beyond it, the circles outside four times that spread clamp into the edge cells.
  static constexpr double kTrim = 1.0 / 64;
  static constexpr double kTrimSpread = 0x1p20;
  // The least base cell whose inverse is finite without a scale: 2^-1000, with room to spare (1/2^-1023 is).
  static constexpr double kLeastScaledBase = 0x1p-1000;
  double origin_x_ = 0, origin_y_ = 0, base_cell_ = 1;
  bool trimmed_ = false;  // plan() left far circles out of the grid's cover
  double scale_ = 1;  // 2^s: 1, or for a base cell below kLeastScaledBase the power of two that lifts it there
  std::array<double, kLevels> inverse_{};  // inv_L = 4^-L / (base cell · scale)
};

// ── The order ─────────────────────────────────────────────────────────────────────────────────────────

// The permutation that sorts keys, in linear time, on up to `threads` threads. Keys whose fields pack into 32
// bits (KeyPacking in broad_phase.cpp; every single-level scene measured) are sorted by digits, an LSD radix
// sort of 8-byte entries in two or three passes, each in parts on the threads. The others are sorted guided by
// their previous keys, in linear time when they are nearly sorted already. The digits are the faster where
// both apply: at 10^6 circles and 10% coverage, with lists of 6 steps, a guided re-sort made its rebuild 178 ms
// against 143 by digits; at 0.1%, and with velocities a twentieth of the scene's, the digits were as fast or
// faster.
//
// Guided and in parallel, slots are split into chunks, and the output into parts by the previous keys at the chunks'
// first slots (the previous keys are sorted, so part c is the key range that chunk c held): every key of part
// c is less than every key of part c + 1. Each chunk sorts the slots whose key stayed in its own part (most
// of them; the guided repair below) and hands the others to their parts; each part then merges what it kept
// with what it was handed and writes its range of the output. (key, slot) is a total order, so the result is
// the same for every thread count.
class CellOrder {
 public:
  // Sets `order` to the slots of `keys` in ascending key order (ties in slot order), keys[order[0]] ≤
  // keys[order[1]] ≤ …, and leaves `keys` in that order, the old keys[order[t]] at t. `previous` holds the keys
  // the same slots had when they were last sorted (ascending by slot), or is empty; it only guides the work of
  // keys that do not pack, never the result. Returns true when `keys` were sorted already (`order` is then the
  // identity). The sort by digits makes its entries in the keys' own memory and leaves them there as keys, so
  // that it writes 8 bytes a slot less of new memory than a sort beside them (8 MB at 10^6 circles, in a first
  // step that writes its memory for the first time); the guided sort's result is gathered.
  bool sort_in_place(Buffer<CellKey>& keys, std::span<const CellKey> previous, Buffer<std::uint32_t>& order,
                     unsigned threads = 1);
  // True when the sorts go by digits for these keys, unsorted: kRadixFrom (1,024) keys or more whose fields
  // pack into 32 bits; else they are sorted guided by `previous`.
  static bool by_digits(std::span<const CellKey> keys);

 private:
  // The sort guided by `previous` (below), for keys that do not pack.
  void guided(std::span<const CellKey> keys, std::span<const CellKey> previous, Buffer<std::uint32_t>& order,
              unsigned threads);
  struct Entry {
    CellKey key;
    std::uint32_t slot;
    std::uint32_t part;  // the part of the output it belongs to
  };
  // One chunk's work: its slots split by how far their band moved, each list repaired, then merged.
  struct Chunk {
    Buffer<Entry> same, up, down, other, foreign, merged, spare, incoming;
    // Splits slots [begin, end) of keys whose key is in [low, high) (this chunk's part) by how far their band
    // moved since `previous` (guided, or all in `other`); the rest go to `foreign`, marked with their part.
    void split(std::span<const CellKey> keys, std::span<const CellKey> previous, std::size_t begin,
               std::size_t end, std::span<const CellKey> splitters, std::size_t part);
    // Sorts what split() kept with `incoming` (entries handed over by other chunks) into out[0, size).
    void merge_into(std::span<std::uint32_t> out);
  };
  std::vector<Chunk> chunks_;
  // n keys' room, kept between sorts: the digits' second buffer, or the guided sort's gathered keys. A sort
  // that took it new each time would write 8 bytes a slot of new memory per rebuild (impl/buffers.hpp).
  Buffer<CellKey> scratch_;
};

// ── The query ─────────────────────────────────────────────────────────────────────────────────────────

// Circles in cell order, as the query reads them: slot t has key[t] (ascending), px[t], py[t], r[t].
struct CellView {
  std::span<const CellKey> key;
  std::span<const double> px, py, r;
  std::span<const unsigned> levels;  // the levels that hold a circle, ascending, the global level excluded
  std::span<const std::size_t> level_begin;  // level L holds slots [level_begin[L], level_begin[L + 1])
  // The walk's form, a speed choice (few_per_cell below): a's column and the next as one run, and the band
  // above as one, rather than one run per cell range.
  bool wide_runs = false;
};

// True when the cells that hold a slot hold at most kFewPerCell slots each on average: then the walk's wide
// runs (CellView::wide_runs) cost less than its narrow ones. A wide run holds, beyond a's neighbours, about 7
// cells' slots more (the rest of a's column and the next, a band being 8 rows), each rejected by one
// branch-free filter of a few cycles; it saves a seek and a run, each ending in a mispredicted branch, worth
// some 8 filters. So wide runs pay while a cell holds about one slot or fewer: on random scenes a mean of λ
// slots per cell puts λ/(1 − e^−λ) in each cell that holds any, 1.58 at λ = 1. Measured on the benchmarks'
// dense scene (10^6 circles, 10%): a step without a list, whose cells hold 0.26 slots each (1.13 per occupied
// cell), took 15% less time with wide runs; a list of horizon 8, whose inflated cells hold about 3.3, took
// 18% more. Sorted keys: one pass counting the distinct ones.
inline constexpr double kFewPerCell = 1.5;
bool few_per_cell(std::span<const CellKey> key) noexcept;

// Indexes keys sorted ascending by level: level_begin[L] is the first slot of level L (level_begin[kLevels]
// is the size), and `levels` lists the levels below the global one that hold a circle.
void index_levels(std::span<const CellKey> key, std::array<std::size_t, CellGrid::kLevels + 1>& level_begin,
                  std::vector<unsigned>& levels);

// The least slot from `at` on whose key is ≥ first, or the view's size, where the keys from `at` on ascend:
// the keys below `first` are a prefix, counted a block of four at a time, and the loop ends at the first
// block they do not fill (mostly the first, a branch that predicts well where a loop slot by slot mispredicts
// its exit once per call).
[[gnu::always_inline]] inline std::size_t first_at_least(std::span<const CellKey> key, std::size_t at, CellKey first) noexcept {
  constexpr std::size_t kBlock = 4;
  const std::size_t n = key.size();
  while (at + kBlock <= n) {
    std::size_t below = 0;
    for (std::size_t i = 0; i < kBlock; ++i) below += key[at + i] < first;
    at += below;
    if (below < kBlock) return at;
  }
  while (at < n && key[at] < first) ++at;
  return at;
}

// The query's position in the view: cursors that only move forward, one into the next column of a's band
// and one into the band above. One per run of ascending slots (one per thread's chunk).
struct NeighbourCursor {
  std::size_t column = 0, above = 0;
  bool column_ready = false, above_ready = false;
};

// Calls visit_run(from, last) for runs of consecutive slots, the slots from `from` on whose keys are ≤ last
// (none when key[from] > last), that together hold every slot b after a (b > a) in a's forward neighbourhood,
// once each; visit_run visits them and returns the first slot after them (the least slot ≥ from that is the
// view's size or has a key > last). At a's level,
//   a's column, from a to the end of the next row when that row is in a's band;
//   the next column, from one row below a's to one above, within a's band;
//   when a's row is its band's top row, the next band's bottom row, from one column left of a's to one right;
// and the slots of every higher level in a's neighbourhood there (step 4). Over all a, every pair of
// non-global slots whose cells make them neighbours is visited exactly once:
//   same level, same band: both spans are ≤ 1, so by step 4 the two cells are at most one apart on each axis;
//     in one column, the earlier slot (lower row, or the same cell) visits the later one in its own column;
//     in two, the left one visits the right one in its next column, and the right one never looks left.
//   same level, two bands: only rows one apart are neighbours, the lower band's top row and the upper band's
//     bottom row; the lower one visits the upper one, and no slot looks into a lower band.
//   different levels: only the lower level's slot searches the higher level.
// With view.wide_runs, a's column and the next are one run, from a to the next column's row above a's, and
// the band above is one run, from its bottom row in the column left of a's to its bottom row in the column
// right of a's. They hold the same neighbours, and other slots visited at most once as well: rows further up
// a's column and further down the next, and the upper band's rows above its bottom one in the left and middle
// columns. None of those is a neighbour (two cells apart on an axis): the caller's filter rejects them.
// Slots a must be visited in ascending order with one NeighbourCursor. Global circles (level kGlobalLevel)
// visit nothing and are visited by no one: the caller pairs them with every circle. Runs (at most five at
// a's level, two with wide runs, a few per higher level) let the caller's loop over a run keep a's values in
// registers; a run bounded by its last key, not by its end, lets that loop find the end as it goes, with one
// mispredicted exit per run where scanning for the end first and then looping over the run took two.
// visit_neighbourhood below hands the slots over one by one.
template <class VisitRun>
void visit_neighbourhood_runs(const CellGrid& grid, const CellView& view, std::size_t a, NeighbourCursor& cursor,
                              VisitRun&& visit_run) {
  using G = CellGrid;
  const CellKey k = view.key[a];
  const unsigned level = G::level(k);
  if (level == G::kGlobalLevel) return;
  const std::uint32_t cx = G::cell_x(k), cy = G::cell_y(k);
  const std::uint32_t row = cy & (G::kBandRows - 1);  // a's row within its band
  const bool band_top = row == G::kBandRows - 1;
  // A cursor moved forward to the first key ≥ first. Each cursor's `first` only grows with a's key (shown at
  // each use), so a cursor moves over the whole view once: linear in all.
  const auto seek = [&](std::size_t& cursor_at, bool& ready, CellKey first) {
    // A local, stored once: a key is a std::uint64_t, the type a std::size_t is, so the compiler must assume
    // that each key read may alias the cursor, and would store it at every step of the loop.
    std::size_t at = cursor_at;
    if (!ready) {
      at = static_cast<std::size_t>(std::lower_bound(view.key.begin(), view.key.end(), first) - view.key.begin());
      ready = true;
    }
    at = first_at_least(view.key, at, first);
    cursor_at = at;
    return at;
  };
  // a's column to the end of the next row, if the band has one; then the next column, rows cy − 1 … cy + 1
  // within the band. Its first key (level, band, cx + 1, row − 1 or the band's first row) only grows with a's
  // key (level, band, cx, row).
  const std::uint32_t y1 = band_top ? cy : cy + 1;
  const bool next_column = cx + 1 < G::kCells;
  if (view.wide_runs) {
    visit_run(a + 1, G::pack(level, y1, next_column ? cx + 1 : cx));
  } else {
    visit_run(a + 1, G::pack(level, y1, cx));
    if (next_column) {
      const std::uint32_t y0 = row > 0 ? cy - 1 : cy;
      visit_run(seek(cursor.column, cursor.column_ready, G::pack(level, y0, cx + 1)), G::pack(level, y1, cx + 1));
    }
  }
  // The band above, from a band's top row: its bottom row, columns cx − 1 … cx + 1, one run per column (one in
  // all with wide runs). Its first key (level, band + 1, cx − 1, 0) only grows with a's key among the top
  // rows' slots.
  if (band_top && cy + 1 < G::kCells) {
    const std::uint32_t x0 = cx > 0 ? cx - 1 : 0, x1 = cx + 1 < G::kCells ? cx + 1 : cx;
    std::size_t b = seek(cursor.above, cursor.above_ready, G::pack(level, cy + 1, x0));
    if (view.wide_runs) {
      visit_run(b, G::pack(level, cy + 1, x1));
    } else {
      for (std::uint32_t x = x0; x <= x1; ++x) {
        const CellKey cell = G::pack(level, cy + 1, x);
        b = visit_run(first_at_least(view.key, b, cell), cell);
      }
    }
  }
  // Each level above: step 4's range, column by column, one run per band, by binary search within the level.
  for (const unsigned above : view.levels) {
    if (above <= level) continue;
    const G::Range range = grid.neighbourhood(view.px[a], view.py[a], view.r[a], above);
    const auto first = view.key.begin() + static_cast<std::ptrdiff_t>(view.level_begin[above]);
    const auto last = view.key.begin() + static_cast<std::ptrdiff_t>(view.level_begin[above + 1]);
    // Cell indices are below 2^27, so x + 1 and y + 1 cannot wrap. A run stops at the level's end too: keys
    // of later levels are larger than any key of this one.
    for (std::uint32_t x = range.x0; x <= range.x1; ++x)
      for (std::uint32_t y = range.y0; y <= range.y1;) {
        const std::uint32_t end = std::min(range.y1, y | (G::kBandRows - 1));  // the range's last row in y's band
        visit_run(static_cast<std::size_t>(std::lower_bound(first, last, G::pack(above, y, x)) - view.key.begin()),
                  G::pack(above, end, x));
        y = end + 1;
      }
  }
}

// The same slots one by one: visit(b) for each.
template <class Visit>
void visit_neighbourhood(const CellGrid& grid, const CellView& view, std::size_t a, NeighbourCursor& cursor,
                         Visit&& visit) {
  visit_neighbourhood_runs(grid, view, a, cursor, [&visit, &view](std::size_t from, CellKey last) {
    std::size_t b = from;
    for (; b < view.key.size() && view.key[b] <= last; ++b) visit(b);
    return b;
  });
}

// A contact that one chunk of slots finds for a slot of a later chunk: slot `to` intersects slot `from`
// (PairList::least_contacts, impl/pair_list_impl.hpp, offers it after the parallel part).
struct ContactOffer {
  std::uint32_t to, from;
};

// ── For tests ─────────────────────────────────────────────────────────────────────────────────────────

// A candidate pair, i < j (indices into the world).
struct CandidatePair {
  std::uint32_t i;
  std::uint32_t j;
  friend bool operator==(const CandidatePair&, const CandidatePair&) = default;
  friend auto operator<=>(const CandidatePair&, const CandidatePair&) = default;
};

// The test hooks' check, all pairs: true when `candidates` holds every pair {i, j}, i ≠ j, that intersects
// exactly (impl::intersect_exact). Pairs may appear in either orientation. O(n²): for tests only.
bool candidates_cover_all_intersecting_pairs(std::span<const double> px, std::span<const double> py,
                                             std::span<const double> r, std::span<const CandidatePair> candidates);

}  // namespace circles::impl
