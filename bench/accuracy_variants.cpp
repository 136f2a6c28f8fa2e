// The variants of bench/accuracy.hpp, their decisions and errors, and the run that follows them beside the
// exact engine.
#include "bench/accuracy.hpp"

#include "impl/broad_phase.hpp"
#include "impl/exact_engine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace circles::bench::accuracy {
namespace {

using spec::Q;

constexpr impl::EngineOptions kOneThread{.threads = 1};

// ── The double variants: one template over the arithmetic ───────────────────────────────────────────

template <class A>
class EngineVariant final : public Variant {
 public:
  explicit EngineVariant(const Circles& scene) : engine_(impl::World(scene), kOneThread) {}

  void step() override { engine_.step(); }

  Decisions decisions() const override {
    // find_contacts of impl/engine.cpp on the same pairs with the same test and order: the least circle under
    // World::precedes among the candidates that A::intersect accepts.
    const impl::World w = engine_.world();
    Decisions least(w.size());
    std::iota(least.begin(), least.end(), std::uint32_t{0});
    const auto offer = [&](std::uint32_t a, std::uint32_t b) {
      if (least[a] == a || w.precedes(b, least[a])) least[a] = b;
    };
    for (const impl::CandidatePair& c : engine_.candidates())
      if (A::intersect(w.px()[c.i], w.py()[c.i], w.r()[c.i], w.px()[c.j], w.py()[c.j], w.r()[c.j])) {
        offer(c.i, c.j);
        offer(c.j, c.i);
      }
    return least;
  }

  std::variant<impl::World, spec::Sequence> state() const override { return engine_.world(); }

 private:
  impl::BasicEngine<A> engine_;
};

// Every field rounded to float, held as the double of that float (exact).
Circles to_float(const Circles& scene) {
  Circles out = scene;
  for (auto& circle : out)
    for (double& x : circle) x = static_cast<double>(static_cast<float>(x));
  return out;
}

class ExactVariant final : public Variant {
 public:
  explicit ExactVariant(const Circles& scene) : engine_(impl::World(scene), kOneThread) {}
  void step() override { engine_.step(); }
  Decisions decisions() const override { return exact_decisions(engine_.exact()); }
  std::variant<impl::World, spec::Sequence> state() const override { return engine_.exact(); }

 private:
  impl::ExactEngine engine_;
};

class OracleVariant final : public Variant {
 public:
  explicit OracleVariant(const Circles& scene) : w_(spec::from_doubles(scene, spec::Radii::non_negative)) {}
  void step() override { w_ = spec::resolved_step(w_); }
  Decisions decisions() const override { return exact_decisions(w_); }
  std::variant<impl::World, spec::Sequence> state() const override { return w_; }

 private:
  spec::Sequence w_;
};

// ── Errors ───────────────────────────────────────────────────────────────────────────────────────────

Q abs_of(Q x) { return x < 0 ? Q(-x) : x; }

// ulp(x) of the file comment for the exact x whose nearest double is `rounded`: the binade of x is that of
// `rounded`, except when `rounded` is a power of two above x (x rounded up into the next binade).
double ulp_of(const Q& x, double rounded) {
  const double a = std::fabs(rounded);
  if (a < 0x1p-1022) return 0x1p-1074;  // zero and the subnormal binade: spacing 2^-1074
  int e = std::ilogb(a);
  if (a == std::ldexp(1.0, e) && abs_of(x) < spec::exact(a)) --e;
  return std::ldexp(1.0, std::max(e, -1022) - 52);
}

// ── The run ──────────────────────────────────────────────────────────────────────────────────────────

bool finite_world(const impl::World& w) {
  for (const auto field : {w.px(), w.py(), w.vx(), w.vy(), w.r()})
    for (const double x : field)
      if (!std::isfinite(x)) return false;
  return true;
}

// True when every circle's velocity in `after` is the velocity its decision named in `before`.
bool velocities_follow(const std::variant<impl::World, spec::Sequence>& before,
                       const std::variant<impl::World, spec::Sequence>& after, const Decisions& d) {
  if (const auto* b = std::get_if<impl::World>(&before)) {
    const auto& a = std::get<impl::World>(after);
    for (std::size_t k = 0; k < d.size(); ++k)
      if (!(a.vx()[k] == b->vx()[d[k]] && a.vy()[k] == b->vy()[d[k]])) return false;
    return true;
  }
  const auto& b = std::get<spec::Sequence>(before);
  const auto& a = std::get<spec::Sequence>(after);
  for (std::size_t k = 0; k < d.size(); ++k)
    if (a[k].v != b[d[k]].v) return false;
  return true;
}

std::string circle_or_none(std::uint32_t k, std::uint32_t self) {
  return k == self ? std::string("none") : "circle " + std::to_string(k);
}

}  // namespace

std::string_view id_of(Kind kind) {
  switch (kind) {
    case Kind::float_naive: return "float_naive";
    case Kind::naive_sqrt: return "naive_sqrt";
    case Kind::naive_squares: return "naive_squares";
    case Kind::exact_decisions: return "exact_decisions";
    case Kind::double_engine: return "double_engine";
    case Kind::exact: return "exact";
    case Kind::oracle: return "oracle";
  }
  return "?";
}

std::unique_ptr<Variant> make_variant(Kind kind, const Circles& scene) {
  switch (kind) {
    case Kind::float_naive: return std::make_unique<EngineVariant<impl::FloatNaiveArithmetic>>(to_float(scene));
    case Kind::naive_sqrt: return std::make_unique<EngineVariant<impl::NaiveSqrtArithmetic>>(scene);
    case Kind::naive_squares: return std::make_unique<EngineVariant<impl::NaiveArithmetic>>(scene);
    case Kind::exact_decisions: return std::make_unique<EngineVariant<impl::ExactDecisionArithmetic>>(scene);
    case Kind::double_engine: return std::make_unique<EngineVariant<impl::RoundedArithmetic>>(scene);
    case Kind::exact: return std::make_unique<ExactVariant>(scene);
    case Kind::oracle: return std::make_unique<OracleVariant>(scene);
  }
  throw std::invalid_argument("make_variant: unknown kind");
}

std::size_t float_changes(const Circles& scene) {
  std::size_t changed = 0;
  for (const auto& circle : scene)
    for (const double x : circle) changed += static_cast<double>(static_cast<float>(x)) != x;
  return changed;
}

Decisions exact_decisions(const spec::Sequence& w) {
  // Boxes that contain [p − r, p + r] on each axis: mpq_get_d (Boost's convert_to) truncates, so each of
  // cx, cy, r is within ulp < 2^-52·|value| + 2^-1074 of the exact value; e covers the three errors with a
  // margin of 4 for its own roundings, and outward_lower/upper (impl/broad_phase.hpp) round outward.
  // Exactly intersecting circles have overlapping exact boxes, so their computed boxes overlap.
  struct Box {
    double xlo, xhi, ylo, yhi;
    std::uint32_t k;
  };
  constexpr double inf = std::numeric_limits<double>::infinity();
  const std::size_t n = w.size();
  std::vector<Box> boxes(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double cx = w[k].p.x().convert_to<double>(), cy = w[k].p.y().convert_to<double>();
    const double r = w[k].r.convert_to<double>();
    const double e = (std::max(std::fabs(cx), std::fabs(cy)) + r) * 0x1p-49 + 0x1p-1072;
    const double reach = impl::outward_upper(r, e);
    Box& b = boxes[k];
    b = {impl::outward_lower(cx, reach), impl::outward_upper(cx, reach), impl::outward_lower(cy, reach),
         impl::outward_upper(cy, reach), static_cast<std::uint32_t>(k)};
    if (!(std::isfinite(b.xlo) && std::isfinite(b.xhi) && std::isfinite(b.ylo) && std::isfinite(b.yhi)))
      b = {-inf, inf, -inf, inf, static_cast<std::uint32_t>(k)};  // beyond the doubles: meets everything
  }
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) { return a.xlo < b.xlo; });
  Decisions least(n);
  std::iota(least.begin(), least.end(), std::uint32_t{0});
  const auto precedes = [&](std::uint32_t a, std::uint32_t b) {
    const int s = spec::lex_compare(w[a], w[b]);
    return s < 0 || (s == 0 && a < b);
  };
  const auto offer = [&](std::uint32_t a, std::uint32_t b) {
    if (least[a] == a || precedes(b, least[a])) least[a] = b;
  };
  // Sort and sweep: every pair whose x-intervals overlap is met with the later-starting one inside.
  for (std::size_t s = 0; s < n; ++s)
    for (std::size_t t = s + 1; t < n && boxes[t].xlo <= boxes[s].xhi; ++t) {
      const Box &a = boxes[s], &b = boxes[t];
      if (a.ylo > b.yhi || b.ylo > a.yhi) continue;
      if (spec::intersect(w[a.k], w[b.k])) {
        offer(a.k, b.k);
        offer(b.k, a.k);
      }
    }
  return least;
}

spec::Sequence swept_step(const spec::Sequence& w) {
  const Decisions least = exact_decisions(w);
  spec::Sequence next;
  next.reserve(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) next.push_back(spec::u(spec::h(w[k], w[least[k]])));
  return next;
}

void Error::add_one(double p, const Q& x, double rounded) {
  // Filter: x is within half the gap above |rounded| of it, and the spacing of x's binade is at least the gap
  // below |rounded|; fl(|p − rounded|) is within a factor (1 + 2^-53) of the exact difference.
  const double a = std::fabs(rounded);
  const double up = std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
  const double down = a == 0 ? 0x1p-1074 : a - std::nextafter(a, 0.0);
  const double bound = (std::fabs(p - rounded) + up / 2) * (1 + 0x1p-50);
  if (bound <= abs_below_ && bound / down <= ulps) return;
  const Q d = abs_of(spec::exact(p) - x);
  if (d == 0) return;
  if (d > abs) {
    abs = d;
    abs_below_ = std::nextafter(d.convert_to<double>(), 0.0);
  }
  ulps = std::max(ulps, Q(d / spec::exact(ulp_of(x, rounded))).convert_to<double>());
}

void Error::add(const impl::World& w, const spec::Sequence& exact, const impl::World& rounded) {
  for (std::size_t k = 0; k < w.size(); ++k) {
    add_one(w.px()[k], exact[k].p.x(), rounded.px()[k]);
    add_one(w.py()[k], exact[k].p.y(), rounded.py()[k]);
  }
}

void Error::add(const spec::Sequence& w, const spec::Sequence& exact) {
  for (std::size_t k = 0; k < w.size(); ++k)
    for (int c = 0; c < 2; ++c) {
      const Q& p = w[k].p[c];
      const Q& x = exact[k].p[c];
      if (p == x) continue;
      const Q d = abs_of(p - x);
      if (d > abs) {
        abs = d;
        abs_below_ = std::nextafter(d.convert_to<double>(), 0.0);
      }
      ulps = std::max(ulps, Q(d / spec::exact(ulp_of(x, spec::nearest_double(x)))).convert_to<double>());
    }
}

void Error::add(const Error& other) {
  if (other.abs > abs) {
    abs = other.abs;
    abs_below_ = other.abs_below_;
  }
  ulps = std::max(ulps, other.ulps);
}

std::string Departure::describe() const {
  return "circle " + std::to_string(circle) + " took " + circle_or_none(took, circle) + " where the exact run took " +
         circle_or_none(exact_took, circle);
}

std::vector<Outcome> follow(const Circles& scene, std::uint64_t steps, std::span<const Kind> kinds,
                            std::uint64_t oracle_steps) {
  struct Run {
    Outcome out;
    std::unique_ptr<Variant> variant;
    std::uint64_t limit = 0;
    std::variant<impl::World, spec::Sequence> before;
    Decisions decided;
  };
  std::vector<Run> runs;
  for (const Kind kind : kinds) {
    Run run;
    run.out.kind = kind;
    run.limit = kind == Kind::oracle ? std::min(steps, oracle_steps) : steps;
    if (kind == Kind::float_naive) {
      if (const std::size_t changed = float_changes(scene))
        run.out.input = "rounded to float: " + std::to_string(changed) + " of " + std::to_string(5 * scene.size()) +
                        " fields change";
    }
    try {
      run.variant = make_variant(kind, scene);
    } catch (const std::exception& e) {
      run.out.end = std::string("input refused: ") + e.what();
    }
    runs.push_back(std::move(run));
  }
  impl::ExactEngine reference(impl::World(scene), kOneThread);
  spec::Sequence exact = reference.exact();
  impl::World rounded = reference.world();
  const auto measure = [&](Run& run) {
    run.before = run.variant->state();
    Error now;
    if (const auto* w = std::get_if<impl::World>(&run.before)) {
      if (!finite_world(*w)) {
        run.out.non_finite = true;
        run.out.end = "a NaN or infinity in the world";
        run.variant.reset();
        return;
      }
      now.add(*w, exact, rounded);
    } else {
      now.add(std::get<spec::Sequence>(run.before), exact);
    }
    run.out.error.add(now);
    if (!run.out.departure) run.out.error_before.add(now);
    if ((run.out.kind == Kind::exact || run.out.kind == Kind::oracle) && now.abs != 0)
      throw std::logic_error(std::string(id_of(run.out.kind)) + " differs from the exact run at step " +
                             std::to_string(run.out.steps));
  };
  for (Run& run : runs)
    if (run.variant) measure(run);
  for (std::uint64_t t = 1; t <= steps; ++t) {
    bool any = false, undecided = false;
    for (Run& run : runs) {
      if (run.variant && t > run.limit) run.variant.reset();
      any = any || run.variant;
      undecided = undecided || (run.variant && !run.out.departure);
    }
    if (!any) break;
    // Decisions of step t, on world t − 1, for the variants that have not departed yet.
    if (undecided) {
      const Decisions expected = exact_decisions(exact);
      for (Run& run : runs) {
        run.decided.clear();
        if (!run.variant || run.out.departure) continue;
        run.decided = run.variant->decisions();
        for (std::uint32_t k = 0; k < expected.size(); ++k)
          if (run.decided[k] != expected[k]) {
            run.out.departure = Departure{t, k, run.decided[k], expected[k]};
            if (run.out.kind == Kind::exact || run.out.kind == Kind::oracle)
              throw std::logic_error(std::string(id_of(run.out.kind)) + " departs from the exact run: " +
                                     run.out.departure->describe());
            break;
          }
      }
    }
    try {
      reference.step();
    } catch (const impl::PositionOverflow& e) {
      // No exact world t to compare with; each variant takes step t once more to show what it does there.
      for (Run& run : runs) {
        if (!run.variant) continue;
        try {
          run.variant->step();
          const auto now = run.variant->state();
          const auto* w = std::get_if<impl::World>(&now);
          run.out.non_finite = w && !finite_world(*w);
          run.out.end = std::string("took step ") + std::to_string(t) + " where the exact run stops (" + e.what() + ")";
        } catch (const std::exception& mine) {
          run.out.end = mine.what();
        }
        run.variant.reset();
      }
      break;
    }
    exact = reference.exact();
    rounded = reference.world();
    for (Run& run : runs) {
      if (!run.variant) continue;
      try {
        run.variant->step();
      } catch (const std::exception& e) {
        run.out.end = e.what();
        run.variant.reset();
        continue;
      }
      run.out.steps = t;
      const auto before = std::move(run.before);
      measure(run);
      if (run.variant && !run.decided.empty() && !velocities_follow(before, run.before, run.decided))
        throw std::logic_error(std::string(id_of(run.out.kind)) + ": the velocities after step " + std::to_string(t) +
                               " are not those its decisions name");
    }
  }
  std::vector<Outcome> out;
  for (Run& run : runs) out.push_back(std::move(run.out));
  return out;
}

std::optional<double> ns_per_circle_step(Kind kind, const Circles& scene, std::uint64_t steps, int repetitions) {
  if (scene.empty() || steps == 0) return std::nullopt;
  std::vector<double> times;
  for (int r = 0; r < repetitions; ++r) {
    try {
      const std::unique_ptr<Variant> v = make_variant(kind, scene);
      const auto start = std::chrono::steady_clock::now();
      for (std::uint64_t t = 0; t < steps; ++t) v->step();
      const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - start;
      times.push_back(took.count() / (static_cast<double>(steps) * static_cast<double>(scene.size())));
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  std::sort(times.begin(), times.end());
  const std::size_t m = times.size();
  return m % 2 ? times[m / 2] : (times[m / 2 - 1] + times[m / 2]) / 2;
}

}  // namespace circles::bench::accuracy
