#include "tests/gallery.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>

#include "impl/predicate.hpp"
#include "impl/rounding.hpp"
#include "spec/circle.hpp"
#include "spec/equations.hpp"

namespace circles::testing {
namespace {

bool touches(const spec::CircleDoubles& a, const spec::CircleDoubles& b, Mistakes::Contact how) {
  switch (how) {
    case Mistakes::Contact::exact: return impl::intersect_exact(a[0], a[1], a[4], b[0], b[1], b[4]);
    case Mistakes::Contact::strict: {
      const spec::Q dx = spec::exact(b[0]) - spec::exact(a[0]), dy = spec::exact(b[1]) - spec::exact(a[1]);
      const spec::Q s = spec::exact(a[4]) + spec::exact(b[4]);
      return s * s > dx * dx + dy * dy;
    }
    case Mistakes::Contact::hypot: return std::hypot(b[0] - a[0], b[1] - a[1]) <= a[4] + b[4];
    case Mistakes::Contact::small_grid:
      // Cells of side 1 and only the 3×3 around a circle's centre: misses circles whose centres are further
      // apart than a cell and a bit, however large their radii.
      return std::fabs(std::floor(a[0]) - std::floor(b[0])) <= 1 && std::fabs(std::floor(a[1]) - std::floor(b[1])) <= 1 &&
             impl::intersect_exact(a[0], a[1], a[4], b[0], b[1], b[4]);
  }
  return false;
}

// True when circle j should be taken over circle best as the contact of choice.
bool better(const Circles& w, std::size_t j, std::size_t best, Mistakes::Choice how) {
  const auto key = [&](std::size_t i) { return std::tie(w[i][0], w[i][1], w[i][2], w[i][3], w[i][4]); };
  const auto y_first = [&](std::size_t i) { return std::tie(w[i][1], w[i][0], w[i][2], w[i][3], w[i][4]); };
  switch (how) {
    case Mistakes::Choice::least: return std::make_pair(key(j), j) < std::make_pair(key(best), best);
    case Mistakes::Choice::y_key_first: return std::make_pair(y_first(j), j) < std::make_pair(y_first(best), best);
    case Mistakes::Choice::first_in_index: return false;
    case Mistakes::Choice::literal_fold: {
      // (7) folded left to right: the running minimum stays unless it is not ≤ the next one.
      const spec::Circle a = spec::from_doubles(w[best], best, spec::Radii::non_negative);
      const spec::Circle b = spec::from_doubles(w[j], j, spec::Radii::non_negative);
      return !(spec::m(a, b) == a);
    }
  }
  return false;
}

}  // namespace

Circles mistaken_step(const Circles& input, const Mistakes& m) {
  Circles w = input;
  if (m.flush_subnormals)
    for (auto& c : w)
      for (double& x : c)
        if (std::fpclassify(x) == FP_SUBNORMAL) x = 0;
  const Circles old = w;
  Circles out = w;
  const Circles& read = m.in_place ? out : old;
  std::vector<std::array<double, 2>> velocity(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) velocity[k] = {w[k][2], w[k][3]};
  if (m.swap_pairs) {
    for (std::size_t i = 0; i < w.size(); ++i)
      for (std::size_t j = i + 1; j < w.size(); ++j)
        if (touches(old[i], old[j], m.contact)) {
          velocity[i] = {old[j][2], old[j][3]};
          velocity[j] = {old[i][2], old[i][3]};
        }
  }
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (!m.swap_pairs) {
      std::size_t best = k;
      for (std::size_t j = 0; j < w.size(); ++j) {
        if (j == k || (m.identity_by_value && read[j] == read[k])) continue;
        if (!touches(read[k], read[j], m.contact)) continue;
        if (best == k || better(read, j, best, m.choice)) best = j;
      }
      velocity[k] = {read[best][2], read[best][3]};
    }
    const auto update = [&](double p, double v) { return m.naive_update ? p + v * (1.0 / 60) : impl::advance_rounded(p, v); };
    out[k] = {update(read[k][0], velocity[k][0]), update(read[k][1], velocity[k][1]), velocity[k][0], velocity[k][1], read[k][4]};
  }
  return out;
}

const std::vector<GalleryEntry>& gallery() {
  using C = Mistakes::Contact;
  using H = Mistakes::Choice;
  static const std::vector<GalleryEntry> entries{
      {"strict-intersect", "< instead of <= in (3)", {.contact = C::strict}},
      {"hypot-distance", "hypot distance in doubles", {.contact = C::hypot}},
      {"naive-update", "p + v*(1/60)", {.naive_update = true}},
      {"in-place", "in-place updates in index order", {.in_place = true}},
      {"y-key-first", "the lexicographic key in the wrong order (py first)", {.choice = H::y_key_first}},
      {"first-contact", "the first intersecting circle instead of the least", {.choice = H::first_in_index}},
      {"literal-fold", "the literal (7) folded left to right", {.choice = H::literal_fold}},
      {"swap-pairs", "velocities swapped pairwise", {.swap_pairs = true}},
      {"identity-by-value", "identity by value instead of by index", {.identity_by_value = true}},
      {"small-grid", "a grid whose cells are too small", {.contact = C::small_grid}},
      {"flush-subnormals", "subnormals flushed to zero", {.flush_subnormals = true}},
  };
  return entries;
}

const GalleryEntry* find_entry(std::string_view name) {
  static const GalleryEntry none{"none", "none", {}};
  if (name == none.name) return &none;
  const auto entry =
      std::find_if(gallery().begin(), gallery().end(), [&](const GalleryEntry& e) { return e.name == name; });
  return entry == gallery().end() ? nullptr : &*entry;
}

std::string entry_names() {
  std::string names = "none";
  for (const GalleryEntry& e : gallery()) names += ", " + e.name;
  return names;
}

}  // namespace circles::testing
