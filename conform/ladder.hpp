// The time budget's schedule of big worlds (`circles conform --budget SECONDS`, docs/conform.md "The time
// budget"): a ladder of world sizes, from kFirstRung circles doubling up to the top (--max-circles), climbed one
// rung a stage while the program's measured speed predicts that the next rung fits in the time left; then, until
// the budget is spent, more stages at the rungs climbed, each time at the one that has had the least time so far
// (of those that still fit), so that every rung gets an equal share of the time.
//
// The prediction: a stage at size s that took t seconds predicts t · (s'/s)^p at size s', where p is the growth
// measured over the last two rungs climbed, clamped to [1, 2] (a step's time grows at least as n and, testing
// every pair, at most as n²), and 2 before there are two (a rung run before: its longest time); a rung fits when
// kMargin times its prediction is
// within the time left. Only what stages take decides: which worlds a stage asks never depends on the timing,
// so that a counterexample's case replays exactly whatever the budget.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace circles::conform {

class Ladder {
 public:
  // The first rung: enough circles that every big family draws its own largest world (properties::kMinMaxCircles is
  // 320) and that a program's big-world path (a grid, threads) is taken.
  static constexpr std::size_t kFirstRung = 512;
  // A stage is started only when kMargin times its predicted time fits in the time left: room for the time's
  // noise on a shared machine, and for the swarm's worlds, whose time at one size varies with their features
  // (with 1.25, `circles serve` on a machine loaded 5 deep on 2 cores ended at 76 s of 60).
  static constexpr double kMargin = 2;

  // Rungs kFirstRung, 2·kFirstRung, … below `top`, then `top`.
  explicit Ladder(std::size_t top);
  const std::vector<std::size_t>& rungs() const { return rungs_; }

  // The size of the next stage's worlds, with `seconds_left` of the budget: the first rung always, first; then
  // the next rung up while it fits, then the rung climbed with the least time so far that fits; nothing when
  // none does.
  std::optional<std::size_t> next(double seconds_left);
  // Records that a stage of worlds of `size` circles (a rung) took `seconds`.
  void took(std::size_t size, double seconds);
  // The predicted seconds of a stage at rung k, from the measurements so far (none before the first).
  std::optional<double> predicted(std::size_t k) const;
  // The largest rung a stage ran at (0 before any).
  std::size_t largest() const { return climbed_ == 0 ? 0 : rungs_[climbed_ - 1]; }

 private:
  std::vector<std::size_t> rungs_;
  std::vector<double> seconds_;  // the longest time measured at each rung climbed
  std::vector<double> spent_;    // the time of all stages at each rung climbed
  std::size_t climbed_ = 0;      // rungs run so far: 0 … climbed_ − 1
  bool stopped_ = false;         // the next rung up did not fit once: no more climbing
};

}  // namespace circles::conform
