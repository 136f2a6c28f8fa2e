// The cell grid and the cell order; the conservativeness argument is in broad_phase.hpp.
#include "impl/broad_phase.hpp"

#include "impl/buffers.hpp"
#include "impl/contacts.hpp"
#include "impl/predicate.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace circles::impl {

namespace {

// The finite values of value(k) at `sample` slots k of n spread evenly over them: what plan() takes its median
// and quantiles from, a speed choice (any plan is correct), so that no plan sorts n values.
template <class Value>
std::vector<double> sampled(std::size_t n, std::size_t sample, Value value) {
  std::vector<double> values;
  values.reserve(sample);
  for (std::size_t s = 0; s < sample; ++s)
    if (const double v = value(s * n / sample); std::isfinite(v)) values.push_back(v);
  return values;
}

// The k-th smallest of values (reordering them).
double kth(std::vector<double>& values, std::size_t k) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

void CellGrid::plan(std::span<const double> px, std::span<const double> py, std::span<const double> r) {
  const std::size_t n = px.size();
  if (py.size() != n || r.size() != n) throw std::invalid_argument("CellGrid::plan: px, py and r differ in size");
  // The median width from at most kMedianSample circles spread evenly over the slots: the median only sets
  // the limit below, a speed choice (any base cell is correct).
  const std::size_t sample = std::min(n, kMedianSample);
  std::vector<double> widths =
      sampled(n, sample, [&](std::size_t k) { return outward_upper(px[k], r[k]) - outward_lower(px[k], r[k]); });
  const double limit = widths.empty() ? 0 : kWidthSpread * kth(widths, widths.size() / 2);
  // The base cell: the largest width within kWidthSpread medians (0 for an empty world, or one whose sample
  // has no finite width); the extent of the boxes.
  double base = 0;
  double xlo = std::numeric_limits<double>::infinity(), ylo = xlo, xhi = -xlo, yhi = -xlo;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = outward_lower(px[k], r[k]), b = outward_upper(px[k], r[k]);
    const double c = outward_lower(py[k], r[k]), d = outward_upper(py[k], r[k]);
    if (b - a <= limit) base = std::max(base, b - a);
    if (std::isfinite(a)) xlo = std::min(xlo, a);
    if (std::isfinite(b)) xhi = std::max(xhi, b);
    if (std::isfinite(c)) ylo = std::min(ylo, c);
    if (std::isfinite(d)) yhi = std::max(yhi, d);
  }
  // A box's computed width depends on where the circle is (the roundings of x ± r): a circle that moves can
  // come out an ulp wider than it was planned with, miss level 0, and make every circle search the level
  // above. kBaseSlack keeps the widest planned box inside level 0 after such moves.
  base *= kBaseSlack;
  // At least the extent over kPlannedCells, so the scene fits in the grid; halves keep the extent finite. But
  // a few far circles (outliers near ±2^1023 among ordinary ones) would make that a cell wider than the whole
  // of the rest, and every step a test of every pair: when the extent is more than kTrimSpread times the
  // spread of the sampled centres between their kTrim and (1 − kTrim) quantiles, the grid covers that spread
  // (four times over, centred on it) and the circles beyond it clamp into the edge cells, which is correct,
  // only slower for them (trimmed()).
  double extent = std::max(xhi / 2 - xlo / 2, yhi / 2 - ylo / 2);
  trimmed_ = false;
  if (std::isfinite(extent) && n > 0) {
    const auto quantiles = [&](std::span<const double> v) {
      std::vector<double> centres = sampled(n, sample, [&](std::size_t k) { return v[k]; });
      if (centres.empty()) return std::pair{0.0, 0.0};
      const std::size_t trim = static_cast<std::size_t>(static_cast<double>(centres.size()) * kTrim);
      return std::pair{kth(centres, trim), kth(centres, centres.size() - 1 - trim)};
    };
    const auto [qx0, qx1] = quantiles(px);
    const auto [qy0, qy1] = quantiles(py);
    // The spread as half-widths, at least the median box's, so a world of coinciding centres is not trimmed.
    const double spread = std::max({qx1 / 2 - qx0 / 2, qy1 / 2 - qy0 / 2, limit / kWidthSpread});
    if (extent > kTrimSpread * spread) {
      trimmed_ = true;
      extent = 4 * spread;
      xlo = qx0 - 3 * spread;  // centred on the quantiles' middle: (qx0 + qx1)/2 ± 4·spread
      xhi = qx1 + 3 * spread;
      ylo = qy0 - 3 * spread;
      yhi = qy1 + 3 * spread;
    }
  }
  if (std::isfinite(extent)) base = std::max(base, extent / (kPlannedCells / 2));
  // Keep the base finite and positive: at most 2^1000, far above any width that matters here, and at least
  // the least subnormal, so that a world at the subnormal scale gets cells of its own size, not one cell.
  base_cell_ = std::clamp(std::isfinite(base) ? base : 0x1p1000, std::numeric_limits<double>::denorm_min(), 0x1p1000);
  // Below 2^-1000, 1/base would overflow: cell() first scales x − origin by 2^s, exactly (a power of two,
  // and no overflow: |x − origin| is within 2^27 base cells, or clamped anyway), so that base·2^s ≥ 2^-1000.
  scale_ = base_cell_ < kLeastScaledBase ? std::ldexp(1.0, std::ilogb(kLeastScaledBase) - std::ilogb(base_cell_)) : 1;
  const double centre_x = std::isfinite(extent) ? xlo / 2 + xhi / 2 : 0;
  const double centre_y = std::isfinite(extent) ? ylo / 2 + yhi / 2 : 0;
  origin_x_ = centre_x - static_cast<double>(kCells / 2) * base_cell_;
  origin_y_ = centre_y - static_cast<double>(kCells / 2) * base_cell_;
  // inv_L = 4^-L / (base·2^s): exact powers of two apart (or 0 once they underflow, which keeps cell()
  // monotone).
  for (unsigned level = 0; level < kLevels; ++level)
    inverse_[level] = std::ldexp(1 / (base_cell_ * scale_), -2 * static_cast<int>(level));
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
  // The loop for a scale of 1 (every world above the subnormal scale) multiplies by no scale at all.
  const auto first_pass = [&]<bool kScaled>(std::bool_constant<kScaled>) {
    const double inv = inverse_[0], ox = origin_x_, oy = origin_y_, scale = scale_;
    for (std::size_t t = 0; t < n; ++t) {
      const double x = px[t], y = py[t], radius = r[t];
      const double xlo = outward_lower(x, radius), xhi = outward_upper(x, radius);
      const double ylo = outward_lower(y, radius), yhi = outward_upper(y, radius);
      const auto scaled = [scale](double d) { return kScaled ? d * scale : d; };
      const auto at0 = [&](double v, double origin) {
        double c = scaled(v - origin) * inv;
        c = c > 0 ? c : 0;
        c = c < kLastCell ? c : kLastCell;
        return static_cast<std::int32_t>(c);
      };
      const std::int32_t cx = at0(xlo, ox), cy = at0(ylo, oy), cx1 = at0(xhi, ox), cy1 = at0(yhi, oy);
      const bool fits = (scaled(xhi - xlo) * inv <= 1) & (cx1 - cx <= 1) & (cy1 - cy <= 1);
      const CellKey key = pack(0, static_cast<std::uint32_t>(cy), static_cast<std::uint32_t>(cx));
      out[t] = fits ? key : kMisfit;
    }
  };
  if (scale_ == 1) first_pass(std::false_type{});
  else first_pass(std::true_type{});
  for (std::size_t t = 0; t < n; ++t)
    if (out[t] == kMisfit) [[unlikely]]
      out[t] = key_at_any_level(outward_lower(px[t], r[t]), outward_upper(px[t], r[t]), outward_lower(py[t], r[t]),
                                outward_upper(py[t], r[t]));
}

CellKey CellGrid::key_at_any_level(double xlo, double xhi, double ylo, double yhi) const noexcept {
  // Start at the least level whose cell is at least the box's width in base cells, q = width·inv_0:
  // 4^L ≥ q for L = ⌈log4 q⌉ = ⌈(ilogb(q) + 1)/2⌉ (q < 2^(ilogb(q)+1)). Only a start: the span check decides.
  const double q = (xhi - xlo) * scale_ * inverse_[0];
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

namespace {

// (key, slot): a total order.
constexpr auto kBefore = [](const auto& a, const auto& b) {
  return a.key < b.key || (a.key == b.key && a.slot < b.slot);
};

// The radix sorts' digits. kRadixBits = 11: 2^11 four-byte counters (8 KiB) stay in the first-level cache,
// and the packed keys (KeyPacking) of a scene take two or three passes.
// kRadixFrom = 1,024: each pass clears and sums 2^11 counters besides reading the list twice, work that a
// list of about as many entries does not pay back, so short lists (most of them between rebuilds of one
// horizon) keep std::sort. A speed choice, not measured at the crossover: both sorts give the same order.
inline constexpr int kRadixBits = 11;
inline constexpr std::size_t kRadixFrom = 1024;
inline constexpr std::uint64_t kDigit = (std::uint64_t{1} << kRadixBits) - 1;

// Keys as the radix sorts below read them: each field of the key (level, band, column, row: broad_phase.hpp)
// less its least value among the keys sorted, in the fewest bits that hold its range, the fields in their
// order of significance. Each field is offset by a constant and keeps its order, so packed keys order as the
// keys do. Sorting by the bits where keys differ instead would take nearly all 54 of them: plan() centres the
// scene on cell kCells / 2 of each axis (at level 0), so the columns and bands of one scene straddle a power
// of two, and their XOR has every bit below it set. Packed, the keys of 10^6 circles at 10% coverage take about 24 bits.
class KeyPacking {
 public:
  template <class Keys, class KeyOf>
  KeyPacking(const Keys& keys, KeyOf key_of) {
    std::array<std::uint64_t, kFields> low, high;
    low.fill(std::numeric_limits<std::uint64_t>::max());
    high.fill(0);
    for (const auto& e : keys)
      for (std::size_t f = 0; f < kFields; ++f) {
        const std::uint64_t v = field(key_of(e), f);
        low[f] = std::min(low[f], v);
        high[f] = std::max(high[f], v);
      }
    for (std::size_t f = kFields; f-- > 0;) {
      low_[f] = low[f];
      at_[f] = bits_;
      bits_ += high[f] >= low[f] ? static_cast<int>(std::bit_width(high[f] - low[f])) : 0;
    }
  }
  // The key's packed value: below 2^bits().
  std::uint64_t operator()(CellKey k) const noexcept {
    std::uint64_t packed = 0;
    for (std::size_t f = 0; f < kFields; ++f) packed |= (field(k, f) - low_[f]) << at_[f];
    return packed;
  }
  int bits() const noexcept { return bits_; }
  // The key a packed value below 2^bits() came from: each field read back from its bits, plus its least value.
  CellKey unpack(std::uint64_t packed) const noexcept {
    CellKey k = 0;
    for (std::size_t f = 0; f < kFields; ++f) {
      const int width = (f == 0 ? bits_ : at_[f - 1]) - at_[f];  // at_ grows from the last field to the first
      const std::uint64_t mask = (std::uint64_t{1} << width) - 1;  // width < 64 (kField)
      k |= (((packed >> at_[f]) & mask) + low_[f]) << kField[f][0];
    }
    return k;
  }

 private:
  // (shift, width) of each field, most significant first: level, band, column, row.
  static constexpr std::size_t kFields = 4;
  static constexpr std::array<std::array<int, 2>, kFields> kField = {{
      {2 * CellGrid::kCellBits, 64 - 2 * CellGrid::kCellBits},
      {CellGrid::kCellBits + CellGrid::kBandBits, CellGrid::kCellBits - CellGrid::kBandBits},
      {CellGrid::kBandBits, CellGrid::kCellBits},
      {0, CellGrid::kBandBits},
  }};
  static_assert([] {
    for (const auto& f : kField)
      if (f[1] >= 64) return false;
    return true;
  }(), "unpack() shifts by a field's width");
  static std::uint64_t field(CellKey k, std::size_t f) noexcept {
    return (k >> kField[f][0]) & ((std::uint64_t{1} << kField[f][1]) - 1);
  }
  std::array<std::uint64_t, kFields> low_{};
  std::array<int, kFields> at_{};
  int bits_ = 0;
};

// One stable pass of an LSD radix sort: `to` gets `from` ordered by the kRadixBits-bit digit(e), over
// `chunks` parts of `from` on up to `threads` threads. Each part counts its digits; a digit's entries then go
// to the output part by part, each part's from its own offset, which is the order one pass over the whole list
// gives: the same result for every part count.
using DigitCounts = std::array<std::uint32_t, std::size_t{1} << kRadixBits>;  // fewer than 2^32 slots
template <class T, class Digit>
void radix_pass(std::span<const T> from, std::span<T> to, Digit digit, std::size_t chunks = 1, unsigned threads = 1) {
  const std::size_t n = from.size();
  std::vector<DigitCounts> at(chunks, DigitCounts{});
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    DigitCounts& count = at[c];
    for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t) ++count[digit(from[t])];
  });
  std::uint32_t sum = 0;
  for (std::size_t d = 0; d < at[0].size(); ++d)
    for (DigitCounts& count : at) sum += std::exchange(count[d], sum);
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    DigitCounts& place = at[c];
    for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t)
      to[place[digit(from[t])]++] = from[t];
  });
}

// Sorts entries that are in ascending slot order by key, stably, so into kBefore's (key, slot) order, in time
// linear in their number: least significant digit first, kRadixBits bits of the packed keys a pass.
template <class Entry>
void sort_slot_ordered(std::span<Entry> list, Buffer<Entry>& scratch) {
  if (list.size() < kRadixFrom) {
    std::sort(list.begin(), list.end(), kBefore);
    return;
  }
  const KeyPacking packing(list, [](const Entry& e) { return e.key; });
  if (packing.bits() == 0) return;  // one key: slot order is the order
  scratch.resize(list.size());
  std::span<Entry> from = list, to = scratch;
  for (int shift = 0; shift < packing.bits(); shift += kRadixBits) {
    radix_pass<Entry>(from, to, [&](const Entry& e) { return (packing(e.key) >> shift) & kDigit; });
    std::swap(from, to);
  }
  if (from.data() != list.data()) std::copy(from.begin(), from.end(), list.begin());
}

// Insertion sort of entries in slot order with a budget of moves linear in the list (it may overrun by the
// last insertion's moves, fewer than the list's size): once it is spent, the front [0, a] is sorted and the
// rest is still in slot order, so sort_slot_ordered sorts the rest and one merge joins the two.
template <class Entry>
void repair(Buffer<Entry>& list, Buffer<Entry>& scratch) {
  std::size_t budget = 8 * list.size() + 64;
  for (std::size_t a = 1; a < list.size(); ++a) {
    const Entry e = list[a];
    std::size_t b = a;
    for (; b > 0 && kBefore(e, list[b - 1]); --b) list[b] = list[b - 1];
    list[b] = e;
    if (a - b >= budget) {
      const auto rest = list.begin() + static_cast<std::ptrdiff_t>(a + 1);
      sort_slot_ordered(std::span<Entry>(rest, list.end()), scratch);
      std::inplace_merge(list.begin(), rest, list.end(), kBefore);
      return;
    }
    budget -= a - b;
  }
}

// The packing of the sort by digits, if it applies: kRadixFrom keys or more whose fields pack into 32 bits.
std::optional<KeyPacking> digits_for(std::span<const CellKey> keys) {
  if (keys.size() < kRadixFrom) return std::nullopt;
  const KeyPacking packing(keys, [](CellKey k) { return k; });
  if (packing.bits() > 32) return std::nullopt;
  return packing;
}

// The sort by digits, guided by nothing, of `keys` in place: the slots by (key, slot) through 8-byte entries,
// the packed key (KeyPacking) in the upper half and the slot in the lower, half the bytes of an Entry, sorted
// by the packed bits as sort_slot_ordered sorts Entries, each pass in parts on up to `threads` threads; the
// input is in slot order, so ties stay in slot order. Each entry is made where its slot's key was, and the
// sorted ones then give `order` and, unpacked in place, leave `keys` holding the old keys[order[t]] at t.
// `other` is the passes' second buffer (resized to the keys'; it may be swapped with them). Returns false,
// with nothing written, when digits_for does not apply (the guided path sorts those keys).
bool sort_packed(Buffer<CellKey>& keys, Buffer<std::uint32_t>& order, unsigned threads, Buffer<std::uint64_t>& other) {
  static_assert(std::is_same_v<CellKey, std::uint64_t>, "an entry becomes its key in place");
  const std::size_t n = keys.size();
  const std::optional<KeyPacking> digits = digits_for(keys);
  if (!digits) return false;
  const KeyPacking& packing = *digits;
  for_each_slot(n, threads, [&](std::size_t s) { keys[s] = packing(keys[s]) << 32 | s; });
  other.resize(n);
  Buffer<std::uint64_t>*from = &keys, *to = &other;
  const std::size_t chunks = chunk_count(n, threads);
  for (int shift = 32; shift < 32 + packing.bits(); shift += kRadixBits) {
    radix_pass<std::uint64_t>(*from, *to, [shift](std::uint64_t e) { return (e >> shift) & kDigit; }, chunks, threads);
    std::swap(from, to);
  }
  if (from != &keys) keys.swap(other);
  for_each_slot(n, threads, [&](std::size_t t) {
    order[t] = static_cast<std::uint32_t>(keys[t]);
    keys[t] = packing.unpack(keys[t] >> 32);
  });
  return true;
}

}  // namespace

void CellOrder::Chunk::split(std::span<const CellKey> keys, std::span<const CellKey> previous, std::size_t begin,
                             std::size_t end, std::span<const CellKey> splitters, std::size_t part) {
  for (Buffer<Entry>* list : {&same, &up, &down, &other, &foreign, &incoming}) list->clear();
  const bool guided = previous.size() == keys.size();
  // Unguided, every slot goes to `other`: room for all of them at once.
  if (!guided) other.reserve(end - begin);
  // Part c holds the keys k with splitters[c] ≤ k < splitters[c + 1]; the first part has no lower bound and
  // the last no upper one.
  const std::size_t parts = splitters.size() - 1;
  const auto part_of = [&](CellKey k) {
    return static_cast<std::size_t>(std::upper_bound(splitters.begin() + 1, splitters.end() - 1, k) -
                                    (splitters.begin() + 1));
  };
  for (std::size_t s = begin; s < end; ++s) {
    const CellKey k = keys[s];
    Entry e{k, static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(part)};
    if ((part > 0 && k < splitters[part]) || (part + 1 < parts && k >= splitters[part + 1])) {
      e.part = static_cast<std::uint32_t>(part_of(k));
      foreign.push_back(e);
      continue;
    }
    // Split by how far the slot's band moved since `previous`, which was sorted: the slots that kept their
    // band are in band order, and within a band nearly in (column, row) order (a circle moves by one cell at
    // most, for most); so are those that moved one band up, and one band down. Each such list needs only
    // local repair. The band includes the level: a change of level is never a neighbouring band.
    if (guided) {
      const CellKey now = CellGrid::band(k), then = CellGrid::band(previous[s]);
      if (now == then) {
        same.push_back(e);
        continue;
      }
      if (now == then + 1 && CellGrid::level(k) == CellGrid::level(previous[s])) {
        up.push_back(e);
        continue;
      }
      if (now + 1 == then && CellGrid::level(k) == CellGrid::level(previous[s])) {
        down.push_back(e);
        continue;
      }
    }
    other.push_back(e);
  }
}

void CellOrder::Chunk::merge_into(std::span<std::uint32_t> out) {
  // Each list is in slot order: split() reads slots ascending, and `incoming` takes the chunks' hand-overs in
  // chunk order, each in slot order.
  repair(same, spare);
  repair(up, spare);
  repair(down, spare);
  sort_slot_ordered(std::span<Entry>(other), spare);
  sort_slot_ordered(std::span<Entry>(incoming), spare);
  // Every list but the longest merged into `merged` (together short: the longest holds most slots, `same` in
  // a guided sort, `other` in the first layout or after the grid's plan changed), then that list and the
  // longest straight into the order, so no list as long as the chunk is copied again. (key, slot) is a strict
  // total order, so any order of merging gives the same result.
  Buffer<Entry>* longest = &same;
  for (Buffer<Entry>* list : {&up, &down, &other, &incoming})
    if (list->size() > longest->size()) longest = list;
  merged.clear();
  for (Buffer<Entry>* list : {&same, &up, &down, &other, &incoming}) {
    if (list == longest || list->empty()) continue;
    spare.resize(merged.size() + list->size());
    std::merge(merged.begin(), merged.end(), list->begin(), list->end(), spare.begin(), kBefore);
    merged.swap(spare);
  }
  const Buffer<Entry>& rest = *longest;
  std::size_t a = 0, b = 0, at = 0;
  while (a < rest.size() && b < merged.size())
    out[at++] = kBefore(merged[b], rest[a]) ? merged[b++].slot : rest[a++].slot;
  while (a < rest.size()) out[at++] = rest[a++].slot;
  while (b < merged.size()) out[at++] = merged[b++].slot;
  // Memory that held a large share of the chunk in a list a guided sort keeps short (the first layout's
  // `other` and its radix scratch: 320 MB at 10^7 circles) is given back, as is `same`'s when it held little
  // (a sort after the grid's plan changed): the steps between rebuilds would otherwise carry it.
  const std::size_t large = out.size() / 4;
  for (Buffer<Entry>* list : {&up, &down, &other, &incoming, &merged, &spare})
    if (list->capacity() > large) Buffer<Entry>().swap(*list);
  if (same.capacity() > large && same.size() < large) Buffer<Entry>().swap(same);
}

bool CellOrder::by_digits(std::span<const CellKey> keys) { return digits_for(keys).has_value(); }

bool CellOrder::sort_in_place(Buffer<CellKey>& keys, std::span<const CellKey> previous,
                              Buffer<std::uint32_t>& order, unsigned threads) {
  const std::size_t n = keys.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("CellOrder::sort_in_place: more than 2^32 - 1 slots");
  order.resize(n);
  // Already sorted (a quiet world, or one whose circles all kept their cells): the identity.
  if (std::is_sorted(keys.begin(), keys.end())) {
    for (std::size_t s = 0; s < n; ++s) order[s] = static_cast<std::uint32_t>(s);
    return true;
  }
  if (sort_packed(keys, order, threads, scratch_)) return false;
  guided(keys, previous, order, threads);
  scratch_.resize(n);
  for_each_slot(n, threads, [&](std::size_t t) { scratch_[t] = keys[order[t]]; });
  keys.swap(scratch_);
  return false;
}

void CellOrder::guided(std::span<const CellKey> keys, std::span<const CellKey> previous,
                       Buffer<std::uint32_t>& order, unsigned threads) {
  const std::size_t n = keys.size();
  // Parts need the previous keys, sorted, as splitters: without them, one chunk does it all.
  const std::size_t chunks = previous.size() == n ? chunk_count(n, threads) : 1;
  chunks_.resize(chunks);
  std::vector<CellKey> splitters(chunks + 1, 0);
  for (std::size_t c = 1; c < chunks; ++c) splitters[c] = previous[chunk_begin(n, chunks, c)];
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    chunks_[c].split(keys, previous, chunk_begin(n, chunks, c), chunk_begin(n, chunks, c + 1), splitters, c);
  });
  // Each part collects what the other chunks handed it, then its range of the output is known.
  for_each_chunk(chunks, threads, [&](std::size_t part) {
    for (std::size_t c = 0; c < chunks; ++c)
      if (c != part)
        for (const Entry& e : chunks_[c].foreign)
          if (e.part == part) chunks_[part].incoming.push_back(e);
  });
  std::vector<std::size_t> begin(chunks + 1, 0);
  for (std::size_t c = 0; c < chunks; ++c) {
    const Chunk& k = chunks_[c];
    begin[c + 1] = begin[c] + k.same.size() + k.up.size() + k.down.size() + k.other.size() + k.incoming.size();
  }
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    chunks_[c].merge_into(std::span<std::uint32_t>(order).subspan(begin[c], begin[c + 1] - begin[c]));
  });
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

bool few_per_cell(std::span<const CellKey> key) noexcept {
  std::size_t cells = key.empty() ? 0 : 1;
  for (std::size_t t = 1; t < key.size(); ++t) cells += key[t] != key[t - 1];
  return static_cast<double>(key.size()) <= kFewPerCell * static_cast<double>(cells);
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
