// The engines' default thread count (impl/threads.hpp): one thread per core that other programs leave free,
// read from the machine when an engine starts and again during its run. The count never changes a result (the
// golden tests and engine_options_test.cpp hold every count to the same bits); these check which count is
// chosen, from readings given and from the machine with its cores made busy.
#include "impl/engine.hpp"
#include "impl/exact_engine.hpp"
#include "formats/random_scene.hpp"
#include "impl/threads.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

extern char** environ;

namespace circles::impl {
namespace {

TEST(threads, one_per_core_that_other_programs_leave_free) {
  // {cores this process may use, online cores, tasks of other programs running}
  EXPECT_EQ(threads_for({2, 2, 0}, 256), 2u);
  EXPECT_EQ(threads_for({2, 2, 1}, 256), 1u);
  EXPECT_EQ(threads_for({2, 2, 2}, 256), 1u);
  EXPECT_EQ(threads_for({2, 2, 9}, 256), 1u);  // never fewer than one
  EXPECT_EQ(threads_for({64, 64, 40}, 256), 24u);
  EXPECT_EQ(threads_for({8, 8, 0}, 4), 4u);  // never more than the engine takes
  // A CPU quota or affinity of 2 cores on a machine of 64: the other programs' tasks run on the other cores.
  EXPECT_EQ(threads_for({2, 64, 40}, 256), 2u);
  EXPECT_EQ(threads_for({2, 64, 63}, 256), 1u);
}

TEST(threads, reads_the_running_tasks_the_quota_and_the_task_state_from_their_files) {
  EXPECT_EQ(running_tasks("0.61 0.40 0.33 3/151 4117\n"), 3u);
  EXPECT_EQ(running_tasks("6.38 4.50 2.11 12/166 12660"), 12u);
  EXPECT_EQ(running_tasks("0.61 0.40 0.33"), std::nullopt);
  EXPECT_EQ(running_tasks("0.61 0.40 0.33 x/151 4117"), std::nullopt);
  // cgroup v2 cpu.max: QUOTA PERIOD in µs, or "max"; whole cores, at least one.
  EXPECT_EQ(quota_cores("max 100000\n"), std::nullopt);
  EXPECT_EQ(quota_cores("200000 100000\n"), 2u);
  EXPECT_EQ(quota_cores("150000 100000\n"), 1u);
  EXPECT_EQ(quota_cores("50000 100000\n"), 1u);
  EXPECT_EQ(quota_cores(""), std::nullopt);  // no such file
  // cgroup v1: cpu.cfs_quota_us (-1 for none) and cpu.cfs_period_us.
  EXPECT_EQ(quota_cores("-1\n", "100000\n"), std::nullopt);
  EXPECT_EQ(quota_cores("300000\n", "100000\n"), 3u);
  EXPECT_EQ(quota_cores("300000\n", "0\n"), std::nullopt);
  // /proc/PID/task/TID/stat: the state follows the command's name, which may hold ") ".
  EXPECT_TRUE(task_running("4117 (circles) R 1 4117 4117 0 -1"));
  EXPECT_FALSE(task_running("4117 (circles) S 1 4117 4117 0 -1"));
  EXPECT_TRUE(task_running("4117 (a) S (b) R 1 4117"));
  EXPECT_FALSE(task_running("4117 (circles"));
}

TEST(threads, a_count_asked_for_is_kept_and_a_small_world_runs_on_one_without_a_reading) {
  const ThreadCount asked(3, 256, 1'000'000);
  EXPECT_EQ(asked.count(), 3u);
  EXPECT_EQ(asked.load(), std::nullopt);
  const ThreadCount small(0, 256, kParallelFrom - 1);
  EXPECT_EQ(small.count(), 1u);
  EXPECT_EQ(small.load(), std::nullopt);
  EXPECT_THROW(ThreadCount(257, 256, 10), std::invalid_argument);
}

// `n` processes of /bin/sh spinning in a loop while the object lives: other programs' tasks, always running.
class BusyProcesses {
 public:
  explicit BusyProcesses(unsigned n) {
    char sh[] = "/bin/sh", c[] = "-c", loop[] = "while :; do :; done";
    char* argv[] = {sh, c, loop, nullptr};
    for (unsigned i = 0; i < n; ++i) {
      pid_t pid = 0;
      if (posix_spawn(&pid, sh, nullptr, nullptr, argv, environ) == 0) pids_.push_back(pid);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // each one running
  }
  ~BusyProcesses() {
    for (const pid_t pid : pids_) kill(pid, SIGKILL);
    for (const pid_t pid : pids_) waitpid(pid, nullptr, 0);
  }
  BusyProcesses(const BusyProcesses&) = delete;
  BusyProcesses& operator=(const BusyProcesses&) = delete;
  std::size_t size() const { return pids_.size(); }

 private:
  std::vector<pid_t> pids_;
};

unsigned online_cores() { return static_cast<unsigned>(sysconf(_SC_NPROCESSORS_ONLN)); }

TEST(threads, with_every_core_busy_the_engines_of_a_big_world_step_on_one_thread) {
  const BusyProcesses busy(online_cores());
  ASSERT_EQ(busy.size(), online_cores());
  const World w(formats::random_scene(20'000, 0.1, 1));
  DoubleEngine engine(w);
  EXPECT_EQ(engine.threads(), 1u);
  ASSERT_TRUE(engine.thread_count().load());
  EXPECT_GE(engine.thread_count().load()->others, online_cores());
  engine.step();
  EXPECT_EQ(engine.threads(), 1u);
  EXPECT_EQ(ExactEngine(w).threads(), 1u);
}

TEST(threads, a_load_that_comes_during_a_run_lowers_the_count_at_the_next_reading) {
  ThreadCount count(0, 256, 20'000);
  ASSERT_TRUE(count.load());
  const BusyProcesses busy(online_cores());
  std::this_thread::sleep_for(ThreadCount::kReadEvery);
  EXPECT_EQ(count.next(), 1u);
  EXPECT_GE(count.load()->others, online_cores());
  EXPECT_EQ(count.least(), 1u);
}

}  // namespace
}  // namespace circles::impl
