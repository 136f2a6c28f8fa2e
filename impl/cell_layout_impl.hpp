// The member templates of CellLayout (impl/cell_layout.hpp) that run on the library's threads. Only the
// engines' .cpp files include this header (it needs the library's OpenMP flags).
#pragma once

#include "impl/cell_layout.hpp"
#include "impl/contacts.hpp"
#include "impl/pair_list_impl.hpp"

#include <type_traits>

namespace circles::impl {

template <class Rebuild, class MakeTest, class Move>
void CellLayout::step(EngineStats& stats, unsigned threads, Rebuild&& rebuild, MakeTest&& make_test, Move&& move) {
  if (due(stats.steps)) rebuild();
  std::size_t contacts = 0, tested = 0;
  const std::uint64_t j = stats.steps - built_at_;  // this step's place in the list's horizon
  if (in_step_) {
    auto test = make_test();
    contacts = pairs_.contacts_now(grid_, in_step_->view, threads, in_step_->lister, least_, touched_, tested,
                                   test.intersect, test.precedes);
    // The counts list() and the contacts of its list would give.
    stats.pairs_listed += tested;
    if (tested == 0) ++stats.quiet_steps;
    if (in_step_->learn) schedule_.update(tested, id_.size());
    in_step_.reset();
  } else if (!pairs_.quiet(j)) {
    auto test = make_test();
    contacts = pairs_.least_contacts(j, threads, least_, touched_, tested, test.intersect, test.precedes,
                                     test.prefetch);
  } else {
    ++stats.quiet_steps;
    for (Buffer<std::uint32_t>& list : touched_) list.clear();
  }
  move();
  ++stats.steps;
  stats.pairs_tested += tested;
  stats.contacts += contacts;
  stats.lonely_circle_steps += pairs_.lonely();
}

template <class... T>
void CellLayout::arrange(unsigned threads, std::uint64_t horizon, const Buffer<double>& x, const Buffer<double>& y,
                         const Buffer<double>& inflated, Columns<T>... columns) {
  const std::size_t n = id_.size();
  pairs_.release();  // rebuilt by list() after this; memory peaks during the sort below otherwise
  const bool planned = horizon != planned_horizon_;
  if (planned) {
    grid_.plan(x, y, inflated);
    planned_horizon_ = horizon;
  }
  // The first layout: no previous order to guide the sort, and id_ is still the identity.
  const bool first = key_.size() != n;
  // The sort goes by digits where the keys pack (CellOrder); the last keys guide only keys that do not. A new
  // plan gives every slot a key of other cells: then the last keys would guide nothing, and the new keys are
  // written over them; otherwise beside them. The keys are left in the new order by the sort itself.
  const bool guided = !planned && !first;
  Buffer<CellKey>& keys = guided ? next_key_ : key_;
  keys.resize(n);
  locate(grid_, threads, x, y, inflated, keys);
  const bool sorted = order_.sort_in_place(
      keys, guided ? std::span<const CellKey>{key_} : std::span<const CellKey>{}, permutation_, threads);
  if (guided) std::swap(key_, next_key_);
  if (!sorted) {
    // least_ is the identity between steps, so it stays.
    (gather(threads, columns), ...);
    // The id last, written over the permutation, which it alone reads then: id[t] ← id[permutation[t]]; the
    // first layout's id, the identity, gives the permutation itself.
    if (!first) for_each_slot(n, threads, [&](std::size_t t) { permutation_[t] = id_[permutation_[t]]; });
    id_.swap(permutation_);
  }
  index_levels(key_, level_begin_, levels_);
  wide_runs_ = few_per_cell(key_);
}

template <class T>
void CellLayout::gather(unsigned threads, const Columns<T>& set) {
  const std::size_t n = id_.size();
  const std::size_t chunks = chunk_count(n, threads);
  set.scratch.resize(n);
  for (Buffer<T>* column : set.columns) {
    for_each_chunk(chunks, threads, [&](std::size_t c) {
      for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t) {
        if constexpr (std::is_trivially_copyable_v<T>)
          set.scratch[t] = (*column)[permutation_[t]];
        else
          set.scratch[t].swap((*column)[permutation_[t]]);
      }
    });
    column->swap(set.scratch);
  }
}

}  // namespace circles::impl
