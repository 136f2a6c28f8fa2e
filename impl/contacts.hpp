// The parts of a step that every engine shares, whatever its numbers: threads, chunks of slots, and each
// slot's least contact found through the broad phase (impl/broad_phase.hpp).
//
//   Invariant: find_least_contacts gives every slot t the least slot (under `precedes`, a strict total order)
//   among the slots that `intersect` t, or t itself when there is none, for every thread count: the least is
//   a minimum under a strict total order, so the order in which contacts are offered cannot change it.
//
// Include it from .cpp files of circles::impl only: for_each_chunk's pragma needs the library's OpenMP flags.
//
// The double engines (impl/engine.cpp) and the exact engine (impl/exact_engine.cpp) differ only in the
// `intersect` and `precedes` they pass and in the numbers behind the view's boxes.
#pragma once

#include "impl/broad_phase.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace circles::impl {

// Worlds below this size run on one thread: a parallel region costs more than it saves.
inline constexpr std::size_t kParallelFrom = 8192;
// Slots per chunk at least, and chunks per thread (more chunks than threads balance uneven cells).
inline constexpr std::size_t kMinChunk = 2048;
inline constexpr std::size_t kChunksPerThread = 4;

// `requested` threads, or one per core for 0. Throws std::invalid_argument above `max`.
inline unsigned resolve_threads(unsigned requested, unsigned max) {
  if (requested > max)
    throw std::invalid_argument("EngineOptions::threads: " + std::to_string(requested) + " is more than " +
                                std::to_string(max));
  if (requested != 0) return requested;
  const unsigned cores = std::thread::hardware_concurrency();
  return std::clamp(cores, 1u, max);
}

// The chunks of n slots for `threads` threads: chunk c is [n·c/C, n·(c + 1)/C).
inline std::size_t chunk_count(std::size_t n, unsigned threads) {
  if (threads <= 1 || n < kParallelFrom) return 1;
  return std::clamp<std::size_t>(n / kMinChunk, 1, std::size_t{threads} * kChunksPerThread);
}
inline std::size_t chunk_begin(std::size_t n, std::size_t chunks, std::size_t c) { return n * c / chunks; }

// Runs f(c) for every chunk c, on up to `threads` threads (OpenMP; the including target links it).
template <class F>
void for_each_chunk(std::size_t chunks, unsigned threads, F&& f) {
  const auto count = static_cast<long>(chunks);
#pragma omp parallel for num_threads(threads) schedule(static) if (chunks > 1)
  for (long c = 0; c < count; ++c) f(static_cast<std::size_t>(c));
}

// least[t] = the least slot under precedes(a, b) among the slots that intersect(t, ·), or t; the view's slots
// in cell order, global slots from view.level_begin[kGlobalLevel] on. `offers` is scratch (one list per chunk).
// Returns 0 exactly when no pair intersects.
template <class Intersect, class Precedes>
std::size_t find_least_contacts(const CellGrid& grid, const CellView& view, unsigned threads,
                                std::vector<std::uint32_t>& least, std::vector<std::vector<ContactOffer>>& offers,
                                Intersect&& intersect, Precedes&& precedes) {
  const std::size_t n = view.key.size();
  least.resize(n);
  const std::size_t chunks = chunk_count(n, threads);
  offers.resize(chunks);
  std::vector<unsigned char> touched(chunks, 0);
  const auto offer = [&](std::size_t to, std::size_t from) {
    if (least[to] == to || precedes(from, least[to])) least[to] = static_cast<std::uint32_t>(from);
  };
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    const std::size_t begin = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1);
    offers[c].clear();
    for (std::size_t t = begin; t < end; ++t) least[t] = static_cast<std::uint32_t>(t);  // no contact yet
    // A chunk writes the least contact of its own slots only; a contact found for a slot of a later chunk
    // is recorded and offered after the parallel part.
    NeighbourCursor cursor;
    bool any = false;
    for (std::size_t a = begin; a < end; ++a) {
      visit_neighbourhood(grid, view, a, cursor, [&](std::size_t b) {
        if (!intersect(a, b)) return;
        any = true;
        offer(a, b);
        if (b < end)
          offer(b, a);
        else
          offers[c].push_back({static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(a)});
      });
    }
    touched[c] = any;
  });
  auto contacts = static_cast<std::size_t>(std::count(touched.begin(), touched.end(), 1));
  for (const std::vector<ContactOffer>& list : offers) {
    for (const ContactOffer& o : list) offer(o.to, o.from);
    contacts += list.size();
  }
  // Global circles (a box too wide for every level): tested against every circle, each pair once (a pair of
  // two global circles from the earlier one).
  const std::size_t global = view.level_begin[CellGrid::kGlobalLevel];
  for (std::size_t g = global; g < n; ++g)
    for (std::size_t b = 0; b < n; ++b) {
      if (b == g || (b >= global && b < g)) continue;
      if (intersect(g, b)) {
        offer(g, b);
        offer(b, g);
        ++contacts;
      }
    }
  return contacts;
}

}  // namespace circles::impl
