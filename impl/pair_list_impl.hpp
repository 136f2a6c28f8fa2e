// The member templates of PairList (impl/pair_list.hpp). Include it from .cpp files of circles::impl only:
// for_each_chunk's pragma needs the library's OpenMP flags.
#pragma once

#include "impl/buffers.hpp"
#include "impl/contacts.hpp"
#include "impl/pair_list.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace circles::impl {

inline std::size_t PairList::chunk_of(std::size_t slot) const noexcept {
  const std::size_t c = chunks_.size();
  std::size_t guess = std::min(c - 1, slot * c / slots_);  // chunk_begin is n·c/C: the guess is off by ≤ 1
  while (guess + 1 < c && chunk_begin(slots_, c, guess + 1) <= slot) ++guess;
  while (guess > 0 && chunk_begin(slots_, c, guess) > slot) --guess;
  return guess;
}

// The broad phase's walk over the slots [begin, end) of `view`, in ascending order: for each slot a, the
// candidates b that visit_neighbourhood_runs offers (impl/broad_phase.hpp) and lister.near(a, b) keeps, handed
// to batch(pairs) in the order found, kWalkBatch pairs at a time (the last batch fewer), each pair as
// packed_pair(a, b). The candidates near enough to ask are gathered without a branch from all of a's runs, and the
// batches span many slots: the caller's loop over a batch runs long, without a loop exit per slot or per run
// to mispredict.
inline constexpr std::size_t kWalkBatch = 256;

template <class Batch>
void walk_near(const CellGrid& grid, const CellView& view, std::size_t begin, std::size_t end, const Lister& lister,
               Batch&& batch) {
  const std::size_t n = view.key.size();
  NeighbourCursor cursor;
  std::uint64_t kept[kWalkBatch];
  std::size_t kept_so_far = 0;
  for (std::size_t a = begin; a < end; ++a) {
    visit_neighbourhood_runs(grid, view, a, cursor, [&](std::size_t from, CellKey last) {
      // A copy of the lister per run, in registers: the callers' marks are char stores, which may alias
      // anything, so values in memory would be read again for every candidate.
      const Lister near = lister;
      const CellKey* const key = view.key.data();
      // a's values, the view's size and the kept array's address as locals too: the hand-over inside the loop
      // calls out, after which values reached through this lambda's captures would be read again for every
      // candidate.
      const double ax = near.px[a], ay = near.py[a], ari = near.ri[a];
      const std::size_t slots = n;
      std::uint64_t* const into = kept;
      const std::uint64_t pair_of_a = packed_pair(a, 0);  // + b: packed_pair(a, b), for b < 2^32
      std::size_t held = kept_so_far, b = from;
      for (; b < slots && key[b] <= last; ++b) {
        into[held] = pair_of_a + b;
        held += near.near_to(ax, ay, ari, b);
        if (held == kWalkBatch) [[unlikely]] {
          batch(std::span<const std::uint64_t>(into, held));
          held = 0;
        }
      }
      kept_so_far = held;
      return b;  // the run ended: a larger key, or the view's end
    });
  }
  batch(std::span<const std::uint64_t>(kept, kept_so_far));
}

// Global slots (a box too wide for every level) of `view` against every slot, each pair once: pair(g, b).
template <class Pair>
void walk_global(const CellView& view, Pair&& pair) {
  const std::size_t n = view.key.size();
  const std::size_t global = view.level_begin[CellGrid::kGlobalLevel];
  for (std::size_t g = global; g < n; ++g)
    for (std::size_t b = 0; b < n; ++b)
      if (b != g && (b < global || b > g)) pair(g, b);
}

template <class Taken>
void PairList::list_global(const CellView& view, const Lister& first, std::uint64_t horizon, Taken&& taken) {
  global_.clear();
  walk_global(view, [&](std::size_t g, std::size_t b) {
    const std::uint32_t step = first(g, b);
    if (step > horizon) return;
    global_.push_back({static_cast<std::uint32_t>(std::min(g, b)), static_cast<std::uint32_t>(std::max(g, b)), step});
    taken(global_.back());
  });
}

inline void PairList::build(const CellGrid& grid, const CellView& view, unsigned threads, std::uint64_t horizon,
                            const Lister& first) {
  const std::size_t n = view.key.size();
  slots_ = n;
  horizon_ = horizon;
  const std::size_t chunks = chunk_count(n, threads);
  chunks_.resize(chunks);
  clear_marks(n);
  // A listed pair counted in a tally (its tests over the horizon, its earliest first step) and its slots marked.
  using Tally = std::array<std::uint64_t, 2>;
  const auto take = [marks = listed_.data(), horizon](Tally& into, const ListedPair& p) {
    into[0] += horizon + 1 - p.first;
    into[1] = std::min<std::uint64_t>(into[1], p.first);
    mark_in(marks, p.a, p.b);
  };
  std::vector<Tally> tally(chunks + 1, Tally{0, horizon + 1});  // per chunk, then the global pairs'
  // The pairs of each chunk in the order the broad phase offers them (by first slot), each counted in its
  // (block, bucket) bin and in the chunk's tally as it is found: its tests over the horizon, its earliest
  // first step, its slots' marks.
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    Chunk& chunk = chunks_[c];
    Buffer<ListedPair>& found = chunk.pairs;
    const std::size_t begin = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1);
    chunk.starts.assign((end - begin + kBlockSlots - 1) / kBlockSlots * kBuckets + 1, 0);
    std::uint32_t* const count = chunk.starts.data() + 1;
    // The room: the last build's count and an eighth; with no count to go by (a first build, or a last one
    // that listed nothing here), kFirstRoom pairs per slot, which cost address space only (a Buffer's pages
    // are backed as they are written), so that a first list does not grow by copies through new memory.
    const std::size_t room = chunk.size > 0 ? chunk.size + chunk.size / 8 + 1024
                                            : std::max<std::size_t>(kFirstRoom * (end - begin), 1024);
    if (found.size() < room) {
      found.clear();  // nothing in it is kept: the build writes every pair again
      found.resize(room);
    }
    std::size_t size = 0;
    Tally mine{0, horizon + 1};  // a local, kept in registers, written to tally[c] at the end
    const Lister first_of = first;
    // The pairs' address and room as locals, read again only when the room grows: the marks' char stores
    // would otherwise make the compiler read them from the vector after every pair.
    ListedPair* out = found.data();
    std::size_t capacity = found.size();
    walk_near(grid, view, begin, end, first, [&](std::span<const std::uint64_t> batch) {
      std::uint32_t steps[kWalkBatch];
      first_of.steps(batch, steps);
      for (std::size_t k = 0; k < batch.size(); ++k) {
        const std::uint32_t step = steps[k];
        if (step > horizon) continue;
        if (size == capacity) [[unlikely]] {
          found.resize(size + size / 2);
          out = found.data();
          capacity = found.size();
        }
        const ListedPair p{static_cast<std::uint32_t>(first_slot(batch[k])),
                           static_cast<std::uint32_t>(second_slot(batch[k])), step};
        out[size++] = p;
        ++count[(p.a - begin) / kBlockSlots * kBuckets + std::min(step, kBuckets - 1)];
        take(mine, p);
      }
    });
    chunk.size = size;
    tally[c] = mine;
  });
  list_global(view, first, horizon, [&](const ListedPair& p) { take(tally[chunks], p); });
  // Per chunk, the rest of a counting sort by (block, bucket), stable, so each bucket stays in slot order: the
  // pairs are by first slot already, so each block's pairs are one run, sorted by bucket where it is through a
  // copy of that run alone.
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    Chunk& chunk = chunks_[c];
    const std::size_t blocks = (chunk.starts.size() - 1) / kBuckets;
    const std::size_t begin = chunk_begin(n, chunks, c);
    Buffer<ListedPair>& pairs = chunk.pairs;
    for (std::size_t k = 1; k < chunk.starts.size(); ++k) chunk.starts[k] += chunk.starts[k - 1];
    // A horizon of 0 has one first step, 0: each block's run is in bucket order as it was found.
    if (horizon == 0) return;
    Buffer<std::uint32_t>& at = chunk.at;
    Buffer<ListedPair>& run = chunk.run;
    at.assign(chunk.starts.begin(), chunk.starts.end() - 1);
    for (std::size_t k = 0; k < blocks; ++k) {
      // Block k's pairs: [starts[k·K], starts[(k + 1)·K]), since every earlier block's pairs come first.
      run.assign(pairs.begin() + chunk.starts[k * kBuckets], pairs.begin() + chunk.starts[(k + 1) * kBuckets]);
      for (const ListedPair& p : run)
        pairs[at[(p.a - begin) / kBlockSlots * kBuckets + std::min(p.first, kBuckets - 1)]++] = p;
    }
  });
  size_ = global_.size();
  tests_ = 0;
  earliest_ = horizon + 1;
  for (const Chunk& chunk : chunks_) size_ += chunk.size;
  for (const auto& [tests, earliest] : tally) {
    tests_ += tests;
    earliest_ = std::min(earliest_, earliest);
  }
  lonely_ = unmarked();
}

// One chunk's contacts in a step: test(a, b) tests a pair with `intersect` and offers an intersecting one to
// both its slots (offer_least_contact, impl/contacts.hpp), recording a slot that takes its first offer in
// `touched`. A chunk writes the least contact of its own slots only (below `end`); a later chunk's slot is
// offered through `offers`, after the parallel part (PairList::offer_the_rest).
template <class Intersect, class Precedes>
struct ChunkContacts {
  Intersect intersects;
  Precedes before;
  Buffer<std::uint32_t>& least;
  Buffer<std::uint32_t>& touched;
  std::vector<ContactOffer>& offers;
  std::size_t end;
  std::size_t seen = 0, hits = 0;

  void test(std::size_t a, std::size_t b) {
    ++seen;
    if (!intersects(a, b)) [[likely]]
      return;
    offer(a, b);
  }
  // The offers of a pair found intersecting, counted as a hit (test() counts it as seen).
  void offer(std::size_t a, std::size_t b) {
    ++hits;
    if (offer_least_contact(least, a, b, before)) touched.push_back(static_cast<std::uint32_t>(a));
    if (b >= end)
      offers.push_back({static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(a)});
    else if (offer_least_contact(least, b, a, before))
      touched.push_back(static_cast<std::uint32_t>(b));
  }
};

template <class Intersect, class Precedes>
ChunkContacts<Intersect, Precedes> PairList::chunk_contacts(std::size_t c, Buffer<std::uint32_t>& least,
                                                            std::vector<Buffer<std::uint32_t>>& touched,
                                                            const Intersect& intersect, const Precedes& precedes) {
  const std::size_t chunks = chunks_.size();
  Chunk& chunk = chunks_[c];
  touched[c].clear();
  // Room for every slot of the chunk, which costs address space only until it is written: the list then
  // never grows by copies through new memory (a first step's touched slots are a third of a dense scene).
  touched[c].reserve(chunk_begin(slots_, chunks, c + 1) - chunk_begin(slots_, chunks, c));
  chunk.offers.clear();
  // Copies of the caller's functors: the loop's stores (least, touched) cannot make the compiler reload them
  // for every pair.
  return {intersect, precedes, least, touched[c], chunk.offers, chunk_begin(slots_, chunks, c + 1)};
}

template <class Intersect, class Precedes>
std::size_t PairList::offer_the_rest(std::span<const std::array<std::size_t, 2>> counts,
                                     std::span<const ListedPair> global, std::uint64_t j, Buffer<std::uint32_t>& least,
                                     std::vector<Buffer<std::uint32_t>>& touched, std::size_t& tested,
                                     Intersect&& intersect, Precedes&& precedes) {
  const auto offer = [&](std::size_t to, std::size_t from) {
    if (offer_least_contact(least, to, from, precedes)) touched[chunk_of(to)].push_back(static_cast<std::uint32_t>(to));
  };
  for (const Chunk& chunk : chunks_)
    for (const ContactOffer& o : chunk.offers) offer(o.to, o.from);
  tested = 0;
  std::size_t contacts = 0;
  for (const auto& [seen, hits] : counts) {
    tested += seen;
    contacts += hits;
  }
  for (const ListedPair& p : global) {
    if (p.first > j) continue;
    ++tested;
    if (!intersect(p.a, p.b)) continue;
    ++contacts;
    offer(p.a, p.b);
    offer(p.b, p.a);
  }
  return contacts;
}

template <class Intersect, class Precedes, class Prefetch>
std::size_t PairList::least_contacts(std::uint64_t j, unsigned threads, Buffer<std::uint32_t>& least,
                                     std::vector<Buffer<std::uint32_t>>& touched, std::size_t& tested,
                                     Intersect&& intersect, Precedes&& precedes, Prefetch&& prefetch) {
  const std::size_t chunks = chunks_.size();
  touched.resize(chunks);
  std::vector<std::array<std::size_t, 2>> counts(chunks);  // per chunk: pairs tested, pairs intersecting
  // The buckets active at step j: 0 … j, the last one (first steps ≥ kBuckets − 1) pair by pair.
  const std::size_t last = std::min<std::uint64_t>(j, kBuckets - 1);
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    const Chunk& chunk = chunks_[c];
    auto contacts = chunk_contacts(c, least, touched, intersect, precedes);
    const std::size_t blocks = (chunk.starts.size() - 1) / kBuckets;
    const auto ask = prefetch;
    const ListedPair* const pairs = chunk.pairs.data();
    // Pairs [from, to) in order, each tested when it is due; the circles of the pair kPrefetchAhead places on
    // are asked for meanwhile (their loads are the step's cache misses where pairs are far apart in memory).
    // kTestBlock pairs at a time: their tests first, each answer kept without a branch (in a dense scene a
    // third of the tested pairs intersect, so a branch on the answer mispredicts often), then the offers of
    // those that intersect, in the same order. A pair that is not due is tested too, in the last bucket only,
    // and its answer dropped.
    const auto test_due = [&](std::size_t from, std::size_t to, auto due) {
      std::uint16_t hit[kTestBlock];
      for (std::size_t block = from; block < to; block += kTestBlock) {
        const std::size_t end = std::min(to, block + kTestBlock);
        std::size_t hits = 0;
        for (std::size_t i = block; i < end; ++i) {
          if (i + kPrefetchAhead < to) ask(pairs[i + kPrefetchAhead].a, pairs[i + kPrefetchAhead].b);
          const bool is_due = due(pairs[i]);
          contacts.seen += is_due;
          hit[hits] = static_cast<std::uint16_t>(i - block);
          hits += is_due & contacts.intersects(pairs[i].a, pairs[i].b);
        }
        for (std::size_t k = 0; k < hits; ++k) contacts.offer(pairs[block + hit[k]].a, pairs[block + hit[k]].b);
      }
    };
    for (std::size_t k = 0; k < blocks; ++k) {
      const std::uint32_t* starts = chunk.starts.data() + k * kBuckets;
      const std::size_t whole = last == kBuckets - 1 ? starts[kBuckets - 1] : starts[last + 1];
      test_due(starts[0], whole, [](const ListedPair&) { return true; });
      if (last == kBuckets - 1)
        test_due(starts[kBuckets - 1], starts[kBuckets], [j](const ListedPair& p) { return p.first <= j; });
    }
    counts[c] = {contacts.seen, contacts.hits};
  });
  return offer_the_rest(counts, global_, j, least, touched, tested, intersect, precedes);
}

template <class Intersect, class Precedes>
std::size_t PairList::contacts_now(const CellGrid& grid, const CellView& view, unsigned threads, const Lister& first,
                                   Buffer<std::uint32_t>& least, std::vector<Buffer<std::uint32_t>>& touched,
                                   std::size_t& tested, Intersect&& intersect, Precedes&& precedes) {
  const std::size_t n = view.key.size();
  slots_ = n;
  horizon_ = 0;
  const std::size_t chunks = chunk_count(n, threads);
  chunks_.resize(chunks);
  touched.resize(chunks);
  // No list: a later build makes its room without a count to go by.
  for (Chunk& chunk : chunks_) {
    chunk.size = 0;
    chunk.starts.clear();
  }
  // The slots of the tested pairs are marked as build() marks the listed ones.
  clear_marks(n);
  std::vector<std::array<std::size_t, 2>> counts(chunks);  // per chunk: pairs tested, pairs intersecting
  // Each pair a list of horizon 0 would hold (its first step 0) tested as the walk finds it.
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    auto contacts = chunk_contacts(c, least, touched, intersect, precedes);
    const Lister first_of = first;
    walk_near(grid, view, chunk_begin(n, chunks, c), chunk_begin(n, chunks, c + 1), first,
              [&](std::span<const std::uint64_t> batch) {
                std::uint32_t steps[kWalkBatch];
                first_of.steps(batch, steps);
                for (std::size_t k = 0; k < batch.size(); ++k) {
                  if (steps[k] != 0) continue;
                  const std::size_t a = first_slot(batch[k]), b = second_slot(batch[k]);
                  mark(a, b);
                  contacts.test(a, b);
                }
              });
    counts[c] = {contacts.seen, contacts.hits};
  });
  list_global(view, first, 0, [&](const ListedPair& p) { mark(p.a, p.b); });
  const std::size_t contacts = offer_the_rest(counts, global_, 0, least, touched, tested, intersect, precedes);
  global_.clear();
  size_ = 0;
  tests_ = tested;
  earliest_ = 1;
  lonely_ = unmarked();
  return contacts;
}

}  // namespace circles::impl
