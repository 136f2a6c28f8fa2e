// Candidate pairs kept across steps: a neighbour list with a proven skin (a Verlet list, as molecular-dynamics
// codes keep them), shared by the double engines (impl/engine.cpp) and the exact engine (impl/exact_engine.cpp).
//
//   Invariant (conservative): a list built at world t for a horizon of H steps holds every pair {a, b} of slots
//   that intersects exactly in any of the worlds t, t + 1, …, t + H. So the step from each of those worlds
//   tests only the listed pairs and still finds every contact.
//
// Why (docs/engine.md, "Pairs kept across steps"): velocities are only ever copied (h of (9)), so no circle of
// any later world moves faster than the fastest circle of world t, |v| ≤ vmax. Over H steps every circle
// moves at most `skin` (a bound on H steps of motion, below) from where it is in world t. A pair that
// intersects in world t + j, j ≤ H, is therefore within r_a + r_b + 2·skin in world t, by the triangle
// inequality; the list holds every pair that intersects exactly with each radius inflated to r' ≥ r + skin.
// The engine's broad phase (impl/broad_phase.hpp) is run on the inflated radii, so no such pair is missed.
//
// Which H to use is a question of speed only (HorizonSchedule): a long horizon rebuilds the list rarely but
// lists more pairs, each tested every step. No horizon changes a bit of any world.
#pragma once

#include "impl/broad_phase.hpp"
#include "impl/predicate.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace circles::impl {

// ── The skin ──────────────────────────────────────────────────────────────────────────────────────────
// The bound on H steps of motion: kSpeedBound, kDriftBound and kDriftAbsolute, with their derivation, are in
// impl/double_bounds.hpp.

// A double n with √(vx² + vy²) ≤ n·(1 + 2^-50) + 2^-1074: m·√(1 + q²) with m = max(|vx|, |vy|) and
// q = min/max ≤ 1, so nothing underflows or overflows early; five roundings of relative 2^-53 each (kSpeedBound's
// margin covers them), and an absolute 2^-1075 when n is subnormal (within kDriftAbsolute's margin over
// 2√2·2^-1075, since 2^-1074/60 is less). +∞ when the norm is beyond the double range.
inline double norm_upper(double vx, double vy) noexcept {
  double a = std::fabs(vx), b = std::fabs(vy);
  if (a < b) std::swap(a, b);
  if (a == 0) return 0;
  const double q = b / a;
  return a * std::sqrt(1 + q * q);
}

// The bound above on one step of motion within a horizon of H steps, for the world's vmax and reach and an
// update whose rounding moves a coordinate by at most |p′|·drift + kDriftAbsolute (drift = kDriftBound for one
// double rounding; see impl/arithmetic.hpp); +∞ when it overflows, never NaN (the inputs are finite, ≥ 0).
inline double step_bound(std::uint64_t horizon, double vmax, double reach, double drift = kDriftBound) noexcept {
  const double far = reach + static_cast<double>(horizon) * vmax * kSpeedBound;
  return vmax * kSpeedBound + far * drift + kDriftAbsolute;
}

// The skin: the bound on H steps of motion, H·step_bound.
inline double skin_for(std::uint64_t horizon, double vmax, double reach, double drift = kDriftBound) noexcept {
  return static_cast<double>(horizon) * step_bound(horizon, vmax, reach, drift);
}

// ── When a pair can first meet ────────────────────────────────────────────────────────────────────────
// A pair's first step from below: kGapRelative, kGapAbsolute and kQuotientShrink, with their derivation, are in
// impl/double_bounds.hpp.
inline constexpr std::uint32_t kNever = ~std::uint32_t{0};
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The first step of a horizon of `horizon` steps, each moving a circle at most `step`, at which two circles of
// radii ar and br whose centres are `root` ≥ their distance apart (from below: root ≤ D·(1 + 2^-50) + 2^-536,
// above) may intersect: 0 … horizon, or kNever. Without a branch on the pair, so that a loop over a batch of
// pairs (Lister::steps) runs without mispredictions: each case is a select.
[[gnu::always_inline]] inline std::uint32_t first_step_of_root(double root, double ar, double br, double step,
                                                               std::uint64_t horizon) noexcept {
  const double gap = root * (1 - kGapRelative) - (ar + br) * (1 + kGapRelative) - kGapAbsolute;
  const double q = gap / (2 * step) * kQuotientShrink;
  // A gap that is not finite (only within reach of the double range) or ≤ 0: test from the first step. A
  // quotient past the horizon (also +∞ or NaN for step = 0): never. Otherwise 0 ≤ q ≤ horizon, and ⌈q⌉ is
  // its truncation t, plus one where t < q; q itself is converted only then (a negative or huge one does not
  // fit the integer), 0 in its place otherwise.
  const bool now = !(gap > 0) | !(gap < kInfinity);
  const bool within = q <= static_cast<double>(horizon);
  const double asked = (!now & within) ? q : 0.0;
  const auto truncated = static_cast<std::uint32_t>(asked);
  const std::uint32_t ceiling = truncated + (static_cast<double>(truncated) < asked);
  return now ? 0 : within ? ceiling : kNever;
}

// The same for centres dx = RN(bx − ax), dy = RN(by − ay) apart, with d2 = RN(RN(dx²) + RN(dy²)).
[[gnu::always_inline]] inline std::uint32_t first_step_from(double dx, double dy, double d2, double ar, double br, double step,
                                     std::uint64_t horizon) noexcept {
  const double root = d2 < kInfinity ? std::sqrt(d2) : norm_upper(dx, dy);
  return first_step_of_root(root, ar, br, step, horizon);
}

// The same for the circles (ax, ay, ar) and (bx, by, br).
inline std::uint32_t first_step(double ax, double ay, double ar, double bx, double by, double br, double step,
                                std::uint64_t horizon) noexcept {
  const double dx = bx - ax, dy = by - ay;
  return first_step_from(dx, dy, dx * dx + dy * dy, ar, br, step, horizon);
}

// A pair's first step in a list (PairList::build), for radii ar, br ≥ 0 widened to ar′ ≥ ar and br′ ≥ br by
// the skin: kNever when the widened circles are certainly disjoint (intersect_filter says so: they cannot meet
// within the horizon), 0 when the circles certainly intersect now, first_step otherwise. The same answer as
// those three calls, with the difference and the sum of squares computed once for all three (the filter's q
// and first_step's d2 are the same RN(RN(dx²) + RN(dy²))), so that a pair the broad phase offers for nothing
// costs little more than one filter. Lister::steps gives the same answers for a batch of pairs.
[[gnu::always_inline]] inline std::uint32_t listing_step(double ax, double ay, double ar, double ar_wide, double bx, double by, double br,
                                  double br_wide, double step, std::uint64_t horizon) noexcept {
  const double dx = bx - ax, dy = by - ay;
  const double d2 = dx * dx + dy * dy;
  if (certainly_disjoint_of_squares(d2, ar_wide + br_wide, filter::kAbsolute)) [[likely]]
    return kNever;
  if (certainly_intersecting_of_squares(d2, ar + br, filter::kAbsolute)) return 0;
  return first_step_from(dx, dy, d2, ar, br, step, horizon);
}

// A candidate pair of slots a, b as the walk hands it over (walk_near, impl/pair_list_impl.hpp): a·2^32 + b.
inline constexpr std::uint64_t packed_pair(std::size_t a, std::size_t b) noexcept { return std::uint64_t{a} << 32 | b; }
inline constexpr std::size_t first_slot(std::uint64_t pair) noexcept { return pair >> 32; }
inline constexpr std::size_t second_slot(std::uint64_t pair) noexcept { return pair & 0xffff'ffffu; }

// What PairList::build lists with, for both engines: circles (px, py) with radii r (the padded ones, bounding
// the exact gap below) and ri ≥ r (inflated by the skin), for a horizon of `horizon` steps of at most `step`.
// near(a, b) is listing_step's first filter alone, false exactly when that filter returns kNever, so that the
// broad phase can reject most candidates without a branch on each (half of them go either way: a branch per
// candidate mispredicts about every other time); (a, b) is listing_step.
struct Lister {
  const double *px, *py, *r, *ri;
  double step;
  std::uint64_t horizon;

  [[gnu::always_inline]] bool near(std::size_t a, std::size_t b) const noexcept { return near_to(px[a], py[a], ri[a], b); }
  // near(a, b) from a's values (ax, ay, ari) = (px[a], py[a], ri[a]), which a loop over b holds in registers.
  [[gnu::always_inline]] bool near_to(double ax, double ay, double ari, std::size_t b) const noexcept {
    const double dx = px[b] - ax, dy = py[b] - ay;
    return !certainly_disjoint_of_squares(dx * dx + dy * dy, ari + ri[b], filter::kAbsolute);
  }
  [[gnu::always_inline]] std::uint32_t operator()(std::size_t a, std::size_t b) const noexcept {
    return listing_step(px[a], py[a], r[a], ri[a], px[b], py[b], r[b], ri[b], step, horizon);
  }
  // (a, b) for a batch of packed pairs: out[k] = (*this)(a, b) for pairs[k] = packed_pair(a, b). One loop with
  // no branch on a pair (listing_step's cases, as selects), so that the list build's loop over the candidates the walk
  // kept neither mispredicts on whether a pair touches now nor waits on a division it would not use. The root
  // is RN(√d2) for every pair; the pairs whose d2 overflows (within reach of the double range only) are
  // answered again by listing_step, whose root there is norm_upper.
  void steps(std::span<const std::uint64_t> pairs, std::uint32_t* out) const noexcept {
    const double *x = px, *y = py, *padded = r, *wide = ri;
    const double at = step;
    const std::uint64_t h = horizon;
    bool overflow = false;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::size_t a = first_slot(pairs[k]), b = second_slot(pairs[k]);
      const double dx = x[b] - x[a], dy = y[b] - y[a];
      const double d2 = dx * dx + dy * dy;
      const bool disjoint = certainly_disjoint_of_squares(d2, wide[a] + wide[b], filter::kAbsolute);
      const bool touching = certainly_intersecting_of_squares(d2, padded[a] + padded[b], filter::kAbsolute);
      const std::uint32_t later = first_step_of_root(std::sqrt(d2), padded[a], padded[b], at, h);
      out[k] = disjoint ? kNever : touching ? 0 : later;
      overflow |= !(d2 < kInfinity);
    }
    if (overflow) [[unlikely]]
      for (std::size_t k = 0; k < pairs.size(); ++k) out[k] = (*this)(first_slot(pairs[k]), second_slot(pairs[k]));
  }
};

// The prefetch hint of least_contacts for an intersect that reads circles (x[a], y[a], r[a]) and (x[b], y[b],
// r[b]) from three arrays: both engines' tests (the exact engine's through its approximations) read these.
struct PrefetchCircles {
  const double *x, *y, *r;

  void operator()(std::size_t a, std::size_t b) const noexcept {
    for (const double* column : {x, y, r}) {
      __builtin_prefetch(column + a);
      __builtin_prefetch(column + b);
    }
  }
};

// ── The schedule ──────────────────────────────────────────────────────────────────────────────────────
//
// The next horizon from what the last list cost. A list serves H + 1 steps, testing at step j the pairs whose
// first step is ≤ j; rebuilding costs about kRebuildCost pair tests per circle (a rebuild of n circles, keys,
// sort, gather and query, takes about as long as that many pair tests per circle: measured with
// `circles run --stats` on the random scenes of 0.1% and 10% coverage, where the best fixed horizons were
// 16 to 32 and 4 to 8). The horizon doubles while the pair tests of a step cost less than half the rebuild's
// share of it, n·kRebuildCost/(H + 1), and halves when they cost more than twice it, which keeps the two near
// balance, where their sum is least to within a small factor. Where they cost less than 1/kFarBelow of the
// share it grows fourfold instead. Each doubling halves the share and multiplies the tests of a step by the
// growth of the pairs within reach and of their tests: in the 0.1% scene the ratio of tests to share went
// from 1/57 at H = 8 to 1/1.8 at 32, about 5.6 per doubling, so from 1/16 two doublings land near balance.
// A scene whose tests grow faster can overshoot once (at most 16 times per doubling, pairs in reach × 4 and
// their tests × 2, with the share halved); the halving then brings it back. It is speed only, never a bit of
// a world. It starts at kFirstHorizon, where the 10% scene settles (at 10^6 circles 8 measured faster than
// 4); the 0.1% scene grows fourfold once, 8 to 32, where it settles, instead of doubling three times from 4
// with a re-sort each. Only counts decide it, never time, so a run is the same on every machine.
class HorizonSchedule {
 public:
  static constexpr std::uint64_t kMaxHorizon = std::uint64_t{1} << 16;
  static constexpr std::uint64_t kFirstHorizon = 8;
  static constexpr double kRebuildCost = 8;
  static constexpr double kFarBelow = 16;

  std::uint64_t horizon() const noexcept { return horizon_; }
  // After a list whose tests over the steps it served add up to `tests` was built for `circles` circles: sets
  // the next horizon. The tests of a step against the rebuild's share of it, both over the same steps, are the
  // list's tests against one rebuild: the rule holds for a list shorter than horizon() + 1 steps as well.
  void update(std::size_t tests, std::size_t circles) noexcept {
    const double tested = static_cast<double>(tests);
    const double rebuild = kRebuildCost * static_cast<double>(circles);
    if (tested < rebuild / kFarBelow)
      horizon_ = std::min(kMaxHorizon, horizon_ == 0 ? 1 : 4 * horizon_);
    else if (tested < rebuild / 2)
      horizon_ = std::min(kMaxHorizon, horizon_ == 0 ? 1 : 2 * horizon_);
    else if (tested > 2 * rebuild)
      horizon_ /= 2;
  }
  // A horizon whose skin was not finite: the next list covers its own world only.
  void collapse() noexcept { horizon_ = 0; }

 private:
  std::uint64_t horizon_ = kFirstHorizon;
};

// What an engine's steps did, for `circles run --stats` and the benchmarks: the work it skipped is visible.
struct EngineStats {
  std::uint64_t steps = 0;                // steps taken
  std::uint64_t rebuilds = 0;             // pair lists built: keys, re-sort and broad phase
  std::uint64_t pairs_listed = 0;         // pairs in those lists
  std::uint64_t pairs_tested = 0;         // exact pair tests in the steps (a listed pair from its first step)
  std::uint64_t contacts = 0;             // of those, the pairs that intersect
  std::uint64_t quiet_steps = 0;          // steps with no pair to test
  std::uint64_t lonely_circle_steps = 0;  // circle-steps of circles in no listed pair: no contact test
};

// ── The list ──────────────────────────────────────────────────────────────────────────────────────────

// A listed pair of slots, a < b, and the first step of the list's horizon from which it is tested.
struct ListedPair {
  // Uninitialized: PairList::build makes room for a list at once and writes every pair it keeps.
  ListedPair() noexcept {}  // NOLINT: not = default, which would zero the room
  constexpr ListedPair(std::uint32_t slot_a, std::uint32_t slot_b, std::uint32_t first_step) noexcept
      : a(slot_a), b(slot_b), first(first_step) {}
  std::uint32_t a, b, first;
};

template <class Intersect, class Precedes>
struct ChunkContacts;

// Pairs of slots grouped by the chunk (impl/contacts.hpp) of their first slot, so that each thread offers
// contacts to its own slots; within a chunk by blocks of kBlockSlots slots (by first slot), so that a step
// reads each block's circles while they are in cache; within a block by first step, so that a step reaches
// its active pairs without looking at the others. The member templates are defined in
// impl/pair_list_impl.hpp, which only the engines' .cpp files include (it needs the library's OpenMP flags).
class PairList {
 public:
  static constexpr std::size_t kBlockSlots = 1024;
  // First steps 0 … kBuckets − 2 have a bucket each; the last bucket holds every later one, checked per pair.
  // 64 covers the horizons the schedule settles on (4 to 8 at 10% coverage, 32 at 0.1%), so a step rarely
  // checks a pair it does not test: with 16, the sparse scene's steps 15 to 32 looked at the pairs of 16 more
  // steps, and that check mispredicted about one branch in three (callgrind: 626,000 of 5.1 million in a
  // run of 2·10^5 circles, 35,000 with 64).
  static constexpr std::uint32_t kBuckets = 64;
  // least_contacts asks for the circles of the pair this many places ahead of the one it tests. In a sparse
  // scene the listed pairs are far apart in memory and each test waited for its circles (at 10^6 circles,
  // 0.1% coverage, H = 32: 8.2 ns per circle-step without prefetching, 6.6 with 8 ahead, 5.9–6.3 with 16);
  // at 10% coverage a slot's pairs are neighbours in memory and it changes nothing measurable.
  static constexpr std::size_t kPrefetchAhead = 16;
  // least_contacts tests this many pairs before it offers the contacts among them: enough that the loop over
  // the offers is one loop per block of a slot's pairs, few enough that their indices fit on the stack.
  static constexpr std::size_t kTestBlock = 256;
  // A first build's room, in pairs per slot (build()). The dense scene's first list (10^6 circles, 10%, 6
  // steps) holds 2.1 a slot: from one a slot it grew twice, through 57 MB of new memory where 25 MB hold the
  // list, and new memory costs more than the copies (up to 2 ms a MB on a virtual machine whose host backs
  // the pages as they are first written). Four a slot hold it at once, as 48 bytes a circle of address space,
  // six columns' worth.
  static constexpr std::size_t kFirstRoom = 4;

  // Gives the pairs' memory back, keeping each chunk's count, the room the next build makes at once: a
  // rebuild's sort runs between the two, and would otherwise hold the old list beside its own lists (at 10^7
  // circles and 10% coverage, 440 MB of pairs).
  void release() noexcept {
    for (Chunk& chunk : chunks_) Buffer<ListedPair>().swap(chunk.pairs);
  }
  // Lists every pair {a, b} among those the broad phase offers over `view` (whose radii are the inflated
  // ones), global slots against every slot, for which first(a, b) ≤ horizon, from that step on (candidates
  // for which first.near(a, b) is false are not asked: first(a, b) would be kNever). first must be
  // conservative: no later than the first step of the horizon at which the pair may intersect.
  void build(const CellGrid& grid, const CellView& view, unsigned threads, std::uint64_t horizon,
             const Lister& first);

  // At step j of the horizon (j = 0 in the world the list was built in): least[t] for every slot t that
  // intersects some partner listed from step ≤ j, the least such partner under precedes (a strict total
  // order), and `touched[c]` lists those slots of chunk c. On entry least[t] == t for every t (the caller
  // restores that after using it). Returns the number of intersecting pairs; `tested` gets the pairs tested.
  template <class Intersect, class Precedes, class Prefetch>
  std::size_t least_contacts(std::uint64_t j, unsigned threads, Buffer<std::uint32_t>& least,
                             std::vector<Buffer<std::uint32_t>>& touched, std::size_t& tested,
                             Intersect&& intersect, Precedes&& precedes, Prefetch&& prefetch);

  // A step's contacts without a list, for a list of horizon 0, which only the step of the world it is built in
  // would read: the walk build() makes over `view` with `first`, each pair that list would hold (its first step
  // 0) tested as it is found, with least_contacts' result and counts, and lonely() as the list would give it.
  // Afterwards the list is empty; tests() gives the pairs tested.
  template <class Intersect, class Precedes>
  std::size_t contacts_now(const CellGrid& grid, const CellView& view, unsigned threads, const Lister& first,
                           Buffer<std::uint32_t>& least, std::vector<Buffer<std::uint32_t>>& touched,
                           std::size_t& tested, Intersect&& intersect, Precedes&& precedes);

  std::size_t size() const noexcept { return size_; }
  // The pairs tested over the whole horizon: Σ (H + 1 − first step).
  std::size_t tests() const noexcept { return tests_; }
  // True when step j of the horizon has no pair to test.
  bool quiet(std::uint64_t j) const noexcept { return size_ == 0 || j < earliest_; }
  // Slots that are in no listed pair: they need no contact test until the next build.
  std::size_t lonely() const noexcept { return lonely_; }
  // True when `slot` is in some listed pair.
  bool listed(std::size_t slot) const noexcept { return listed_[slot] != 0; }
  // Every listed pair, for the validator.
  template <class F>
  void for_each(F&& f) const {
    for (const Chunk& chunk : chunks_)
      for (std::size_t i = 0; i < chunk.size; ++i) f(chunk.pairs[i].a, chunk.pairs[i].b);
    for (const ListedPair& p : global_) f(p.a, p.b);
  }

 private:
  // A chunk's pairs are listed in the order the broad phase offers them (by first slot, so each block's pairs
  // are one run), then each block's run is put in bucket order where it is: the list needs no second copy of
  // its pairs, which at 10^7 circles is hundreds of megabytes.
  struct Chunk {
    // pairs[0, size): by block, then first step's bucket, then first slot. The vector is the room (its
    // elements uninitialized until written), so that a build writes its pairs without calling out of its
    // loop to append; the room starts at the last build's count and an eighth (a pair per slot without one),
    // and grows by half.
    Buffer<ListedPair> pairs;
    std::size_t size = 0;
    Buffer<std::uint32_t> starts;  // pairs of block k, bucket q: [starts[k·K + q], starts[k·K + q + 1])
    std::vector<ContactOffer> offers;   // a step's contacts for slots of later chunks
    // The build's sort by bucket: the next place of each bin, and a block's pairs copied out. Kept between
    // builds, as the rebuild's other scratch is (impl/cell_layout.hpp): at 10^6 circles `at` is 250 KB.
    Buffer<std::uint32_t> at;
    Buffer<ListedPair> run;
  };
  // The chunk that holds `slot`.
  std::size_t chunk_of(std::size_t slot) const noexcept;
  // Which slots are in a pair: no slot of n, then both slots of a pair. A pair's second slot may be another
  // chunk's, so the marks are relaxed atomic stores, all of the same value.
  void clear_marks(std::size_t n) {
    listed_.reserve(n);
    listed_.assign(n, 0);
  }
  void mark(std::size_t a, std::size_t b) noexcept { mark_in(listed_.data(), a, b); }
  // The same through the marks' address, which a loop holds in a register: a char store may alias anything,
  // the vector's own pointer included, so listed_.data() would be read again after every mark.
  static void mark_in(unsigned char* listed, std::size_t a, std::size_t b) noexcept {
    std::atomic_ref<unsigned char>(listed[a]).store(1, std::memory_order_relaxed);
    std::atomic_ref<unsigned char>(listed[b]).store(1, std::memory_order_relaxed);
  }
  // The slots in no pair, once every pair is marked.
  std::size_t unmarked() const { return static_cast<std::size_t>(std::count(listed_.begin(), listed_.end(), 0)); }
  // global_ ← the pairs of a global slot (walk_global) that a list of `horizon` holds by `first`, each with its
  // first step, and also handed to taken(pair).
  template <class Taken>
  void list_global(const CellView& view, const Lister& first, std::uint64_t horizon, Taken&& taken);
  // Chunk c's tester for a step: its touched slots and offers cleared, room made for them.
  template <class Intersect, class Precedes>
  ChunkContacts<Intersect, Precedes> chunk_contacts(std::size_t c, Buffer<std::uint32_t>& least,
                                                    std::vector<Buffer<std::uint32_t>>& touched,
                                                    const Intersect& intersect, const Precedes& precedes);
  // After the parallel part of a step, whose chunks tested and found counts[c] = {pairs tested, pairs
  // intersecting}: the chunks' offers to later chunks' slots, then the pairs of `global` due at step j. Sets
  // `tested` to all the pairs tested, and returns all the intersecting ones.
  template <class Intersect, class Precedes>
  std::size_t offer_the_rest(std::span<const std::array<std::size_t, 2>> counts, std::span<const ListedPair> global,
                             std::uint64_t j, Buffer<std::uint32_t>& least,
                             std::vector<Buffer<std::uint32_t>>& touched, std::size_t& tested,
                             Intersect&& intersect, Precedes&& precedes);

  std::vector<Chunk> chunks_;
  Buffer<ListedPair> global_;  // pairs with a global slot, tested from their first step every step
  Buffer<unsigned char> listed_;  // which slots are in a pair
  std::uint64_t horizon_ = 0, earliest_ = 0;
  std::size_t size_ = 0, tests_ = 0, slots_ = 0, lonely_ = 0;
};

// The listed pairs as circle indices {i, j}, i < j, each once, in order, for slots where slot t holds circle
// id[t]: what the engines' candidates() give the tests.
inline std::vector<CandidatePair> listed_pairs(const PairList& pairs, std::span<const std::uint32_t> id) {
  std::vector<CandidatePair> out;
  pairs.for_each([&](std::size_t a, std::size_t b) {
    const std::uint32_t i = id[a], j = id[b];
    out.push_back(i < j ? CandidatePair{i, j} : CandidatePair{j, i});
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace circles::impl
