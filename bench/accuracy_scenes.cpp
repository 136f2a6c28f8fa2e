// The scenes of the accuracy benchmark and the stability stress (bench/accuracy.hpp), each with the pairs
// designed to touch and the arithmetic that places them. check_designed verifies every design in the exact
// run, and tests/accuracy_test.cpp repeats the check on the committed files.
//
// Notation: a circle is [px, py, vx, vy, r]; a circle with velocity v moves v/60 per step, so after N steps
// it has moved N·v/60. A moving circle A and a circle B at rest touch at step N when B sits at
// A's start + N·v/60 + (r_a + r_b)·(unit direction of v).
#include "bench/accuracy.hpp"

#include "impl/exact_engine.hpp"
#include "formats/random_scene.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>

namespace circles::bench::accuracy {
namespace {

// ── The bundled scenes (scenes/*.json) ──────────────────────────────────────────────────────────────

// Two lines of five touching balls (r = 20, centres 40 apart). Line 1 (y = 360): a striker from x = 0 at
// 100/60 per step (a move no double holds) touches the ball at 200 at step 96 (96·100/60 = 160 = 200 − 40).
// Line 2 (y = 480): a striker from x = 470 at −7/60 per step touches the ball at 360 at step 600
// (470 − 600·7/60 = 400 = 360 + 40). Every later distance along a line is 40 plus multiples of the moves,
// so the exact run meets tangencies again and again.
Scene cradle() {
  Scene s{"cradle", "cradle: two Newton's cradles of five touching balls, struck at 100/60 and -7/60 per step", 1200,
          {}, {}, {}};
  s.circles.push_back({0, 360, 100, 0, 20});
  s.circle_names.push_back("striker 1: touches ball 1 at step 96");
  for (int i = 0; i < 5; ++i) {
    s.circles.push_back({200.0 + 40 * i, 360, 0, 0, 20});
    s.circle_names.push_back(i == 0 ? "ball 1" : "");
  }
  for (int i = 0; i < 5; ++i) {
    s.circles.push_back({200.0 + 40 * i, 480, 0, 0, 20});
    s.circle_names.push_back(i == 4 ? "ball 10" : "");
  }
  s.circles.push_back({470, 480, -7, 0, 20});
  s.circle_names.push_back("striker 2: touches ball 10 at step 600");
  s.designed = {{0, 1, 96, 0}, {11, 10, 600, 0}};
  return s;
}

// Appends an n × n lattice of circles of radius r, (x0 + spacing·i, y0 + spacing·j) row by row, each with an
// integer velocity (vx, then vy) drawn uniformly from [−limit, limit] by std::mt19937_64(seed): the standard
// fixes that generator's sequence, and the draw, (x >> 11) mod (2·limit + 1), is written here rather than left
// to a library's distribution, so the scene is the same everywhere.
void add_lattice(Scene& s, int n, double x0, double y0, double spacing, double r, std::uint64_t seed, int limit) {
  std::mt19937_64 random(seed);
  const auto span = static_cast<std::uint64_t>(2 * limit + 1);
  const auto draw = [&] { return static_cast<double>(static_cast<int>((random() >> 11) % span) - limit); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double vx = draw();
      const double vy = draw();
      s.circles.push_back({x0 + spacing * i, y0 + spacing * j, vx, vy, r});
    }
}

// A 16 × 16 lattice of radius 5 at spacing 10, so every circle touches its four neighbours exactly, with
// integer velocities in [−100, 100] (seed 2024): most moves are k/60, which no double holds.
Scene dense() {
  Scene s{"dense", "dense: a 16 x 16 lattice of touching circles with random integer velocities", 1000, {}, {}, {}};
  add_lattice(s, 16, 0, 0, 10, 5, 2024, 100);
  return s;
}

// The benchmarks' random scene (formats/random_scene.hpp) at 40% coverage: 128 circles, radii in [2, 6], |v| ≤ 100,
// every field a full double. Nothing is designed: contacts come at distances no rounding will flip, unless the
// trajectory wanders onto one.
Scene random() {
  Scene s{"random", "random: the benchmarks' random scene, 128 circles at 40% coverage (formats::random_scene, seed 1)", 1000,
          {}, {}, {}};
  s.circles = formats::random_scene(128, 0.4, 1);
  return s;
}

// Every move is exact in doubles: v = 60·q with q a dyadic rational. Pairs (A moving, B at rest):
//   0, 1  q = (3/4, 0), r = 1: A at 600·3/4 = 450 at step 600, B at 452. The control: every double variant
//         lands on it exactly.
//   2, 3  q = (2^-10, 0) at x = 2^20 = 1048576: A at 1048576 + 600/1024 = 1048576.5859375 at step 600, B 2
//         beyond. A float's ulp at 2^20 is 2^-3, so in float A never moves.
//   4, 5  q = (3/64, 4/64), r = 2.5: A at (30, 240) at step 640, B at A + (3, 4): a 3-4-5 tangency.
//   6, 7  q = (5/4, 21/16), r = 29m/2 with m = 67108873 (a 20-21-29 triangle scaled by m): A from
//         (10^10, 10^10) is at (10^10 + 80, 10^10 + 84) at step 64, B at A + (20m, 21m). dx² and dy² need
//         more than 53 bits: both naive tests round to "apart" at this exact tangency.
//   8, 9  the same with m = 67108891 from (2·10^10, 2·10^10): the √ test rounds to "touching", the
//         squares test to "apart".
// (Found by trying odd m from 2^26 + 1 up; each m is rechecked at run time by check_designed and the tests.)
Scene tangency_exact() {
  Scene s{"tangency_exact", "tangency_exact: pairs that touch after 64-640 steps of moves exact in doubles (v = 60 q, q dyadic)",
          1200, {}, {}, {}};
  const double m1 = 67108873, m2 = 67108891;
  s.circles = {
      {0, 0, 45, 0, 1},
      {452, 0, 0, 0, 1},
      {1048576, 100, 0.05859375, 0, 1},
      {1048578.5859375, 100, 0, 0, 1},
      {0, 200, 2.8125, 3.75, 2.5},
      {33, 244, 0, 0, 2.5},
      {1e10, 1e10, 75, 78.75, 29 * m1 / 2},
      {1e10 + 80 + 20 * m1, 1e10 + 84 + 21 * m1, 0, 0, 29 * m1 / 2},
      {2e10, 2e10, 75, 78.75, 29 * m2 / 2},
      {2e10 + 80 + 20 * m2, 2e10 + 84 + 21 * m2, 0, 0, 29 * m2 / 2},
  };
  s.circle_names = {"a0: touches b0 at step 600", "b0", "a1: touches b1 at step 600 (moves of 2^-10 at 2^20)", "b1",
                    "a2: touches b2 at step 640 (3-4-5)", "b2", "a3: touches b3 at step 64 (20-21-29 times 67108873)",
                    "b3", "a4: touches b4 at step 64 (20-21-29 times 67108891)", "b4"};
  s.designed = {{0, 1, 600, 0}, {2, 3, 600, 0}, {4, 5, 640, 0}, {6, 7, 64, 0}, {8, 9, 64, 0}};
  return s;
}

// Moves of k/60, which no double holds, so every rounding engine drifts. Pairs (A moving, B at rest, r = 1
// unless said); the fates are those of the doubles p ← p + v·RN(1/60) and p ← RN(p + v/60) over the steps:
//   0, 1  v = 7 from 0: A at 70 at step 600, B at 72. Both roundings land short: the contact is missed.
//   2, 3  v = 86 from 1: A at 87 at step 60, B at 89. The naive update lands on 87, the correctly rounded
//         one short.
//   4, 5  v = 94 from 1: A at 95 at step 60, B at 97. The correctly rounded update lands on 95, the naive
//         one short.
//   6, 7  v = 1 from 0: A at 10 at step 600, B at 12 + 2^-46, a near miss by 2^-46: the exact run has no
//         contact at step 600, the roundings land 7.6e-14 beyond 10 and make one.
//   8, 9  v = (3, 4), r = 2.5, from (0, 400): A at (30, 440) at step 600, B at A + (3, 4).
Scene tangency_sixtieths() {
  Scene s{"tangency_sixtieths", "tangency_sixtieths: pairs that touch after 60-600 steps of moves of k/60 (no double holds them)",
          1200, {}, {}, {}};
  s.circles = {
      {0, 0, 7, 0, 1},     {72, 0, 0, 0, 1},
      {1, 100, 86, 0, 1},  {89, 100, 0, 0, 1},
      {1, 200, 94, 0, 1},  {97, 200, 0, 0, 1},
      {0, 300, 1, 0, 1},   {12 + 0x1p-46, 300, 0, 0, 1},
      {0, 400, 3, 4, 2.5}, {33, 444, 0, 0, 2.5},
  };
  s.circle_names = {"a0: touches b0 at step 600", "b0", "a1: touches b1 at step 60", "b1", "a2: touches b2 at step 60", "b2",
                    "a3: misses b3 by 2^-46 at step 600", "b3", "a4: touches b4 at step 600 (3-4-5)", "b4"};
  s.designed = {{0, 1, 600, 0}, {2, 3, 60, 0}, {4, 5, 60, 0}, {6, 7, 600, 0x1p-46}, {8, 9, 600, 0}};
  return s;
}

// ── Stress scenes (docs/stability.md) ───────────────────────────────────────────────────────────────

// tangency_sixtieths with every field times 2^e: the exact trajectory is the same one times 2^e.
Scene scaled(const Scene& base, int e, const std::string& label) {
  Scene s = base;
  s.id = "magnitude_" + label;
  s.name = "tangency_sixtieths times 2^" + std::to_string(e) + " (about " + label + ")";
  for (auto& circle : s.circles)
    for (double& x : circle) x = std::ldexp(x, e);
  for (Designed& d : s.designed) d.gap = std::ldexp(d.gap, e);
  s.circle_names.clear();
  return s;
}

// Radii far below the spacing of the doubles at the circles' positions.
//   0, 1  two circles of radius 2^-20 at (2^60, 0), v = ±1: they touch (d = 0), swap, and in the exact run
//         move apart by 1/30 per step. In doubles 2^60 ± 1/60 rounds to 2^60 (ulp 256): they stay put.
//   2, 3  radius 1 at (2^996, 2^996) (about 6.7e299), A moving 2^940 per step toward B at 2^996 + 2^944:
//         A reaches B's centre at step 16 (gap −2: d = 0). In doubles 2^996 + 2^940 rounds to 2^996
//         (ulp 2^944), so A never moves.
Scene huge_positions() {
  Scene s{"huge_tiny", "tiny radii at huge positions (2^60 and 2^996)", 600, {}, {}, {}};
  const double big = 0x1p996;
  s.circles = {
      {0x1p60, 0, 1, 0, 0x1p-20},
      {0x1p60, 0, -1, 0, 0x1p-20},
      {big, big, 60 * 0x1p940, 0, 1},
      {big + 0x1p944, big, 0, 0, 1},
  };
  s.designed = {{2, 3, 16, -2}};
  return s;
}

// Subnormal velocities, radius 2^-1070:
//   0, 1  v = 2^-1074 (the least subnormal) from 0: it moves 2^-1074/60 per step, below every double's
//         spacing, so every rounding engine leaves A where it is; the exact run has A at 10·2^-1074 at
//         step 600, touching B at 2^-1069 + 10·2^-1074.
//   2, 3  v = 60·2^-1074 from (0, 2^-1060): a move of exactly 2^-1074 per step, which doubles hold; A at
//         600·2^-1074 at step 600, touching B.
Scene subnormal() {
  Scene s{"subnormal", "subnormal velocities and radii", 1200, {}, {}, {}};
  const double r = 0x1p-1070, unit = 0x1p-1074;
  s.circles = {
      {0, 0, unit, 0, r},
      {2 * r + 10 * unit, 0, 0, 0, r},
      {0, 0x1p-1060, 60 * unit, 0, r},
      {2 * r + 600 * unit, 0x1p-1060, 0, 0, r},
  };
  s.designed = {{0, 1, 600, 0}, {2, 3, 600, 0}};
  return s;
}

// A long run of n steps (n a multiple of 100): pairs that touch only at its end. For n = 10^6 the rounding
// engines' A lands 2.83e-6 short of 150000 in pair 0, 1 and 6.7e-7 beyond 50000 in pair 2, 3.
//   0, 1  v = 9 from 0: A at 3n/20 at step n, B at 3n/20 + 2.
//   2, 3  v = 3 from (0, 100): A at n/20 at step n, B at n/20 + 2.
//   4, 5  v = (9, 12), r = 2.5, from (0, 1000): A at (3n/20, 1000 + n/5) at step n, B at A + (3, 4).
// (Each product and quotient below is an integer below 2^53, so exact in doubles.)
Scene long_run(std::uint64_t n) {
  if (n == 0 || n % 100 != 0) throw std::invalid_argument("the long run's steps must be a positive multiple of 100");
  const double N = static_cast<double>(n);
  Scene s{"long", "a long run: three pairs that touch after " + std::to_string(n) + " steps", n + 100, {}, {}, {}};
  s.circles = {
      {0, 0, 9, 0, 1},
      {3 * N / 20 + 2, 0, 0, 0, 1},
      {0, 100, 3, 0, 1},
      {N / 20 + 2, 100, 0, 0, 1},
      {0, 1000, 9, 12, 2.5},
      {3 * N / 20 + 3, 1000 + N / 5 + 4, 0, 0, 2.5},
  };
  s.designed = {{0, 1, n, 0}, {2, 3, n, 0}, {4, 5, n, 0}};
  return s;
}

// Clusters with many simultaneous contacts:
//   circles 0-47, a pile: radius 1, all at (0, 0) (every pair touches), v = (i − 24, (7i mod 13) − 6);
//   circle 48 and circles 49-68, a ring: a circle of radius 30 at rest at (3000, 0) and 20 of radius 2.5 that
//   start at 682.5·u from it and move at −65·u, for the 20 rational unit vectors u of (1, 0), (3, 4)/5,
//   (5, 12)/13 and their reflections: after 600 steps each has moved 650 and sits at 32.5·u, touching the
//   centre; all 20 tangencies come at once (neighbours stay apart: the least angle between two u is
//   14.25°, a chord of 8.06 > 5 at 32.5). 682.5·u and 65·u are doubles (682.5·3/5 = 409.5, 682.5·5/13 =
//   262.5, 65·5/13 = 25);
//   circles 69-168, a lattice: 10 × 10 at spacing 1 from (0, 3000), radius 2 (each touches up to 20 others),
//   integer velocities in [−30, 30].
Scene clusters() {
  Scene s{"clusters", "clusters: 48 circles at one point, 20 reaching one circle at once, a lattice of overlaps", 1200,
          {}, {}, {}};
  for (int i = 0; i < 48; ++i) s.circles.push_back({0, 0, i - 24.0, ((7 * i) % 13) - 6.0, 1});
  const std::uint32_t centre = 48;
  s.circles.push_back({3000, 0, 0, 0, 30});
  // u = (a, b)/c with a² + b² = c²; 682.5·a and 65·a are exact, and so are their quotients by c (doubles).
  std::vector<std::array<double, 3>> units = {{1, 0, 1}, {0, 1, 1}, {-1, 0, 1}, {0, -1, 1}};
  for (const auto& [a, b, c] : {std::array<double, 3>{3, 4, 5}, {4, 3, 5}, {5, 12, 13}, {12, 5, 13}})
    for (const double sa : {1.0, -1.0})
      for (const double sb : {1.0, -1.0}) units.push_back({sa * a, sb * b, c});
  for (const auto& [a, b, c] : units) {
    s.circles.push_back({3000 + 682.5 * a / c, 682.5 * b / c, -65 * a / c, -65 * b / c, 2.5});
    s.designed.push_back({static_cast<std::uint32_t>(s.circles.size() - 1), centre, 600, 0});
  }
  add_lattice(s, 10, 0, 3000, 1, 2, 7, 30);
  return s;
}

// Positions that leave the range of float, then of double, one circle each:
//   float_range   from 3·10^38 moving 10^36 per step (v = 6·10^37): beyond FLT_MAX ≈ 3.4028·10^38 at step 41,
//                 where the float variant's position becomes infinity; doubles hold it.
//   double_range  from DBL_MAX − 16·2^971 moving 2^971 (an ulp of DBL_MAX) per step: the exact position is
//                 DBL_MAX at step 16 and DBL_MAX + 2^971 at step 17, beyond the midpoint DBL_MAX + 2^970 where
//                 the nearest double becomes infinity, so the exact run stops at step 17 with PositionOverflow.
Scene float_range() {
  Scene s{"float_range", "a position that leaves the range of float", 100, {}, {}, {}};
  s.circles = {{3e38, 0, 6e37, 0, 1}};
  return s;
}
Scene double_range() {
  Scene s{"double_range", "a position that leaves the range of double", 100, {}, {}, {}};
  s.circles = {{std::numeric_limits<double>::max() - 16 * 0x1p971, 0, 60 * 0x1p971, 0, 1}};
  return s;
}

// A number as the JSON token that reads back as the same double: integers as integers.
nlohmann::json number(double x) {
  if (x == std::trunc(x) && std::fabs(x) < 0x1p53) return static_cast<std::int64_t>(x);
  return x;
}

}  // namespace

std::vector<Scene> bundled_scenes() { return {cradle(), dense(), random(), tangency_exact(), tangency_sixtieths()}; }

std::vector<Scene> stress_scenes(std::uint64_t long_steps) {
  const Scene base = tangency_sixtieths();
  return {scaled(base, -996, "1e-300"), scaled(base, -498, "1e-150"), scaled(base, 498, "1e150"),
          scaled(base, 990, "1e298"),   huge_positions(),           subnormal(),
          long_run(long_steps),         clusters(),                 float_range(),
          double_range()};
}

std::string scene_json(const Scene& scene) {
  std::string out = "{\n  \"name\": " + nlohmann::json(scene.name).dump() + ",\n  \"steps\": " +
                    std::to_string(scene.steps) + ",\n  \"circles\": [\n";
  for (std::size_t k = 0; k < scene.circles.size(); ++k) {
    const auto& c = scene.circles[k];
    const std::string name = k < scene.circle_names.size() ? scene.circle_names[k] : "";
    if (name.empty()) {
      out += "    [" + number(c[0]).dump() + ", " + number(c[1]).dump() + ", " + number(c[2]).dump() + ", " +
             number(c[3]).dump() + ", " + number(c[4]).dump() + "]";
    } else {
      // nlohmann::json objects sort their keys; the agreed order p, v, r, name is written by hand.
      out += "    {\"p\": [" + number(c[0]).dump() + ", " + number(c[1]).dump() + "], \"v\": [" + number(c[2]).dump() +
             ", " + number(c[3]).dump() + "], \"r\": " + number(c[4]).dump() + ", \"name\": " + nlohmann::json(name).dump() +
             "}";
    }
    out += k + 1 < scene.circles.size() ? ",\n" : "\n";
  }
  return out + "  ]\n}\n";
}

std::vector<Contact> designed_contacts(const Scene& scene, std::span<const Kind> kinds) {
  std::vector<Designed> pairs = scene.designed;
  std::sort(pairs.begin(), pairs.end(), [](const Designed& x, const Designed& y) { return x.step < y.step; });
  // The exact run's decisions first, then each variant's, on the worlds of the designed steps.
  std::vector<std::uint32_t> expected;
  {
    impl::ExactEngine engine(impl::World(scene.circles), impl::EngineOptions{.threads = 1});
    for (const Designed& d : pairs) {
      while (engine.steps() < d.step) engine.step();
      expected.push_back(exact_decisions(engine.exact())[d.a]);
    }
  }
  std::vector<Contact> out;
  for (const Kind kind : kinds) {
    std::unique_ptr<Variant> v;
    std::string end;
    std::uint64_t t = 0;
    try {
      v = make_variant(kind, scene.circles);
    } catch (const std::exception& e) {
      end = std::string("input refused: ") + e.what();
    }
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      Contact c{pairs[p], kind, std::nullopt, expected[p], end};
      try {
        for (; v && t < pairs[p].step; ++t) v->step();
        if (v) c.took = v->decisions()[pairs[p].a];
      } catch (const std::exception& e) {
        c.end = end = e.what();
        v.reset();
      }
      out.push_back(c);
    }
  }
  return out;
}

void check_designed(const Scene& scene) {
  if (scene.designed.empty()) return;
  // The steps to look at: step − 1 and step of each pair.
  std::map<std::uint64_t, std::vector<const Designed*>> at;
  for (const Designed& d : scene.designed) {
    at[d.step - 1].push_back(&d);
    at[d.step].push_back(&d);
  }
  impl::ExactEngine engine(impl::World(scene.circles), impl::EngineOptions{.threads = 1});
  for (const auto& [step, pairs] : at) {
    while (engine.steps() < step) engine.step();
    const spec::Sequence w = engine.exact();
    for (const Designed* d : pairs) {
      const spec::Circle &a = w[d->a], &b = w[d->b];
      const spec::Q reach = a.r + b.r + spec::exact(d->gap);
      const spec::Q distance2 = (b.p - a.p).squaredNorm();
      const bool ok = step == d->step ? reach >= 0 && distance2 == reach * reach : distance2 > reach * reach;
      if (!ok)
        throw std::logic_error(scene.id + ": circles " + std::to_string(d->a) + " and " + std::to_string(d->b) +
                               (step == d->step ? " are not at distance r_a + r_b + gap at step "
                                                : " are already that close at step ") +
                               std::to_string(step));
    }
  }
}

}  // namespace circles::bench::accuracy
