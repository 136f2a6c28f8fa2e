// The speed of `circles conform`: worlds checked per second in process, and what the step protocol adds per
// request beyond the candidate's own time (the conform throughput and protocol overhead targets,
// docs/benchmarks.md, Targets). scripts/benchmarks runs this program and writes the conform section of
// docs/benchmarks.md from its JSON output.
//
// Every benchmark works on the cases conform draws by default: seed kSeed, kRounds rounds of one case per
// boundary family (properties/boundaries.hpp), worlds of up to 8 circles, level exact. The "asked" worlds are
// those conform puts to the candidate, recorded from a run (asked_worlds): one per case and step of its
// chain, less the cases conform skips (their next world leaves the double range; it computes their expected
// answer and asks nothing). Every figure is per asked world, a request, so that the figures of one run
// subtract.
//
//   conform_in_process/engine:E/profile:P   conform::check on conform::EngineCandidate (`circles conform --engine E
//                                           --threads 1`): drawing, the expected answer, the engine's step and
//                                           the comparison: A per world (its CPU time: worlds per second per core).
//   conform_protocol/serve:double           conform::check on conform::ProcessCandidate running `circles serve
//                                           --engine double --threads 1` (`circles conform --exec ...`): the
//                                           same work, the step done by the other process, and the protocol.
//                                           Real time: P per request.
//   candidate_step/engine:double            engines::step_once on each asked world: S, the engine's step alone,
//                                           the part of A that the protocol run does in the other process.
//   candidate_answer/engine:double          conform::answer on each asked world's request line: C, what `circles
//                                           serve` does per request short of reading and writing its pipes
//                                           (parse the request, step, format the response): the candidate's
//                                           own time.
//   pipe_echo/worlds                        conform::ProcessCandidate running `cat` on the asked worlds, in the
//                                           batches conform sends them in (conform::Candidate::answer_all; Relay
//                                           records them): conform's side of the protocol (format the requests,
//                                           write, wait, read, parse the answers) with a candidate that does
//                                           nothing but echo.
//   pipe_echo/empty                         the empty world, {"id":N,"circles":[]}, one request at a time: the
//                                           pipe round trip itself, which a batch of requests pays once.
//
// The protocol's overhead per request is then O = P − (A − S) − C: the request's time through the pipes less
// the checker's own work (A − S) less the candidate's own (C). What is left is conform formatting requests and
// parsing answers, both processes' reads and writes, and the wake-ups between them, which a batch of requests
// shares (conform_protocol's counter requests_per_batch says how many it had on average). In wall-clock
// time the two processes also overlap within a batch (conform parses an answer while the candidate steps the
// next world), which the CPU time does not count as a saving. scripts/benchmarks
// computes it from the medians, twice: in wall-clock time (what a request takes) and in CPU time (the work the
// protocol adds, which the machine's load does not inflate: P's CPU time is then conform's plus the candidate
// process's, which the counter child_cpu_per_item gives); docs/benchmarks.md says so beside the figures.
#include "bench/harness.hpp"
#include "conform/candidate.hpp"
#include "conform/conform.hpp"
#include "engines/registry.hpp"
#include "formats/protocol.hpp"
#include "conform/serve.hpp"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::bench {
namespace {

using spec::Circles;
using properties::Profile;

constexpr std::uint64_t kSeed = 1;
// 100 rounds: 2,600 resolved cases (26 families), 1,600 literal ones (16): more than the default --cases 1000,
// in whole rounds, so that every family weighs the same, as in a long run. The big families' cases are left out
// (Options::skip): these figures are the cost per world of up to 8 circles; a big world's is the candidate's.
constexpr std::uint64_t kRounds = 100;
constexpr std::chrono::milliseconds kDeadline{10'000};  // conform's default --timeout
// Iterations are fixed, never calibrated (bench/harness.hpp): each conform iteration takes 0.05-0.2 s here.
constexpr benchmark::IterationCount kConformIterations = 5;
constexpr benchmark::IterationCount kPassIterations = 20;  // passes over the asked worlds
constexpr benchmark::IterationCount kEmptyRoundTrips = 20'000;

std::uint64_t cases(Profile profile) { return kRounds * properties::families(profile).size(); }

conform::Options default_cases(Profile profile) {
  conform::Options options;
  options.cases = cases(profile);
  options.seed = kSeed;
  options.profile = profile;
  for (const properties::Family f : properties::families(profile))
    if (properties::is_big(f)) options.skip.push_back(f);
  return options;
}

// A candidate behind conform that counts its requests and the batches conform sends them in
// (conform::Candidate::answer_all) and, given a list, records each world asked. It does
// not pass on the end of the input (conform ends each run with finish(), which would close a process's
// input): a process candidate then lasts over a benchmark's iterations, its start-up and exit outside the
// timing, which is per request, and the benchmark finishes it itself.
class Relay : public conform::Candidate {
 public:
  explicit Relay(conform::Candidate& inner, std::vector<Circles>* record = nullptr) : inner_(inner), record_(record) {}
  Circles answer(const Circles& world, std::uint64_t id) override {
    return std::move(answer_all(std::span(&world, 1), id).all().front());
  }
  // Passed on whole, so that a process candidate gets conform's batches as conform sends them.
  conform::Answers answer_all(std::span<const Circles> worlds, std::uint64_t first_id,
                              std::span<const conform::Spelling> spellings = {}) override {
    requests += worlds.size();
    batches.push_back(worlds.size());
    if (record_) record_->insert(record_->end(), worlds.begin(), worlds.end());
    return inner_.answer_all(worlds, first_id, spellings);
  }
  std::string name() const override { return inner_.name(); }
  std::uint64_t requests = 0;
  std::vector<std::size_t> batches;  // the requests of each batch, in order

 private:
  conform::Candidate& inner_;
  std::vector<Circles>* record_;
};

// Runs conform once on `candidate`; a verdict other than "conforms" is the benchmark's error, not a figure.
void check(conform::Candidate& candidate, Profile profile) {
  const conform::Verdict verdict = conform::check(candidate, default_cases(profile));
  if (verdict.outcome != conform::Outcome::conforms)
    throw std::runtime_error(std::string("conform's verdict: ") + conform::name(verdict.outcome) + " " + verdict.error);
}

// The worlds conform asks a conforming candidate, in order, recorded from a run on the double engine, and,
// given a list, the requests of each batch it sends them in.
std::vector<Circles> asked_worlds(Profile profile, std::vector<std::size_t>* batches = nullptr) {
  conform::EngineCandidate engine(engines::engine("double"), 1);
  std::vector<Circles> asked;
  Relay recorder(engine, &asked);
  check(recorder, profile);
  if (batches) *batches = recorder.batches;
  return asked;
}

// `circles serve` built beside this program (CMake passes its path).
std::string serve_command() {
  return "exec '" + std::string(CIRCLES_PROGRAM) + "' serve --engine double --threads 1";
}

// items = what one iteration handled (worlds, requests); the report script divides the iteration's time by
// the counter items_per_iteration, for real and CPU time alike.
void count(benchmark::State& state, std::size_t items_per_iteration) {
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(items_per_iteration));
  state.counters["items_per_iteration"] = static_cast<double>(items_per_iteration);
}

// The CPU time, user and system, of this process's children that have exited and been waited for.
double children_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The CPU time of a candidate process per item: the children's CPU time from before it started (`before`) to
// after it was waited for, over the items of the run. Its start-up and its first, untimed request are in it
// (`circles serve` takes 10-20 ms of CPU time to start: 1-2 µs per request over a run of 5 × 1,700), which
// errs towards a larger overhead.
void count_child_cpu(benchmark::State& state, std::size_t items_per_iteration, double before) {
  const double items = static_cast<double>(state.iterations()) * static_cast<double>(items_per_iteration);
  state.counters["child_cpu_per_item"] = (children_cpu_seconds() - before) / items;
}

// Runs conform on `candidate` once per iteration. Returns the requests of one iteration (every iteration
// asks the same worlds).
std::size_t run_conform(benchmark::State& state, conform::Candidate& candidate, Profile profile) {
  Relay relay(candidate);
  for (auto _ : state) check(relay, profile);
  const auto asked = static_cast<std::size_t>(relay.requests / static_cast<std::uint64_t>(state.iterations()));
  count(state, asked);
  state.counters["requests_per_batch"] = static_cast<double>(relay.requests) / static_cast<double>(relay.batches.size());
  return asked;
}

void conform_in_process(benchmark::State& state, const char* engine, Profile profile) {
  conform::EngineCandidate candidate(engines::engine(engine), 1);
  run_conform(state, candidate, profile);
}

void conform_protocol(benchmark::State& state) {
  const double before = children_cpu_seconds();
  conform::ProcessCandidate serve(serve_command(), kDeadline);
  serve.answer({}, 0);  // untimed: waits for the program to start and load
  const std::size_t asked = run_conform(state, serve, Profile::resolved);
  serve.finish();
  count_child_cpu(state, asked, before);
}

void candidate_step(benchmark::State& state) {
  const std::vector<Circles> worlds = asked_worlds(Profile::resolved);
  const engines::EngineEntry& engine = engines::engine("double");
  for (auto _ : state)
    for (const Circles& w : worlds) benchmark::DoNotOptimize(engines::step_once(engine, w, 1));
  count(state, worlds.size());
}

void candidate_answer(benchmark::State& state) {
  std::vector<std::string> requests;
  for (const Circles& w : asked_worlds(Profile::resolved))
    requests.push_back(formats::format_line(formats::kId, requests.size() + 1, w));
  const engines::EngineEntry& engine = engines::engine("double");
  for (auto _ : state)
    for (std::size_t k = 0; k < requests.size(); ++k)
      benchmark::DoNotOptimize(conform::answer(engine, 1, requests[k], k + 1));
  count(state, requests.size());
}

void pipe_echo(benchmark::State& state, bool empty) {
  // The asked worlds in conform's batches; the empty world alone, one round trip per request.
  std::vector<std::size_t> batches{1};
  const std::vector<Circles> worlds = empty ? std::vector<Circles>(1) : asked_worlds(Profile::resolved, &batches);
  const double before = children_cpu_seconds();
  conform::ProcessCandidate cat("exec cat", kDeadline);
  std::uint64_t id = 0;
  cat.answer({}, id++);  // untimed: waits for cat to start
  for (auto _ : state) {
    std::span<const Circles> rest = worlds;
    for (const std::size_t n : batches) {
      benchmark::DoNotOptimize(cat.answer_all(rest.first(n), id).all());  // all(): a fault stops the benchmark
      rest = rest.subspan(n);
      id += n;
    }
  }
  count(state, worlds.size());
  cat.finish();
  count_child_cpu(state, worlds.size(), before);
}

void register_all() {
  const auto conform_bench = [](const std::string& name, auto run) {
    return benchmark::RegisterBenchmark(name.c_str(), run)
        ->Iterations(kConformIterations)
        ->Unit(benchmark::kMillisecond);
  };
  for (const char* engine : {"double", "exact"})
    conform_bench(std::string("conform_in_process/engine:") + engine + "/profile:resolved",
                  [engine](benchmark::State& s) { conform_in_process(s, engine, Profile::resolved); });
  conform_bench("conform_in_process/engine:double/profile:literal",
                [](benchmark::State& s) { conform_in_process(s, "double", Profile::literal); });
  // The candidate is another process: only real time sees its share.
  conform_bench("conform_protocol/serve:double", conform_protocol)->UseRealTime();
  benchmark::RegisterBenchmark("candidate_step/engine:double", candidate_step)
      ->Iterations(kPassIterations)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("candidate_answer/engine:double", candidate_answer)
      ->Iterations(kPassIterations)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("pipe_echo/worlds", [](benchmark::State& s) { pipe_echo(s, false); })
      ->Iterations(kPassIterations)
      ->UseRealTime()
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("pipe_echo/empty", [](benchmark::State& s) { pipe_echo(s, true); })
      ->Iterations(kEmptyRoundTrips)
      ->UseRealTime()
      ->Unit(benchmark::kMicrosecond);
}

// The protocol benchmarks need the `circles` program; say where it was looked for rather than fail in them.
bool ready() {
  if (std::filesystem::exists(CIRCLES_PROGRAM)) return true;
  std::fprintf(stderr, "conform_bench: %s does not exist: build the circles target first\n", CIRCLES_PROGRAM);
  return false;
}

}  // namespace
}  // namespace circles::bench

int main(int argc, char** argv) {
  return circles::bench::bench_main(argc, argv, "conform_bench", circles::bench::ready, circles::bench::register_all);
}
