// The exact engine's step; the invariant is stated in exact_engine.hpp, the design in docs/exact-engine.md.
//
// A step from the exact state (integers, circle k at index k):
//   locate         double boxes that contain each circle's exact box, their keys, and cell order (slots);
//   find contacts  impl/contacts.hpp over those boxes, with the exact integer intersect and order;
//   advance        V ← V[least], X ← X + V; a wide state first checks that no position rounds to ±infinity.
#include "impl/exact_engine.hpp"

#include "impl/contacts.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <type_traits>

namespace circles::impl {
namespace {

using exact::Narrow;
using exact::NarrowMagnitude;
using exact::Wide;

// The boxes (locate): the approximate centre is within 2^-50·|a| + 2^-1075 of the exact one per coordinate
// (exact::approximate), so a radius inflated by e = RN(RN(max(|ax|, |ay|)·2^-49) + 2^-1073) ≥ that error
// (a factor of two to spare on each term, which covers e's own two roundings) makes the box around the
// approximate centre contain the exact box.
constexpr double kBoxRelative = 0x1p-49;
constexpr double kBoxAbsolute = 0x1p-1073;

mpz_srcptr raw(const Wide& z) noexcept { return z.backend().data(); }
mpz_ptr raw(Wide& z) noexcept { return z.backend().data(); }

Wide widen(Narrow x) {
  const NarrowMagnitude m = x < 0 ? NarrowMagnitude{0} - static_cast<NarrowMagnitude>(x) : static_cast<NarrowMagnitude>(x);
  Wide w(static_cast<std::uint64_t>(m >> 64));
  w <<= 64;
  w += Wide(static_cast<std::uint64_t>(m));
  return x < 0 ? Wide(-w) : w;
}
// For |z| < 2^127: its two low 64-bit limbs (mpz_getlimbn gives 0 past the size).
Narrow narrow_of(const Wide& z) {
  static_assert(sizeof(mp_limb_t) == 8, "64-bit GMP limbs");
  const NarrowMagnitude m = (NarrowMagnitude{mpz_getlimbn(raw(z), 1)} << 64) | mpz_getlimbn(raw(z), 0);
  return z < 0 ? -static_cast<Narrow>(m) : static_cast<Narrow>(m);
}
const Wide& widen(const Wide& z) { return z; }

Wide magnitude(const Wide& z) { return z < 0 ? Wide(-z) : z; }

// A double at least the rational r.
double upper_double(const spec::Q& r) {
  const double d = spec::nearest_double(r);
  return spec::exact(d) < r ? std::nextafter(d, std::numeric_limits<double>::infinity()) : d;
}

// The integer q·scale, for a rational q whose denominator divides scale.
Wide scaled(const spec::Q& q, const Wide& scale) {
  const spec::Q product = q * spec::Q(scale);
  return boost::multiprecision::numerator(product);
}

template <class Int>
bool precedes(const std::vector<Int>* const (&fields)[5], std::uint32_t i, std::uint32_t j) {
  // (7) on integers scaled by D > 0 or L > 0: the same order as the rationals, then the index.
  for (const std::vector<Int>* field : fields) {
    if ((*field)[i] < (*field)[j]) return true;
    if ((*field)[j] < (*field)[i]) return false;
  }
  return i < j;
}

spec::Sequence sequence_of(const World& w) {
  spec::Sequence out;
  const auto circles = w.circles();
  out.reserve(circles.size());
  for (std::size_t k = 0; k < circles.size(); ++k) out.push_back(spec::from_doubles(circles[k], k, spec::Radii::non_negative));
  return out;
}

}  // namespace

ExactEngine::ExactEngine(const World& w, EngineOptions options) : ExactEngine(sequence_of(w), options) {}

ExactEngine::ExactEngine(const spec::Sequence& circles, EngineOptions options)
    : options_(options), threads_(resolve_threads(options.threads, kMaxThreads)) {
  const std::size_t n = circles.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("ExactEngine: " + std::to_string(n) + " circles; at most 2^32 - 1");
  // L: the least common multiple of every field's denominator (2^K for doubles).
  Wide l = 1;
  r_upper_.resize(n);
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
    r_upper_[k] = upper_double(c.r);
  }
  den_v_ = l;
  den_ = 60 * l;
  // RN(x) = ±infinity exactly when |x| ≥ 2^1024 − 2^970, the midpoint between DBL_MAX = 2^1024 − 2^971 and
  // 2^1024, which ties to the even 2^1024 (DBL_MAX's last bit is 1).
  overflow_at_ = ((Wide(1) << 1024) - (Wide(1) << 970)) * den_;
  Columns<Wide> s;
  for (std::vector<Wide>* field : {&s.x, &s.y, &s.vx, &s.vy, &s.r}) field->reserve(n);
  for (const spec::Circle& c : circles) {
    s.x.push_back(scaled(c.p.x(), den_));
    s.y.push_back(scaled(c.p.y(), den_));
    s.vx.push_back(scaled(c.v.x(), den_v_));
    s.vy.push_back(scaled(c.v.y(), den_v_));
    s.r.push_back(scaled(c.r, den_));
  }
  state_ = std::move(s);
  prove_narrow_headroom();
}

void ExactEngine::prove_narrow_headroom() {
  // Velocities are only copied, so max |V| never grows, and each step moves a coordinate by at most max |V|:
  // from max |X| now, every |X| stays within 2^125 for (2^125 − max |X|)/max |V| more steps. Radii never change.
  Wide reach = 0, speed = 0, radius = 0;
  std::visit(
      [&](const auto& s) {
        for (std::size_t k = 0; k < s.x.size(); ++k) {
          reach = std::max({reach, magnitude(widen(s.x[k])), magnitude(widen(s.y[k]))});
          speed = std::max({speed, magnitude(widen(s.vx[k])), magnitude(widen(s.vy[k]))});
          radius = std::max(radius, widen(s.r[k]));
        }
      },
      state_);
  const Wide limit = Wide(1) << exact::kNarrowBits;
  std::uint64_t ahead = 0;
  if (den_ <= limit && radius <= limit && speed <= limit && reach <= limit) {
    constexpr auto kForever = std::numeric_limits<std::uint64_t>::max();
    const Wide steps = speed == 0 ? Wide(kForever) : Wide((limit - reach) / speed);
    ahead = steps >= Wide(kForever - steps_) ? kForever - steps_ : steps.convert_to<std::uint64_t>();
  }
  if (ahead == 0) {
    if (narrow()) state_ = converted<Wide>(std::get<0>(state_));  // promote: the same integers, in GMP
    return;
  }
  narrow_until_ = steps_ + ahead;
  if (narrow()) return;
  narrow_den_ = static_cast<NarrowMagnitude>(narrow_of(den_));
  narrow_den_v_ = static_cast<NarrowMagnitude>(narrow_of(den_v_));
  inverse_den_ = exact::round_quotient(Narrow{1}, narrow_den_);
  state_ = converted<Narrow>(std::get<1>(state_));
}

template <class To, class From>
ExactEngine::Columns<To> ExactEngine::converted(const Columns<From>& s) {
  Columns<To> out;
  const std::vector<From>* from[5] = {&s.x, &s.y, &s.vx, &s.vy, &s.r};
  std::vector<To>* to[5] = {&out.x, &out.y, &out.vx, &out.vy, &out.r};
  for (std::size_t f = 0; f < 5; ++f) {
    to[f]->reserve(from[f]->size());
    for (const From& value : *from[f]) {
      if constexpr (std::is_same_v<To, Wide>)
        to[f]->push_back(widen(value));
      else
        to[f]->push_back(narrow_of(value));
    }
  }
  return out;
}

void ExactEngine::step() {
  if (narrow() && steps_ >= narrow_until_) prove_narrow_headroom();
  std::visit([this](auto& s) { step_with(s); }, state_);
  ++steps_;
}

template <class Int>
void ExactEngine::locate(const Columns<Int>& s) {
  const std::size_t n = s.x.size();
  if (id_.size() != n) {
    id_.resize(n);
    std::iota(id_.begin(), id_.end(), std::uint32_t{0});
    key_.clear();
  }
  for (std::vector<double>* field : {&ax_, &ay_, &ar_}) field->resize(n);
  next_key_.resize(n);
  const std::size_t chunks = chunk_count(n, threads_);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    for (std::size_t t = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); t < end; ++t) {
      const std::uint32_t k = id_[t];
      if constexpr (std::is_same_v<Int, Narrow>) {
        ax_[t] = exact::approximate(s.x[k], inverse_den_);
        ay_[t] = exact::approximate(s.y[k], inverse_den_);
      } else {
        ax_[t] = exact::approximate(s.x[k], den_);
        ay_[t] = exact::approximate(s.y[k], den_);
      }
      const double error = std::max(std::fabs(ax_[t]), std::fabs(ay_[t])) * kBoxRelative + kBoxAbsolute;
      ar_[t] = outward_upper(r_upper_[k], error);  // ≥ r + error; +infinity makes the circle global
    }
  });
  if (!planned_ || (n > 0 && !grid_.covers(*std::min_element(ax_.begin(), ax_.end()), *std::max_element(ax_.begin(), ax_.end()),
                                           *std::min_element(ay_.begin(), ay_.end()), *std::max_element(ay_.begin(), ay_.end())))) {
    grid_.plan(ax_, ay_, ar_);
    planned_ = true;
  }
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    const std::size_t b = chunk_begin(n, chunks, c), e = chunk_begin(n, chunks, c + 1);
    grid_.keys(std::span<const double>(ax_).subspan(b, e - b), std::span<const double>(ay_).subspan(b, e - b),
               std::span<const double>(ar_).subspan(b, e - b), std::span<CellKey>(next_key_).subspan(b, e - b));
  });
  if (!order_.sort(next_key_, key_, permutation_)) {
    const auto gather = [this](auto& field) {
      auto moved = field;
      for (std::size_t t = 0; t < moved.size(); ++t) moved[t] = field[permutation_[t]];
      field.swap(moved);
    };
    gather(id_);
    gather(next_key_);
    gather(ax_);
    gather(ay_);
    gather(ar_);
  }
  key_.swap(next_key_);
  index_levels(key_, level_begin_, levels_);
}

template <class Int>
void ExactEngine::check_overflow(const Columns<Int>& s) const {
  // Only a wide state can reach the double range's end: a narrow |X| ≤ 2^125 with D ≥ 60 is below 2^125.
  if constexpr (std::is_same_v<Int, Wide>) {
    Wide next;
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      next = s.x[k] + s.next_vx[k];
      if (mpz_cmpabs(raw(next), raw(overflow_at_)) >= 0) throw PositionOverflow(steps_ + 1, k, "px");
      next = s.y[k] + s.next_vy[k];
      if (mpz_cmpabs(raw(next), raw(overflow_at_)) >= 0) throw PositionOverflow(steps_ + 1, k, "py");
    }
  }
}

template <class Int>
void ExactEngine::step_with(Columns<Int>& s) {
  const std::size_t n = s.x.size();
  locate(s);
  const CellView view{key_, ax_, ay_, ar_, levels_, level_begin_};
  const std::vector<Int>* const fields[5] = {&s.x, &s.y, &s.vx, &s.vy, &s.r};
  find_least_contacts(
      grid_, view, threads_, least_, offers_,
      [&](std::size_t a, std::size_t b) {
        const std::uint32_t i = id_[a], j = id_[b];
        return exact::intersect_scaled(Int(s.r[i] + s.r[j]), Int(s.x[j] - s.x[i]), Int(s.y[j] - s.y[i]));
      },
      [&](std::size_t a, std::size_t b) { return precedes(fields, id_[a], id_[b]); });
  s.next_vx.resize(n);
  s.next_vy.resize(n);
  const std::size_t chunks = chunk_count(n, threads_);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    for (std::size_t t = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); t < end; ++t) {
      const std::uint32_t k = id_[t], from = id_[least_[t]];
      s.next_vx[k] = s.vx[from];
      s.next_vy[k] = s.vy[from];
    }
  });
  check_overflow(s);  // throws before anything of the state changed
  s.vx.swap(s.next_vx);
  s.vy.swap(s.next_vy);
  for_each_chunk(chunks, threads_, [&](std::size_t c) {
    for (std::size_t k = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1); k < end; ++k) {
      s.x[k] += s.vx[k];
      s.y[k] += s.vy[k];
    }
  });
}

World ExactEngine::world() const {
  std::vector<std::array<double, 5>> out(size());
  std::visit(
      [&](const auto& s) {
        using Int = std::decay_t<decltype(s.x[0])>;
        const auto round = [this](const Int& x, bool velocity) {
          if constexpr (std::is_same_v<Int, Narrow>)
            return exact::round_quotient(x, velocity ? narrow_den_v_ : narrow_den_);
          else
            return exact::round_quotient(x, velocity ? den_v_ : den_);
        };
        for (std::size_t k = 0; k < out.size(); ++k)
          out[k] = {round(s.x[k], false), round(s.y[k], false), round(s.vx[k], true), round(s.vy[k], true),
                    round(s.r[k], false)};
      },
      state_);
  return World(out);
}

spec::Sequence ExactEngine::exact() const {
  spec::Sequence out;
  out.reserve(size());
  std::visit(
      [&](const auto& s) {
        const spec::Q d(den_), l(den_v_);
        for (std::size_t k = 0; k < s.x.size(); ++k)
          out.push_back(spec::circle(spec::Q(widen(s.x[k])) / d, spec::Q(widen(s.y[k])) / d,
                                     spec::Q(widen(s.vx[k])) / l, spec::Q(widen(s.vy[k])) / l,
                                     spec::Q(widen(s.r[k])) / d));
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
