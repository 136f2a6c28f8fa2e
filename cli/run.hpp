// `circles run` and the main job's printing: an engine stepping a world many times, with a trace, PNG frames and a
// video if asked (docs/run.md), and the line of an engine stepped side by side with the oracle
// (conform::compare_with_oracle).
#pragma once

#include "conform/check_trace.hpp"  // Comparison
#include "engines/registry.hpp"
#include "formats/output_file.hpp"
#include "formats/scene.hpp"
#include "impl/threads.hpp"
#include "spec/circle.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace circles::cli {

// A trace that cannot be written: what() names the file and the system's reason (formats/output_file.hpp).
using TraceError = formats::OutputError;

struct RunOptions {
  std::uint64_t steps = 0;
  const engines::EngineEntry* engine = nullptr;
  unsigned threads = 0;     // 0: one per core free of other work (impl::ThreadCount)
  std::string trace{};      // the trace file, or empty for none
  std::string exact_trace{};  // --exact-trace FILE: the exact worlds as rationals (an exact engine only), or empty
  std::string render{};     // --render DIR: the directory of the PNG frames, or empty for none
  std::uint64_t every = 1;  // --every K: a frame of w_t for each t that is a multiple of K (K >= 1)
  std::string video{};      // --video FILE.mp4, or empty for none
  bool fit = false;         // --fit: View::fit of every frame's circles instead of world units = pixels
  std::ostream* progress = nullptr;  // the progress bar's terminal (pictures/progress.hpp), or nullptr: quiet
};

struct RunResult {
  using Seconds = std::chrono::duration<double>;
  std::uint64_t steps = 0;               // steps taken: the last world is w_steps
  std::optional<engines::StepOverflow> overflow;  // what stopped the run early, if anything
  Seconds stepping{};                    // wall time of the steps alone (not the trace, not the pictures)
  std::uint64_t frames = 0;              // pictures made: w_0, w_K, w_2K, ... up to w_steps
  Seconds fitting{};                     // --fit's first pass (stepping without pictures, for the view)
  Seconds drawing{}, png{}, video{};     // Cairo drawing the frames; encoding and writing PNGs; piping to
                                         // ffmpeg (and waiting for it at the end)
  Seconds tracing{};                     // formatting and writing the trace (not the exact trace)
  std::uint64_t trace_bytes = 0;         // the trace's size
  Seconds total{};                       // the whole of run(), from its first output file to its last
  std::optional<impl::EngineStats> work;  // what the engine's steps did and skipped (engines of impl/ only)
  // The engine's threads (an engine with threads): options.threads, or for 0 from the machine's load.
  std::optional<impl::ThreadCount> threads;
};

// Steps w_0 = `world` with options.engine up to options.steps times, stopping at the first overflow.
//
// With a trace, writes one line {"step": t, "circles": [...]} per world w_0, w_1, ..., w_steps to a temporary
// file beside options.trace and renames it into place at the end, after an overflow too (so the trace holds
// every world before it). With --render DIR and/or --video FILE, draws w_t for each t that is a multiple of
// options.every (w_0 first; the last world is drawn only when its step is such a multiple) and writes it as
// DIR/frame_name(t) and as the next frame of the video; after an overflow the video is kept too, with the
// frames before it. With --fit, a first pass steps the same engine from w_0 without drawing to find the box
// of every frame's circles (the engines are deterministic, so the second pass meets the same worlds). With an
// exact trace (an engine whose EngineEntry::exact is set, else std::invalid_argument), writes the same lines
// with each number the exact rational "n/d" (a string, d > 0, in lowest terms: docs/run.md), as the trace is.
//
// Every output is checked before the first step: the name of the video and ffmpeg (VideoError), the trace's
// and the video's temporary files and the frames' directory (OutputError). A failure leaves no trace and no
// video file behind; frames already written stay, each a complete PNG.
//
// `world` is taken by value so that a caller done with it can move it in: run() frees it once the stepper holds
// w_0, which for a big world is memory the steps can use.
RunResult run(spec::Circles world, const RunOptions& options);

// "100 steps of 10 circles with the double engine (1 thread): 0.000135 s stepping, 135 ns per circle-step" (for
// threads chosen from the load, "(2 threads, chosen from the load)", or "(1 to 2 threads, ...)" where the count
// changed during the run),
// then a line for each output: "trace: t.jsonl (w_0 to w_100, 101 lines)", "frames: f/frame-000000.png to
// f/frame-000099.png (34, every 3 steps)", "video: v.mp4 (34 frames at 60 frames/s, 0.567 s)"; figures to 3 significant digits in plain decimals.
void print_summary(const RunResult& result, std::size_t circles, const RunOptions& options, std::ostream& out);

// The lines of --stats about the engine's work: lists built, pairs tested, contacts, steps and circle-steps
// with no test (docs/run.md).
void print_work(const impl::EngineStats& work, std::size_t circles, std::ostream& out);

// --stats: one "name: value" line for each figure of the run, those that do not apply left out:
//   steps: 1000                    stepping: 0.00123 s            drawing: 1.2 s (3.6 ms per frame)
//   circles: 10                    ns per circle-step: 123        png: 2.1 s (6.3 ms per frame)
//   engine: double                 fit pass: 0.0011 s             video: 0.9 s (2.7 ms per frame)
//   threads: 2 (see below)         frames: 334                    trace: 0.5 s (209000000 bytes, 418 MB/s)
//                                                                 total: 4.3 s
// in that order, one a line (down the first column, then the second, then the third); an engine of impl/
// adds print_work's lines after "ns per circle-step". Threads chosen for --threads 0 say why: "1 (chosen from
// the load: 2 cores, 2 tasks of other programs running)", "1 to 2 (chosen from the load, read every 100 ms; last:
// 2 cores, no other program running)", "1 (a world of fewer than 8192 circles runs on one)".
void print_stats(const RunResult& result, std::size_t circles, const RunOptions& options, std::ostream& out);

// One line: "double engine: agrees with the correctly rounded oracle at each of the 100 steps" or "double
// engine: DIFFERS from the correctly rounded oracle at step 5, circle 3, field vx: ...".
void print_comparison(const engines::EngineEntry& engine, const conform::Comparison& c, std::ostream& out);

}  // namespace circles::cli
