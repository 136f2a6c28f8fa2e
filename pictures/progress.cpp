#include "pictures/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace circles::pictures {

Progress::Progress(std::ostream* out, std::uint64_t steps, unsigned passes, Clock::time_point start, Timing timing,
                   Line line)
    : out_(out), steps_(steps), passes_(std::max(passes, 1u)), timing_(timing), line_(std::move(line)), start_(start),
      pass_start_(start), seen_(start) {}

Progress::Progress(std::ostream* out, std::uint64_t steps, unsigned passes, Clock::time_point start)
    : Progress(out, steps, passes, start, Timing{}, Line{}) {}

namespace {

double seconds(Progress::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

void Progress::update(unsigned pass, std::uint64_t step, Clock::time_point now) {
  if (!out_ || steps_ == 0) return;
  if (pass != pass_) {
    // The previous pass ended at its last update.
    pass_ = pass;
    pass_start_ = seen_;
  }
  seen_ = now;
  const auto elapsed = now - start_;
  if (elapsed < timing_.earliest || (shown() && now - drawn_ < kRedraw)) return;
  // What is left of this pass at this pass's rate so far (a --fit run's first pass, which does not draw, is
  // far quicker than its second: each pass has its own bar and estimate).
  const double left = step > 0 ? seconds(now - pass_start_) * static_cast<double>(steps_ - std::min(step, steps_)) /
                                     static_cast<double>(step)
                               : INFINITY;
  if (!shown() && elapsed < timing_.show_after && seconds(elapsed) + left < seconds(timing_.long_run)) return;
  const std::string line = line_ ? line_(pass, step, left) : progress_line(pass, passes_, step, steps_, left);
  // Back to the start of the line; spaces cover what is left of a longer previous line.
  *out_ << '\r' << line << std::string(width_ > line.size() ? width_ - line.size() : 0, ' ') << std::flush;
  width_ = std::max(width_, line.size());
  drawn_ = now;
}

void Progress::finish() {
  if (!shown()) return;
  *out_ << '\r' << std::string(width_, ' ') << '\r' << std::flush;
  width_ = 0;
}

std::string progress_line(unsigned pass, unsigned passes, std::uint64_t step, std::uint64_t steps, double left,
                          std::string_view unit, std::string_view note) {
  constexpr int kBar = 20;
  const double fraction = steps == 0 ? 1.0 : static_cast<double>(std::min(step, steps)) / static_cast<double>(steps);
  const int filled = static_cast<int>(std::floor(fraction * kBar));
  std::string line(1, '[');
  line.append(static_cast<std::size_t>(filled), '#').append(static_cast<std::size_t>(kBar - filled), '.').append("] ");
  char text[96];
  std::snprintf(text, sizeof text, "%3d%%  ", static_cast<int>(std::floor(fraction * 100)));
  line.append(text).append(unit);
  std::snprintf(text, sizeof text, " %llu of %llu", static_cast<unsigned long long>(step),
                static_cast<unsigned long long>(steps));
  line += text;
  if (passes > 1) line += pass == 0 ? " (fit pass)" : " (run)";
  line += note;
  if (std::isfinite(left)) {
    std::snprintf(text, sizeof text, "  %.1f s left", left);
    line += text;
  }
  return line;
}

}  // namespace circles::pictures
