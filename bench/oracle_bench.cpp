// How slow the oracle is, on purpose: one resolved and one literal step of (1) on worlds of n circles.
// The oracle is O(n^2) set operations on GMP rationals per step; these figures say how large a world the
// property suite and `circles conform` can afford to check against it.
#include "spec/oracle.hpp"

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace circles::spec;

// n circles of radius 2..6 on a square sized for about 10% coverage, velocities up to 100 per axis,
// all from doubles as an engine's input would be.
Sequence random_world(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const double side = std::sqrt(static_cast<double>(n) * 3.14159 * 16 / 0.10);
  std::uniform_real_distribution<double> pos(0, side), vel(-100, 100), rad(2, 6);
  Sequence w;
  for (std::size_t k = 0; k < n; ++k)
    w.push_back(from_doubles({pos(rng), pos(rng), vel(rng), vel(rng), rad(rng)}, k, Radii::positive));
  return w;
}

void resolved_step_of_n_circles(benchmark::State& state) {
  const Sequence w = random_world(static_cast<std::size_t>(state.range(0)), 1);
  for (auto _ : state) benchmark::DoNotOptimize(resolved_step(w));
  state.SetItemsProcessed(state.iterations() * state.range(0));  // circle-steps
}
BENCHMARK(resolved_step_of_n_circles)->RangeMultiplier(2)->Range(4, 256);

void literal_step_of_n_circles(benchmark::State& state) {
  const LiteralWorld w = literal_world(random_world(static_cast<std::size_t>(state.range(0)), 1));
  for (auto _ : state) benchmark::DoNotOptimize(literal_step(w));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(literal_step_of_n_circles)->RangeMultiplier(2)->Range(4, 256);

void nearest_double_of_a_step_result(benchmark::State& state) {
  const Q x = exact(123.456) + exact(-78.9) / 60;
  for (auto _ : state) benchmark::DoNotOptimize(nearest_double(x));
}
BENCHMARK(nearest_double_of_a_step_result);

}  // namespace

BENCHMARK_MAIN();
