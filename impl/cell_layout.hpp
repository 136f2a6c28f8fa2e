// The cell layout both engines share: their circles in cell order (slots), the kept pair list, the horizon
// schedule and when to rebuild. An engine owns only its arithmetic (its columns by slot, how a step moves
// them, how its radii are padded and widened for a list, how it decides a pair); the layout owns the rest:
//
//   CellLayout
//     slots      id (slot t holds circle id[t]), keys, CellOrder's permutation, the gather of the id, the keys
//                and every column an engine registers with arrange()
//     grid       CellGrid (planned per horizon), the levels that hold a circle
//     pair list  PairList over the slots, each slot's least contact and the slots touched by a step
//     schedule   HorizonSchedule, the step the list was built in and the step that rebuilds
//
// A step (CellLayout::step): rebuild when the list's horizon has ended (the engine's rebuild calls horizon(),
// arrange() and list()), the contacts of the listed pairs by the engine's pair test, the engine's move, the
// statistics. The member templates step, arrange and gather are defined in impl/cell_layout_impl.hpp, which
// only the engines' .cpp files include (it needs the library's OpenMP flags). docs/engine.md draws the layout.
#pragma once

#include "impl/broad_phase.hpp"
#include "impl/buffers.hpp"
#include "impl/pair_list.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <numeric>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace circles::impl {

struct EngineOptions {
  // Worker threads; 0 means one per core that other programs leave free, for a world big enough to use
  // threads (impl/threads.hpp: choose_threads). Results are the same bits for every value.
  unsigned threads = 0;
  // Keep candidate pairs across steps (impl/pair_list.hpp: a list with a proven skin, rebuilt when its
  // horizon ends); false builds a list for every step alone. Results are the same bits either way.
  bool keep_pairs = true;
  // The horizon of every list, in steps, instead of HorizonSchedule's choice (0 means that choice); for tests
  // and benchmarks. With keep_pairs false it is ignored. Results are the same bits for every value.
  std::uint64_t horizon = 0;
  // The steps the engine will be asked for, when the caller knows (0: not known). No list then looks past the
  // last of them: a list built in step s serves steps s to s + H, so H ≤ steps − s − 1, and a 1-step run
  // lists only the pairs that touch now, with no skin. Results are the same bits for every value.
  std::uint64_t steps = 0;
};

// The columns of one element type an engine keeps by slot, for arrange() to gather into the new cell order,
// with `scratch`, a vector of the same type, as the gather's target (it is swapped with each column).
template <class T>
struct Columns {
  Buffer<T>& scratch;
  std::initializer_list<Buffer<T>*> columns;
};

// An engine's pair test for one step, as PairList::least_contacts takes it: intersect(a, b), precedes(a, b)
// on slots, and the prefetch hint.
template <class Intersect, class Precedes, class Prefetch>
struct PairTest {
  Intersect intersect;
  Precedes precedes;
  Prefetch prefetch;
};
template <class I, class P, class F>
PairTest(I, P, F) -> PairTest<I, P, F>;

class CellLayout {
 public:
  // n circles, slot k holding circle k until the first rebuild sorts them; every slot its own least contact.
  explicit CellLayout(std::size_t n = 0) {
    id_.resize(n);
    std::iota(id_.begin(), id_.end(), std::uint32_t{0});
    least_.reserve(n);
    least_ = id_;
  }

  std::size_t size() const noexcept { return id_.size(); }
  // The circle slot t holds.
  std::span<const std::uint32_t> id() const noexcept { return id_; }
  // What a step's contacts found, for its move: each slot's least contact (itself if none; the move sets
  // every touched slot's back to itself) and, per chunk of `chunks`, the slots the contacts touched.
  struct Found {
    Buffer<std::uint32_t>& least;
    std::vector<Buffer<std::uint32_t>>& touched;
  };
  Found found(std::size_t chunks) {
    touched_.resize(chunks);
    return {least_, touched_};
  }
  const PairList& pairs() const noexcept { return pairs_; }
  // True when the step numbered `steps` (steps taken so far) rebuilds the list.
  bool due(std::uint64_t steps) const noexcept { return steps == rebuild_at_; }

  // One step: rebuild() when due, then the contacts by the pair test make_test() returns (called after the
  // rebuild, so that it reads the columns as arranged), then move(), then the statistics.
  template <class Rebuild, class MakeTest, class Move>
  void step(EngineStats& stats, unsigned threads, Rebuild&& rebuild, MakeTest&& make_test, Move&& move);

  // The horizon of the list built in the step numbered `steps` (steps taken so far): none without kept pairs,
  // the options' fixed one, or the schedule's. When the options give the run's length, the R steps left are
  // split evenly among the k = ⌈R/(H + 1)⌉ lists that the chosen H needs to cover them: this list serves
  // ⌈R/k⌉ steps. That is as many lists as cutting only the last one at the run's end, each with a horizon as
  // short or shorter, so a skin as thin or thinner and no more pairs to list (20 steps at H = 8: lists of 7,
  // 7 and 6 steps rather than 9, 9 and 2).
  std::uint64_t horizon(const EngineOptions& options, std::uint64_t steps) const noexcept {
    const std::uint64_t chosen = !options.keep_pairs ? 0 : options.horizon > 0 ? options.horizon : schedule_.horizon();
    if (options.steps <= steps) return chosen;
    const std::uint64_t left = options.steps - steps;
    if (chosen >= left - 1) return left - 1;  // one list to the end
    const auto ceil_div = [](std::uint64_t a, std::uint64_t b) { return a / b + (a % b != 0); };
    return ceil_div(left, ceil_div(left, chosen + 1)) - 1;
  }
  // A horizon whose skin was not finite: the list covers its own world, and so does the schedule's next.
  void collapse() noexcept { schedule_.collapse(); }

  // The slots in cell order for circles at (x, y) with radii `inflated` (all by slot): the grid planned
  // again when the horizon changed, keys, CellOrder's sort (by digits, or guided by the last keys), and, when
  // the order changed, one gather of the id, the keys and every registered column (x, y and inflated among
  // them).
  template <class... T>
  void arrange(unsigned threads, std::uint64_t horizon, const Buffer<double>& x, const Buffer<double>& y,
               const Buffer<double>& inflated, Columns<T>... columns);

  // After arrange(): the list for the horizon, over the circles at (x, y) with radii `inflated` (as
  // arranged), each pair from its first step by `lister`; then the schedule's bookkeeping for a list built in
  // the step numbered stats.steps.
  void list(EngineStats& stats, const EngineOptions& options, unsigned threads, std::uint64_t horizon,
            const Buffer<double>& x, const Buffer<double>& y, const Buffer<double>& inflated,
            const Lister& lister) {
    const CellView view{key_, x, y, inflated, levels_, level_begin_, wide_runs_};
    pairs_.build(grid_, view, threads, horizon, lister);
    built_at_ = stats.steps;
    stats.pairs_listed += pairs_.size();
    ++stats.rebuilds;
    if (learns(options)) schedule_.update(pairs_.tests(), id_.size());
    rebuild_at_ = stats.steps + horizon + 1;
  }

  // After arrange(), for a horizon of 0, instead of list(): no list is written, since only this step would
  // read it; the step finds its contacts during the walk list() would make (PairList::contacts_now), with the
  // same `lister`, testing the pairs that list would hold. The columns must stay where they are until then.
  void list_in_step(EngineStats& stats, const EngineOptions& options, const Buffer<double>& x,
                    const Buffer<double>& y, const Buffer<double>& inflated, const Lister& lister) {
    in_step_ = InStep{CellView{key_, x, y, inflated, levels_, level_begin_, wide_runs_}, lister, learns(options)};
    built_at_ = stats.steps;
    ++stats.rebuilds;
    rebuild_at_ = stats.steps + 1;
  }

  // The pairs {i, j}, i < j (circle indices) of the kept list, once each; after list_in_step(), of the list it
  // does not write.
  std::vector<CandidatePair> listed() const {
    if (!in_step_) return listed_pairs(pairs_, id_);
    PairList list;
    list.build(grid_, in_step_->view, 1, 0, in_step_->lister);
    return listed_pairs(list, id_);
  }

 private:
  // column[t] ← column[permutation[t]] for every registered column, per chunk. Values that own memory (GMP
  // integers) are swapped rather than copied (no allocation); the column is scratch afterwards either way, and
  // stays with the engine for the next gather.
  template <class T>
  void gather(unsigned threads, const Columns<T>& set);
  // True when the schedule learns from the tests of the lists: when it chooses their horizons. A list shorter
  // than its choice (a run of known length shares its steps evenly) teaches it as well: its rule weighs a
  // list's tests against one rebuild, whatever the number of steps the list served.
  static bool learns(const EngineOptions& options) noexcept { return options.keep_pairs && options.horizon == 0; }

  // What list_in_step() leaves for the step: the view and lister of the walk, and whether the schedule learns
  // from the step's tests (as list() lets it from a list).
  struct InStep {
    CellView view;
    Lister lister;
    bool learn;
  };
  std::optional<InStep> in_step_;
  // The rebuild's scratch (permutation_, next_key_; the sort's and the gathers' own) stays between rebuilds,
  // 28 bytes a circle or more, so that a rebuild writes no memory that an earlier one did not: each 2 MiB of
  // new memory is a page fault, and on a virtual machine whose host backs the pages as they are first written
  // one cost about 3 ms (impl/buffers.hpp).
  Buffer<std::uint32_t> id_, least_, permutation_;
  std::vector<Buffer<std::uint32_t>> touched_;
  Buffer<CellKey> key_, next_key_;  // by the inflated radii of the last rebuild
  std::vector<unsigned> levels_;          // the levels that hold a circle, ascending, the global level excluded
  std::array<std::size_t, CellGrid::kLevels + 1> level_begin_{};  // level L: [level_begin[L], level_begin[L + 1])
  bool wide_runs_ = false;  // few_per_cell(key_): the walk's form for these keys
  CellGrid grid_;
  CellOrder order_;
  PairList pairs_;
  HorizonSchedule schedule_;
  std::uint64_t rebuild_at_ = 0;  // the step whose world gets the next list
  std::uint64_t built_at_ = 0;    // the step whose world got the current one
  std::uint64_t planned_horizon_ = ~std::uint64_t{0};  // the horizon the grid was planned for
};

}  // namespace circles::impl
