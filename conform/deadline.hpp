// The deadline of each answer of a program under check, predicted from its own earlier answers
// (docs/conform.md, "Deadlines"): a slow program is given the time its speed needs, and one that hangs is still
// stopped.
//
// The rule: before any answer, `floor` up to kFirstCircles circles and floor · (n / kFirstCircles)² above, as an
// O(n²) step's time grows. After answers, with t the longest time taken by an answer to the largest world
// answered so far, of m circles: kFactor · t · (n/m)² for a world of n >= m circles (the growth of a step that
// tests every pair), kFactor · t · n/m for n < m; never less than `floor` · sqrt(n / kFirstCircles) (and `floor`). An answer's time is measured from its
// request's write, or from the previous answer when requests are batched. The copies of a program (--jobs) share
// one model, the same program's speed.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <stdexcept>

namespace circles::conform {

class Deadlines {
 public:
  explicit Deadlines(std::chrono::milliseconds floor) : floor_(floor) {}

  // The deadline of the answer to a world of `circles` circles.
  std::chrono::milliseconds for_world(std::size_t circles) const;
  // Records that the answer to a world of `circles` circles took `took`.
  void answered(std::size_t circles, std::chrono::duration<double> took);

  // How many times the predicted time an answer is given: room for a machine whose load changes while it runs,
  // for a garbage collector's pause, for a step whose time varies with the world's layout.
  static constexpr double kFactor = 20;
  // Before any answer, worlds up to this size get the floor.
  static constexpr std::size_t kFirstCircles = 512;

 private:
  std::chrono::milliseconds floor_;
  mutable std::mutex mutex_;
  std::size_t largest_ = 0;  // m: the most circles of a world answered
  double seconds_ = 0;       // t: the longest time an answer to a world of m circles took
};

// The end of a stage that may be cut (docs/conform.md, "The time budget"): the ladder's stages after its first
// are optional, and one whose worlds take far longer than the ladder predicted (a program's cliff on some
// world, which no earlier stage shows) is cut at the budget's end rather than let run on past it. While a
// StageCut is alive, throw_if_cut() throws StageCutOff once its time has passed; a program's answer is awaited
// (ProcessCandidate) and a batch's expected answers are computed (Checker) with it called at least every 100 ms
// and between worlds.
// Process-wide, as an interruption is: one check runs at a time in a process, its jobs on threads of it.
class StageCut {
 public:
  explicit StageCut(std::chrono::steady_clock::time_point at);
  ~StageCut();
  StageCut(const StageCut&) = delete;
  StageCut& operator=(const StageCut&) = delete;
};

// A stage was cut at the budget's end. Not a BrokenCandidate: the program did nothing wrong.
class StageCutOff : public std::runtime_error {
 public:
  StageCutOff() : std::runtime_error("the stage was cut at the budget's end") {}
};

// Throws StageCutOff when a StageCut's time has passed.
void throw_if_cut();

}  // namespace circles::conform
