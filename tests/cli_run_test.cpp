// `circles run` in process (cli/run.hpp): its trace and exact trace, held to spec::resolved_step_rounded and to
// the oracle's exact sequence, what it leaves when a write fails, its summary and stats (its pictures are
// cli_run_pictures_test.cpp's).
#include "cli/run.hpp"
#include "engines/registry.hpp"
#include "formats/protocol.hpp"
#include "formats/scene.hpp"
#include "formats/trace_writer.hpp"

#include "spec/oracle.hpp"
#include "tests/step_worlds.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace circles::cli {
namespace {

using engines::engine;
using engines::EngineEntry;
using engines::max_threads;
using formats::format_line;
using formats::kPartCircles;
using formats::Line;
using formats::kStep;
using formats::parse_line;
using formats::random_world;
using spec::Circles;

using circles::testing::kOverflowsAtStep4;
using circles::testing::kTouching;
using circles::testing::oracle_worlds;
using circles::testing::thrown;

// w_0 … w_n of the oracle's exact sequence, each rounded: what an exact engine (EngineEntry::exact) shows.
std::vector<Circles> exact_worlds(const Circles& w0, std::size_t n) {
  spec::Sequence w;
  for (std::size_t k = 0; k < w0.size(); ++k) w.push_back(spec::from_doubles(w0[k], k, spec::Radii::non_negative));
  std::vector<Circles> worlds{w0};
  for (std::size_t t = 0; t < n; ++t) {
    w = spec::resolved_step(w);
    worlds.emplace_back();
    for (const spec::Circle& c : w) worlds.back().push_back(spec::nearest_doubles(c));
  }
  return worlds;
}

std::vector<std::string> lines_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

using circles::testing::TempDir;

TEST(run, writes_a_trace_of_every_world_equal_to_the_oracles) {
  for (const EngineEntry& e : engines::engines()) {
    TempDir dir;
    const auto trace = dir.path / "t.jsonl";
    const RunResult result = run(kTouching, RunOptions{5, &e, 1, trace.string()});
    EXPECT_EQ(result.steps, 5u);
    EXPECT_FALSE(result.overflow);
    // The circles move by ±1/60, which no double holds: the exact sequence and the rounded one may part.
    const auto want = e.exact ? exact_worlds(kTouching, 5) : oracle_worlds(kTouching, 5);
    const auto lines = lines_of(trace);
    ASSERT_EQ(lines.size(), 6u) << e.name;
    for (std::size_t t = 0; t < lines.size(); ++t) {
      const Line line = parse_line(lines[t], t + 1, kStep);
      EXPECT_EQ(line.number, t);
      EXPECT_EQ(line.circles, want[t]) << e.name << ", step " << t;
    }
    EXPECT_EQ(dir.files(), std::vector<std::string>{"t.jsonl"}) << "a temporary file was left behind";
  }
}

TEST(run, keeps_the_trace_of_every_step_before_an_overflow) {
  TempDir dir;
  const auto trace = dir.path / "t.jsonl";
  const RunResult result = run(kOverflowsAtStep4, RunOptions{10, &engine("double"), 1, trace.string()});
  EXPECT_EQ(result.steps, 3u);
  ASSERT_TRUE(result.overflow);
  EXPECT_STREQ(result.overflow->what(), "step 4, circle 1, field px: the position p + v/60 overflows to infinity");
  const auto want = oracle_worlds(kOverflowsAtStep4, 3);
  const auto lines = lines_of(trace);
  ASSERT_EQ(lines.size(), 4u);
  for (std::size_t t = 0; t < lines.size(); ++t) EXPECT_EQ(parse_line(lines[t], t + 1, kStep).circles, want[t]);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"t.jsonl"});
}

// A world of several of LineWriter's parts, stepped until the engine has re-sorted its slots: each line is
// append_line's of the engine's world (read a part at a time from the engine's own arrays, formatted on the
// threads), and the file is the same bytes for 1 and 2 threads.
TEST(run, writes_the_same_trace_bytes_as_append_line_on_one_thread_and_two) {
  const Circles world = random_world(3 * kPartCircles + 11, 0.5, 2, 0);
  const std::uint64_t steps = 3;
  std::string want;
  const auto stepper = engine("double").start(world, 1, 0);
  want += format_line(kStep, 0, world) + "\n";
  for (std::uint64_t t = 1; t <= steps; ++t) {
    stepper->step();
    want += format_line(kStep, t, stepper->circles()) + "\n";
  }
  for (const unsigned threads : {1u, 2u}) {
    TempDir dir;
    const auto trace = dir.path / "t.jsonl";
    const RunResult result = run(world, RunOptions{steps, &engine("double"), threads, trace.string()});
    std::ifstream in(trace, std::ios::binary);
    const std::string got{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_TRUE(got == want) << threads << " threads: " << got.size() << " bytes, want " << want.size();
    EXPECT_EQ(result.trace_bytes, want.size());
  }
}

// A trace that cannot be written midway (a file size limit, the way a full disk fails a write): the system's
// reason, and no file left, neither the trace nor its temporary file.
TEST(run, leaves_no_file_when_writing_the_trace_fails_midway) {
  const Circles world = random_world(2 * kPartCircles, 0.5, 3, 0);
  TempDir dir;
  const auto trace = dir.path / "t.jsonl";
  rlimit before{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &before), 0);
  const auto ignored = std::signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead of a signal
  rlimit small = before;
  small.rlim_cur = 1 << 20;  // 1 MiB: the first line is about 3 MB
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::optional<TraceError> e;
  try {
    run(world, RunOptions{2, &engine("double"), 2, trace.string()});
  } catch (const TraceError& error) {
    e = error;
  }
  setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, ignored);
  ASSERT_TRUE(e) << "nothing was thrown";
  const std::string what = e->what();
  EXPECT_TRUE(what.starts_with("trace " + trace.string() + ": cannot write to " + trace.string() + ".partial-"))
      << what;
  EXPECT_TRUE(what.ends_with(": File too large")) << what;
  EXPECT_TRUE(dir.files().empty());
}

// The exact state written by --exact-trace, read back with GMP's own parser of "n/d" (not our formatter):
// world t must be the oracle's exact w_t. kTouching's circles move by ±1/60, which no double holds, so a trace
// of rounded values would differ from step 1 on.
TEST(run, writes_the_exact_engines_state_as_the_oracles_exact_rationals) {
  TempDir dir;
  const auto exact_trace = dir.path / "x.jsonl";
  RunOptions options{5, &engine("exact"), 1, ""};
  options.exact_trace = exact_trace.string();
  const RunResult result = run(kTouching, options);
  EXPECT_EQ(result.steps, 5u);
  spec::Sequence want;
  for (std::size_t k = 0; k < kTouching.size(); ++k)
    want.push_back(spec::from_doubles(kTouching[k], k, spec::Radii::non_negative));
  const auto lines = lines_of(exact_trace);
  ASSERT_EQ(lines.size(), 6u);
  for (std::size_t t = 0; t < lines.size(); ++t) {
    const nlohmann::json line = nlohmann::json::parse(lines[t]);
    EXPECT_EQ(line.at("step"), t);
    ASSERT_EQ(line.at("circles").size(), want.size());
    for (std::size_t k = 0; k < want.size(); ++k) {
      const spec::Circle& c = want[k];
      const spec::Q* fields[] = {&c.p.x(), &c.p.y(), &c.v.x(), &c.v.y(), &c.r};
      for (std::size_t f = 0; f < 5; ++f)
        EXPECT_EQ(spec::Q(line.at("circles")[k][f].get<std::string>()), *fields[f]) << "step " << t << ", circle " << k;
    }
    want = spec::resolved_step(want);
  }
  // Circle 0 touches circle 1 in w_0, takes its velocity −1 and moves to −1/60, a value no double holds.
  EXPECT_EQ(spec::Q(nlohmann::json::parse(lines[1]).at("circles")[0][0].get<std::string>()), spec::Q(-1, 60));
  EXPECT_EQ(dir.files(), std::vector<std::string>{"x.jsonl"}) << "a temporary file was left behind";
}

TEST(run, refuses_an_exact_trace_from_an_engine_without_exact_state_before_writing_anything) {
  for (const char* name : {"double", "oracle"}) {
    TempDir dir;
    RunOptions options{3, &engine(name), 1, (dir.path / "t.jsonl").string()};
    options.exact_trace = (dir.path / "x.jsonl").string();
    const auto e = thrown<std::invalid_argument>([&] { run(kTouching, options); });
    ASSERT_TRUE(e) << name;
    EXPECT_EQ(std::string(e->what()), "--exact-trace: the " + std::string(name) +
                                          " engine keeps no exact state (only --engine exact does)");
    EXPECT_TRUE(dir.files().empty()) << name;
  }
}

TEST(run, runs_without_a_trace) {
  const RunResult result = run(kTouching, RunOptions{3, &engine("double"), 0, ""});
  EXPECT_EQ(result.steps, 3u);
  EXPECT_FALSE(result.overflow);
}

TEST(run, leaves_no_file_when_the_trace_cannot_be_created) {
  TempDir dir;
  const auto trace = dir.path / "missing" / "t.jsonl";
  const auto e = thrown<TraceError>([&] { run(kTouching, RunOptions{3, &engine("double"), 1, trace.string()}); });
  ASSERT_TRUE(e);
  const std::string what = e->what();
  EXPECT_TRUE(what.starts_with("trace " + trace.string() + ": cannot create " + trace.string() + ".partial-")) << what;
  EXPECT_TRUE(what.ends_with(": No such file or directory")) << what;
  EXPECT_TRUE(dir.files().empty());
}

// 2e-6 s over 4 steps of 5 circles is 2000 ns / 20 = 100 ns per circle-step.
TEST(run, summarizes_steps_circles_engine_threads_and_time) {
  RunResult result;
  result.steps = 4;
  result.stepping = std::chrono::duration<double>(2e-6);
  const auto summary = [&](const char* name, unsigned threads, const std::string& trace) {
    std::ostringstream out;
    result.threads.reset();
    if (engine(name).threaded) result.threads.emplace(threads, max_threads(), 5);
    print_summary(result, 5, RunOptions{4, &engine(name), threads, trace}, out);
    return out.str();
  };
  // --threads 0 on a world of 5 circles: one thread, which is all such a world uses.
  EXPECT_EQ(summary("double", 0, "t.jsonl"),
            "4 steps of 5 circles with the double engine (1 thread): 0.000002 s stepping, 100 ns per circle-step\n"
            "trace: t.jsonl (w_0 to w_4, 5 lines)\n");
  EXPECT_EQ(summary("double", 3, ""),
            "4 steps of 5 circles with the double engine (3 threads): 0.000002 s stepping, 100 ns per circle-step\n");
  EXPECT_EQ(summary("oracle", 0, ""),
            "4 steps of 5 circles with the oracle engine (1 thread): 0.000002 s stepping, 100 ns per circle-step\n");
  // Times to 3 significant digits in plain decimals, never "5.6454e-05 s" or 6 digits; one step and one circle in
  // the singular; "-" named as stdout.
  result.steps = 1;
  result.stepping = std::chrono::duration<double>(5.6454e-05);
  std::ostringstream one;
  print_summary(result, 1, RunOptions{1, &engine("double"), 1, "-"}, one);
  EXPECT_EQ(one.str(),
            "1 step of 1 circle with the double engine (1 thread): 0.0000565 s stepping, 56500 ns per circle-step\n"
            "trace: standard output (w_0 to w_1, 2 lines)\n");
}

// --every 3 over 10 steps: frames of w_0, w_3, w_6, w_9, the last at step 9; 4 frames at 60 a second last 1/15 s.
TEST(run, summarizes_the_frames_and_the_video) {
  RunResult result;
  result.steps = 10;
  result.frames = 4;
  RunOptions options{10, &engine("double"), 1, ""};
  options.render = "out";
  options.every = 3;
  options.video = "v.mp4";
  std::ostringstream out;
  print_summary(result, 5, options, out);
  EXPECT_EQ(out.str(),
            "10 steps of 5 circles with the double engine (1 thread): 0 s stepping, 0 ns per circle-step\n"
            "frames: out/frame-000000.png to out/frame-000009.png (4, every 3 steps)\n"
            "video: v.mp4 (4 frames at 60 frames/s, 0.0667 s)\n");
}

// 2e-6 s over 4 steps of 5 circles is 100 ns per circle-step; 3 frames in 0.006 s of drawing are 2 ms each.
TEST(run, prints_stats_one_figure_a_line_leaving_out_what_does_not_apply) {
  RunResult result;
  result.steps = 4;
  result.frames = 3;
  result.stepping = std::chrono::duration<double>(2e-6);
  result.fitting = std::chrono::duration<double>(1e-6);
  result.drawing = std::chrono::duration<double>(0.006);
  result.png = std::chrono::duration<double>(0.012);
  result.video = std::chrono::duration<double>(0.003);
  result.tracing = std::chrono::duration<double>(0.5);
  result.trace_bytes = 209000000;
  result.total = std::chrono::duration<double>(2);
  const auto stats = [&](const RunOptions& options) {
    std::ostringstream out;
    print_stats(result, 5, options, out);
    return out.str();
  };
  RunOptions options{4, &engine("double"), 3, ""};
  EXPECT_EQ(stats(options),
            "steps: 4\ncircles: 5\nengine: double\nthreads: 3\nstepping: 0.000002 s\nns per circle-step: 100\n"
            "total: 2 s\n");
  options.engine = &engine("oracle");
  options.trace = "t.jsonl";
  options.render = "frames";
  options.video = "v.mp4";
  options.fit = true;
  EXPECT_EQ(stats(options),
            "steps: 4\ncircles: 5\nengine: oracle\nthreads: 1 (the oracle engine has none)\nstepping: 0.000002 s\n"
            "ns per circle-step: 100\nfit pass: 0.000001 s\nframes: 3\ndrawing: 0.006 s (2 ms per frame)\n"
            "png: 0.012 s (4 ms per frame)\nvideo: 0.003 s (1 ms per frame)\n"
            "trace: 0.5 s (209000000 bytes, 418 MB/s)\ntotal: 2 s\n");
  options.engine = &engine("double");
  options.threads = 0;
  result.threads.emplace(0, max_threads(), 5);
  EXPECT_NE(stats(options).find("\nthreads: 1 (a world of fewer than 8192 circles runs on one)\n"), std::string::npos);
  // A big world's count is chosen from the machine's load, which the line gives.
  result.threads.emplace(0, max_threads(), 10'000);
  const std::string chosen = "\nthreads: " + std::to_string(result.threads->count()) + " (chosen from the load: " +
                             std::to_string(result.threads->load()->cores);
  EXPECT_NE(stats(options).find(chosen), std::string::npos) << stats(options);
  result.threads.reset();
  result.steps = 0;
  EXPECT_EQ(stats(RunOptions{0, &engine("exact"), 2, ""}),
            "steps: 0\ncircles: 5\nengine: exact\nthreads: 2\nstepping: 0.000002 s\ntotal: 2 s\n");
}

// 4 steps of 5 circles (20 circle-steps): 2 lists built, one per 2 steps; 30 pairs tested, 1.5 per
// circle-step; 3 in contact, 10%; 1 quiet step, 25%; 5 circle-steps with no test, 25%.
TEST(run, prints_what_the_engine_did_and_skipped_after_the_time_per_circle_step) {
  RunResult result;
  result.steps = 4;
  result.stepping = std::chrono::duration<double>(2e-6);
  result.total = std::chrono::duration<double>(2);
  result.work = impl::EngineStats{.steps = 4, .rebuilds = 2, .pairs_listed = 12, .pairs_tested = 30,
                                  .contacts = 3, .quiet_steps = 1, .lonely_circle_steps = 5};
  std::ostringstream out;
  print_stats(result, 5, RunOptions{4, &engine("double"), 1, ""}, out);
  EXPECT_EQ(out.str(),
            "steps: 4\ncircles: 5\nengine: double\nthreads: 1\nstepping: 0.000002 s\nns per circle-step: 100\n"
            "pair lists built: 2 (keys, re-sort and broad phase; one per 2 steps)\n"
            "pairs tested: 30 (1.5 per circle-step)\n"
            "pairs in contact: 3 (10%)\n"
            "steps with no pair to test: 1 (25%)\n"
            "circle-steps with no contact test: 5 (25%)\n"
            "total: 2 s\n");
}

TEST(run, gives_the_double_engines_work_and_none_for_the_oracle) {
  // Two circles far apart for 50 steps: every step of the double engine is quiet and no circle is tested;
  // the oracle reports no work of its own.
  const Circles apart{{0, 0, 1, 0, 1}, {100, 0, -1, 0, 1}};
  const RunResult double_run = run(apart, RunOptions{50, &engine("double"), 1, ""});
  ASSERT_TRUE(double_run.work);
  EXPECT_EQ(double_run.work->steps, 50u);
  EXPECT_EQ(double_run.work->quiet_steps, 50u);
  EXPECT_EQ(double_run.work->lonely_circle_steps, 100u);
  EXPECT_LT(double_run.work->rebuilds, 5u);
  EXPECT_FALSE(run(apart, RunOptions{3, &engine("oracle"), 1, ""}).work);
}

TEST(run, gives_the_exact_engines_work_counted_as_the_double_engine_counts_it) {
  // The same two circles: the exact engine keeps its pair lists as the double engine does, so the same
  // steps, lists built, quiet steps and circle-steps with no test; on touching circles, the same contacts.
  const Circles apart{{0, 0, 1, 0, 1}, {100, 0, -1, 0, 1}};
  for (const Circles& w : {apart, kTouching}) {
    const RunResult double_run = run(w, RunOptions{50, &engine("double"), 1, ""});
    const RunResult exact_run = run(w, RunOptions{50, &engine("exact"), 1, ""});
    ASSERT_TRUE(double_run.work);
    ASSERT_TRUE(exact_run.work);
    EXPECT_EQ(exact_run.work->steps, 50u);
    EXPECT_EQ(exact_run.work->rebuilds, double_run.work->rebuilds);
    EXPECT_EQ(exact_run.work->contacts, double_run.work->contacts);
    EXPECT_EQ(exact_run.work->quiet_steps, double_run.work->quiet_steps);
    EXPECT_EQ(exact_run.work->lonely_circle_steps, double_run.work->lonely_circle_steps);
  }
}

TEST(run, refuses_a_frame_every_0_steps) {
  RunOptions options{3, &engine("double"), 1, ""};
  options.every = 0;
  EXPECT_THROW(run(kTouching, options), std::invalid_argument);
}

}  // namespace
}  // namespace circles::cli
