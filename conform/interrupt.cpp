#include "conform/interrupt.hpp"

#include <array>
#include <atomic>
#include <csignal>

namespace circles::conform {
namespace {

std::atomic<int> recorded{0};
// 0 marks a free slot. Lock-free on every platform circles builds for (static_assert below), as a handler needs.
std::array<std::atomic<pid_t>, kMaxTrackedGroups> groups{};
static_assert(std::atomic<pid_t>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

}  // namespace

void interrupt(int signal) noexcept {
  int none = 0;
  recorded.compare_exchange_strong(none, signal);
  for (std::atomic<pid_t>& group : groups)
    if (const pid_t g = group.load(); g > 0) kill(-g, SIGKILL);
}

int interruption() noexcept { return recorded.load(); }

void clear_interruption() noexcept { recorded.store(0); }

std::string signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal " + std::to_string(signal);
  }
}

Interrupted::Interrupted(int signal) : std::runtime_error("interrupted by " + signal_name(signal)), signal_(signal) {}

void throw_if_interrupted() {
  if (const int signal = interruption()) throw Interrupted(signal);
}

bool track_group(pid_t group) noexcept {
  for (std::atomic<pid_t>& slot : groups) {
    pid_t free = 0;
    if (slot.compare_exchange_strong(free, group)) return true;
  }
  return false;
}

void untrack_group(pid_t group) noexcept {
  for (std::atomic<pid_t>& slot : groups) {
    pid_t tracked = group;
    if (slot.compare_exchange_strong(tracked, 0)) return;
  }
}

}  // namespace circles::conform
