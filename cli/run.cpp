#include "cli/run.hpp"

#include "formats/counted.hpp"

#include "formats/json_number.hpp"
#include "formats/trace_writer.hpp"
#include "pictures/progress.hpp"
#include "formats/protocol.hpp"
#include "pictures/render.hpp"
#include "formats/vectors.hpp"  // append_exact_line
#include "pictures/video.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace circles::cli {

using conform::Comparison;
using engines::EngineEntry;
using engines::max_threads;
using engines::StepOverflow;
using engines::Stepper;
using formats::append_exact_line;
using formats::counted;
using formats::kStep;
using formats::LineWriter;
using formats::output_name;
using formats::source_of;
using formats::TextSink;

using namespace circles::pictures;

using Clock = std::chrono::steady_clock;

namespace {

// Runs `work` and adds its wall time to `figure`.
template <class Work>
void timed(RunResult::Seconds& figure, Work work) {
  const auto begin = Clock::now();
  work();
  figure += Clock::now() - begin;
}

// --fit's first pass: the same engine stepped from w_0 without drawing, for the box of every frame's circles (the
// engines are deterministic, so the run's pass meets the same worlds).
View fitted_view(const Circles& world, const RunOptions& options, Progress& progress) {
  Box box;
  box.add(world);
  const auto stepper = options.engine->start(world, options.threads, options.steps);
  while (stepper->steps() < options.steps) {
    try {
      stepper->step();
    } catch (const StepOverflow&) {
      break;  // the run's pass stops at the same step and reports it
    }
    if (stepper->steps() % options.every == 0) box.add(stepper->circles());
    progress.update(0, stepper->steps(), Clock::now());
  }
  return View::fit(box);
}

// Frame t of world `w` drawn, and written as a PNG and as the video's next frame where asked.
void draw(Frame& frame, const Circles& w, const View& view, std::uint64_t t, std::optional<FrameDirectory>& frames,
          std::optional<Video>& video, RunResult& result) {
  timed(result.drawing, [&] { frame.draw(w, view); });
  if (frames) timed(result.png, [&] { frames->write(frame, t); });
  if (video) timed(result.video, [&] { video->add(frame); });
  ++result.frames;
}

// The outputs renamed into place (the video: ffmpeg waited for), each timed with its own figure.
void commit(std::optional<OutputFile>& trace, std::optional<OutputFile>& exact_trace, std::optional<Video>& video,
            RunResult& result) {
  if (trace) timed(result.tracing, [&] { trace->commit(); });
  if (exact_trace) exact_trace->commit();
  if (video) timed(result.video, [&] { video->commit(); });
}

}  // namespace

RunResult run(Circles world, const RunOptions& options) {
  if (options.every == 0) throw std::invalid_argument("RunOptions::every: a frame every 0 steps");
  const auto started = Clock::now();
  RunResult result;
  // The video first: its checks (the name, ffmpeg on PATH) create nothing, so a run refused for them leaves
  // no file and no directory behind.
  std::optional<Video> video;
  if (!options.video.empty()) video.emplace(options.video);
  if (!options.exact_trace.empty() && !options.engine->exact)
    throw std::invalid_argument("--exact-trace: the " + std::string(options.engine->name) +
                                " engine keeps no exact state (only --engine exact does)");
  std::optional<OutputFile> trace, exact_trace;
  if (!options.trace.empty()) trace.emplace(options.trace, "trace " + options.trace);
  if (!options.exact_trace.empty()) exact_trace.emplace(options.exact_trace, "exact trace " + options.exact_trace);
  std::optional<FrameDirectory> frames;
  if (!options.render.empty()) frames.emplace(options.render);
  const bool pictures = video || frames, fit = pictures && options.fit;
  Progress progress(options.progress, options.steps, fit ? 2 : 1, started);

  View view = View::pixels();
  if (fit) timed(result.fitting, [&] { view = fitted_view(world, options, progress); });

  std::optional<Frame> frame;
  if (pictures) frame.emplace();
  // The trace's threads, for --threads 0 chosen from the load as the engine's are.
  LineWriter writer(impl::ThreadCount(options.threads, max_threads(), world.size()).count());
  const std::size_t circles = world.size();
  const TextSink to_trace = [&](std::string_view text) { trace->write(text); };
  std::string line;
  // World t, read from `w` where the caller holds it (w_0), else from the stepper: a part at a time for the
  // trace (LineWriter), whole only for a frame.
  const auto record = [&](std::uint64_t t, const Circles* w, const Stepper& stepper) {
    if (trace)
      timed(result.tracing, [&] {
        result.trace_bytes += writer.write(to_trace, kStep, t, circles, w ? source_of(*w) : stepper.source());
      });
    if (exact_trace) {
      line.clear();
      append_exact_line(line, t, *stepper.exact());
      line += '\n';
      exact_trace->write(line);
    }
    if (pictures && t % options.every == 0) draw(*frame, w ? *w : stepper.circles(), view, t, frames, video, result);
  };

  const auto stepper = options.engine->start(world, options.threads, options.steps);
  record(0, &world, *stepper);
  // The stepper keeps w_0 in its own form: the copy given to run() is no longer needed (10^7 circles: 400 MB).
  Circles().swap(world);
  const unsigned pass = fit ? 1 : 0;
  while (result.steps < options.steps) {
    const auto start = Clock::now();
    try {
      stepper->step();
    } catch (const StepOverflow& e) {
      result.overflow = e;
      break;
    }
    const auto stepped = Clock::now();
    result.stepping += stepped - start;
    result.steps = stepper->steps();
    if (trace || exact_trace || (pictures && result.steps % options.every == 0)) {
      record(result.steps, nullptr, *stepper);
      progress.update(pass, result.steps, Clock::now());
    } else {
      progress.update(pass, result.steps, stepped);
    }
  }
  result.work = stepper->work();
  if (const impl::ThreadCount* threads = stepper->threads()) result.threads = *threads;
  commit(trace, exact_trace, video, result);
  progress.finish();
  result.total = Clock::now() - started;
  return result;
}

namespace {

// The threads the steps ran on: "2", or "1 to 2" where the load changed the count during the run.
std::string thread_counts(const RunResult& result, const RunOptions& options) {
  if (!options.engine->threaded) return "1";
  if (!result.threads) return std::to_string(options.threads);
  const impl::ThreadCount& t = *result.threads;
  return std::to_string(t.least()) + (t.least() == t.most() ? "" : " to " + std::to_string(t.most()));
}

std::string threads_text(const RunResult& result, const RunOptions& options) {
  const std::string counts = thread_counts(result, options);
  return counts + (counts == "1" ? " thread" : " threads") +
         (options.engine->threaded && result.threads && result.threads->load() ? ", chosen from the load" : "");
}

// Why --threads 0 gave the count it did: "chosen from the load: 2 cores, 2 tasks of other programs running" (at
// the last reading), "a world of fewer than 8192 circles runs on one"; empty for a count given.
std::string threads_reason(const RunResult& result, const RunOptions& options) {
  if (options.threads != 0 || !result.threads) return {};
  const std::optional<impl::CoreLoad>& load = result.threads->load();
  if (!load) return "a world of fewer than " + std::to_string(impl::kParallelFrom) + " circles runs on one";
  std::string text = "chosen from the load";
  if (result.threads->least() != result.threads->most())
    text += ", read every " + std::to_string(impl::ThreadCount::kReadEvery.count()) + " ms; last";
  text += ": " + std::to_string(load->cores) + (load->cores == 1 ? " core" : " cores");
  if (load->online != load->cores) text += " of the machine's " + std::to_string(load->online);
  if (load->others == 0) return text + ", no other program running";
  return text + ", " + std::to_string(load->others) + (load->others == 1 ? " task" : " tasks") +
         " of other programs running";
}

// The last multiple of `every` up to `steps`: the step of the last frame.
std::uint64_t last_frame(std::uint64_t steps, std::uint64_t every) { return steps / every * every; }

// A figure of the summary and --stats to 3 significant digits, in plain decimals: "6.67", "0.006",
// "0.0000565", "0"; from 1000 up, a whole number rounded to 3 digits ("1230") rather than "1.23e+03".
std::string figure(double x) {
  std::ostringstream o;
  if (!std::isfinite(x) || x == 0) {
    o << x;
    return o.str();
  }
  const int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(x))));
  if (magnitude >= 3) {
    const double unit = std::pow(10.0, magnitude - 2);
    o << std::fixed << std::setprecision(0) << std::round(x / unit) * unit;
    return o.str();
  }
  o << std::fixed << std::setprecision(2 - magnitude) << x;
  std::string text = o.str();
  if (text.find('.') != std::string::npos) {  // zeros closing the decimals say nothing: "0.006", not "0.00600"
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

}  // namespace

void print_summary(const RunResult& result, std::size_t circles, const RunOptions& options, std::ostream& out) {
  out << counted(result.steps, "step") << " of " << counted(circles, "circle") << " with the " << options.engine->name
      << " engine (" << threads_text(result, options) << "): " << figure(result.stepping.count()) << " s stepping";
  const double circle_steps = static_cast<double>(result.steps) * static_cast<double>(circles);
  if (circle_steps > 0) out << ", " << figure(result.stepping.count() * 1e9 / circle_steps) << " ns per circle-step";
  out << "\n";
  if (!options.trace.empty())
    out << "trace: " << output_name(options.trace) << " (w_0 to w_" << result.steps << ", "
        << counted(result.steps + 1, "line") << ")\n";
  if (!options.exact_trace.empty())
    out << "exact trace: " << output_name(options.exact_trace) << " (w_0 to w_" << result.steps << ", "
        << counted(result.steps + 1, "line") << ", as rationals)\n";
  const std::uint64_t every = std::max<std::uint64_t>(options.every, 1);
  if (!options.render.empty()) {
    out << "frames: ";
    if (options.render == "-") out << "standard output, one PNG after another";
    else out << frame_path(options.render, 0) << " to " << frame_path(options.render, last_frame(result.steps, every));
    out << " (" << result.frames << ", every " << counted(every, "step") << ")\n";
  }
  if (!options.video.empty())
    out << "video: " << output_name(options.video) << " (" << counted(result.frames, "frame") << " at "
        << kVideoFrameRate << " frames/s, " << figure(static_cast<double>(result.frames) / kVideoFrameRate) << " s)\n";
}

void print_work(const impl::EngineStats& work, std::size_t circles, std::ostream& out) {
  // Each figure with its share, so what the engine skipped reads at a glance.
  const auto share = [](std::uint64_t part, double whole) {
    return whole > 0 ? " (" + figure(100.0 * static_cast<double>(part) / whole) + "%)" : std::string();
  };
  const auto steps = static_cast<double>(work.steps);
  const double circle_steps = steps * static_cast<double>(circles);
  out << "pair lists built: " << work.rebuilds << " (keys, re-sort and broad phase";
  if (work.rebuilds > 0) out << "; one per " << figure(steps / static_cast<double>(work.rebuilds)) << " steps";
  out << ")\npairs tested: " << work.pairs_tested;
  if (circle_steps > 0) out << " (" << figure(static_cast<double>(work.pairs_tested) / circle_steps) << " per circle-step)";
  out << "\n";
  out << "pairs in contact: " << work.contacts << share(work.contacts, static_cast<double>(work.pairs_tested)) << "\n";
  out << "steps with no pair to test: " << work.quiet_steps << share(work.quiet_steps, steps) << "\n";
  out << "circle-steps with no contact test: " << work.lonely_circle_steps
      << share(work.lonely_circle_steps, circle_steps) << "\n";
}

void print_stats(const RunResult& result, std::size_t circles, const RunOptions& options, std::ostream& out) {
  out << "steps: " << result.steps << "\n";
  out << "circles: " << circles << "\n";
  out << "engine: " << options.engine->name << "\n";
  out << "threads: ";
  if (!options.engine->threaded)
    out << "1 (the " << options.engine->name << " engine has none)\n";
  else if (const std::string why = threads_reason(result, options); !why.empty())
    out << thread_counts(result, options) << " (" << why << ")\n";
  else
    out << thread_counts(result, options) << "\n";
  out << "stepping: " << figure(result.stepping.count()) << " s\n";
  const double circle_steps = static_cast<double>(result.steps) * static_cast<double>(circles);
  if (circle_steps > 0) out << "ns per circle-step: " << figure(result.stepping.count() * 1e9 / circle_steps) << "\n";
  if (result.work) print_work(*result.work, circles, out);
  const bool pictures = !options.render.empty() || !options.video.empty();
  if (pictures && options.fit) out << "fit pass: " << figure(result.fitting.count()) << " s\n";
  if (pictures) {
    out << "frames: " << result.frames << "\n";
    const auto per_frame = [&](const char* name, RunResult::Seconds t) {
      out << name << ": " << figure(t.count()) << " s";
      if (result.frames > 0) out << " (" << figure(t.count() * 1e3 / static_cast<double>(result.frames)) << " ms per frame)";
      out << "\n";
    };
    per_frame("drawing", result.drawing);
    if (!options.render.empty()) per_frame("png", result.png);
    if (!options.video.empty()) per_frame("video", result.video);
  }
  if (!options.trace.empty()) {
    out << "trace: " << figure(result.tracing.count()) << " s (" << result.trace_bytes << " bytes";
    if (result.tracing.count() > 0)
      out << ", " << figure(static_cast<double>(result.trace_bytes) / 1e6 / result.tracing.count()) << " MB/s";
    out << ")\n";
  }
  out << "total: " << figure(result.total.count()) << " s\n";
}

void print_comparison(const EngineEntry& engine, const Comparison& c, std::ostream& out) {
  out << engine.name << " engine: ";
  const char* oracle = engine.exact ? "the oracle's exact sequence, rounded," : "the correctly rounded oracle";
  if (c.difference) {
    out << "DIFFERS from " << oracle << " at " << *c.difference << "\n";
    return;
  }
  out << "agrees with " << oracle << (c.steps == 1 ? " at its one step" : " at each of the " + counted(c.steps, "step"));
  if (c.overflow) out << ", after which both stop: " << c.overflow->what();
  out << "\n";
}

}  // namespace circles::cli
