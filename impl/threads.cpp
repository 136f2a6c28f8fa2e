#include "impl/threads.hpp"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

namespace circles::impl {
namespace {

std::optional<unsigned long long> number(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  unsigned long long n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc{} || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return n;
}

// Whole cores of a quota of `quota` µs of CPU time in every `period` µs, at least 1.
unsigned whole_cores(unsigned long long quota, unsigned long long period) {
  return static_cast<unsigned>(std::clamp<unsigned long long>(quota / period, 1, 1u << 16));
}

// Whether the comma-separated `list` holds `name`.
bool lists(std::string_view list, std::string_view name) {
  for (;;) {
    const std::size_t comma = list.find(',');
    if (list.substr(0, comma) == name) return true;
    if (comma == std::string_view::npos) return false;
    list.remove_prefix(comma + 1);
  }
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The least quota of the cgroups this process is in, and of their ancestors, in cores: from cgroup v2's
// cpu.max, or cgroup v1's cpu controller. Nothing where no quota is set.
std::optional<unsigned> cgroup_quota_cores() {
  std::optional<unsigned> least;
  const auto take = [&least](std::optional<unsigned> cores) {
    if (cores && (!least || *cores < *least)) least = cores;
  };
  std::istringstream lines(read_file("/proc/self/cgroup"));
  for (std::string line; std::getline(lines, line);) {
    // "ID:CONTROLLERS:PATH": v2 is "0::PATH"; v1's cpu controller is listed alone or as "cpu,cpuacct".
    const std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string_view controllers = std::string_view(line).substr(first + 1, second - first - 1);
    const bool v2 = controllers.empty(), v1 = lists(controllers, "cpu");
    if (!v2 && !v1) continue;
    for (std::filesystem::path group = line.substr(second + 1);; group = group.parent_path()) {
      const std::filesystem::path dir = (v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/cpu") / group.relative_path();
      if (v2) take(quota_cores(read_file(dir / "cpu.max")));
      else take(quota_cores(read_file(dir / "cpu.cfs_quota_us"), read_file(dir / "cpu.cfs_period_us")));
      if (!group.has_relative_path()) break;
    }
  }
  return least;
}

// This process's tasks that are running or waiting for a core: the one reading, and any of the engines'
// threads still spinning at the end of a parallel region (OpenMP's active wait), which /proc/loadavg counts.
unsigned own_running_tasks() {
  unsigned running = 0;
  std::error_code error;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", error))
    running += task_running(read_file(task.path() / "stat"));
  return std::max(running, 1u);
}

}  // namespace

std::optional<unsigned> running_tasks(std::string_view loadavg) {
  // The fourth field is "RUNNING/TOTAL".
  std::istringstream fields{std::string(loadavg)};
  std::string field;
  for (int i = 0; i < 4; ++i)
    if (!(fields >> field)) return std::nullopt;
  const std::size_t slash = field.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const auto n = number(std::string_view(field).substr(0, slash));
  if (!n) return std::nullopt;
  return static_cast<unsigned>(std::min<unsigned long long>(*n, 1u << 30));
}

std::optional<unsigned> quota_cores(std::string_view quota, std::string_view period) {
  const auto q = number(quota), p = number(period);  // a quota of -1 (none) is no number here
  if (!q || !p || *p == 0) return std::nullopt;
  return whole_cores(*q, *p);
}

std::optional<unsigned> quota_cores(std::string_view cpu_max) {
  const std::size_t space = cpu_max.find(' ');
  if (space == std::string_view::npos) return std::nullopt;
  return quota_cores(cpu_max.substr(0, space), cpu_max.substr(space + 1));  // "max PERIOD": no number, none
}

bool task_running(std::string_view stat) {
  // "TID (COMM) STATE ...": COMM may hold spaces and parentheses, so the state follows the last ")".
  const std::size_t close = stat.rfind(')');
  return close != std::string_view::npos && close + 2 < stat.size() && stat[close + 2] == 'R';
}

unsigned threads_for(const CoreLoad& load, unsigned max) {
  const unsigned free = load.online > load.others ? load.online - load.others : 0;
  return std::clamp(std::min(load.cores, free), 1u, std::max(max, 1u));
}

CoreLoad read_core_load() {
  CoreLoad load;
  load.cores = std::max(std::thread::hardware_concurrency(), 1u);
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) load.cores = std::max(CPU_COUNT(&set), 1);
  if (const auto quota = cgroup_quota_cores()) load.cores = std::min(load.cores, *quota);
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  load.online = online > 0 ? static_cast<unsigned>(online) : load.cores;
  const std::optional<unsigned> running = running_tasks(read_file("/proc/loadavg"));
  if (running) {
    const unsigned own = own_running_tasks();
    load.others = *running > own ? *running - own : 0;
  }
  return load;
}

ThreadCount::ThreadCount(unsigned requested, unsigned max, std::size_t circles) : max_(max), count_(requested) {
  if (requested > max)
    throw std::invalid_argument("EngineOptions::threads: " + std::to_string(requested) + " is more than " +
                                std::to_string(max));
  if (requested == 0 && circles < kParallelFrom) count_ = 1;
  if (count_ == 0) read();
  least_ = most_ = count_;
}

unsigned ThreadCount::next() {
  if (load_ && std::chrono::steady_clock::now() - read_at_ >= kReadEvery) {
    read();
    least_ = std::min(least_, count_);
    most_ = std::max(most_, count_);
  }
  return count_;
}

void ThreadCount::read() {
  load_ = read_core_load();
  count_ = threads_for(*load_, max_);
  read_at_ = std::chrono::steady_clock::now();
}

}  // namespace circles::impl
