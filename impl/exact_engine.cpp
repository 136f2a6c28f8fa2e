// The exact engine's step; the invariant is stated in exact_engine.hpp, the design in docs/exact-engine.md.
//
// The state: integers X, Y, V_x, V_y by slot (cell order, like the double engine's doubles) and R by circle;
// beside them, by slot, approximations of the centres and radii with one error bound for the step, and a
// list of the pairs that can meet before its horizon ends (impl/pair_list.hpp). A step from it:
//   rebuild   when the list's horizon has ended: the skin (the speed term alone: moves are exact), keys of
//             the boxes inflated by it and by the centres' errors, CellOrder's permutation and one gather,
//             then the broad phase fills the list (parallel);
//   contacts  each listed pair from its first step: the filter on approximations, the integers past it, the
//             order (7) on the integers; each slot's least contact (parallel);
//   advance   V ← V[least] for the slots with a contact (a GMP state first checks that no new position
//             rounds to ±infinity), then X ← X + V in place and the approximations again (parallel).
// The slots keep their order between rebuilds: a step moves no circle in memory.
#include "impl/exact_engine.hpp"

#include "impl/exact_bounds.hpp"
#include "impl/buffers.hpp"
#include "impl/cell_layout_impl.hpp"
#include "impl/detail/exact_int.hpp"

#include <gmp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <span>
#include <tuple>
#include <type_traits>

namespace circles::impl {
namespace {

using exact::Narrow;
using exact::raw;
using exact::NarrowMagnitude;
using exact::Wide;
using exact::Word;

// The approximations' error bounds (centres, radii, the walk) are in impl/exact_bounds.hpp.
// The list's skin (rebuild) is the speed term alone, step_bound(H, vmax, 0, 0) per step (impl/pair_list.hpp):
// X ← X + V is exact, so a circle moves by |v|/60 exactly. vmax = max norm_upper(v′) over the velocities'
// approximations v′ (speed_bound), each coordinate within 2^-50·|v′_i| + 2^-1075 of v, so
// |v| ≤ vmax·(1 + 2^-50)² + 2^-1073: kSpeedBound's margin (1/60)·2^-45 covers the relative part with the
// five roundings that follow (step_bound's two, skin_for's, the sum with the padding, none in speed_bound):
// (1 + 2^-50)²·(1 + 2^-53)^5 < 1 + 2^-48; kDriftAbsolute = 2^-1073 covers the absolute part over 60. The
// radii are padded by exact::kCentreSpread·e for the approximations' errors. That padding is slack wherever
// the centres are doubles (2.5·2^-49 of a circle's largest coordinate; a pair whose gap is 2H·s has
// |a|∞ + |b|∞ ≥ 2H·s/√2, so at least 2^-48.2 of that gap), so no world shows kSpeedBound's edge here: a
// speed term short of 1/60 by 2^-47.8 lists the same pairs in every world tried. The tests put the skin and
// the padding together at their edge instead (two points, one at the origin, are dropped by a speed term
// short by 2^-47.6): tests/exact_engine_test.cpp, "Pairs kept across steps".
constexpr auto kForever = std::numeric_limits<std::uint64_t>::max();

template <class Int>
constexpr bool kFixed = !std::is_same_v<Int, Wide>;

Wide widen(NarrowMagnitude m) {
  Wide w(static_cast<std::uint64_t>(m >> 64));
  w <<= 64;
  w += Wide(static_cast<std::uint64_t>(m));
  return w;
}
NarrowMagnitude magnitude(Narrow x) noexcept {
  return x < 0 ? NarrowMagnitude{0} - static_cast<NarrowMagnitude>(x) : static_cast<NarrowMagnitude>(x);
}
Wide widen(Narrow x) {
  const Wide w = widen(magnitude(x));
  return x < 0 ? Wide(-w) : w;
}
// For |z| < 2^127: its two low 64-bit limbs (mpz_getlimbn gives 0 past the size).
Narrow narrow_of(const Wide& z) {
  static_assert(sizeof(mp_limb_t) == 8, "64-bit GMP limbs");
  const NarrowMagnitude m = (NarrowMagnitude{mpz_getlimbn(raw(z), 1)} << 64) | mpz_getlimbn(raw(z), 0);
  return z < 0 ? -static_cast<Narrow>(m) : static_cast<Narrow>(m);
}

// x in another width; the value must fit.
template <class To, class From>
To convert(const From& x) {
  if constexpr (std::is_same_v<To, From>)
    return x;
  else if constexpr (std::is_same_v<To, Wide>)
    return widen(Narrow{x});
  else if constexpr (std::is_same_v<From, Wide>)
    return static_cast<To>(narrow_of(x));
  else
    return static_cast<To>(x);
}

}  // namespace

ExactEngine::ExactEngine(const World& w, EngineOptions options)
    : options_(options), thread_count_(options.threads, kMaxThreads, w.size()), threads_(thread_count_.count()) {
  // A double is m·2^e with m odd (detail::dyadic). With K = max(0, max −e) over every field, L = 2^K, and each
  // scaled field is 60·m·2^(e+K) (positions, radii) or m·2^(e+K) (velocities). When all of them and D fit in
  // kNarrowBits bits, they are built in __int128 directly; otherwise (subnormals, huge values) through GMP.
  const std::size_t n = w.size();
  const std::span<const double> fields[5] = {w.px(), w.py(), w.vx(), w.vy(), w.r()};
  int k = 0, top = std::numeric_limits<int>::min();  // K, and the largest e + bit width of m
  for (const std::span<const double> field : fields)
    for (const double x : field) {
      const detail::Dyadic d = detail::dyadic(x);
      if (d.m == 0) continue;
      k = std::max(k, -d.e);
      top = std::max(top, d.e + static_cast<int>(std::bit_width(static_cast<std::uint64_t>(d.m < 0 ? -d.m : d.m))));
    }
  constexpr int kSixty = 6;  // 60 < 2^6
  if (k + kSixty > exact::kNarrowBits || top + k + kSixty > exact::kNarrowBits) {
    from_rationals(spec::from_doubles(w.circles(), spec::Radii::non_negative));
    return;
  }
  Columns<Narrow> s;
  const auto scale = [k](double x, Narrow factor) {
    const detail::Dyadic d = detail::dyadic(x);
    return d.m == 0 ? Narrow{0} : (Narrow{d.m} * factor) << (d.e + k);  // e + K ≥ 0; fits by the check above
  };
  std::vector<Buffer<Narrow>*> columns{&s.x, &s.y, &s.vx, &s.vy, &s.r};
  for (std::size_t f = 0; f < 5; ++f) {
    columns[f]->resize(n);
    const Narrow factor = f == 2 || f == 3 ? 1 : 60;
    for (std::size_t i = 0; i < n; ++i) (*columns[f])[i] = scale(fields[f][i], factor);
  }
  den_v_ = Wide(1) << k;
  den_ = 60 * den_v_;
  // Radii are doubles: ρ = r exactly.
  start(std::move(s), Buffer<double>(w.r().begin(), w.r().end()), Buffer<double>(n, 0.0));
}

ExactEngine::ExactEngine(const spec::Sequence& circles, EngineOptions options)
    : options_(options), thread_count_(options.threads, kMaxThreads, circles.size()),
      threads_(thread_count_.count()) {
  from_rationals(circles);
}

void ExactEngine::from_rationals(const spec::Sequence& circles) {
  const std::size_t n = circles.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("ExactEngine: " + std::to_string(n) + " circles; at most 2^32 - 1");
  exact::Scaled scaled = exact::scale(circles);
  Buffer<double> radius(n), radius_error(n);
  for (std::size_t k = 0; k < n; ++k) {
    radius[k] = scaled.rounded[k][4];
    radius_error[k] = spec::exact(radius[k]) == circles[k].r ? 0.0 : exact::radius_bound(radius[k]);
  }
  den_v_ = std::move(scaled.den_v);
  den_ = std::move(scaled.den);
  Columns<Wide> s;
  Buffer<Wide>* columns[5] = {&s.x, &s.y, &s.vx, &s.vy, &s.r};
  for (std::size_t f = 0; f < 5; ++f)
    columns[f]->assign(std::make_move_iterator(scaled.columns[f].begin()), std::make_move_iterator(scaled.columns[f].end()));
  start(std::move(s), std::move(radius), std::move(radius_error));
}

template <class Int>
void ExactEngine::start(Columns<Int> s, Buffer<double> radius, Buffer<double> radius_error) {
  // RN(x) = ±infinity exactly when |x| ≥ 2^1024 − 2^970, the midpoint between DBL_MAX = 2^1024 − 2^971 and
  // 2^1024, which ties to the even 2^1024 (DBL_MAX's last bit is 1).
  overflow_at_ = ((Wide(1) << 1024) - (Wide(1) << 970)) * den_;
  radius_ = std::move(radius);
  radius_error_ = std::move(radius_error);
  radii_exact_ = std::all_of(radius_error_.begin(), radius_error_.end(), [](double e) { return e == 0; });
  // The first layout: slot k holds circle k until the first step's rebuild sorts them; every slot its own
  // least contact until a step finds one.
  const std::size_t n = radius_.size();
  layout_ = CellLayout(n);
  approx_.rho = radius_;
  state_ = std::move(s);
  choose_width();
  std::visit([this](auto& columns) { this->settle(columns, 0); }, state_);
}

unsigned ExactEngine::width() const noexcept {
  switch (state_.index()) {
    case 0:
      return 64;
    case 1:
      return 128;
    default:
      return 0;
  }
}

void ExactEngine::choose_width() {
  // Velocities are only copied, so max |V| never grows, and each step moves a coordinate by at most max |V|:
  // from max |X| now, every |X| stays within 2^b for (2^b − max |X|)/max |V| more steps. Radii never change.
  Wide reach = 0, speed = 0, radius = 0;
  std::visit(
      [&](const auto& s) {
        using Int = typename std::decay_t<decltype(s.x)>::value_type;
        if constexpr (kFixed<Int>) {
          NarrowMagnitude x = 0, v = 0, r = 0;
          for (std::size_t t = 0; t < s.x.size(); ++t) {
            x = std::max({x, magnitude(s.x[t]), magnitude(s.y[t])});
            v = std::max({v, magnitude(s.vx[t]), magnitude(s.vy[t])});
            r = std::max(r, magnitude(s.r[t]));
          }
          reach = widen(x);
          speed = widen(v);
          radius = widen(r);
        } else {
          const Wide* x = &reach;
          const Wide* v = &speed;
          const Wide* r = &radius;
          for (std::size_t t = 0; t < s.x.size(); ++t) {
            for (const Wide* y : {&s.x[t], &s.y[t]})
              if (mpz_cmpabs(raw(*y), raw(*x)) > 0) x = y;
            for (const Wide* y : {&s.vx[t], &s.vy[t]})
              if (mpz_cmpabs(raw(*y), raw(*v)) > 0) v = y;
            if (s.r[t] > *r) r = &s.r[t];
          }
          reach = abs(*x);
          speed = abs(*v);
          radius = *r;
        }
      },
      state_);
  const auto ahead = [&](int bits) -> std::uint64_t {
    const Wide limit = Wide(1) << bits;
    if (den_ > limit || radius > limit || speed > limit || reach > limit) return 0;
    if (speed == 0) return kForever - stats_.steps;
    const Wide steps = (limit - reach) / speed;
    return steps >= Wide(kForever - stats_.steps) ? kForever - stats_.steps : steps.convert_to<std::uint64_t>();
  };
  const auto to = [this](auto width) {
    using Int = decltype(width);
    std::visit(
        [this](auto& s) {
          using From = typename std::decay_t<decltype(s.x)>::value_type;
          if constexpr (!std::is_same_v<Int, From>) state_ = converted<Int>(s);
        },
        state_);
  };
  if (const std::uint64_t word = ahead(exact::kWordBits); word > 0) {
    to(Word{});
    proven_until_ = stats_.steps + word;
  } else if (const std::uint64_t narrow = ahead(exact::kNarrowBits); narrow > 0) {
    to(Narrow{});
    proven_until_ = stats_.steps + narrow;
  } else {
    to(Wide{});
    walking_ = false;  // GMP states settle every step (step_with), so no approximation walks any more
    return;
  }
  narrow_den_ = static_cast<NarrowMagnitude>(narrow_of(den_));
  narrow_den_v_ = static_cast<NarrowMagnitude>(narrow_of(den_v_));
  inverse_den_ = exact::round_quotient(Narrow{1}, narrow_den_);
  inverse_den_v_ = exact::round_quotient(Narrow{1}, narrow_den_v_);
}

template <class To, class From>
ExactEngine::Columns<To> ExactEngine::converted(const Columns<From>& s) {
  Columns<To> out;
  const Buffer<From>* from[5] = {&s.x, &s.y, &s.vx, &s.vy, &s.r};
  Buffer<To>* to[5] = {&out.x, &out.y, &out.vx, &out.vy, &out.r};
  for (std::size_t f = 0; f < 5; ++f) {
    to[f]->reserve(from[f]->size());
    for (const From& value : *from[f]) to[f]->push_back(convert<To>(value));
  }
  return out;
}

void ExactEngine::step() {
  threads_ = thread_count_.next();
  if (narrow() && stats_.steps >= proven_until_) {
    std::visit([this](auto& s) { settle(s, pending_); }, state_);  // the proof measures every position
    choose_width();
  }
  std::visit([this](auto& s) { step_with(s); }, state_);
}

template <class Int>
decltype(auto) ExactEngine::now(const Buffer<Int>& x, const Buffer<Int>& v, std::size_t t) const {
  // |X + k·V| is the position of a later world, within the width's proven bound 2^b, and k·|V| ≤ 2^b too
  // (k counts moves since the last proof); the stored X is then within 2^(b+1) (take_velocities), so nothing
  // here leaves the type (b = 61 or 125). A GMP state has no pending moves.
  if constexpr (kFixed<Int>)
    return Int(x[t] + static_cast<Int>(pending_) * v[t]);
  else
    return static_cast<const Int&>(x[t]);
}

template <class Int>
bool ExactEngine::precedes(const Columns<Int>& s, std::size_t a, std::size_t b) const noexcept {
  // (7) on integers scaled by D > 0 or L > 0: the same order as the rationals, then the index. The centre's
  // coordinates are compared by their approximations first (filtered): least_contacts compares slots of
  // intersecting listed pairs only, whose approximations are each within E = error_bound_ of the exact
  // coordinate, so d = RN(a_b − a_a) > 4E gives a_b − a_a ≥ (1 − u)·d > 2E and P_b > P_a (a difference of
  // doubles that is subnormal is exact; RN(4E) = 4E, or +∞, which decides nothing). Only approximations
  // closer than that read the integers, which the pair test did not load.
  const Approximations& near = approx_;
  const double apart = exact::kOrderSpread * error_bound_;
  for (const auto& [approximation, field, velocity] :
       {std::tuple{&near.x, &s.x, &s.vx}, std::tuple{&near.y, &s.y, &s.vy}}) {
    const double d = (*approximation)[b] - (*approximation)[a];
    if (d > apart) return true;
    if (-d > apart) return false;
    const auto& at_a = now(*field, *velocity, a);
    const auto& at_b = now(*field, *velocity, b);
    if (at_a < at_b) return true;
    if (at_b < at_a) return false;
  }
  for (const Buffer<Int>* field : {&s.vx, &s.vy}) {
    if ((*field)[a] < (*field)[b]) return true;
    if ((*field)[b] < (*field)[a]) return false;
  }
  const std::uint32_t i = layout_.id()[a], j = layout_.id()[b];
  if (s.r[i] < s.r[j]) return true;
  if (s.r[j] < s.r[i]) return false;
  return i < j;
}

// The error bound for a largest coordinate m and circle's radius (exact::error_bound).
inline double ExactEngine::error(double m, std::uint32_t circle) const noexcept {
  return exact::error_bound(m, radii_exact_ ? 0.0 : radius_error_[circle]);
}

template <class Int>
inline void ExactEngine::approximate(const Int& x, const Int& y, double& ax, double& ay) const noexcept {
  if constexpr (kFixed<Int>) {
    ax = exact::approximate(x, inverse_den_);
    ay = exact::approximate(y, inverse_den_);
  } else {
    ax = exact::approximate(x, den_);
    ay = exact::approximate(y, den_);
  }
}

template <class Int>
bool ExactEngine::intersect_exactly(const Columns<Int>& s, std::size_t i, std::size_t j) const {
  const std::uint32_t ci = layout_.id()[i], cj = layout_.id()[j];
  return exact::intersect_scaled(Int(s.r[ci] + s.r[cj]), Int(now(s.x, s.vx, j) - now(s.x, s.vx, i)),
                                 Int(now(s.y, s.vy, j) - now(s.y, s.vy, i)));
}

template <class Int>
void ExactEngine::step_with(Columns<Int>& s) {
  layout_.step(
      stats_, threads_, [&] { rebuild(s); },
      [&] {
        const double e = error_bound_;
        return PairTest{[&s, &a = approx_, e, this](std::size_t i, std::size_t k) {
                          const Decision d =
                              exact::intersect_approximate(a.x[i], a.y[i], a.rho[i], e, a.x[k], a.y[k], a.rho[k], e);
                          if (d != Decision::undecided) [[likely]]
                            return d == Decision::intersect;
                          return intersect_exactly(s, i, k);
                        },
                        [&s, this](std::size_t i, std::size_t k) { return precedes(s, i, k); },
                        PrefetchCircles{approx_.x.data(), approx_.y.data(), approx_.rho.data()}};
      },
      [&] { move(s); });
}

template <class Int>
void ExactEngine::move(Columns<Int>& s) {
  take_velocities(s);
  // Where at least a quarter of the slots are in no listed pair (a fixed width), X waits and the listed
  // slots' approximations walk; the rest catch up at the next rebuild. Otherwise every slot moves now: in a
  // dense scene a third of the slots change velocity every step, and each change would cost a waiting X an
  // update of its own (take_velocities). A GMP state moves every slot: its overflow check reads them all.
  if (kFixed<Int> && walking_)
    walk();
  else
    settle(s, 1);
}

template <class Int>
void ExactEngine::take_velocities(Columns<Int>& s) {
  const std::size_t n = layout_.size();
  const std::size_t chunks = chunk_count(n, threads_);
  const CellLayout::Found found = layout_.found(chunks);
  const auto untouch = [&] {
    for (const Buffer<std::uint32_t>& list : found.touched)
      for (const std::uint32_t t : list) found.least[t] = t;
  };
  if constexpr (!kFixed<Int>) {
    // Only a GMP state can reach the double range's end (a fixed-width |X| ≤ 2^125 with D ≥ 60 is below
    // 2^125): every new position X + V[least] is checked before anything changes (least[t] == t for a slot
    // without contact). The lowest circle, px before py, is reported.
    constexpr std::uint64_t kNone = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t first = kNone;  // 2·circle + (0 for px, 1 for py)
    Wide next;
    for (std::size_t t = 0; t < n; ++t) {
      next = s.x[t] + s.vx[found.least[t]];
      if (mpz_cmpabs(raw(next), raw(overflow_at_)) >= 0) first = std::min(first, 2 * std::uint64_t{layout_.id()[t]});
      next = s.y[t] + s.vy[found.least[t]];
      if (mpz_cmpabs(raw(next), raw(overflow_at_)) >= 0) first = std::min(first, 2 * std::uint64_t{layout_.id()[t]} + 1);
    }
    if (first != kNone) {
      untouch();
      throw PositionOverflow(stats_.steps + 1, first / 2, first % 2 ? spec::Field::py : spec::Field::px);
    }
  }
  // Every new velocity first, read from world t (a slot's least contact may be touched too), then written;
  // with it, its move per step (the same double: approximate is a function of V). A contact whose velocity
  // equals the slot's own changes nothing (in a dense scene most of them: circles in contact share one).
  s.moves.resize(chunks);
  Approximations& a = approx_;
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    s.moves[c].clear();
    // The velocities of the slot kPrefetchAhead places on are asked for meanwhile: nothing else in the step
    // reads the velocity columns before this (the pair tests read the approximations), and at 10^6 circles
    // these loads were most of this loop's time (dense, one thread: 38.0 -> 36.2 ns a circle-step, the
    // medians of six alternated runs, five of them faster).
    const Buffer<std::uint32_t>& touched = found.touched[c];
    for (std::size_t i = 0; i < touched.size(); ++i) {
      if (i + PairList::kPrefetchAhead < touched.size()) {
        const std::uint32_t ahead = touched[i + PairList::kPrefetchAhead];
        __builtin_prefetch(&s.vx[ahead]);
        __builtin_prefetch(&s.vy[ahead]);
      }
      const std::uint32_t t = touched[i];
      const std::uint32_t l = found.least[t];
      found.least[t] = t;  // only t reads least[t]
      if (s.vx[l] == s.vx[t] && s.vy[l] == s.vy[t]) continue;
      // A walking list's contacts are between listed slots, whose moves walk() has computed.
      if (kFixed<Int> && walking_)
        s.moves[c].push_back({t, s.vx[l], s.vy[l], a.wx[l], a.wy[l]});
      else
        s.moves[c].push_back({t, s.vx[l], s.vy[l], 0, 0});
    }
  });
  // X + k·V_old, the position now, must stay X′ + k·V_new with the k = pending_ moves X has not taken: X′ is
  // X + k·V_old − k·V_new, within 2^(b+1) for the width's bound 2^b (both terms within 2^b, now()).
  const Int k = static_cast<Int>(kFixed<Int> ? pending_ : 0);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    for (Move<Int>& m : s.moves[c]) {
      const std::uint32_t t = m.slot;
      if (kFixed<Int> && walking_) {
        if (k != 0) {
          s.x[t] = Int(s.x[t] + k * s.vx[t]) - k * m.vx;
          s.y[t] = Int(s.y[t] + k * s.vy[t]) - k * m.vy;
        }
        a.wx[t] = m.wx;
        a.wy[t] = m.wy;
      }
      std::swap(s.vx[t], m.vx);
      std::swap(s.vy[t], m.vy);
    }
  });
}

template <class Int>
void ExactEngine::settle(Columns<Int>& s, std::uint64_t moves) {
  const std::size_t n = layout_.size();
  const std::size_t chunks = chunk_count(n, threads_);
  Approximations& a = approx_;
  for (Buffer<double>* column : {&a.x, &a.y}) column->resize(n);
  // k·|V| ≤ k·max |V| fits the width: its proof covers every step since it was made, and this runs before
  // each proof. For a GMP state moves is 1 (its step) or 0.
  const Int k = static_cast<Int>(moves);
  pending_ = 0;
  std::vector<std::array<double, 2>> largest(chunks);  // per chunk: max(|a_x|, |a_y|), the radius error
  // One loop per kind of k, so that a dense step (k = 1) adds without multiplying 128-bit integers.
  const auto settle_chunk = [&](std::size_t c, auto kind) {
    double reach = 0, radius = 0;
    for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t) {
      if constexpr (kind() == 1) {
        s.x[t] += s.vx[t];
        s.y[t] += s.vy[t];
      } else if constexpr (kind() == 2) {
        s.x[t] += k * s.vx[t];
        s.y[t] += k * s.vy[t];
      }
      approximate(s.x[t], s.y[t], a.x[t], a.y[t]);
      reach = std::max({reach, std::fabs(a.x[t]), std::fabs(a.y[t])});
      if (!radii_exact_) radius = std::max(radius, radius_error_[layout_.id()[t]]);
    }
    largest[c] = {reach, radius};
  };
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    if (moves == 0) settle_chunk(c, std::integral_constant<int, 0>{});
    else if (moves == 1) settle_chunk(c, std::integral_constant<int, 1>{});
    else settle_chunk(c, std::integral_constant<int, 2>{});
  });
  // error(m, ·) is RN of sums and products of non-negative terms, monotone in m and in the radius error, so
  // that of the largest of each is at least every slot's.
  double reach = 0, radius = 0;
  for (const auto& [m, r] : largest) {
    reach = std::max(reach, m);
    radius = std::max(radius, r);
  }
  error_bound_ = exact::error_bound(reach, radii_exact_ ? 0.0 : radius);
}

void ExactEngine::walk() {
  const std::size_t n = layout_.size();
  const std::size_t chunks = chunk_count(n, threads_);
  Approximations& a = approx_;
  ++pending_;
  std::vector<double> largest(chunks);  // per chunk: max(|a_x|, |a_y|) after the walk
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    double* const x = a.x.data();
    double* const y = a.y.data();
    const double* const wx = a.wx.data();
    const double* const wy = a.wy.data();
    const std::size_t b = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1);
    const auto first = std::lower_bound(listed_.begin(), listed_.end(), b);
    const auto last = std::lower_bound(first, listed_.end(), e);
    // The new values from registers, not read back through x and y (which the stores may alias), and a
    // largest |coordinate| per axis: two chains of one max a slot, where one chain of two made the loop wait.
    double reach_x = 0, reach_y = 0;
    for (auto t = first; t != last; ++t) {
      const std::uint32_t s = *t;
      const double nx = x[s] + wx[s], ny = y[s] + wy[s];
      x[s] = nx;
      y[s] = ny;
      reach_x = std::max(reach_x, std::fabs(nx));
      reach_y = std::max(reach_y, std::fabs(ny));
    }
    largest[c] = std::max(reach_x, reach_y);
  });
  error_bound_ = exact::walked(error_bound_, largest_move_, *std::max_element(largest.begin(), largest.end()));
}

template <class Int>
double ExactEngine::speed_bound(const Columns<Int>& s) const {
  // For approximations v′ within 2^-50·|v′_i| + 2^-1075 of v per coordinate (exact::approximate),
  // |v| ≤ |v′|·(1 + 2^-50) + √2·2^-1075 ≤ norm_upper(v′)·(1 + 2^-50)² + 2^-1073: kSpeedBound's margin and
  // kDriftAbsolute cover both terms (the skin's derivation at the top of this file).
  const std::size_t n = layout_.size();
  const std::size_t chunks = chunk_count(n, threads_);
  std::vector<double> largest(chunks, 0.0);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    double vmax = 0;
    for (std::size_t t = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1); t < e; ++t) {
      if constexpr (kFixed<Int>)
        vmax = std::max(vmax, norm_upper(exact::approximate(s.vx[t], inverse_den_v_),
                                         exact::approximate(s.vy[t], inverse_den_v_)));
      else
        vmax = std::max(vmax, norm_upper(exact::approximate(s.vx[t], den_v_), exact::approximate(s.vy[t], den_v_)));
    }
    largest[c] = vmax;
  });
  return *std::max_element(largest.begin(), largest.end());
}

template <class Int>
void ExactEngine::rebuild(Columns<Int>& s) {
  // A list for world t and the horizon H (docs/exact-engine.md, "Pairs kept across steps"): the skin from
  // vmax alone (moves are exact), boxes of the radii inflated by it and by the centres' errors, keys, the
  // slots in their cell order, and the broad phase over the inflated radii, each pair it offers listed from
  // its first step.
  // The pending moves, and every slot's approximations from the integers (error() bounds each of them).
  if (pending_ > 0) settle(s, pending_);
  const std::size_t n = layout_.size();
  Approximations& a = approx_;
  // Velocities are only copied: the first world's bound holds for every later one.
  if (!(vmax_ >= 0)) vmax_ = speed_bound(s);
  const double vmax = vmax_;
  std::uint64_t horizon = layout_.horizon(options_, stats_.steps);
  double step = step_bound(horizon, vmax, 0, 0);
  double skin = skin_for(horizon, vmax, 0, 0);
  if (!(skin < kInfinity)) {
    // Motion too fast to bound in doubles: a list for this world alone.
    horizon = 0;
    step = 0;
    skin = 0;
    layout_.collapse();
  }
  // ρ + kCentreSpread·e ≥ ρ + (1 + √2)·e ≥ r + |c − p|: the circle's disc around its approximate centre
  // holds the exact one; with the skin added, it holds every position of the horizon.
  const auto padding = [&](std::size_t t) {
    return error(std::max(std::fabs(a.x[t]), std::fabs(a.y[t])), layout_.id()[t]) * exact::kCentreSpread;
  };
  inflated_.resize(n);
  for (std::size_t t = 0; t < n; ++t) inflated_[t] = outward_upper(a.rho[t], padding(t) + skin);
  // The slots in cell order, every slot column gathered with them (the radii's integers stay by circle).
  layout_.arrange(threads_, horizon, a.x, a.y, inflated_, impl::Columns<Int>{s.spare, {&s.x, &s.y, &s.vx, &s.vy}},
                  impl::Columns<double>{scratch_, {&a.x, &a.y, &a.rho, &inflated_}});
  padded_.resize(n);
  for (std::size_t t = 0; t < n; ++t) padded_[t] = outward_upper(a.rho[t], padding(t));
  // A pair disjoint at the inflated radii cannot meet within the horizon; one that intersects at the padded
  // radii may meet now; the rest from their gap (first_step), the padded radii bounding the exact gap below.
  const double *px = a.x.data(), *py = a.y.data(), *r = padded_.data(), *ri = inflated_.data();
  layout_.list(stats_, options_, threads_, horizon, a.x, a.y, inflated_, Lister{px, py, r, ri, step, horizon});
  const PairList& pairs = layout_.pairs();
  // The listed slots ascending, written without a branch: each slot at the next place, which only a listed
  // one claims (a branch per slot mispredicts where listed and lonely slots mix, as in a sparse scene). The
  // place past the last is room for the writes that follow it.
  const std::size_t listed = n - pairs.lonely();
  listed_.resize(listed + 1);
  for (std::size_t t = 0, k = 0; t < n; ++t) {
    listed_[k] = static_cast<std::uint32_t>(t);
    k += pairs.listed(t);
  }
  listed_.resize(listed);
  // A walking list: the moves per step of its listed slots, V·RN(1/D), each within 2^-50·|w| + 2^-1075 of
  // v/60 (exact::approximate), and W, the largest of them; contacts copy them, so W holds for the list.
  walking_ = kFixed<Int> && pairs.lonely() * 4 >= n;
  if constexpr (kFixed<Int>) {
    if (walking_) {
      a.wx.resize(n);
      a.wy.resize(n);
      double move = 0;
      for (const std::uint32_t t : listed_) {
        approximate(s.vx[t], s.vy[t], a.wx[t], a.wy[t]);
        move = std::max({move, std::fabs(a.wx[t]), std::fabs(a.wy[t])});
      }
      largest_move_ = move;
    }
  }
}

std::vector<CandidatePair> ExactEngine::candidates() const {
  if (!layout_.due(stats_.steps)) return layout_.listed();
  ExactEngine copy = *this;
  std::visit([&copy](auto& s) { copy.rebuild(s); }, copy.state_);
  return copy.layout_.listed();
}

World ExactEngine::world() const {
  spec::Circles out(size());
  std::visit(
      [&](const auto& s) {
        using Int = typename std::decay_t<decltype(s.x)>::value_type;
        const auto round = [this](const Int& x, bool velocity) {
          if constexpr (kFixed<Int>)
            return exact::round_quotient(Narrow{x}, velocity ? narrow_den_v_ : narrow_den_);
          else
            return exact::round_quotient(x, velocity ? den_v_ : den_);
        };
        for (std::size_t t = 0; t < out.size(); ++t) {
          const std::uint32_t k = layout_.id()[t];
          out[k] = {round(now(s.x, s.vx, t), false), round(now(s.y, s.vy, t), false), round(s.vx[t], true),
                    round(s.vy[t], true), round(s.r[k], false)};
        }
      },
      state_);
  return World(out);
}

spec::Sequence ExactEngine::exact() const {
  spec::Sequence out(size());
  std::visit(
      [&](const auto& s) {
        const spec::Q d(den_), l(den_v_);
        for (std::size_t t = 0; t < out.size(); ++t) {
          const std::uint32_t k = layout_.id()[t];
          out[k] = spec::circle(spec::Q(convert<Wide>(now(s.x, s.vx, t))) / d,
                                spec::Q(convert<Wide>(now(s.y, s.vy, t))) / d,
                                spec::Q(convert<Wide>(s.vx[t])) / l, spec::Q(convert<Wide>(s.vy[t])) / l,
                                spec::Q(convert<Wide>(s.r[k])) / d);
        }
      },
      state_);
  return out;
}

bool ExactEngine::approximations_hold() const {
  return std::visit(
      [&](const auto& s) {
        const spec::Q d(den_), e = spec::exact(error_bound_);
        const auto within = [&](double approximation, const spec::Q& exact) {
          return abs(spec::exact(approximation) - exact) <= e;
        };
        const auto holds = [&](std::size_t t) {
          const std::uint32_t k = layout_.id()[t];
          return within(approx_.x[t], spec::Q(convert<Wide>(now(s.x, s.vx, t))) / d) &&
                 within(approx_.y[t], spec::Q(convert<Wide>(now(s.y, s.vy, t))) / d) &&
                 within(approx_.rho[t], spec::Q(convert<Wide>(s.r[k])) / d);
        };
        if (walking_) return std::all_of(listed_.begin(), listed_.end(), holds);
        for (std::size_t t = 0; t < size(); ++t)
          if (!holds(t)) return false;
        return true;
      },
      state_);
}

std::vector<std::array<std::string, 5>> ExactEngine::rationals() const {
  std::vector<std::array<std::string, 5>> out;
  for (const spec::Circle& c : exact())
    out.push_back({spec::to_string(c.p.x()), spec::to_string(c.p.y()), spec::to_string(c.v.x()),
                   spec::to_string(c.v.y()), spec::to_string(c.r)});
  return out;
}

}  // namespace circles::impl
