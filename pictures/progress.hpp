// The progress bar of `circles run` and `circles conform`: one line on a terminal, redrawn in place, for runs
// long enough to want one, and erased at the end so that only the summary stays.
//
// When (Progress::Timing, these by default): the bar appears once the run has taken kShowAfter (0.5 s), or
// already after kEarliest (0.2 s) when the time so far plus the estimate of what is left, at the rate so far,
// is kLong (1 s) or more; a shorter run never shows it, so a quick run prints nothing but its summary. It is redrawn at most every kRedraw (0.1 s): a few writes per
// second, whatever the step rate. main() gives it stderr only when stderr is a terminal (isatty): in a pipe, a
// file or CI the run is quiet.
//
// Times come from the caller (the run loop already reads the clock at every step), so the tests can drive it.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace circles::pictures {

class Progress {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kEarliest{200}, kShowAfter{500}, kLong{1000}, kRedraw{100};

  struct Timing {
    std::chrono::milliseconds earliest = kEarliest, show_after = kShowAfter, long_run = kLong;
  };
  // The line for `step` of pass `pass`, with `left` seconds estimated to go in it; by default progress_line's.
  using Line = std::function<std::string(unsigned pass, std::uint64_t step, double left)>;

  // A run of `steps` steps in `passes` passes (2 with --fit: a pass to frame the view, then the run), started
  // at `start`, shown as `timing` says, each line drawn by `line`. With out == nullptr it stays quiet.
  Progress(std::ostream* out, std::uint64_t steps, unsigned passes, Clock::time_point start, Timing timing, Line line);
  Progress(std::ostream* out, std::uint64_t steps, unsigned passes, Clock::time_point start);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() { finish(); }

  // `step` steps of pass `pass` (0-based) are done at `now`.
  void update(unsigned pass, std::uint64_t step, Clock::time_point now);
  // Erases the bar if it is shown (the end of the run, or an error about to be printed).
  void finish();
  bool shown() const noexcept { return width_ > 0; }

 private:
  std::ostream* out_;
  std::uint64_t steps_;
  unsigned passes_, pass_ = 0;
  Timing timing_;
  Line line_;
  Clock::time_point start_, pass_start_, seen_, drawn_{};  // seen_: the last update's time
  std::size_t width_ = 0;  // characters of the line on screen; 0: nothing shown
};

// The bar's text, for `step` of `steps` in pass `pass` with `left` seconds estimated to go in it:
// "[##########..........]  50%  step 500 of 1000  1.2 s left". With two passes each has its own bar, marked
// "(fit pass)" or "(run)"; with no estimate (left infinite) the time is left out. `unit` names what is
// counted ("case": "case 500 of 1000"), and `note`, if any, follows the count ("  2 families failing").
std::string progress_line(unsigned pass, unsigned passes, std::uint64_t step, std::uint64_t steps, double left,
                          std::string_view unit = "step", std::string_view note = "");

}  // namespace circles::pictures
