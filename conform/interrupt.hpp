// How a check ends on a signal (SIGINT from Ctrl-C, SIGTERM from a CI time-out or kill, SIGHUP from a closed
// terminal): the handler records the signal and kills the process group of every candidate program running
// (nothing conform starts outlives it), and the check, at its next request or case, stops with the verdict
// `interrupted`: the cases checked so far, the seed, and its reports written as usual.
//
// interrupt() is all the handler calls: it is async-signal-safe (an atomic store, kill(2)). The groups are kept
// in a fixed table of atomics, so the handler reads them without a lock while the check adds and removes them.
#pragma once

#include <stdexcept>
#include <string>

#include <sys/types.h>

namespace circles::conform {

// Records `signal` as the check's interruption (the first one recorded stays) and sends SIGKILL to every tracked
// process group. Async-signal-safe; for a signal handler.
void interrupt(int signal) noexcept;

// The signal that interrupted the check, 0 while none has.
int interruption() noexcept;

// Forgets an interruption, so that a process (a test) can check again.
void clear_interruption() noexcept;

// "SIGINT", "SIGTERM", "SIGHUP"; "signal N" for another.
std::string signal_name(int signal);

// The check stopped on a signal. Not a BrokenCandidate: the candidate did nothing wrong, and nothing that
// retries a broken candidate (shrinking) may take it for a failure of the world being asked.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const noexcept { return signal_; }

 private:
  int signal_;
};

// Throws Interrupted if a signal has interrupted the check.
void throw_if_interrupted();

// The process groups interrupt() kills: a candidate program's group, from its start until it is reaped. At most
// kMaxTrackedGroups at once (one per program conform runs at a time); track_group returns false when the
// table is full, and the caller then stops that program itself when it sees the interruption.
inline constexpr int kMaxTrackedGroups = 1024;
bool track_group(pid_t group) noexcept;
void untrack_group(pid_t group) noexcept;

}  // namespace circles::conform
