#include "conform/ladder.hpp"

#include <algorithm>
#include <cmath>

namespace circles::conform {

Ladder::Ladder(std::size_t top) {
  for (std::size_t s = kFirstRung; s < top; s *= 2) rungs_.push_back(s);
  rungs_.push_back(top);
}

std::optional<double> Ladder::predicted(std::size_t k) const {
  if (climbed_ == 0) return std::nullopt;
  if (k < climbed_) return seconds_[k];
  const std::size_t last = climbed_ - 1;
  double p = 2;
  if (last >= 1 && seconds_[last - 1] > 0 && seconds_[last] > 0)
    p = std::clamp(std::log(seconds_[last] / seconds_[last - 1]) /
                       std::log(static_cast<double>(rungs_[last]) / static_cast<double>(rungs_[last - 1])),
                   1.0, 2.0);
  return seconds_[last] * std::pow(static_cast<double>(rungs_[k]) / static_cast<double>(rungs_[last]), p);
}

std::optional<std::size_t> Ladder::next(double seconds_left) {
  if (climbed_ == 0) return rungs_.front();
  if (!stopped_ && climbed_ < rungs_.size()) {
    if (kMargin * *predicted(climbed_) <= seconds_left) return rungs_[climbed_];
    stopped_ = true;
  }
  // The rung climbed that has had the least time so far, of those that fit (the smallest on a tie): each rung
  // gets an equal share of the time, so that a small rung, whose stages cost little, asks many more worlds than
  // the top, and the swarm's features meet in many combinations (its extreme frames only in small worlds).
  std::optional<std::size_t> least;
  for (std::size_t k = 0; k < climbed_; ++k)
    if (kMargin * seconds_[k] <= seconds_left && (!least || spent_[k] < spent_[*least])) least = k;
  if (!least) return std::nullopt;
  return rungs_[*least];
}

void Ladder::took(std::size_t size, double seconds) {
  const std::size_t k = static_cast<std::size_t>(std::find(rungs_.begin(), rungs_.end(), size) - rungs_.begin());
  if (k >= rungs_.size()) return;
  if (k == climbed_) {
    seconds_.push_back(seconds);
    spent_.push_back(seconds);
    ++climbed_;
  } else if (k < climbed_) {
    seconds_[k] = std::max(seconds_[k], seconds);
    spent_[k] += seconds;
  }
}

}  // namespace circles::conform
