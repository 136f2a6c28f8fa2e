#include "engines/registry.hpp"

#include "impl/engine.hpp"
#include "impl/exact_engine.hpp"
#include "spec/oracle.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace circles::engines {

void Stepper::step() {
  if (const auto overflow = advance()) throw StepOverflow(steps_ + 1, overflow->index, overflow->field);
  ++steps_;
}

formats::CircleSource Stepper::source() const {
  auto held = std::make_shared<const Circles>(circles());
  return [held, whole = formats::source_of(*held)](std::size_t first, std::span<spec::CircleDoubles> out) {
    whole(first, out);
  };
}

namespace {

// An engine of impl/ (impl::DoubleEngine or impl::ExactEngine): its step, with PositionOverflow as an Overflow.
template <class E>
class ImplStepper final : public Stepper {
 public:
  ImplStepper(const Circles& world, unsigned threads, std::uint64_t steps)
      : engine_(impl::World(world), impl::EngineOptions{.threads = threads, .steps = steps}) {}
  Circles circles() const override { return engine_.world().circles(); }
  formats::CircleSource source() const override {
    if constexpr (requires { engine_.slots(); }) {
      auto slots = std::make_shared<const std::vector<std::uint32_t>>(engine_.slots());
      return [this, slots](std::size_t first, std::span<spec::CircleDoubles> out) {
        engine_.read_circles(*slots, first, out);
      };
    } else {
      return Stepper::source();
    }
  }
  std::optional<spec::Sequence> exact() const override {
    if constexpr (requires { engine_.exact(); }) return engine_.exact();
    return std::nullopt;
  }
  std::optional<impl::EngineStats> work() const override {
    if constexpr (requires { engine_.stats(); }) return engine_.stats();
    return std::nullopt;
  }
  const impl::ThreadCount* threads() const override { return &engine_.thread_count(); }

 private:
  std::optional<Overflow> advance() override {
    try {
      engine_.step();
    } catch (const impl::PositionOverflow& e) {
      return Overflow{e.index, e.field};
    }
    return std::nullopt;
  }
  E engine_;
};

// spec::resolved_step_rounded: the exact step in rationals, rounded. Slow, and the reference of every other.
class OracleStepper final : public Stepper {
 public:
  OracleStepper(const Circles& world, unsigned, std::uint64_t) : world_(world) {}
  Circles circles() const override { return world_; }
  formats::CircleSource source() const override { return formats::source_of(world_); }

 private:
  std::optional<Overflow> advance() override {
    Circles next = spec::resolved_step_rounded(world_);  // rounds a position beyond DBL_MAX to ±infinity
    for (std::size_t k = 0; k < next.size(); ++k)
      for (const spec::Field f : {spec::Field::px, spec::Field::py})
        if (!std::isfinite(next[k][static_cast<std::size_t>(f)])) return Overflow{k, f};
    world_ = std::move(next);
    return std::nullopt;
  }
  Circles world_;
};

// spec::resolved_step on the exact sequence from w_0, each world rounded: the reference of the exact engines.
class ExactOracleStepper final : public Stepper {
 public:
  explicit ExactOracleStepper(const Circles& world) : world_(spec::from_doubles(world, spec::Radii::non_negative)) {}
  Circles circles() const override {
    Circles out;
    for (const spec::Circle& c : world_) out.push_back(spec::nearest_doubles(c));
    return out;
  }
  std::optional<spec::Sequence> exact() const override { return world_; }

 private:
  std::optional<Overflow> advance() override {
    spec::Sequence next = spec::resolved_step(world_);
    for (std::size_t k = 0; k < next.size(); ++k)
      for (const spec::Field f : {spec::Field::px, spec::Field::py}) {
        const spec::Q& p = f == spec::Field::px ? next[k].p.x() : next[k].p.y();
        if (!std::isfinite(spec::nearest_double(p))) return Overflow{k, f};
      }
    world_ = std::move(next);
    return std::nullopt;
  }
  spec::Sequence world_;
};

template <class S>
std::unique_ptr<Stepper> start(const Circles& world, unsigned threads, std::uint64_t steps) {
  return std::make_unique<S>(world, threads, steps);
}

// bytes_per_circle: the peak resident memory of `circles run --engine NAME` on random scenes (/usr/bin/time's
// maximum resident set size, less the 8 MB of an empty run), divided by the circles, on Debian 12 x86-64 with
// glibc's malloc:
//   double   207-210 bytes (1e6 and 4e6 circles, 1 to 20 steps, 1 or 2 threads): the engine's five arrays,
//            their next-step copies, its cell keys and index arrays, and the scene
//   exact    370 bytes (1e6 circles): integers over a common denominator, wider than doubles
//   oracle   1560 bytes (4000 circles, 1 step): the exact rationals of two worlds
// Each bound is the figure with 20-40% to spare, rounded to a power of two, so that a world the check lets
// through fits; a count between the figure and the bound is refused though it might have fitted, which is the
// side to err on, since with Linux's overcommit the alternative is the OOM killer.
constexpr std::array kEngines{
    EngineEntry{"double",
                "the double engine of impl/: exact decisions, correctly rounded positions, a broad phase, threads",
                true, false, 256, &start<ImplStepper<impl::DoubleEngine>>},
    EngineEntry{"exact",
                "the exact engine of impl/: the oracle's exact sequence in integers, each output rounded; a broad "
                "phase, threads",
                true, true, 512, &start<ImplStepper<impl::ExactEngine>>},
    EngineEntry{"oracle", "the exact oracle of spec/, rounded to doubles: the reference, slow, one thread", false,
                false, 2048, &start<OracleStepper>},
};

}  // namespace

std::span<const EngineEntry> engines() { return kEngines; }

unsigned max_threads() { return impl::DoubleEngine::kMaxThreads; }

std::string engine_names() {
  std::string names;
  for (const EngineEntry& e : kEngines) (names += names.empty() ? "" : ", ") += e.name;
  return names;
}

const EngineEntry* find_engine(std::string_view name) {
  for (const EngineEntry& e : kEngines)
    if (e.name == name) return &e;
  return nullptr;
}

UnknownEngine::UnknownEngine(std::string_view name)
    : std::invalid_argument("unknown engine \"" + std::string(name) + "\" (the engines are: " + engine_names() + ")") {}

const EngineEntry& engine(std::string_view name) {
  const EngineEntry* e = find_engine(name);
  if (!e) throw UnknownEngine(name);
  return *e;
}

std::unique_ptr<Stepper> reference(const EngineEntry& engine, const Circles& world) {
  if (engine.exact) return std::make_unique<ExactOracleStepper>(world);
  return engines::engine("oracle").start(world, 1, 0);
}

Circles step_once(const EngineEntry& engine, const Circles& world, unsigned threads) {
  const auto stepper = engine.start(world, threads, 1);
  stepper->step();
  return stepper->circles();
}

}  // namespace circles::engines
