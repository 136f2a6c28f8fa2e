#include "fuzz/step_judge.hpp"

#include "impl/engine.hpp"
#include "impl/exact_engine.hpp"
#include "impl/exact_grid_reference.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

namespace circles::fuzz {

namespace {

// The first circle, px before py, whose position is not finite.
std::optional<Overflow> first_overflow(const Circles& w, std::uint64_t step) {
  for (std::size_t k = 0; k < w.size(); ++k)
    for (std::size_t f = 0; f < 2; ++f)
      if (!std::isfinite(w[k][f])) return Overflow{step, k, f == 0 ? spec::Field::px : spec::Field::py};
  return std::nullopt;
}

std::optional<Overflow> first_overflow(const spec::Sequence& w, std::uint64_t step) {
  for (std::size_t k = 0; k < w.size(); ++k)
    for (std::size_t f = 0; f < 2; ++f)
      if (!std::isfinite(spec::nearest_double(w[k].p[static_cast<Eigen::Index>(f)])))
        return Overflow{step, k, f == 0 ? spec::Field::px : spec::Field::py};
  return std::nullopt;
}

std::string describe(const std::optional<Overflow>& o) {
  if (!o) return "no overflow";
  std::ostringstream out;
  out << "an overflow at step " << o->step;
  if (o->index != Overflow::kUnknown) out << ", circle " << o->index << ' ' << spec::name(o->field);
  return out.str();
}

template <class World>
std::optional<std::string> chain_difference(const BasicChain<World>& want, const BasicChain<World>& got) {
  const std::size_t common = std::min(want.worlds.size(), got.worlds.size());
  for (std::size_t t = 0; t < common; ++t) {
    const World& a = want.worlds[t];
    const World& b = got.worlds[t];
    if (a.size() != b.size())
      return "step " + std::to_string(t + 1) + ": " + std::to_string(b.size()) + " circles, not " +
             std::to_string(a.size());
    for (std::size_t k = 0; k < a.size(); ++k)
      if (!(a[k] == b[k])) {  // by value: −0 == +0 for doubles, and rationals have one zero
        std::ostringstream out;
        out << "step " << t + 1 << ", circle " << k << ": got ";
        if constexpr (std::is_same_v<World, Circles>) {
          for (const double x : b[k]) out << std::hexfloat << x << ' ';
          out << "want ";
          for (const double x : a[k]) out << std::hexfloat << x << ' ';
        } else {
          out << b[k] << " want " << a[k];
        }
        return out.str();
      }
  }
  if (want.worlds.size() != got.worlds.size() || want.overflow.has_value() != got.overflow.has_value())
    return "after " + std::to_string(common) + " steps alike: " + describe(got.overflow) + ", want " +
           describe(want.overflow);
  if (want.overflow && got.overflow) {
    const Overflow &a = *want.overflow, &b = *got.overflow;
    if (a.step != b.step || (b.index != Overflow::kUnknown && (a.index != b.index || a.field != b.field)))
      return describe(got.overflow) + ", want " + describe(want.overflow);
  }
  return std::nullopt;
}

}  // namespace

std::uint64_t judged_steps(const StepInput& input) {
  return input.circles.size() <= kOracleCircles ? input.steps : std::min(input.steps, kBigSteps);
}

Chain chain_of(const Circles& w0, std::uint64_t steps, const RoundedStep& one) {
  Chain chain;
  const Circles* now = &w0;
  for (std::uint64_t t = 1; t <= steps; ++t) {
    Chain next = one(*now);
    if (next.overflow) {
      chain.overflow = next.overflow;
      chain.overflow->step = t;
      break;
    }
    chain.worlds.push_back(std::move(next.worlds.at(0)));
    now = &chain.worlds.back();
  }
  return chain;
}

bool oracle_judges(const StepInput& input) {
  if (input.circles.size() > kOracleCircles) return false;
  // FNV-1a over the steps and the bits of every number.
  std::uint64_t hash = 0xcbf29ce484222325;
  const auto mix = [&hash](std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) hash = (hash ^ ((word >> (8 * byte)) & 0xff)) * 0x100000001b3;
  };
  mix(input.steps);
  for (const auto& c : input.circles)
    for (const double x : c) mix(std::bit_cast<std::uint64_t>(x));
  return hash % kOracleSample == 0;
}

namespace {

// One step of a reference engine or step from w, as a chain of one world or of the overflow that stops it.
template <class Step>
Chain one_step(Step step) {
  try {
    return Chain{{step()}, std::nullopt};
  } catch (const impl::PositionOverflow& e) {
    return Chain{{}, Overflow{e.step, e.index, e.field}};
  }
}

}  // namespace

Chain exact_engine_reference(const Circles& w0, std::uint64_t steps) {
  return chain_of(w0, steps, [](const Circles& w) {
    return one_step([&] {
      impl::ExactEngine engine(impl::World{w}, {.threads = 1});
      engine.step();
      return engine.world().circles();
    });
  });
}

Chain all_pairs_reference(const Circles& w0, std::uint64_t steps) {
  return chain_of(w0, steps, [](const Circles& w) { return one_step([&] { return impl::step_all_pairs(impl::World{w}).circles(); }); });
}

Chain judged_reference(const StepInput& input, std::uint64_t steps) {
  Chain exact = exact_engine_reference(input.circles, steps);
  if (auto d = difference(exact, all_pairs_reference(input.circles, steps)))
    fail(input, "impl::step_all_pairs against the exact engine's rounded step (the references)", *d);
  if (oracle_judges(input))
    if (auto d = difference(rounded_reference(input.circles, steps), exact))
      fail(input, "the exact engine's rounded step against the oracle's (the references)", *d);
  return exact;
}

Chain rounded_reference(const Circles& w0, std::uint64_t steps) {
  if (w0.size() <= kOracleCircles)
    return chain_of(w0, steps, [](const Circles& w) {
      Circles next = spec::resolved_step_rounded(w);
      if (auto overflow = first_overflow(next, 1)) return Chain{{}, overflow};
      return Chain{{std::move(next)}, std::nullopt};
    });
  return chain_of(w0, steps, [](const Circles& w) {
    return one_step([&] {
      impl::ExactGrid grid(w);
      grid.step();
      return grid.rounded();
    });
  });
}

ExactChain exact_reference(const Circles& w0, std::uint64_t steps) {
  ExactChain chain;
  spec::Sequence now;
  for (std::size_t k = 0; k < w0.size(); ++k) now.push_back(spec::from_doubles(w0[k], k, spec::Radii::non_negative));
  for (std::uint64_t t = 1; t <= steps; ++t) {
    spec::Sequence next = spec::resolved_step(now);
    if ((chain.overflow = first_overflow(next, t))) break;
    chain.worlds.push_back(next);
    now = std::move(next);
  }
  return chain;
}

std::optional<std::string> difference(const Chain& want, const Chain& got) { return chain_difference(want, got); }
std::optional<std::string> difference(const ExactChain& want, const ExactChain& got) {
  return chain_difference(want, got);
}

std::string scene_text(const Circles& w, std::uint64_t steps, const std::string& name) {
  std::string out = "{\"name\": \"" + name + "\", \"steps\": " + std::to_string(steps) + ", \"circles\": [";
  for (std::size_t k = 0; k < w.size(); ++k) {
    out += k == 0 ? "\n  [" : ",\n  [";
    for (std::size_t f = 0; f < 5; ++f) {
      char digits[32];
      const auto end = std::to_chars(digits, digits + sizeof digits, w[k][f]).ptr;
      if (f > 0) out += ", ";
      out.append(digits, end);
    }
    out += ']';
  }
  out += "\n]}\n";
  return out;
}

void fail(const StepInput& input, const std::string& who, const std::string& what) {
  const char* named = std::getenv("CIRCLES_STEP_FUZZER_SCENE");
  const std::string path = named != nullptr && *named != '\0' ? named : "step_fuzzer-failure.json";
  std::ofstream(path) << scene_text(input.circles, judged_steps(input), "step fuzzer: " + who + " differs from its reference");
  std::cerr << "step fuzzer: " << who << ", " << input.circles.size() << " circles, " << judged_steps(input)
            << " steps: " << what << "\n  the world is the scene " << path << ", whose \"steps\" are the steps judged."
            << "\n  Replay: the fuzzer with libFuzzer's crash file (the input) as its argument, the same engine options"
            << "\n  and references; or circles run " << path << " --engine double --trace t.jsonl, then"
            << "\n  circles check-trace t.jsonl, which holds the trace to the oracle step by step (docs/vectors.md).\n";
  std::abort();
}

}  // namespace circles::fuzz
