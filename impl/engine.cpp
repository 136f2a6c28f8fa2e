// The double engines' step; the invariant is stated in engine.hpp, the design in docs/engine.md.
//
// A step from world t (circles in cell order, keys sorted):
//   find_contacts  each slot's least contact, by the grid's neighbourhoods (parallel over chunks of slots);
//   advance        v ← v[least], p ← update(p, v), keys of the new positions (parallel); throws on overflow
//                  before anything of world t changed;
//   commit         the new world in cell order: CellOrder's permutation, then one gather (parallel).
// A step proven quiet (quiet_for) is advance alone, with every circle its own contact and no keys.
#include "impl/engine.hpp"

#include "impl/contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <thread>
#include <type_traits>

namespace circles::impl {
namespace {

// advance works in blocks that stay in L1 (5 arrays of 256 doubles = 10 KiB).
constexpr std::size_t kBlock = 256;

// The quiet-step proof (docs/engine.md, "Quiet steps"). Horizons start at kFirstHorizon steps and double
// after each success up to kMaxHorizon; after a failure the next attempt waits a gap that doubles up to
// kMaxRetryGap, so a busy world pays for an attempt rarely.
constexpr std::uint64_t kFirstHorizon = 16;
constexpr std::uint64_t kMaxHorizon = std::uint64_t{1} << 16;
constexpr std::uint64_t kMaxRetryGap = 1024;
// Bounds on one step's move per coordinate with a constant velocity v (docs/engine.md, "Quiet steps"):
// |RN(p + v/60) − p| ≤ |v|/60 + ulp(p')/2 ≤ |v|·kSpeedBound + |p'|·kDriftBound + kDriftAbsolute, where
// kSpeedBound = 0.017 > 1/60 = 0.01666… (a 2% margin covers every rounding of the bound's own arithmetic),
// kDriftBound = 2^-50 > 2^-53 (half an ulp, relative) and kDriftAbsolute = 2^-1072 > 2^-1075 (half the
// subnormal ulp).
constexpr double kSpeedBound = 0.017;
constexpr double kDriftBound = 0x1p-50;
constexpr double kDriftAbsolute = 0x1p-1072;

template <class T>
void gather(std::vector<T>& to, const std::vector<T>& from, std::span<const std::uint32_t> permutation,
            std::size_t begin, std::size_t end) {
  for (std::size_t t = begin; t < end; ++t) to[t] = from[permutation[t]];
}

}  // namespace

// ── World ─────────────────────────────────────────────────────────────────────────────────────────────

World::World(const std::vector<std::array<double, 5>>& circles) {
  const std::size_t n = circles.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("World: " + std::to_string(n) + " circles; at most 2^32 - 1");
  for (std::size_t k = 0; k < n; ++k) spec::check_doubles(circles[k], k, spec::Radii::non_negative);
  px_.resize(n);
  py_.resize(n);
  vx_.resize(n);
  vy_.resize(n);
  r_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    px_[k] = circles[k][0];
    py_[k] = circles[k][1];
    vx_[k] = circles[k][2];
    vy_[k] = circles[k][3];
    r_[k] = circles[k][4];
  }
}

std::vector<std::array<double, 5>> World::circles() const {
  std::vector<std::array<double, 5>> out(size());
  for (std::size_t k = 0; k < size(); ++k) out[k] = {px_[k], py_[k], vx_[k], vy_[k], r_[k]};
  return out;
}

bool World::precedes(std::size_t a, std::size_t b) const noexcept {
  // Each key is decided by exact comparisons of doubles; equal values (−0 and +0 included) pass to the next.
  for (const std::vector<double>* key : {&px_, &py_, &vx_, &vy_, &r_}) {
    const double x = (*key)[a];
    const double y = (*key)[b];
    if (x < y) return true;
    if (y < x) return false;
  }
  return a < b;
}

PositionOverflow::PositionOverflow(std::uint64_t s, std::size_t i, const char* f)
    : std::overflow_error("step " + std::to_string(s) + ", circle " + std::to_string(i) + ", field " + f +
                          ": the position p + v/60 overflows to infinity"),
      step(s),
      index(i),
      field(f) {}

// ── The engine ────────────────────────────────────────────────────────────────────────────────────────

template <class A>
BasicEngine<A>::BasicEngine(World w, EngineOptions options)
    : options_(options), threads_(resolve_threads(options.threads, kMaxThreads)) {
  now_.px = std::move(w.px_);
  now_.py = std::move(w.py_);
  now_.vx = std::move(w.vx_);
  now_.vy = std::move(w.vy_);
  now_.r = std::move(w.r_);
  now_.id.resize(now_.px.size());
  std::iota(now_.id.begin(), now_.id.end(), std::uint32_t{0});
  grid_.plan(now_.px, now_.py, now_.r);
  relayout();
}

template <class A>
World BasicEngine<A>::world() const {
  World w;
  const std::size_t n = now_.px.size();
  for (std::vector<double>* field : {&w.px_, &w.py_, &w.vx_, &w.vy_, &w.r_}) field->resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const std::uint32_t k = now_.id[t];
    w.px_[k] = now_.px[t];
    w.py_[k] = now_.py[t];
    w.vx_[k] = now_.vx[t];
    w.vy_[k] = now_.vy[t];
    w.r_[k] = now_.r[t];
  }
  return w;
}

template <class A>
bool BasicEngine<A>::precedes(std::size_t a, std::size_t b) const noexcept {
  // World::precedes on slots: the same keys, then the circles' indices.
  for (const std::vector<double>* key : {&now_.px, &now_.py, &now_.vx, &now_.vy, &now_.r}) {
    const double x = (*key)[a];
    const double y = (*key)[b];
    if (x < y) return true;
    if (y < x) return false;
  }
  return now_.id[a] < now_.id[b];
}

template <class A>
void BasicEngine<A>::step() {
  if (quiet_left_ > 0) {
    // A proven quiet step: no circle touches another, so every circle keeps its velocity (h gives v).
    advance(false);
    commit();
    --quiet_left_;
    ++quiet_steps_;
    ++steps_;
    return;
  }
  if (keys_stale_) relayout();
  find_contacts();
  advance(true);
  commit();
  ++steps_;
  // The quiet-step proof is exact, so only the exact arithmetic may skip steps: the naive test can see a
  // contact the exact one rules out, and the naive engine must not depend on its options either.
  if constexpr (std::is_same_v<A, ExactArithmetic>) {
    if (options_.skip_quiet_steps && contacts_ == 0 && steps_ >= retry_at_) {
      if (horizon_ == 0) horizon_ = kFirstHorizon;
      if (quiet_for(horizon_)) {
        quiet_left_ = horizon_ + 1;
        horizon_ = std::min(2 * horizon_, kMaxHorizon);
      } else {
        const std::uint64_t gap = std::min(kMaxRetryGap, std::max<std::uint64_t>(1, horizon_ / kFirstHorizon));
        retry_at_ = steps_ + gap;
        horizon_ = std::max(kFirstHorizon, horizon_ / 4);
      }
    }
  }
}

template <class A>
void BasicEngine<A>::find_contacts() {
  const CellView view{now_.key, now_.px, now_.py, now_.r, now_.levels, now_.level_begin};
  contacts_ = find_least_contacts(
      grid_, view, threads_, least_, offers_,
      [this](std::size_t a, std::size_t b) {
        return A::intersect(now_.px[a], now_.py[a], now_.r[a], now_.px[b], now_.py[b], now_.r[b]);
      },
      [this](std::size_t a, std::size_t b) { return precedes(a, b); });
}

template <class A>
void BasicEngine<A>::advance(bool with_contacts) {
  const std::size_t n = now_.px.size();
  for (std::vector<double>* v : {&next_px_, &next_py_, &next_vx_, &next_vy_}) v->resize(n);
  next_key_.resize(n);
  const std::size_t chunks = chunk_count(n, threads_);
  // Per chunk: the first fault as 2·index + (0 for px, 1 for py), and the new positions' extent.
  constexpr std::uint64_t kNoFault = std::numeric_limits<std::uint64_t>::max();
  std::vector<std::uint64_t> fault(chunks, kNoFault);
  std::vector<std::array<double, 4>> extent(chunks);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    double xlo = inf, xhi = -inf, ylo = inf, yhi = -inf;
    for (std::size_t b = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); b < end; b += kBlock) {
      const std::size_t e = std::min(end, b + kBlock);
      for (std::size_t t = b; t < e; ++t) {
        const std::size_t s = with_contacts ? least_[t] : t;
        next_vx_[t] = now_.vx[s];
        next_vy_[t] = now_.vy[s];
        next_px_[t] = now_.px[t];
        next_py_[t] = now_.py[t];
      }
      A::advance(std::span<double>(next_px_.data() + b, e - b), std::span<const double>(next_vx_.data() + b, e - b));
      A::advance(std::span<double>(next_py_.data() + b, e - b), std::span<const double>(next_vy_.data() + b, e - b));
      for (std::size_t t = b; t < e; ++t) {
        const double x = next_px_[t], y = next_py_[t];
        // Inputs are finite, so the update gives ±inf only on an overflow, never NaN.
        if (!std::isfinite(x) || !std::isfinite(y)) [[unlikely]]
          fault[c] = std::min(fault[c], 2 * std::uint64_t{now_.id[t]} + (std::isfinite(x) ? 1 : 0));
        xlo = std::min(xlo, x);
        xhi = std::max(xhi, x);
        ylo = std::min(ylo, y);
        yhi = std::max(yhi, y);
      }
      if (with_contacts)
        grid_.keys(std::span<const double>(next_px_.data() + b, e - b), std::span<const double>(next_py_.data() + b, e - b),
                   std::span<const double>(now_.r.data() + b, e - b), std::span<CellKey>(next_key_.data() + b, e - b));
    }
    extent[c] = {xlo, xhi, ylo, yhi};
  });
  const std::uint64_t first = *std::min_element(fault.begin(), fault.end());
  if (first != kNoFault) throw PositionOverflow(steps_ + 1, first / 2, first % 2 ? "py" : "px");
  if (!with_contacts) {
    keys_stale_ = true;
    return;
  }
  // Circles drifted out of the planned grid (their cells clamp, which is correct but slow): plan again.
  bool inside = true;
  for (const auto& [xlo, xhi, ylo, yhi] : extent)
    inside = inside && (xlo > xhi || grid_.covers(xlo, xhi, ylo, yhi));
  if (!inside) {
    grid_.plan(next_px_, next_py_, now_.r);
    for_each_chunk(chunks, threads_, [&](std::size_t c) {
      for (std::size_t t = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); t < end; ++t)
        next_key_[t] = grid_.key(next_px_[t], next_py_[t], now_.r[t]);
    });
  }
}

template <class A>
void BasicEngine<A>::commit() {
  // Nothing of now_ changed before here, so a PositionOverflow from advance left it as it was.
  std::swap(now_.px, next_px_);
  std::swap(now_.py, next_py_);
  std::swap(now_.vx, next_vx_);
  std::swap(now_.vy, next_vy_);
  if (keys_stale_) return;
  const bool sorted = order_.sort(next_key_, now_.key, permutation_);
  std::swap(now_.key, next_key_);
  if (!sorted) {
    // One gather of every field into cell order, through the spare arrays.
    const std::size_t n = now_.px.size();
    scratch_r_.resize(n);
    scratch_id_.resize(n);
    next_px_.resize(n);
    next_py_.resize(n);
    next_vx_.resize(n);
    next_vy_.resize(n);
    next_key_.resize(n);
    const std::size_t chunks = chunk_count(n, threads_);
    for_each_chunk(chunks, threads_, [&](std::size_t c) {
      const std::size_t b = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1);
      gather(next_px_, now_.px, permutation_, b, e);
      gather(next_py_, now_.py, permutation_, b, e);
      gather(next_vx_, now_.vx, permutation_, b, e);
      gather(next_vy_, now_.vy, permutation_, b, e);
      gather(scratch_r_, now_.r, permutation_, b, e);
      gather(scratch_id_, now_.id, permutation_, b, e);
      gather(next_key_, now_.key, permutation_, b, e);
    });
    std::swap(now_.px, next_px_);
    std::swap(now_.py, next_py_);
    std::swap(now_.vx, next_vx_);
    std::swap(now_.vy, next_vy_);
    std::swap(now_.r, scratch_r_);
    std::swap(now_.id, scratch_id_);
    std::swap(now_.key, next_key_);
  }
  index_levels(now_.key, now_.level_begin, now_.levels);
}

template <class A>
void BasicEngine<A>::relayout() {
  // The keys of the current positions, then commit's sort and gather: positions stay, only the order moves.
  const std::size_t n = now_.px.size();
  next_key_.resize(n);
  for (std::size_t t = 0; t < n; ++t) next_key_[t] = grid_.key(now_.px[t], now_.py[t], now_.r[t]);
  next_px_ = now_.px;
  next_py_ = now_.py;
  next_vx_ = now_.vx;
  next_vy_ = now_.vy;
  keys_stale_ = false;
  if (now_.key.size() != n) now_.key.clear();  // the first layout: no previous order to guide the sort
  commit();
}

template <class A>
bool BasicEngine<A>::quiet_for(std::uint64_t horizon) {
  // Proves that no pair intersects in this world or in the next `horizon` worlds, given that velocities stay
  // constant while nothing touches (docs/engine.md, "Quiet steps"): every circle moves at most δ in each of x
  // and y over those steps, so a pair that meets by then is within r_a + r_b + 2δ·√2 ≤ r'_a + r'_b now, with
  // r' ≥ r + 2δ (√2 < 2). No pair intersects exactly at the radii r' ⇒ quiet.
  const std::size_t n = now_.px.size();
  double speed = 0, reach = 0;
  for (std::size_t t = 0; t < n; ++t) {
    speed = std::max({speed, std::fabs(now_.vx[t]), std::fabs(now_.vy[t])});
    reach = std::max({reach, std::fabs(now_.px[t]), std::fabs(now_.py[t])});
  }
  const auto steps = static_cast<double>(horizon);
  // |p| over the horizon is at most reach + steps·speed·kSpeedBound, up to the drift, which is a 2^-50
  // fraction per step: kDriftBound's eightfold margin over half an ulp covers it for horizons below 2^40.
  const double far = reach + steps * speed * kSpeedBound;
  const double delta = steps * (speed * kSpeedBound + far * kDriftBound + kDriftAbsolute);
  if (!std::isfinite(delta)) return false;
  std::vector<double> inflated(n);
  for (std::size_t t = 0; t < n; ++t) inflated[t] = outward_upper(now_.r[t], 2 * delta);
  // The same broad phase over the inflated radii, in a layout of its own.
  CellGrid grid;
  grid.plan(now_.px, now_.py, inflated);
  std::vector<CellKey> key(n);
  for (std::size_t t = 0; t < n; ++t) key[t] = grid.key(now_.px[t], now_.py[t], inflated[t]);
  std::vector<std::uint32_t> order;
  CellOrder{}.sort(key, {}, order);
  std::vector<CellKey> sorted_key(n);
  std::vector<double> px(n), py(n), r(n);
  for (std::size_t t = 0; t < n; ++t) {
    sorted_key[t] = key[order[t]];
    px[t] = now_.px[order[t]];
    py[t] = now_.py[order[t]];
    r[t] = inflated[order[t]];
  }
  std::array<std::size_t, CellGrid::kLevels + 1> level_begin{};
  std::vector<unsigned> levels;
  index_levels(sorted_key, level_begin, levels);
  const CellView view{sorted_key, px, py, r, levels, level_begin};
  NeighbourCursor cursor;
  bool meets = false;
  for (std::size_t a = 0; a < n && !meets; ++a)
    visit_neighbourhood(grid, view, a, cursor, [&](std::size_t b) {
      meets = meets || intersect_exact(px[a], py[a], r[a], px[b], py[b], r[b]);
    });
  for (std::size_t g = level_begin[CellGrid::kGlobalLevel]; g < n && !meets; ++g)
    for (std::size_t b = 0; b < n && !meets; ++b)
      meets = b != g && intersect_exact(px[g], py[g], r[g], px[b], py[b], r[b]);
  return !meets;
}

template <class A>
std::vector<CandidatePair> BasicEngine<A>::candidates() const {
  if (keys_stale_) {
    BasicEngine copy = *this;
    copy.relayout();
    return copy.candidates();
  }
  const std::size_t n = now_.px.size();
  std::vector<CandidatePair> out;
  const auto add = [&](std::size_t a, std::size_t b) {
    const std::uint32_t i = now_.id[a], j = now_.id[b];
    out.push_back(i < j ? CandidatePair{i, j} : CandidatePair{j, i});
  };
  const CellView view{now_.key, now_.px, now_.py, now_.r, now_.levels, now_.level_begin};
  NeighbourCursor cursor;
  for (std::size_t a = 0; a < n; ++a) visit_neighbourhood(grid_, view, a, cursor, [&](std::size_t b) { add(a, b); });
  for (std::size_t g = now_.level_begin[CellGrid::kGlobalLevel]; g < n; ++g)
    for (std::size_t b = 0; b < n; ++b)
      if (b != g) add(g, b);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

template class BasicEngine<ExactArithmetic>;
template class BasicEngine<NaiveArithmetic>;
template class BasicEngine<NaiveSqrtArithmetic>;
template class BasicEngine<FloatNaiveArithmetic>;
template class BasicEngine<ExactDecisionArithmetic>;

// ── The all-pairs reference ───────────────────────────────────────────────────────────────────────────

World step_all_pairs(const World& w) {
  const std::size_t n = w.size();
  std::vector<std::size_t> least(n);
  std::iota(least.begin(), least.end(), std::size_t{0});
  const auto offer = [&](std::size_t a, std::size_t b) {
    if (least[a] == a || w.precedes(b, least[a])) least[a] = b;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (intersect_exact(w.px_[a], w.py_[a], w.r_[a], w.px_[b], w.py_[b], w.r_[b])) {
        offer(a, b);
        offer(b, a);
      }
  World next = w;
  for (std::size_t k = 0; k < n; ++k) {
    next.vx_[k] = w.vx_[least[k]];
    next.vy_[k] = w.vy_[least[k]];
    next.px_[k] = advance_rounded(w.px_[k], next.vx_[k]);
    next.py_[k] = advance_rounded(w.py_[k], next.vy_[k]);
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(next.px_[k])) throw PositionOverflow(1, k, "px");
    if (!std::isfinite(next.py_[k])) throw PositionOverflow(1, k, "py");
  }
  return next;
}

}  // namespace circles::impl
