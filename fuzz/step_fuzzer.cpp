// libFuzzer target for the engines' step (docs/hardening.md, "The step fuzzer"): each input, a world and K
// chained steps (fuzz/step_input.hpp), is stepped by the double engine (impl::DoubleEngine) and the exact engine
// (impl::ExactEngine), each with 1 and 2 threads and pair-list horizons 0 (the schedule's choice), 8 and 64,
// and every chain is held to a reference that shares no arithmetic with it (fuzz/step_judge.hpp):
//   double engine  the exact engine's rounded step from each world, itself held to impl::step_all_pairs (and on
//                  the oracle's sample to the oracle's rounded steps);
//   exact engine   the oracle's exact steps on its sample; else the chain of the first options, which every
//                  other option's chain must equal, whose first step rounded is the double reference's, and
//                  whose every world of doubles the double engine steps to the exact chain's next world rounded.
// A difference aborts with the world as a scene (fuzz::fail).
#include "fuzz/step_input.hpp"
#include "fuzz/step_judge.hpp"
#include "impl/engine.hpp"
#include "impl/exact_engine.hpp"

#include <array>
#include <string>

using namespace circles;

namespace {

constexpr std::array<unsigned, 2> kThreads = {1, 2};
constexpr std::array<std::uint64_t, 3> kHorizons = {0, 8, 64};

std::string options_name(const char* engine, const impl::EngineOptions& o) {
  return std::string(engine) + " (threads " + std::to_string(o.threads) + ", horizon " + std::to_string(o.horizon) +
         ")";
}

// K steps of an engine, to its first PositionOverflow.
template <class Engine, class Chain, class Read>
Chain run(Engine engine, std::uint64_t steps, Read read) {
  Chain chain;
  for (std::uint64_t t = 1; t <= steps; ++t) {
    try {
      engine.step();
    } catch (const impl::PositionOverflow& e) {
      chain.overflow = fuzz::Overflow{e.step, e.index, e.field};
      break;
    }
    chain.worlds.push_back(read(engine));
  }
  return chain;
}

fuzz::Chain double_chain(const fuzz::Circles& w0, std::uint64_t steps, const impl::EngineOptions& o) {
  return run<impl::DoubleEngine, fuzz::Chain>(impl::DoubleEngine(impl::World(w0), o), steps,
                                        [](const impl::DoubleEngine& e) { return e.world().circles(); });
}

fuzz::ExactChain exact_chain(const fuzz::Circles& w0, std::uint64_t steps, const impl::EngineOptions& o) {
  return run<impl::ExactEngine, fuzz::ExactChain>(impl::ExactEngine(impl::World(w0), o), steps,
                                                  [](const impl::ExactEngine& e) { return e.exact(); });
}

// The exact engine's chain rounded to doubles at each step: what a small world's chains are compared by off the
// oracle's sample, since the rationals of exact() would cost more than all the rest of the judging.
fuzz::Chain exact_chain_rounded(const fuzz::Circles& w0, std::uint64_t steps, const impl::EngineOptions& o) {
  return run<impl::ExactEngine, fuzz::Chain>(impl::ExactEngine(impl::World(w0), o), steps,
                                             [](const impl::ExactEngine& e) { return e.world().circles(); });
}

// The exact values of a world of doubles, or nothing when a coordinate of `w` is not a double.
std::optional<fuzz::Circles> as_doubles(const spec::Sequence& w) {
  fuzz::Circles out;
  for (const spec::Circle& c : w) {
    const spec::CircleDoubles d = spec::nearest_doubles(c);
    for (const double x : d)
      if (!std::isfinite(x)) return std::nullopt;
    if (!(spec::from_doubles(d, 0, spec::Radii::non_negative) == c)) return std::nullopt;
    out.push_back(d);
  }
  return out;
}

// A big world's exact chain against the double engine: step t + 1 from w_t wherever w_t is all doubles (w_0
// always is), where the exact step rounded must be the double engine's step by value.
std::optional<std::string> exact_against_double(const fuzz::Circles& w0, const fuzz::ExactChain& got) {
  std::optional<fuzz::Circles> from = w0;
  for (std::size_t t = 0; t <= got.worlds.size() && from; ++t) {
    const fuzz::Chain one = double_chain(*from, 1, {.threads = 1});
    fuzz::Chain exact_one;
    if (t < got.worlds.size()) {
      fuzz::Circles rounded;
      for (const spec::Circle& c : got.worlds[t]) rounded.push_back(spec::nearest_doubles(c));
      exact_one.worlds.push_back(std::move(rounded));
    } else if (got.overflow) {
      exact_one.overflow = got.overflow;
      exact_one.overflow->step = 1;
    } else {
      break;
    }
    if (auto d = fuzz::difference(one, exact_one)) return "from step " + std::to_string(t) + ": " + *d;
    if (t < got.worlds.size()) from = as_doubles(got.worlds[t]);
  }
  return std::nullopt;
}

// The first step of a chain, as a chain of one step.
template <class World>
fuzz::BasicChain<World> first_step(fuzz::BasicChain<World> chain) {
  if (chain.worlds.size() > 1) chain.worlds.resize(1);
  if (chain.worlds.size() == 1) chain.overflow.reset();
  return chain;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::StepInput input = fuzz::decode(std::span<const std::uint8_t>(data, size));
  const fuzz::Circles& w0 = input.circles;
  const bool small = w0.size() <= fuzz::kOracleCircles, oracle = fuzz::oracle_judges(input);
  const std::uint64_t steps = fuzz::judged_steps(input);
  const fuzz::Chain rounded = fuzz::judged_reference(input, steps);
  const fuzz::Chain first = first_step(rounded);
  // The exact chains' references: the oracle's exact steps on its sample; a big world's first options' chain, as
  // rationals, against the double engine's step from each of its worlds that is all doubles, and the other
  // options' chains against it; else, rounded, the first options' chain, whose first step must be the rounded
  // reference's, and which every other option's must equal.
  std::optional<fuzz::ExactChain> exact = oracle ? std::optional(fuzz::exact_reference(w0, steps)) : std::nullopt;
  std::optional<fuzz::Chain> first_options;
  for (const unsigned threads : kThreads)
    for (const std::uint64_t horizon : kHorizons) {
      const impl::EngineOptions o{.threads = threads, .keep_pairs = true, .horizon = horizon};
      const std::string exact_engine = options_name("the exact engine", o);
      if (auto d = fuzz::difference(rounded, double_chain(w0, steps, o)))
        fuzz::fail(input, options_name("the double engine", o), *d);
      if (exact || !small) {
        fuzz::ExactChain got = exact_chain(w0, steps, o);
        if (auto d = exact ? fuzz::difference(*exact, got) : exact_against_double(w0, got))
          fuzz::fail(input, exact_engine, *d);
        if (!exact) exact = std::move(got);  // a big world's first options' chain: the others must equal it
        continue;
      }
      fuzz::Chain got = exact_chain_rounded(w0, steps, o);
      if (auto d = fuzz::difference(first, first_step(got))) fuzz::fail(input, exact_engine, *d);
      if (!first_options) first_options = std::move(got);
      else if (auto d = fuzz::difference(*first_options, got)) fuzz::fail(input, exact_engine, *d);
    }
  return 0;
}
