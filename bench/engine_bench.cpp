// The engines' cost per circle-step and, in the same run, what it is measured against: the same engine with
// naive arithmetic, all-pairs steps, a plain uniform grid, and the streaming floor; the double engine
// (impl::DoubleEngine, family double_engine) and the exact engine (impl::ExactEngine, family exact_engine) at every
// coverage of the coverage sweep, and at 10% coverage also on the scene rounded to multiples of 2^-20 (families
// *_coarse, both engines), which the exact engine holds in 64-bit integers.
// Every scene is formats::random_scene(n, coverage, kSceneSeed); bench/harness.hpp says how steps are timed.
// scripts/benchmarks runs this program and writes docs/benchmarks.md from its JSON output.
//
// Names are <family>/coverage:<percent>/threads:<t>/n:<circles>, and the same figures are counters, so the
// report script needs no name parsing beyond the family.
#include "bench/baselines.hpp"
#include "bench/harness.hpp"
#include "impl/engine.hpp"
#include "impl/exact_engine.hpp"
#include "formats/random_scene.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

namespace circles::bench {
namespace {

constexpr std::size_t kSizes[] = {1'000, 10'000, 100'000, 1'000'000};
// The coverage sweep: 0.1% is the sparse scene (the sparse target: within 3 times the streaming floor), 10% the
// dense one (docs/benchmarks.md, Targets).
constexpr double kCoverages[] = {0.001, 0.01, 0.10, 0.40};
constexpr double kSparseCoverage = 0.001;
constexpr double kTargetCoverage = 0.10;  // the dense scene, where most engine targets are judged
constexpr unsigned kThreadCounts[] = {1, 2};
// All-pairs steps cost O(n²): 1.3 ms at 10^3 and 130 ms at 10^4 circles in one run, so they stop at 10^4 and
// take fewer steps there, for about a second per repetition.
constexpr std::size_t kAllPairsMax = 10'000;
std::size_t all_pairs_steps(std::size_t n) { return n < kAllPairsMax ? kStepsPerStepper : 5; }

// The scene of a configuration (each copy makes its own: at most 100 copies of 10^3 circles, untimed).
Circles scene(std::size_t n, double coverage) { return formats::random_scene(n, coverage, kSceneSeed); }

// The same scene with every value rounded to a multiple of 2^-20. Its common denominator is then at most
// D = 60·2^20 and every scaled position D·p below 2^41 (the side is 23,337 at 10^6 circles), so the exact
// engine holds it in 64-bit integers; the random scene's values need 2^-51 and finer (its radii 2 + 4u alone),
// which takes 128 (docs/exact-engine.md).
Circles coarse_scene(std::size_t n, double coverage) {
  Circles w = scene(n, coverage);
  for (auto& c : w)
    for (double& x : c) x = std::round(x * 0x1p20) * 0x1p-20;
  return w;
}

template <class EngineType>
void register_engine(const std::string& family, std::size_t n, double coverage, unsigned threads,
                     Circles (*make_scene)(std::size_t, double) = scene) {
  register_steps(configuration_name(family, coverage, threads, n), n, copies_for(n, kStepsPerStepper),
                 kStepsPerStepper,
                 [n, coverage, threads, make_scene] {
                   return std::make_unique<EngineType>(impl::World(make_scene(n, coverage)),
                                                   impl::EngineOptions{.threads = threads});
                 },
                 configuration_labels(coverage, threads));
}

// Wraps the reference engine's O(n²) exact step as a stepper.
struct AllPairsExact {
  explicit AllPairsExact(const Circles& circles) : world(circles) {}
  void step() { world = impl::step_all_pairs(world); }
  impl::World world;
};

template <class Stepper>
void register_baseline(const std::string& family, std::size_t n, std::size_t copies, std::size_t steps,
                       double coverage) {
  register_steps(configuration_name(family, coverage, 1, n), n, copies, steps,
                 [n, coverage] { return std::make_unique<Stepper>(scene(n, coverage)); },
                 configuration_labels(coverage, 1));
}

void register_all() {
  for (const std::size_t n : kSizes) {
    // Every family at every coverage: the coverage sweep (scripts/benchmarks picks the configurations it
    // runs). The plain grid is dense over the centres' bounding box: at 0.1% coverage and 10^6 circles that is
    // (side / 12)² = 10^6 · 54.5 / 0.001 / 144 = 3.8·10^8 cells (54.5 = π·E[r²], bench/harness.hpp), past its
    // cap of 2^28, so it starts at 1%.
    for (const double coverage : kCoverages) {
      for (const unsigned threads : kThreadCounts) register_engine<impl::DoubleEngine>("double_engine", n, coverage, threads);
      register_engine<impl::ExactEngine>("exact_engine", n, coverage, 1);
      if (coverage > kSparseCoverage)
        register_baseline<UniformGrid>("uniform_grid", n, copies_for(n, kStepsPerStepper), kStepsPerStepper,
                                       coverage);
      register_baseline<StreamingFloor>("streaming_floor", n, copies_for(n, kStepsPerStepper), kStepsPerStepper,
                                        coverage);
    }
    register_engine<impl::NaiveEngine>("engine_naive", n, kTargetCoverage, 1);
    register_engine<impl::ExactEngine>("exact_engine", n, kTargetCoverage, 2);
    register_engine<impl::DoubleEngine>("double_engine_coarse", n, kTargetCoverage, 1, coarse_scene);
    register_engine<impl::ExactEngine>("exact_engine_coarse", n, kTargetCoverage, 1, coarse_scene);
    if (n <= kAllPairsMax) {
      register_baseline<AllPairsNaive>("all_pairs_naive", n, 1, all_pairs_steps(n), kTargetCoverage);
      register_baseline<AllPairsExact>("all_pairs_exact", n, 1, all_pairs_steps(n), kTargetCoverage);
    }
  }
}

// The baselines must make the decisions they claim, or their figures compare unlike work. On a crowded scene
// (40% coverage: most circles touch another) the grid and all-pairs steps must give the same bits for a few
// steps (same arithmetic, same decisions), and their first step's velocities must be the exact reference's
// (the naive test differs from the exact one only within rounding of tangency, which random doubles miss).
bool baselines_agree() {
  constexpr std::size_t kCircles = 2000, kSteps = 3;
  const Circles start = formats::random_scene(kCircles, 0.40, kSceneSeed);
  AllPairsNaive all_pairs(start);
  UniformGrid grid(start);
  for (std::size_t s = 1; s <= kSteps; ++s) {
    all_pairs.step();
    grid.step();
    if (all_pairs.circles() != grid.circles()) {
      std::fprintf(stderr, "engine_bench: the uniform grid and all-pairs steps differ at step %zu\n", s);
      return false;
    }
  }
  AllPairsNaive first(start);
  first.step();
  const Circles exact = impl::step_all_pairs(impl::World(start)).circles();
  const Circles got = first.circles();
  for (std::size_t k = 0; k < kCircles; ++k)
    if (got[k][2] != exact[k][2] || got[k][3] != exact[k][3]) {
      std::fprintf(stderr, "engine_bench: circle %zu takes another velocity in the naive step than in the exact one\n",
                   k);
      return false;
    }
  return true;
}

}  // namespace
}  // namespace circles::bench

int main(int argc, char** argv) {
  return circles::bench::bench_main(argc, argv, "engine_bench", circles::bench::baselines_agree, circles::bench::register_all);
}
