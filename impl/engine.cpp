// The double engines' step; the invariant is stated in engine.hpp, the design in docs/engine.md.
//
// A step from world t (circles in cell order, a list of the pairs that can meet, impl/pair_list.hpp):
//   rebuild   when the list's horizon has ended: the skin for the next horizon, keys of the inflated circles,
//             CellOrder's permutation and one gather, then the broad phase fills the list (parallel; a list
//             of horizon 0 is not written: the contacts below take its pairs as the broad phase finds them);
//   contacts  each listed pair tested with the arithmetic's intersect; each slot's least contact (parallel);
//   advance   v ← v[least] for the slots that have a contact, then p ← update(p, v) in place (parallel);
//             where the rebuild could not prove that no position overflows, it checks and restores world t.
// The slots keep their order between rebuilds: a step moves no circle in memory.
#include "impl/engine.hpp"

#include "impl/buffers.hpp"
#include "impl/cell_layout_impl.hpp"
#include "impl/double_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <string>

namespace circles::impl {
namespace {

// The resolved profile's order on circles a and b given by their five keys (px, py, vx, vy, r), each decided by
// exact comparisons of doubles: equal values (−0 and +0 included) pass to the next key; tie() decides when all
// five are equal.
template <class Tie>
bool precedes_by_keys(std::initializer_list<const Buffer<double>*> keys, std::size_t a, std::size_t b, Tie tie) {
  for (const Buffer<double>* key : keys) {
    const double x = (*key)[a];
    const double y = (*key)[b];
    if (x < y) return true;
    if (y < x) return false;
  }
  return tie();
}

}  // namespace

// ── World ─────────────────────────────────────────────────────────────────────────────────────────────

World::World(const spec::Circles& circles) {
  const std::size_t n = circles.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("World: " + std::to_string(n) + " circles; at most 2^32 - 1");
  for (std::size_t k = 0; k < n; ++k) spec::check_doubles(circles[k], k, spec::Radii::non_negative);
  for (Buffer<double>* field : {&px_, &py_, &vx_, &vy_, &r_}) field->resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    px_[k] = circles[k][0];
    py_[k] = circles[k][1];
    vx_[k] = circles[k][2];
    vy_[k] = circles[k][3];
    r_[k] = circles[k][4];
  }
}

spec::Circles World::circles() const {
  spec::Circles out(size());
  for (std::size_t k = 0; k < size(); ++k) out[k] = {px_[k], py_[k], vx_[k], vy_[k], r_[k]};
  return out;
}

bool World::precedes(std::size_t a, std::size_t b) const noexcept {
  return precedes_by_keys({&px_, &py_, &vx_, &vy_, &r_}, a, b, [a, b] { return a < b; });
}

// ── The engine ────────────────────────────────────────────────────────────────────────────────────────

template <class A>
BasicEngine<A>::BasicEngine(World w, EngineOptions options)
    : options_(options),
      thread_count_(options.threads, kMaxThreads, w.size()),
      threads_(thread_count_.count()),
      layout_(w.size()) {
  now_.px = std::move(w.px_);
  now_.py = std::move(w.py_);
  now_.vx = std::move(w.vx_);
  now_.vy = std::move(w.vy_);
  now_.r = std::move(w.r_);
}

template <class A>
World BasicEngine<A>::world() const {
  World w;
  const std::size_t n = now_.px.size();
  for (Buffer<double>* field : {&w.px_, &w.py_, &w.vx_, &w.vy_, &w.r_}) field->resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const std::uint32_t k = layout_.id()[t];
    w.px_[k] = now_.px[t];
    w.py_[k] = now_.py[t];
    w.vx_[k] = now_.vx[t];
    w.vy_[k] = now_.vy[t];
    w.r_[k] = now_.r[t];
  }
  return w;
}

template <class A>
std::vector<std::uint32_t> BasicEngine<A>::slots() const {
  const std::span<const std::uint32_t> id = layout_.id();
  std::vector<std::uint32_t> slot(id.size());
  for (std::size_t t = 0; t < slot.size(); ++t) slot[id[t]] = static_cast<std::uint32_t>(t);
  return slot;
}

template <class A>
void BasicEngine<A>::read_circles(std::span<const std::uint32_t> slots, std::size_t first,
                                  std::span<spec::CircleDoubles> out) const {
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::uint32_t t = slots[first + i];
    out[i] = {now_.px[t], now_.py[t], now_.vx[t], now_.vy[t], now_.r[t]};
  }
}

template <class A>
bool BasicEngine<A>::precedes(std::size_t a, std::size_t b) const noexcept {
  // World::precedes on slots: the same keys, then the circles' indices.
  return precedes_by_keys({&now_.px, &now_.py, &now_.vx, &now_.vy, &now_.r}, a, b,
                          [this, a, b] { return layout_.id()[a] < layout_.id()[b]; });
}

template <class A>
void BasicEngine<A>::step() {
  threads_ = thread_count_.next();
  layout_.step(
      stats_, threads_, [this] { rebuild(); },
      [this] {
        // The arrays' addresses as locals: the loop's stores (least, touched) then cannot make the compiler
        // reload them for every pair.
        const double *px = now_.px.data(), *py = now_.py.data(), *r = now_.r.data();
        return PairTest{
            [px, py, r](std::size_t a, std::size_t b) { return A::intersect(px[a], py[a], r[a], px[b], py[b], r[b]); },
            [this](std::size_t a, std::size_t b) { return precedes(a, b); }, PrefetchCircles{px, py, r}};
      },
      [this] { advance(); });
}

template <class A>
void BasicEngine<A>::advance() {
  const std::size_t n = now_.px.size();
  const std::size_t chunks = chunk_count(n, threads_);
  moves_.resize(chunks);
  const CellLayout::Found found = layout_.found(chunks);
  // Every new velocity first, read from world t (a slot's least contact may be another chunk's slot).
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    // Room for all at once: a first step's moves would otherwise grow by copies, into memory not yet touched.
    Buffer<Move>& mine = moves_[c];
    mine.clear();
    mine.reserve(found.touched[c].size());
    for (const std::uint32_t t : found.touched[c]) mine.push_back({t, now_.vx[found.least[t]], now_.vy[found.least[t]]});
  });
  if (!overflow_free_) {
    backup_px_ = now_.px;
    backup_py_ = now_.py;
  }
  // Per chunk: its slots' new velocities (the moves keep the old ones, for an overflow), then p ← update(p, v)
  // in place, which reads only the chunk's own slots.
  constexpr std::uint64_t kNoFault = std::numeric_limits<std::uint64_t>::max();
  std::vector<std::uint64_t> fault(chunks, kNoFault);  // 2·index + (0 for px, 1 for py)
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    for (Move& m : moves_[c]) {
      std::swap(now_.vx[m.slot], m.vx);
      std::swap(now_.vy[m.slot], m.vy);
      found.least[m.slot] = m.slot;
    }
    const std::size_t b = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1);
    A::advance(std::span<double>(now_.px).subspan(b, e - b), std::span<const double>(now_.vx).subspan(b, e - b));
    A::advance(std::span<double>(now_.py).subspan(b, e - b), std::span<const double>(now_.vy).subspan(b, e - b));
    if (overflow_free_) return;
    // Inputs are finite, so the update gives ±inf only on an overflow, never NaN.
    for (std::size_t t = b; t < e; ++t)
      if (!std::isfinite(now_.px[t]) || !std::isfinite(now_.py[t])) [[unlikely]]
        fault[c] = std::min(fault[c], 2 * std::uint64_t{layout_.id()[t]} + (std::isfinite(now_.px[t]) ? 1 : 0));
  });
  const std::uint64_t first = *std::min_element(fault.begin(), fault.end());
  if (first == kNoFault) return;
  // World t again: the positions from the backup, the velocities from the moves.
  now_.px.swap(backup_px_);
  now_.py.swap(backup_py_);
  for (std::size_t c = 0; c < chunks; ++c)
    for (const Move& m : moves_[c]) {
      found.least[m.slot] = m.slot;
      now_.vx[m.slot] = m.vx;
      now_.vy[m.slot] = m.vy;
    }
  throw PositionOverflow(stats_.steps + 1, first / 2, first % 2 ? spec::Field::py : spec::Field::px);
}

template <class A>
void BasicEngine<A>::rebuild() {
  // A list for world t and the horizon H: the skin (impl/pair_list.hpp) from vmax and reach, keys of the
  // inflated circles, the slots in their cell order, and the broad phase over the inflated radii, each pair
  // it offers listed from its first step.
  const std::size_t n = now_.px.size();
  const std::size_t chunks = chunk_count(n, threads_);
  std::vector<std::array<double, 3>> largest(chunks);  // per chunk: vmax, reach, the largest radius
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    double vmax = 0, reach = 0, radius = 0;
    for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t) {
      vmax = std::max(vmax, norm_upper(now_.vx[t], now_.vy[t]));
      reach = std::max({reach, std::fabs(now_.px[t]), std::fabs(now_.py[t])});
      radius = std::max(radius, now_.r[t]);
    }
    largest[c] = {vmax, reach, radius};
  });
  double vmax = 0, reach = 0, radius = 0;
  for (const auto& [v, p, r] : largest) {
    vmax = std::max(vmax, v);
    reach = std::max(reach, p);
    radius = std::max(radius, r);
  }
  std::uint64_t horizon = layout_.horizon(options_, stats_.steps);
  // A naive test may call a pair touching slightly beyond the exact relation: its slack (impl/arithmetic.hpp)
  // widens every radius by `slack` for the list, on top of the skin.
  const double slack = A::slack * reach + A::slack * radius;
  double step = step_bound(horizon, vmax, reach, A::drift);
  double pad = skin_for(horizon, vmax, reach, A::drift) + slack;
  if (!(reach + pad < kOverflowFreeReach)) {
    // Motion too fast or positions too near the double range to bound (or +∞): a list for this world alone.
    horizon = 0;
    step = 0;
    pad = slack;
    layout_.collapse();
  }
  // Until the list's last step is taken, every circle moves at most skin_for(H + 1) from world t: below
  // 2^1023 − reach, no position can overflow (a rounded |p| ≤ 2^1023·(1 + 2^-52) < DBL_MAX), and steps
  // update in place.
  overflow_free_ = reach + skin_for(horizon + 1, vmax, reach, A::drift) < kOverflowFreeReach;
  // Each radius widened by `widen` > 0 (outward, so at least r + widen exactly); per chunk.
  const auto widened = [&](Buffer<double>& to, double widen) {
    to.resize(n);
    for_each_chunk(chunks, threads_, [&](std::size_t c) {
      for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t)
        to[t] = outward_upper(now_.r[t], widen);
    });
  };
  // The slots in cell order, every column gathered with them. A pad of 0 (a list for this world alone, by an
  // arithmetic without slack) inflates nothing: the radii serve as they are, with no copy to write and gather.
  if (pad > 0) {
    widened(inflated_, pad);
    layout_.arrange(threads_, horizon, now_.px, now_.py, inflated_,
                    impl::Columns<double>{scratch_, {&now_.px, &now_.py, &now_.vx, &now_.vy, &now_.r, &inflated_}});
  } else {
    Buffer<double>().swap(inflated_);
    layout_.arrange(threads_, horizon, now_.px, now_.py, now_.r,
                    impl::Columns<double>{scratch_, {&now_.px, &now_.py, &now_.vx, &now_.vy, &now_.r}});
  }
  const Buffer<double>& inflated = pad > 0 ? inflated_ : now_.r;
  // Each pair's first step from its gap (impl/pair_list.hpp), on the radii widened by the slack alone.
  // (With no slack, the exact arithmetic's, the padded radii are the radii: no copy.)
  if (slack > 0) widened(padded_, slack);
  // Most pairs the broad phase offers are decided by the filter of the exact test alone (no square root):
  // disjoint at the inflated radii means never within the horizon, and intersecting at the padded ones means
  // from step 0.
  const double *px = now_.px.data(), *py = now_.py.data(), *r = slack > 0 ? padded_.data() : now_.r.data(),
               *ri = inflated.data();
  const Lister lister{px, py, r, ri, step, horizon};
  // A list for this world alone is read once, by this step: its pairs are tested as the walk finds them.
  if (horizon == 0)
    layout_.list_in_step(stats_, options_, now_.px, now_.py, inflated, lister);
  else
    layout_.list(stats_, options_, threads_, horizon, now_.px, now_.py, inflated, lister);
}

template <class A>
std::vector<CandidatePair> BasicEngine<A>::candidates() const {
  if (!layout_.due(stats_.steps)) return layout_.listed();
  BasicEngine copy = *this;
  copy.rebuild();
  return copy.layout_.listed();
}

template class BasicEngine<RoundedArithmetic>;
template class BasicEngine<NaiveArithmetic>;
template class BasicEngine<NaiveSqrtArithmetic>;
template class BasicEngine<FloatNaiveArithmetic>;
template class BasicEngine<ExactDecisionArithmetic>;

// ── The all-pairs reference ───────────────────────────────────────────────────────────────────────────

World step_all_pairs(const World& w) {
  return step_over_pairs(w, [n = w.size()](const auto& visit) {
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) visit(a, b);
  });
}

World step_from_contacts(const World& w, std::span<const std::size_t> least) {
  const std::size_t n = w.size();
  World next = w;
  for (std::size_t k = 0; k < n; ++k) {
    next.vx_[k] = w.vx_[least[k]];
    next.vy_[k] = w.vy_[least[k]];
    next.px_[k] = advance_rounded(w.px_[k], next.vx_[k]);
    next.py_[k] = advance_rounded(w.py_[k], next.vy_[k]);
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(next.px_[k])) throw PositionOverflow(1, k, spec::Field::px);
    if (!std::isfinite(next.py_[k])) throw PositionOverflow(1, k, spec::Field::py);
  }
  return next;
}

}  // namespace circles::impl
