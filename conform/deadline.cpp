#include "conform/deadline.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

namespace circles::conform {
namespace {

// The time of the StageCut alive, in the steady clock's ticks since its epoch; the largest value while none is.
constexpr std::chrono::steady_clock::rep kNoCut = std::chrono::steady_clock::duration::max().count();
std::atomic<std::chrono::steady_clock::rep> stage_cut_at{kNoCut};

}  // namespace

StageCut::StageCut(std::chrono::steady_clock::time_point at) { stage_cut_at.store(at.time_since_epoch().count()); }

StageCut::~StageCut() { stage_cut_at.store(kNoCut); }

void throw_if_cut() {
  if (std::chrono::steady_clock::now().time_since_epoch().count() >= stage_cut_at.load()) throw StageCutOff();
}

std::chrono::milliseconds Deadlines::for_world(std::size_t circles) const {
  const double floor = std::chrono::duration<double>(floor_).count();
  const double n = static_cast<double>(circles);
  double seconds = floor;
  {
    const std::lock_guard lock(mutex_);
    if (largest_ == 0) {
      const double scale = std::max(1.0, n / kFirstCircles);
      seconds = floor * scale * scale;
    } else {
      const double m = static_cast<double>(largest_);
      seconds = kFactor * seconds_ * (n >= m ? (n / m) * (n / m) : n / m);
    }
  }
  // The floor grows with the world too, as its square root: a world's time depends on its layout (a few giant
  // circles, a dense cluster) as well as its size, and a program's big-world path may be many times slower on
  // one world than on the last of the same size.
  seconds = std::max(seconds, floor * std::sqrt(std::max(1.0, n / kFirstCircles)));
  // At most about 31,700 years: a count of milliseconds that no clock arithmetic overflows.
  const double ms = std::min(seconds * 1000, 1e15);
  return std::chrono::milliseconds(static_cast<std::int64_t>(ms));
}

void Deadlines::answered(std::size_t circles, std::chrono::duration<double> took) {
  if (circles == 0) return;
  const std::lock_guard lock(mutex_);
  if (circles > largest_) {
    largest_ = circles;
    seconds_ = took.count();
  } else if (circles == largest_) {
    seconds_ = std::max(seconds_, took.count());
  }
}

}  // namespace circles::conform
