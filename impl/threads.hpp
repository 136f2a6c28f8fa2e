// The engines' thread count: the one asked for, or for 0 (the default) one thread per core that other
// programs leave free, read from the machine when the engine starts and every kReadEvery after.
//
// Why not one per core: the engines' threads meet at the end of every parallel region (several a step), so a
// step on T threads lasts as long as its slowest thread. On a machine whose cores are busy with other work (a
// CI runner, a shared build machine), a thread waits for a core for a time slice of the scheduler's, and every
// region waits for it: `circles run --random 100000 --coverage 0.1 --steps 60` on 2 cores, both busy, took
// 800-1590 ns a circle-step on 2 threads against 179-270 on one (docs/benchmarks.md, "Threads under load"). A core
// counts as busy while a task of another program is running or waiting to run (Linux's count of runnable
// tasks, /proc/loadavg), so that every thread chosen has a core to itself when it is read.
//
// The count never changes a result: every thread count gives the same bits (impl/contacts.hpp, docs/engine.md).
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string_view>

namespace circles::impl {

// Worlds below this size run on one thread: a parallel region costs more than it saves.
inline constexpr std::size_t kParallelFrom = 8192;

// What the machine looked like to --threads 0.
struct CoreLoad {
  unsigned cores = 1;   // the cores this process may run on: its CPU affinity, or a cgroup's CPU quota if less
  unsigned online = 1;  // the machine's online cores, on which `others` run
  unsigned others = 0;  // tasks of other programs running or waiting for a core
};

// The threads for a reading: one per core free of other programs' tasks, no more than `cores`, at least 1
// and at most `max`.
unsigned threads_for(const CoreLoad& load, unsigned max);

// This machine now. On a system without /proc, `cores` only, from std::thread::hardware_concurrency().
CoreLoad read_core_load();

// The threads an engine steps on: `requested`, or for 0 threads_for(read_core_load(), max), read when the
// engine starts and again before a step when kReadEvery has passed since the last reading, so that a load that
// comes or goes during a run changes the count within that time. A world of fewer than kParallelFrom circles
// runs on one thread whatever the count (impl/contacts.hpp): for it, 0 gives 1 without reading the machine.
// Every count gives the same bits, so a count that changes between steps changes none.
class ThreadCount {
 public:
  // A reading costs about 60 µs (measured on the 2-core development machine, shared): a few small files of
  // /proc and /sys, and one for each of the process's threads. Every 100 ms, that is 0.06% of a run.
  static constexpr std::chrono::milliseconds kReadEvery{100};

  // Throws std::invalid_argument above `max`.
  ThreadCount(unsigned requested, unsigned max, std::size_t circles);

  // The count for the next step, read again if it is due.
  unsigned next();

  unsigned count() const noexcept { return count_; }  // the count of the last step (before any, the first)
  unsigned least() const noexcept { return least_; }  // the least and the most count of the steps so far
  unsigned most() const noexcept { return most_; }
  // The last reading, when the count is chosen from the load.
  const std::optional<CoreLoad>& load() const noexcept { return load_; }

 private:
  void read();

  unsigned max_, count_, least_, most_;
  std::optional<CoreLoad> load_;
  std::chrono::steady_clock::time_point read_at_{};
};

// The parts of the reading, from the text of the files they are read from (exposed for the tests):
// the running tasks of /proc/loadavg ("0.61 0.40 0.33 3/151 4117": 3); the cores of a cgroup v2 cpu.max
// ("150000 100000": 1.5 cores, so 1; "max 100000": none) or of cgroup v1's cpu.cfs_quota_us and
// cpu.cfs_period_us ("-1": none); whether a /proc/PID/task/TID/stat line says the task is running ("R").
std::optional<unsigned> running_tasks(std::string_view loadavg);
std::optional<unsigned> quota_cores(std::string_view quota, std::string_view period);
std::optional<unsigned> quota_cores(std::string_view cpu_max);
bool task_running(std::string_view stat);

}  // namespace circles::impl
