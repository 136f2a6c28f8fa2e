// The chained check of a step against a reference, the one loop that conform (conform/conform.cpp), the main job
// (cli/run.cpp), check-trace (conform/check_trace.cpp) and the conformance property (step_conforms) all run:
// from w_0, the answer to each step's input is compared (compare, at a level) with the reference's answer for
// that input, and the chain goes on from the candidate's own answer, up to its length, its first difference, or
// a step with no reference answer. A reference that keeps its own sequence (the oracle stepping beside an engine)
// meets the same inputs: they are the same worlds as long as the two agree, and the chain stops where they do not.
//
// Who asks the candidate and the reference is the caller's: conform asks many chains' next steps in one batch,
// check-trace reads answers from a file, the main job steps two engines side by side.
#pragma once

#include "properties/conformance.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <optional>
#include <utility>

namespace circles::properties {

// The step of a chain whose answer differs from the reference's: which step (1-based) of how many, the world
// asked, the two answers, and the first difference.
struct ChainFailure {
  std::uint64_t step, steps;
  Circles input, expected, actual;
  Difference difference;
  // Not a wrong answer but none: how the candidate broke instead of answering ("crashed or exited", "hung",
  // "wrote a malformed answer"), with `actual` empty and the whole message in difference.decision. "" for an
  // answer that differs.
  std::string fault{};
};

class Chain {
 public:
  // How a chain that did not fail ended: every step judged; or no reference answer for the step after
  // `step()` (its next world leaves the double range, or the literal domain): at w_0, or later.
  enum class Ending { checked, no_reference_at_w0, no_reference_later };

  Chain(Circles w_0, std::uint64_t steps, Level level = {}) : input_(std::move(w_0)), steps_(steps), level_(level) {}

  const Circles& input() const noexcept { return input_; }  // what the next step is asked: w_0, then the last answer
  std::uint64_t step() const noexcept { return step_; }      // steps judged so far
  std::uint64_t steps() const noexcept { return steps_; }
  bool going() const noexcept { return step_ < steps_ && !failure_ && !ended_; }
  // Whether the step after the next one will be asked too (the caller must wait for the next answer).
  bool goes_on_after_next() const noexcept { return step_ + 1 < steps_; }

  // Judges step step() + 1: `answer`, which has as many circles as input(), against the reference's `expected`.
  // Returns true when they agree (the chain goes on from `answer`); else the chain ends with failure().
  bool judge(Circles answer, Circles expected) {
    ++step_;
    if (auto d = compare(input_, expected, answer, level_)) {
      failure_ = ChainFailure{step_, steps_, std::move(input_), std::move(expected), std::move(answer), std::move(*d)};
      return false;
    }
    input_ = std::move(answer);
    return true;
  }
  // Ends the chain at step step() + 1 with a failure: the candidate broke (`fault`, the kind; `what`, how)
  // instead of answering; `expected` is the reference's answer.
  void broke(Circles expected, std::string fault, std::string what) {
    ++step_;
    Difference d{0, spec::Field::px, expected.empty() ? 0.0 : expected[0][0],
                 std::numeric_limits<double>::quiet_NaN(), "none: " + std::move(what)};
    failure_ = ChainFailure{step_, steps_, std::move(input_), std::move(expected), {}, std::move(d), std::move(fault)};
  }
  // Ends the chain before step step() + 1, which has no reference answer.
  void end() noexcept { ended_ = true; }

  Ending ending() const noexcept {
    if (!ended_) return Ending::checked;
    return step_ == 0 ? Ending::no_reference_at_w0 : Ending::no_reference_later;
  }
  const std::optional<ChainFailure>& failure() const noexcept { return failure_; }
  std::optional<ChainFailure>& failure() noexcept { return failure_; }

 private:
  Circles input_;
  std::uint64_t steps_, step_ = 0;
  Level level_;
  bool ended_ = false;
  std::optional<ChainFailure> failure_;
};

}  // namespace circles::properties
