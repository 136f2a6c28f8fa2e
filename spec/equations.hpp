// The oracle: equations (1)-(9) of the circles spec (docs/math.md restates each), transcribed one function per
// symbol, one branch per case, in the seed's order. Slow on purpose: sets, exact rationals, no shortcuts.
//
// Conventions (the seed's notation on the left):
//   C                Circle                    a circle (p, v, r): position, velocity, radius
//   P(C), W          World<E>                  a world: a set, so "∈" and "≠" compare values
//   c, x, a, b       const E&                  circles; E is the element type of the profile:
//                                                Circle  in the literal profile (the seed to the letter)
//                                                Indexed in the resolved profile (a circle and its index)
//   S                World<E>                  the circles that c intersects, S = i(c, W)
//   Δt               dt                        exactly 1/60
//   w_n              World<E>                  the n-th world of the sequence D
//   (undefined)      std::nullopt              where the seed gives no value: (8) with no least element
//
// The two profiles (docs/spec-notes.md says why each choice was made):
//   literal   worlds are sets of circles; equal circles are one circle; e is (8) over m (7), which is
//             undefined when S has no least element under the product order (6); r > 0.
//   resolved  worlds are sequences: a circle is tagged with its index, so equal circles stay distinct and
//             the image of circle k is circle k; e takes the least circle in lexicographic order on
//             (px, py, vx, vy, r), a linear extension of (6)/(7), so it equals (8) wherever (8) is defined;
//             r ≥ 0.
// Every equation below serves both: the element type picks the profile, and the resolved profile only adds
// the index, which each equation carries through unchanged.
#pragma once

#include "spec/circle.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <set>
#include <variant>
#include <vector>

namespace circles::spec {

// (5) Δt = 1/60, exactly: no binary floating-point number equals it (spec-notes: "1/60 in binary").
inline const Q dt{1, 60};

// ── Elements and worlds ──────────────────────────────────────────────────────────────────────────────

// The resolved profile's element: circle c with its index k in the world's sequence. Indices are distinct,
// so two equal circles are two elements; every equation acts on c and keeps k.
struct Indexed {
  std::size_t k;
  Circle c;
  friend bool operator==(const Indexed& a, const Indexed& b) { return a.k == b.k && a.c == b.c; }
  friend std::ostream& operator<<(std::ostream& os, const Indexed& x) { return os << '#' << x.k << ' ' << x.c; }
};

// The lexicographic comparison of (px, py, vx, vy, r): negative, zero or positive as a <, =, > b.
inline int lex_compare(const Circle& a, const Circle& b) {
  const Q* ka[] = {&a.p.x(), &a.p.y(), &a.v.x(), &a.v.y(), &a.r};
  const Q* kb[] = {&b.p.x(), &b.p.y(), &b.v.x(), &b.v.y(), &b.r};
  for (int j = 0; j < 5; ++j)
    if (int s = ka[j]->compare(*kb[j])) return s;
  return 0;
}

// How a world is stored. A std::set needs a strict total order on its values; this one is lexicographic
// (then by index). It only lays the set out in memory: no equation depends on it, and the properties check
// that the result of a step does not depend on the order in which a world was built.
struct Storage {
  bool operator()(const Circle& a, const Circle& b) const { return lex_compare(a, b) < 0; }
  bool operator()(const Indexed& a, const Indexed& b) const {
    return a.k != b.k ? a.k < b.k : lex_compare(a.c, b.c) < 0;
  }
};

// P(C): a world, or any set of circles.
template <class E>
using World = std::set<E, Storage>;

// ── The equations ────────────────────────────────────────────────────────────────────────────────────

// (3) a intersect b ⟺ |p_b − p_a| ≤ r_a + r_b
// |p_b − p_a| is a square root, which Q does not hold. On [0, ∞), x ≤ y ⟺ x² ≤ y², so when r_a + r_b ≥ 0
// the test is decided exactly on squares; when r_a + r_b < 0 (outside C) no norm is that small.
inline bool intersect(const Circle& a, const Circle& b) {
  const Vec2 d = b.p - a.p;
  const Q s = a.r + b.r;
  return s >= 0 && d.squaredNorm() <= s * s;
}
inline bool intersect(const Indexed& a, const Indexed& b) { return intersect(a.c, b.c); }

// (2) i(c, W) = {x ∈ W | x ≠ c and c intersect x}
// "x ≠ c" compares elements: values in the literal profile, (index, value) in the resolved one.
template <class E>
World<E> i(const E& c, const World<E>& W) {
  World<E> S;
  for (const E& x : W)
    if (x != c && intersect(c, x)) S.insert(x);
  return S;
}

// (5) u((p, v, r)) = (p + Δt v, v, r)
inline Circle u(const Circle& c) { return Circle{c.p + dt * c.v, c.v, c.r}; }
inline Indexed u(const Indexed& c) { return Indexed{c.k, u(c.c)}; }

// (6) (a, b) ≤ (c, d) ⟺ (a ≤ c) ∧ (b ≤ d)
// A partial order on ℝ²: (0, 1) and (1, 0) are incomparable (spec-notes: "a partial order as a minimum").
inline bool leq(const Vec2& ab, const Vec2& cd) { return (ab.x() <= cd.x()) && (ab.y() <= cd.y()); }

// (7) m((p_a, v_a, r_a), (p_b, v_b, r_b)) = (p_a, v_a, r_a) if (p_a ≤ p_b) ∧ (v_a ≤ v_b) ∧ (r_a ≤ r_b),
//                                         = (p_b, v_b, r_b) otherwise.
inline Circle m(const Circle& a, const Circle& b) {
  if ((leq(a.p, b.p)) && (leq(a.v, b.v)) && (a.r <= b.r))
    return a;
  else  // ¬((p_a ≤ p_b) ∧ (v_a ≤ v_b) ∧ (r_a ≤ r_b))
    return b;
}

// The resolved profile's m: the same two cases, with the lexicographic order on (px, py, vx, vy, r) in
// place of the product order, and the index last so that equal circles are ordered too. A total order,
// and a linear extension of (7): if a ≤ b componentwise then a ≤ b lexicographically.
inline Indexed m(const Indexed& a, const Indexed& b) {
  const int s = lex_compare(a.c, b.c);
  if (s < 0 || (s == 0 && a.k <= b.k))
    return a;
  else
    return b;
}

// (8) e(c, S) = x ∈ S s.t. ∀a ∈ S, m(x, a) = x   if S ≠ ∅
// The seed writes d(x, a); d is defined nowhere and m is meant (spec-notes: "d for m").
// e does not use c. When no x qualifies (S has no least element) e is undefined: std::nullopt.
// Two x cannot qualify: m(x, y) = x and m(y, x) = y give x ≤ y ≤ x, so x = y, in either profile.
template <class E>
std::optional<E> e(const E& /*c*/, const World<E>& S) {
  std::vector<E> X;
  for (const E& x : S)
    if (std::all_of(S.begin(), S.end(), [&](const E& a) { return m(x, a) == x; })) X.push_back(x);
  if (X.size() == 1) return X.front();
  return std::nullopt;
}

// (9) h((p_a, v_a, r_a), (p_b, v_b, r_b)) = (p_a, v_b, r_a)
inline Circle h(const Circle& a, const Circle& b) { return Circle{a.p, b.v, a.r}; }
inline Indexed h(const Indexed& a, const Indexed& b) { return Indexed{a.k, h(a.c, b.c)}; }

// (4) f(c, W) = u(h(c, e(c, i(c, W))))  if i(c, W) ≠ ∅
//             = u(c)                      if i(c, W) = ∅
// Undefined (std::nullopt) exactly when e is.
template <class E>
std::optional<E> f(const E& c, const World<E>& W) {
  if (!i(c, W).empty()) {
    const std::optional<E> x = e(c, i(c, W));
    if (!x) return std::nullopt;
    return u(h(c, *x));
  } else {  // i(c, W) = ∅
    return u(c);
  }
}

// A step at which (8) had no value: each circle c of w_{n−1} whose S = i(c, w_{n−1}) has no least element.
template <class E>
struct Undefined {
  struct Meeting {
    E c;
    World<E> S;
  };
  std::vector<Meeting> at;
};

// (1) w_n = {c_n | c_n = f(c_{n−1}, w_{n−1}) for c_{n−1} ∈ w_{n−1}}   for n > 0
// Every f reads the old world w_{n−1}; the new world is a set, so equal images merge (spec-notes).
template <class E>
std::variant<World<E>, Undefined<E>> step(const World<E>& w_prev) {
  World<E> w_n;
  Undefined<E> undefined;
  for (const E& c_prev : w_prev) {
    if (const std::optional<E> c_n = f(c_prev, w_prev))
      w_n.insert(*c_n);
    else
      undefined.at.push_back({c_prev, i(c_prev, w_prev)});
  }
  if (!undefined.at.empty()) return undefined;
  return w_n;
}

// The worlds w_0 … w_n of D, or fewer when a step is undefined; then `undefined` says which circles of the
// last world met it.
template <class E>
struct Trajectory {
  std::vector<World<E>> w;
  std::optional<Undefined<E>> undefined;
};

// (1) D = {w_n}, n = 0, 1, ...: the first n + 1 worlds, w_0 given and each next one by `step`.
template <class E>
Trajectory<E> D(const World<E>& w_0, std::size_t n) {
  Trajectory<E> t{{w_0}, std::nullopt};
  while (t.w.size() <= n) {
    auto w_next = step(t.w.back());
    if (auto* undefined = std::get_if<Undefined<E>>(&w_next)) {
      t.undefined = std::move(*undefined);
      break;
    }
    t.w.push_back(std::get<World<E>>(std::move(w_next)));
  }
  return t;
}

}  // namespace circles::spec
