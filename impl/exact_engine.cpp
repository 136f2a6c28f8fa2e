// The exact engine's step; the invariant is stated in exact_engine.hpp, the design in docs/exact-engine.md.
//
// The state: integers X, Y, V_x, V_y by slot (cell order, like the double engine's doubles) and R by circle;
// beside them, by slot, the broad phase's approximations (centre, radius, box half-width) and keys, and one
// error bound for every approximation of the step. A step from it:
//   contacts  impl/contacts.hpp over the boxes, with the filter on approximations and the exact integer test
//             past it, and the order (7) on the integers;
//   locate    X ← X + V[least] (a GMP state first takes its new velocities and checks that no position rounds
//             to ±infinity), then the approximations and keys, block by block;
//   commit    CellOrder's permutation, then one pass that gathers every slot field (velocities from the least
//             contacts) and computes the approximations in the new order.
#include "impl/exact_engine.hpp"

#include "impl/contacts.hpp"
#include "impl/detail/exact_int.hpp"

#include <gmp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>
#include <type_traits>

namespace circles::impl {
namespace {

using exact::Narrow;
using exact::NarrowMagnitude;
using exact::Wide;
using exact::Word;

// The boxes (locate): the approximate centre is within 2^-50·|a| + 2^-1075 of the exact one per coordinate
// (exact::approximate), so c = RN(RN(max(|ax|, |ay|)·2^-49) + 2^-1073) is at least twice that error (the
// factor of two covers c's own two roundings, and those of adding a radius error below).
constexpr double kBoxRelative = 0x1p-49;
constexpr double kBoxAbsolute = 0x1p-1073;
// A radius that is no double: ρ = RN(r) is within u·ρ + η of it (u = 2^-53, η = 2^-1075); the bound kept is
// RN(2^-52·ρ + 2^-1074), twice that, so that RN(c + it) still bounds the sum of both errors.
constexpr double kRadiusRelative = 0x1p-52;
constexpr double kRadiusAbsolute = 0x1p-1074;
// locate works in blocks that stay in L1, as the double engine's advance does.
constexpr std::size_t kBlock = 256;
constexpr auto kForever = std::numeric_limits<std::uint64_t>::max();

template <class Int>
constexpr bool kFixed = !std::is_same_v<Int, Wide>;

mpz_srcptr raw(const Wide& z) noexcept { return z.backend().data(); }
mpz_ptr raw(Wide& z) noexcept { return z.backend().data(); }

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

// The integer q·scale, for a rational q whose denominator divides scale.
Wide scaled(const spec::Q& q, const Wide& scale) {
  const spec::Q product = q * spec::Q(scale);
  return boost::multiprecision::numerator(product);
}

// to[t] = from[permutation[t]] for the slots of one chunk. GMP integers are swapped rather than copied (no
// allocation); `from` is then scratch.
template <class T>
void gather(std::vector<T>& to, std::vector<T>& from, const std::vector<std::uint32_t>& permutation, std::size_t begin,
            std::size_t end) {
  for (std::size_t t = begin; t < end; ++t) {
    if constexpr (std::is_same_v<T, Wide>)
      to[t].swap(from[permutation[t]]);
    else
      to[t] = from[permutation[t]];
  }
}

spec::Sequence sequence_of(const World& w) {
  spec::Sequence out;
  const auto circles = w.circles();
  out.reserve(circles.size());
  for (std::size_t k = 0; k < circles.size(); ++k) out.push_back(spec::from_doubles(circles[k], k, spec::Radii::non_negative));
  return out;
}

}  // namespace

ExactEngine::ExactEngine(const World& w, EngineOptions options)
    : options_(options), threads_(resolve_threads(options.threads, kMaxThreads)) {
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
    from_rationals(sequence_of(w));
    return;
  }
  Columns<Narrow> s;
  const auto scale = [k](double x, Narrow factor) {
    const detail::Dyadic d = detail::dyadic(x);
    return d.m == 0 ? Narrow{0} : (Narrow{d.m} * factor) << (d.e + k);  // e + K ≥ 0; fits by the check above
  };
  std::vector<std::vector<Narrow>*> columns{&s.x, &s.y, &s.vx, &s.vy, &s.r};
  for (std::size_t f = 0; f < 5; ++f) {
    columns[f]->resize(n);
    const Narrow factor = f == 2 || f == 3 ? 1 : 60;
    for (std::size_t i = 0; i < n; ++i) (*columns[f])[i] = scale(fields[f][i], factor);
  }
  den_v_ = Wide(1) << k;
  den_ = 60 * den_v_;
  // Radii are doubles: ρ = r exactly.
  start(std::move(s), std::vector<double>(w.r().begin(), w.r().end()), std::vector<double>(n, 0.0));
}

ExactEngine::ExactEngine(const spec::Sequence& circles, EngineOptions options)
    : options_(options), threads_(resolve_threads(options.threads, kMaxThreads)) {
  from_rationals(circles);
}

void ExactEngine::from_rationals(const spec::Sequence& circles) {
  const std::size_t n = circles.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("ExactEngine: " + std::to_string(n) + " circles; at most 2^32 - 1");
  // L: the least common multiple of every field's denominator (2^K for doubles).
  Wide l = 1;
  std::vector<double> radius(n), radius_error(n);
  for (std::size_t k = 0; k < n; ++k) {
    const spec::Circle& c = circles[k];
    spec::check_radius(c, k, spec::Radii::non_negative);
    const std::array<double, 5> rounded = spec::nearest_doubles(c);
    const spec::Q* fields[5] = {&c.p.x(), &c.p.y(), &c.v.x(), &c.v.y(), &c.r};
    for (std::size_t f = 0; f < 5; ++f) {
      if (!std::isfinite(rounded[f]))
        throw spec::OutsideC(k, static_cast<spec::Field>(f),
                             "value " + spec::to_string(*fields[f]) + " is beyond the double range");
      mpz_lcm(raw(l), raw(l), raw(boost::multiprecision::denominator(*fields[f])));
    }
    radius[k] = rounded[4];
    radius_error[k] = spec::exact(rounded[4]) == c.r ? 0.0 : radius[k] * kRadiusRelative + kRadiusAbsolute;
  }
  den_v_ = l;
  den_ = 60 * l;
  Columns<Wide> s;
  for (std::vector<Wide>* field : {&s.x, &s.y, &s.vx, &s.vy, &s.r}) field->reserve(n);
  for (const spec::Circle& c : circles) {
    s.x.push_back(scaled(c.p.x(), den_));
    s.y.push_back(scaled(c.p.y(), den_));
    s.vx.push_back(scaled(c.v.x(), den_v_));
    s.vy.push_back(scaled(c.v.y(), den_v_));
    s.r.push_back(scaled(c.r, den_));
  }
  start(std::move(s), std::move(radius), std::move(radius_error));
}

template <class Int>
void ExactEngine::start(Columns<Int> s, std::vector<double> radius, std::vector<double> radius_error) {
  // RN(x) = ±infinity exactly when |x| ≥ 2^1024 − 2^970, the midpoint between DBL_MAX = 2^1024 − 2^971 and
  // 2^1024, which ties to the even 2^1024 (DBL_MAX's last bit is 1).
  overflow_at_ = ((Wide(1) << 1024) - (Wide(1) << 970)) * den_;
  radius_ = std::move(radius);
  radius_error_ = std::move(radius_error);
  radii_exact_ = std::all_of(radius_error_.begin(), radius_error_.end(), [](double e) { return e == 0; });
  // The first layout: slot k holds circle k until commit sorts them.
  const std::size_t n = radius_.size();
  id_.resize(n);
  std::iota(id_.begin(), id_.end(), std::uint32_t{0});
  approx_.rho = radius_;
  key_.clear();
  state_ = std::move(s);
  choose_width();
  std::visit(
      [this](auto& columns) {
        this->locate<false>(columns, false);
        this->commit(columns, false);
      },
      state_);
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
    if (speed == 0) return kForever - steps_;
    const Wide steps = (limit - reach) / speed;
    return steps >= Wide(kForever - steps_) ? kForever - steps_ : steps.convert_to<std::uint64_t>();
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
    proven_until_ = steps_ + word;
  } else if (const std::uint64_t narrow = ahead(exact::kNarrowBits); narrow > 0) {
    to(Narrow{});
    proven_until_ = steps_ + narrow;
  } else {
    to(Wide{});
    return;
  }
  narrow_den_ = static_cast<NarrowMagnitude>(narrow_of(den_));
  narrow_den_v_ = static_cast<NarrowMagnitude>(narrow_of(den_v_));
  inverse_den_ = exact::round_quotient(Narrow{1}, narrow_den_);
}

template <class To, class From>
ExactEngine::Columns<To> ExactEngine::converted(const Columns<From>& s) {
  Columns<To> out;
  const std::vector<From>* from[5] = {&s.x, &s.y, &s.vx, &s.vy, &s.r};
  std::vector<To>* to[5] = {&out.x, &out.y, &out.vx, &out.vy, &out.r};
  for (std::size_t f = 0; f < 5; ++f) {
    to[f]->reserve(from[f]->size());
    for (const From& value : *from[f]) to[f]->push_back(convert<To>(value));
  }
  return out;
}

void ExactEngine::step() {
  if (narrow() && steps_ >= proven_until_) choose_width();
  std::visit([this](auto& s) { step_with(s); }, state_);
  ++steps_;
}

template <class Int>
bool ExactEngine::precedes(const Columns<Int>& s, std::size_t a, std::size_t b) const noexcept {
  // (7) on integers scaled by D > 0 or L > 0: the same order as the rationals, then the index.
  for (const std::vector<Int>* field : {&s.x, &s.y, &s.vx, &s.vy}) {
    if ((*field)[a] < (*field)[b]) return true;
    if ((*field)[b] < (*field)[a]) return false;
  }
  const std::uint32_t i = id_[a], j = id_[b];
  if (s.r[i] < s.r[j]) return true;
  if (s.r[j] < s.r[i]) return false;
  return i < j;
}

// The centre's error bound (kBoxRelative) plus the radius's.
inline double ExactEngine::error(double x, double y, std::uint32_t circle) const noexcept {
  const double centre = std::max(std::fabs(x), std::fabs(y)) * kBoxRelative + kBoxAbsolute;
  return radii_exact_ ? centre : centre + radius_error_[circle];
}

template <class Int>
inline double ExactEngine::approximate(const Int& x, const Int& y, double rho, std::uint32_t circle, double& ax,
                                       double& ay, double& box) const noexcept {
  if constexpr (kFixed<Int>) {
    ax = exact::approximate(x, inverse_den_);
    ay = exact::approximate(y, inverse_den_);
  } else {
    ax = exact::approximate(x, den_);
    ay = exact::approximate(y, den_);
  }
  // ρ ± error holds r and (ax, ay) ± error the centre, so the box of half-width ≥ ρ + error around (ax, ay)
  // holds the exact box (+infinity: a global circle).
  const double e = error(ax, ay, circle);
  box = outward_upper(rho, e);
  return e;
}

template <class Int>
bool ExactEngine::intersect_exactly(const Columns<Int>& s, std::size_t i, std::size_t j) const {
  const std::uint32_t ci = id_[i], cj = id_[j];
  return exact::intersect_scaled(Int(s.r[ci] + s.r[cj]), Int(s.x[j] - s.x[i]), Int(s.y[j] - s.y[i]));
}

template <class Int>
void ExactEngine::step_with(Columns<Int>& s) {
  const Approximations& a = approx_;
  const CellView view{key_, a.x, a.y, a.box, levels_, level_begin_};
  find_least_contacts(
      grid_, view, threads_, least_, offers_,
      [&](std::size_t i, std::size_t j) {
        const double e = error_bound_;
        const Decision d = exact::intersect_approximate(a.x[i], a.y[i], a.rho[i], e, a.x[j], a.y[j], a.rho[j], e);
        if (d != Decision::undecided) [[likely]]
          return d == Decision::intersect;
        return intersect_exactly(s, i, j);
      },
      [&](std::size_t i, std::size_t j) { return precedes(s, i, j); });
  if constexpr (kFixed<Int>) {
    // A fixed-width state cannot overflow (check_overflow): V[least] is read where it is used, X ← X + V in
    // locate and the velocities' gather in commit.
    locate<true>(s, true);
    commit(s, true);
  } else {
    // A GMP state takes its new velocities first and checks every new position before anything changes.
    const std::size_t n = id_.size();
    s.next_vx.resize(n);
    s.next_vy.resize(n);
    for (std::size_t t = 0; t < n; ++t) {
      s.next_vx[t] = s.vx[least_[t]];
      s.next_vy[t] = s.vy[least_[t]];
    }
    check_overflow(s);
    s.vx.swap(s.next_vx);
    s.vy.swap(s.next_vy);
    locate<true>(s, false);
    commit(s, false);
  }
}

template <class Int>
void ExactEngine::check_overflow(const Columns<Int>& s) const {
  // Only a GMP state can reach the double range's end: a fixed-width |X| ≤ 2^125 with D ≥ 60 is below 2^125.
  if constexpr (!kFixed<Int>) {
    constexpr std::uint64_t kNone = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t first = kNone;  // 2·circle + (0 for px, 1 for py): the lowest circle, px before py
    Wide next;
    for (std::size_t t = 0; t < s.x.size(); ++t) {
      next = s.x[t] + s.next_vx[t];
      if (mpz_cmpabs(raw(next), raw(overflow_at_)) >= 0) first = std::min(first, 2 * std::uint64_t{id_[t]});
      next = s.y[t] + s.next_vy[t];
      if (mpz_cmpabs(raw(next), raw(overflow_at_)) >= 0) first = std::min(first, 2 * std::uint64_t{id_[t]} + 1);
    }
    if (first != kNone) throw PositionOverflow(steps_ + 1, first / 2, first % 2 ? "py" : "px");
  }
}

template <bool Advance, class Int>
void ExactEngine::locate(Columns<Int>& s, bool from_least) {
  const std::size_t n = id_.size();
  next_key_.resize(n);
  const std::size_t chunks = chunk_count(n, threads_);
  std::vector<std::array<double, 4>> extent(chunks);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    double xlo = inf, xhi = -inf, ylo = inf, yhi = -inf;
    // The keys need the approximations; commit computes them again in the new order rather than moving them.
    std::array<double, kBlock> bx, by, bbox;
    for (std::size_t b = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); b < end; b += kBlock) {
      const std::size_t e = std::min(end, b + kBlock);
      for (std::size_t t = b; t < e; ++t) {
        if constexpr (Advance) {
          const std::size_t from = from_least ? least_[t] : t;
          s.x[t] += s.vx[from];
          s.y[t] += s.vy[from];
        }
        approximate(s.x[t], s.y[t], approx_.rho[t], id_[t], bx[t - b], by[t - b], bbox[t - b]);
        xlo = std::min(xlo, bx[t - b]);
        xhi = std::max(xhi, bx[t - b]);
        ylo = std::min(ylo, by[t - b]);
        yhi = std::max(yhi, by[t - b]);
      }
      grid_.keys(std::span<const double>(bx.data(), e - b), std::span<const double>(by.data(), e - b),
                 std::span<const double>(bbox.data(), e - b), std::span<CellKey>(next_key_).subspan(b, e - b));
    }
    extent[c] = {xlo, xhi, ylo, yhi};
  });
  // Circles drifted out of the planned grid (their cells clamp, which is correct but slow): plan again, from
  // every slot's approximations.
  bool inside = planned_;
  for (const auto& [xlo, xhi, ylo, yhi] : extent) inside = inside && (xlo > xhi || grid_.covers(xlo, xhi, ylo, yhi));
  if (!inside) {
    Approximations& a = approx_;
    for (std::vector<double>* field : {&a.x, &a.y, &a.box}) field->resize(n);
    for (std::size_t t = 0; t < n; ++t) approximate(s.x[t], s.y[t], a.rho[t], id_[t], a.x[t], a.y[t], a.box[t]);
    grid_.plan(a.x, a.y, a.box);
    planned_ = true;
    for_each_chunk(chunks, threads_, [&](std::size_t c) {
      const std::size_t b = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1);
      grid_.keys(std::span<const double>(a.x).subspan(b, e - b), std::span<const double>(a.y).subspan(b, e - b),
                 std::span<const double>(a.box).subspan(b, e - b), std::span<CellKey>(next_key_).subspan(b, e - b));
    });
  }
}

template <class Int>
void ExactEngine::commit(Columns<Int>& s, bool from_least) {
  // The new order, then one parallel pass: per chunk, every slot field gathered into the new order (the
  // velocities from each slot's least contact when from_least), and the approximations there with their
  // largest error bound. Keys sorted already: the same in place.
  const std::size_t n = id_.size();
  const std::size_t chunks = chunk_count(n, threads_);
  const bool sorted = order_.sort(next_key_, key_, permutation_);
  Approximations& a = approx_;
  for (std::vector<double>* field : {&a.x, &a.y, &a.box}) field->resize(n);
  if (sorted) {
    key_.swap(next_key_);
  } else {
    for (std::vector<Int>* field : {&s.next_x, &s.next_y}) field->resize(n);
    next_rho_.resize(n);
    next_id_.resize(n);
    key_.resize(n);
  }
  if (!sorted || from_least) {
    s.next_vx.resize(n);
    s.next_vy.resize(n);
  }
  // Where each field of the new order is once the pass is done.
  const std::vector<Int>& x = sorted ? s.x : s.next_x;
  const std::vector<Int>& y = sorted ? s.y : s.next_y;
  const std::vector<double>& rho = sorted ? a.rho : next_rho_;
  const std::vector<std::uint32_t>& id = sorted ? id_ : next_id_;
  std::vector<double> largest(chunks, 0.0);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    const std::size_t b = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1);
    if (sorted && from_least) {
      for (std::size_t t = b; t < e; ++t) {
        s.next_vx[t] = s.vx[least_[t]];
        s.next_vy[t] = s.vy[least_[t]];
      }
    } else if (!sorted) {
      gather(s.next_x, s.x, permutation_, b, e);
      gather(s.next_y, s.y, permutation_, b, e);
      if (from_least) {  // fixed widths only: copies, and least_ is no permutation
        for (std::size_t t = b; t < e; ++t) {
          s.next_vx[t] = s.vx[least_[permutation_[t]]];
          s.next_vy[t] = s.vy[least_[permutation_[t]]];
        }
      } else {
        gather(s.next_vx, s.vx, permutation_, b, e);
        gather(s.next_vy, s.vy, permutation_, b, e);
      }
      gather(next_rho_, a.rho, permutation_, b, e);
      gather(next_id_, id_, permutation_, b, e);
      gather(key_, next_key_, permutation_, b, e);
    }
    double bound = 0;
    for (std::size_t t = b; t < e; ++t)
      bound = std::max(bound, approximate(x[t], y[t], rho[t], id[t], a.x[t], a.y[t], a.box[t]));
    largest[c] = bound;
  });
  error_bound_ = *std::max_element(largest.begin(), largest.end());
  if (!sorted) {
    s.x.swap(s.next_x);
    s.y.swap(s.next_y);
    a.rho.swap(next_rho_);
    id_.swap(next_id_);
  }
  if (!sorted || from_least) {
    s.vx.swap(s.next_vx);
    s.vy.swap(s.next_vy);
  }
  index_levels(key_, level_begin_, levels_);
}

World ExactEngine::world() const {
  std::vector<std::array<double, 5>> out(size());
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
          const std::uint32_t k = id_[t];
          out[k] = {round(s.x[t], false), round(s.y[t], false), round(s.vx[t], true), round(s.vy[t], true),
                    round(s.r[k], false)};
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
          const std::uint32_t k = id_[t];
          out[k] = spec::circle(spec::Q(convert<Wide>(s.x[t])) / d, spec::Q(convert<Wide>(s.y[t])) / d,
                                spec::Q(convert<Wide>(s.vx[t])) / l, spec::Q(convert<Wide>(s.vy[t])) / l,
                                spec::Q(convert<Wide>(s.r[k])) / d);
        }
      },
      state_);
  return out;
}

std::vector<std::array<std::string, 5>> ExactEngine::rationals() const {
  std::vector<std::array<std::string, 5>> out;
  for (const spec::Circle& c : exact())
    out.push_back({spec::to_string(c.p.x()), spec::to_string(c.p.y()), spec::to_string(c.v.x()),
                   spec::to_string(c.v.y()), spec::to_string(c.r)});
  return out;
}

}  // namespace circles::impl
