// The parts of a step that every engine shares, whatever its numbers: threads, chunks of slots, and the
// offer of a contact to a slot's least contact so far.
//
//   Invariant: after every contact of a step is offered (offer_least_contact, in any order), least[t] is the
//   least slot under `precedes` (a strict total order) among the slots that intersect t, or t itself when
//   there is none: the least is a minimum under a strict total order, so the order of the offers, and with
//   it the thread count, cannot change it.
//
// Include it from .cpp files of circles::impl only: for_each_chunk's pragma needs the library's OpenMP flags.
//
// The double engines (impl/engine.cpp) and the exact engine (impl/exact_engine.cpp) find their contacts in a
// PairList (impl/pair_list.hpp), which offers them here; they differ only in the `intersect` and `precedes`
// they pass and in the numbers behind the list's boxes.
#pragma once

#include "impl/broad_phase.hpp"
#include "impl/threads.hpp"  // kParallelFrom

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <span>
#include <vector>

namespace circles::impl {

// Slots per chunk at least, and chunks per thread. for_each_chunk hands each thread a contiguous run of chunks
// (schedule(static)). Neither the chunk count nor which thread runs a chunk changes a result: tests/golden_test.cpp
// holds the trajectories for 1, 2 and 4 threads to one hash.
inline constexpr std::size_t kMinChunk = 2048;
inline constexpr std::size_t kChunksPerThread = 4;

// The chunks of n slots for `threads` threads: chunk c is [n·c/C, n·(c + 1)/C).
inline std::size_t chunk_count(std::size_t n, unsigned threads) {
  if (threads <= 1 || n < kParallelFrom) return 1;
  return std::clamp<std::size_t>(n / kMinChunk, 1, std::size_t{threads} * kChunksPerThread);
}
inline std::size_t chunk_begin(std::size_t n, std::size_t chunks, std::size_t c) { return n * c / chunks; }

// Runs f(c) for every chunk c, on up to `threads` threads (OpenMP; the including target links it). An
// exception may not leave an OpenMP region (it would terminate the program), so each is caught in its chunk
// and the one of the least chunk is rethrown after the region: a failed allocation is std::bad_alloc for the
// caller, whatever the thread count. One chunk runs without a region.
template <class F>
void for_each_chunk(std::size_t chunks, unsigned threads, F&& f) {
  if (chunks <= 1) {
    if (chunks == 1) f(std::size_t{0});
    return;
  }
  const auto count = static_cast<long>(chunks);
  std::exception_ptr error;
  long failed = count;  // the least chunk that threw
#pragma omp parallel for num_threads(threads) schedule(static)
  for (long c = 0; c < count; ++c) {
    try {
      f(static_cast<std::size_t>(c));
    } catch (...) {
#pragma omp critical(circles_for_each_chunk)
      if (c < failed) {
        failed = c;
        error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

// f(t) for every slot t of n, in chunks on up to `threads` threads.
template <class F>
void for_each_slot(std::size_t n, unsigned threads, F&& f) {
  const std::size_t chunks = chunk_count(n, threads);
  for_each_chunk(chunks, threads, [&](std::size_t c) {
    for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t) f(t);
  });
}

// keys[t] = grid.key(px[t], py[t], r[t]) for every slot, per chunk. Where a circle has drifted out of the planned
// grid (its cell would clamp, which is correct but slow), the grid is planned again and the keys recomputed,
// unless the plan itself left far circles out (CellGrid::trimmed), which a new plan would do again.
inline void locate(CellGrid& grid, unsigned threads, std::span<const double> px, std::span<const double> py,
                   std::span<const double> r, std::span<CellKey> keys) {
  const std::size_t n = keys.size();
  const std::size_t chunks = chunk_count(n, threads);
  std::vector<std::array<double, 4>> extent(chunks);  // per chunk: the least and largest x, then y
  const auto compute = [&] {
    for_each_chunk(chunks, threads, [&](std::size_t c) {
      const std::size_t b = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1);
      grid.keys(px.subspan(b, e - b), py.subspan(b, e - b), r.subspan(b, e - b), keys.subspan(b, e - b));
      constexpr double inf = std::numeric_limits<double>::infinity();
      double xlo = inf, xhi = -inf, ylo = inf, yhi = -inf;
      for (std::size_t t = b; t < e; ++t) {
        xlo = std::min(xlo, px[t]);
        xhi = std::max(xhi, px[t]);
        ylo = std::min(ylo, py[t]);
        yhi = std::max(yhi, py[t]);
      }
      extent[c] = {xlo, xhi, ylo, yhi};
    });
  };
  compute();
  bool inside = true;
  for (const auto& [xlo, xhi, ylo, yhi] : extent) inside = inside && (xlo > xhi || grid.covers(xlo, xhi, ylo, yhi));
  if (!inside && !grid.trimmed()) {
    grid.plan(px, py, r);
    compute();
  }
}

// Slot `to`'s least contact so far after slot `from`, which intersects it, is offered: least[to] == to means
// none yet. Returns true for the first offer (the caller records `to` as touched), false for a later one,
// which keeps the lesser under precedes.
template <class Precedes>
bool offer_least_contact(Buffer<std::uint32_t>& least, std::size_t to, std::size_t from, Precedes&& precedes) {
  if (least[to] == to) {
    least[to] = static_cast<std::uint32_t>(from);
    return true;
  }
  if (precedes(from, least[to])) least[to] = static_cast<std::uint32_t>(from);
  return false;
}

}  // namespace circles::impl
