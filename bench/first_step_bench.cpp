// The first step of a fresh process, for docs/benchmarks.md ("The first step and the runs of known length,
// measured by hand"): the double engine as `circles run --steps 1 --threads 1` steps it, or the plain grid of
// bench/baselines.hpp, on the benchmarks' random scene, in the scene's own order. The scene is made and the
// stepper built before the clock starts; the scene's copy is then given back, as `circles run` gives back its
// own before stepping. engine_bench's plain-grid figure is a steady step: after an untimed warm-up step, with
// its memory written and its circles left in cell order by the step before. This is the same stepper's first
// step, which pays for both, as the double engine's first step does.
//   first_step_bench --engine double|plain-grid --circles N [--coverage C] [--seed S]
// Prints one line: the engine, the scene and the step's milliseconds. One step per process: a second step
// in the same process would find its memory backed and its circles in order.
#include "bench/baselines.hpp"
#include "impl/engine.hpp"
#include "formats/random_scene.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>
#include <string>

namespace {

using Clock = std::chrono::steady_clock;

// Builds the stepper from `scene`, gives the scene back, and times one step: milliseconds.
template <class Stepper>
double first_step(circles::spec::Circles& scene) {
  Stepper stepper(scene);
  circles::spec::Circles().swap(scene);
  const auto start = Clock::now();
  stepper.step();
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The double engine as `circles run --steps 1 --threads 1` builds it.
struct DoubleEngineRun {
  explicit DoubleEngineRun(const circles::spec::Circles& scene)
      : engine(circles::impl::World(scene), {.threads = 1, .steps = 1}) {}
  void step() { engine.step(); }
  circles::impl::DoubleEngine engine;
};

}  // namespace

int main(int argc, char** argv) {
  enum class Engine { double_engine, plain_grid };
  const std::map<std::string, Engine> engines{{"double", Engine::double_engine}, {"plain-grid", Engine::plain_grid}};
  Engine engine{};
  std::size_t circles = 0;
  double coverage = 0.1;
  std::uint64_t seed = 1;
  CLI::App app{"The first step of a fresh process: the double engine or the plain grid on a random scene"};
  app.add_option("--engine", engine, "double or plain-grid")
      ->required()
      ->transform(CLI::CheckedTransformer(engines, CLI::ignore_case));
  app.add_option("--circles", circles, "Circles of the random scene (formats::random_scene)")
      ->required()
      ->check(CLI::Range(std::size_t{1}, std::size_t{std::numeric_limits<std::uint32_t>::max()}));
  app.add_option("--coverage", coverage, "The circles' area over their square's, in (0, 1]")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--seed", seed, "The scene's seed");
  CLI11_PARSE(app, argc, argv);
  try {
    circles::spec::Circles scene = circles::formats::random_scene(circles, coverage, seed);
    const double ms = engine == Engine::double_engine ? first_step<DoubleEngineRun>(scene)
                                                      : first_step<circles::bench::UniformGrid>(scene);
    std::printf("first_step_bench: %s, %zu circles, coverage %g, seed %llu: first step %.2f ms\n",
                engine == Engine::double_engine ? "double" : "plain-grid", circles, coverage,
                static_cast<unsigned long long>(seed), ms);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "first_step_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
