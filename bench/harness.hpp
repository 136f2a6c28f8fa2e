// How every stepping benchmark runs, so that engines, baselines and Box2D are timed alike.
//
// One benchmark is one configuration (a stepper on the scene formats::random_scene(n, coverage, kSceneSeed)).
// Each repetition builds fresh steppers outside the timed loop, takes one untimed warm-up step on each (the
// first step sorts a random-order input into whatever layout the stepper keeps; later steps start from the
// layout the previous step left, which is what a long run costs), then times one step per iteration.
//
// The scenes are open (no walls): circles drift apart at up to 100/60 per step, so a long run would thin a
// small scene out and measure a sparser one than asked for. Each stepper therefore takes only
// kStepsPerStepper timed steps (half a simulated second); small scenes get several independent copies,
// stepped one after another, so that every repetition covers about kCircleStepsPerRun circle-steps and is long
// enough to time (a few ms at the engines' speed). The iteration count is fixed, never calibrated.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace circles::bench {

inline constexpr std::uint64_t kSceneSeed = 1;
// 30 steps of 1/60: half a simulated second, in which a circle moves at most 50, about 1/15 of the side of
// the smallest scene (10^3 circles at 40% coverage: side √(10^3 · 54.5 / 0.4) ≈ 369, with 54.5 = π·E[r²] and
// E[r²] = (6³ − 2³)/(3·4) = 17.3 for r uniform in [2, 6]).
inline constexpr std::size_t kStepsPerStepper = 30;
inline constexpr std::size_t kCircleStepsPerRun = 3'000'000;  // 10^5 circles × 30 steps

// Coverage (a fraction) in percent as scripts/benchmarks' coverage_label writes it: a whole percent ("1",
// "40"), or one decimal ("0.1", "1.5", "12.5"). Throws std::invalid_argument for a coverage finer than a tenth
// of a percent, which one decimal cannot tell from its neighbours (0.05% and 0.1% would both be "0.1"), and for
// one that is negative or not finite.
inline std::string coverage_percent(double coverage) {
  // Each string built by appending: GCC 12 at -O3 warns falsely (-Wrestrict) of "text" + std::string.
  const auto refusal = [](double shown, const char* why) {
    char text[32];
    std::string message = "coverage ";
    message.append(text, std::to_chars(text, text + sizeof text, shown).ptr);
    message += why;
    return std::invalid_argument(message);
  };
  const double per_mille = coverage * 1000;  // tenths of a percent
  if (!std::isfinite(per_mille) || per_mille < 0) throw refusal(coverage, ": expected a fraction of the area, 0 or more");
  const double tenths = std::round(per_mille);
  if (std::abs(per_mille - tenths) > 1e-9 * std::max(1.0, per_mille))
    throw refusal(coverage * 100, "%: finer than a tenth of a percent, which benchmark names do not tell apart");
  const auto whole = static_cast<std::uint64_t>(tenths);
  std::string percent = std::to_string(whole / 10);
  if (whole % 10 != 0) {
    percent += '.';
    percent += static_cast<char>('0' + whole % 10);
  }
  return percent;
}

// The name of a configuration, <family>/coverage:<percent>/threads:<t>/n:<circles> (engine_bench and
// box2d_bench alike), and its counters coverage_pct and engine_threads, which scripts/benchmarks reads.
inline std::string configuration_name(const std::string& family, double coverage, unsigned threads, std::size_t n) {
  return family + "/coverage:" + coverage_percent(coverage) + "/threads:" + std::to_string(threads) +
         "/n:" + std::to_string(n);
}
inline std::vector<std::pair<std::string, double>> configuration_labels(double coverage, unsigned threads) {
  return {{"coverage_pct", coverage * 100}, {"engine_threads", threads}};
}

// Steppers per repetition for scenes of n circles, so a repetition covers about kCircleStepsPerRun.
inline std::size_t copies_for(std::size_t n, std::size_t steps) {
  return std::max<std::size_t>(1, kCircleStepsPerRun / (n * steps));
}

// Registers `name`: `copies` steppers from make() (each a std::unique_ptr to a type with step()), each
// warmed up by one step, then `steps` timed steps on each in turn. Reports real time (the engines use
// threads), items = circle-steps, and the counters the report script reads: circles, time_per_circle_step,
// plus `extra` (coverage_pct, engine_threads: not "threads", a field of Google Benchmark's own JSON).
template <class Make>
benchmark::internal::Benchmark* register_steps(const std::string& name, std::size_t n, std::size_t copies,
                                               std::size_t steps, Make make,
                                               const std::vector<std::pair<std::string, double>>& extra = {}) {
  auto run = [n, copies, steps, make, extra](benchmark::State& state) {
    std::vector<decltype(make())> steppers;
    for (std::size_t k = 0; k < copies; ++k) {
      steppers.push_back(make());
      steppers.back()->step();
    }
    std::size_t i = 0;
    // Iterations(copies · steps) makes i / steps < copies; the modulo only guards a run asked for more.
    for (auto _ : state) steppers[(i++ / steps) % copies]->step();
    const auto circle_steps = static_cast<double>(state.iterations()) * static_cast<double>(n);
    state.SetItemsProcessed(static_cast<std::int64_t>(circle_steps));
    // A rate counter divides by the measured time and kInvert turns it into seconds per circle-step, which
    // the console shows with an SI prefix ("12.3ns") and the JSON as a plain number of seconds.
    state.counters["time_per_circle_step"] =
        benchmark::Counter(circle_steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["circles"] = static_cast<double>(n);
    for (const auto& [key, value] : extra) state.counters[key] = value;
  };
  return benchmark::RegisterBenchmark(name.c_str(), run)
      ->Iterations(static_cast<benchmark::IterationCount>(copies * steps))
      ->UseRealTime()
      ->Unit(benchmark::kMillisecond);
}

// The main of a benchmark program: Google Benchmark's flags (an unknown one exits 2), then `ready()`, a
// self-check that exits 1 when false, then the benchmarks `register_all()` adds; an exception exits 1.
template <class Ready, class Register>
int bench_main(int argc, char** argv, const char* program, Ready ready, Register register_all) {
  try {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    if (!ready()) return 1;
    register_all();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 1;
  }
  return 0;
}

}  // namespace circles::bench
