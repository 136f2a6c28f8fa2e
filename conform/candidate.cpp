#include "conform/candidate.hpp"

#include "conform/interrupt.hpp"
#include "conform/replay.hpp"
#include "formats/json_number.hpp"
#include "formats/output_file.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <limits>
#include <mutex>
#include <string_view>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace circles::conform {

namespace json_number = formats::json_number;

Circles EngineCandidate::answer(const Circles& world, std::uint64_t id) {
  try {
    return engines::step_once(engine_, world, threads_);
  } catch (const engines::StepOverflow& e) {
    throw BrokenCandidate("request " + std::to_string(id) + ": " + e.what());
  }
}

const char* name(Fault fault) {
  switch (fault) {
    case Fault::exited: return "crashed or exited";
    case Fault::hung: return "hung";
    case Fault::malformed: return "wrote a malformed answer";
    case Fault::other: break;
  }
  return "";
}

struct RequestLog::File {
  std::mutex mutex;
  formats::OutputFile out;
  explicit File(const std::string& path) : out(path, "--log " + path) {}
};

RequestLog::RequestLog(std::string path) : file_(std::make_unique<File>(path)) {}
RequestLog::~RequestLog() = default;

void RequestLog::write(unsigned copy, char direction, std::string_view text) {
  std::string lines;
  const std::string prefix = std::to_string(copy) + direction + ' ';
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.append(prefix).append(text.substr(at, end - at)).push_back('\n');
    at = end + 1;
  }
  const std::lock_guard lock(file_->mutex);
  file_->out.write(lines);
}

void RequestLog::commit() {
  const std::lock_guard lock(file_->mutex);
  file_->out.commit();
}

std::unique_ptr<Candidate> ProcessCandidate::copy() const {
  auto copy = std::make_unique<ProcessCandidate>(command_, deadline_, deadlines_);
  copy->log_ = log_;
  copy->copy_ = copy_ + ++copies_made_;
  return copy;
}

std::string EngineCandidate::name() const { return "the " + std::string(engine_.name) + " engine"; }
std::string EngineCandidate::option() const { return "--engine " + std::string(engine_.name); }
std::string ProcessCandidate::option() const { return "--exec " + shell_quoted(command_); }

namespace {

std::string system_error(const char* what) { return std::string(what) + ": " + std::strerror(errno); }

// "10 s", "0.25 s": the deadline in the shortest decimal form.
std::string seconds(std::chrono::milliseconds deadline) {
  return json_number::plain(std::chrono::duration<double>(deadline).count()) + " s";
}

}  // namespace

ProcessCandidate::ProcessCandidate(std::string command, std::chrono::milliseconds deadline,
                                   std::shared_ptr<Deadlines> deadlines)
    : command_(std::move(command)),
      deadline_(deadline),
      deadlines_(deadlines ? std::move(deadlines) : std::make_shared<Deadlines>(deadline)) {
  std::signal(SIGPIPE, SIG_IGN);
  start();
}

void ProcessCandidate::start() {
  throw_if_interrupted();  // no program is started once the check is ending
  int in[2], out[2];
  if (pipe2(in, O_CLOEXEC) != 0) throw BrokenCandidate(system_error("cannot create a pipe"));
  if (pipe2(out, O_CLOEXEC) != 0) {
    close(in[0]);
    close(in[1]);
    throw BrokenCandidate(system_error("cannot create a pipe"));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // A process group of its own (killed whole at the end), and SIGPIPE back to its default in the program.
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setpgroup(&attributes, 0);
  // The signals that interrupt a check are held from before the program starts until its group is tracked, so
  // that interrupt() cannot fire between the two and miss the group; the program gets the mask we had.
  sigset_t ending, before;
  sigemptyset(&ending);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&ending, signal);
  pthread_sigmask(SIG_BLOCK, &ending, &before);
  posix_spawnattr_setsigmask(&attributes, &before);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::string shell = "/bin/sh", dash_c = "-c";
  char* argv[] = {shell.data(), dash_c.data(), command_.data(), nullptr};
  const int spawned = posix_spawn(&pid_, "/bin/sh", &actions, &attributes, argv, environ);
  // A full table leaves the group to kill_group, when the check sees the interruption.
  if (spawned == 0) track_group(pid_);
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(in[0]);
  close(out[1]);
  to_child_ = in[1];
  from_child_ = out[0];
  if (spawned != 0) {
    pid_ = -1;
    errno = spawned;
    throw BrokenCandidate(system_error(("cannot start " + name()).c_str()));
  }
}

ProcessCandidate::~ProcessCandidate() { stop(); }

void ProcessCandidate::stop() noexcept {
  kill_group();
  if (to_child_ >= 0) close(to_child_);
  if (from_child_ >= 0) close(from_child_);
  to_child_ = from_child_ = -1;
}

void ProcessCandidate::restart() {
  stop();
  buffer_.clear();
  status_.clear();
  unanswered_ = 0;
  start();
}

void ProcessCandidate::kill_group() noexcept {
  if (pid_ <= 0) return;
  kill(-pid_, SIGKILL);  // the whole group: the shell and whatever it started
  reap(true);
  pid_ = -1;
}

std::optional<int> ProcessCandidate::reap(bool wait) noexcept {
  // Seen exited but not yet reaped (WNOWAIT), the shell's pid, which is its group's id, cannot be taken by a new
  // process: the group is untracked and killed while the id is still ours, and only then reaped.
  siginfo_t info{};
  int waited;
  do {
    waited = waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOWAIT | (wait ? 0 : WNOHANG));
  } while (waited < 0 && errno == EINTR);
  if (waited < 0 || info.si_pid != pid_) return std::nullopt;
  untrack_group(pid_);
  kill(-pid_, SIGKILL);  // the shell has exited; anything it left behind in its group goes too
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

std::string ProcessCandidate::exit_status(bool wait) {
  if (pid_ <= 0) return status_;
  const std::optional<int> status = reap(wait);
  if (!status) return "";
  pid_ = -1;
  if (WIFEXITED(*status)) status_ = "exited with status " + std::to_string(WEXITSTATUS(*status));
  else if (WIFSIGNALED(*status)) status_ = "was killed by signal " + std::to_string(WTERMSIG(*status));
  else status_ = "stopped";
  return status_;
}

std::string ProcessCandidate::read_line(std::uint64_t id, std::chrono::milliseconds deadline, std::size_t longest) {
  const auto give_up = std::chrono::steady_clock::now() + deadline;
  // buffer_[0, scanned) holds no newline: an answer of megabytes, read 64 KiB at a time, is searched once.
  for (std::size_t scanned = 0;;) {
    const auto newline = buffer_.find('\n', scanned);
    // Past `longest`, the line is malformed whatever follows: what we hold stays below longest + one chunk.
    if (std::min(newline, buffer_.size()) > longest) {
      kill_group();
      throw BrokenCandidate(name() + " wrote a malformed answer to request " + std::to_string(id) +
                            ": the line is longer than " + std::to_string(longest) +
                            " bytes, more than any answer to its world needs (docs/protocol.md, Limits)",
                            Fault::malformed);
    }
    if (newline != std::string::npos) {
      std::string line = buffer_.substr(0, newline);
      buffer_.erase(0, newline + 1);
      return line;
    }
    throw_if_interrupted();
    throw_if_cut();  // the answer stays unanswered_: the program is started afresh before it is asked again
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      kill_group();
      throw BrokenCandidate(name() + " gave no answer to request " + std::to_string(id) + " within " +
                            seconds(deadline) + " (it was stopped)",
                            Fault::hung);
    }
    // At most 100 ms a wait, so that a stage's cut (throw_if_cut) is seen within a tenth of a second.
    pollfd ready{from_child_, POLLIN, 0};
    const int polled = poll(&ready, 1, static_cast<int>(std::min<long long>(left.count(), 100)));
    if (polled < 0 && errno != EINTR) throw BrokenCandidate(system_error("poll"));
    if (polled <= 0) continue;
    char chunk[65536];
    const ssize_t got = read(from_child_, chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw BrokenCandidate(system_error("cannot read the candidate's answer"));
    if (got == 0) {
      throw_if_interrupted();  // the end of a program that interrupt() killed is not its fault
      const std::string status = exit_status(true);
      throw BrokenCandidate(name() + " " + status + " before answering request " + std::to_string(id) +
                            (buffer_.empty() ? "" : " (it wrote a line without a newline: \"" + buffer_.substr(0, 80) + "\")"),
                            Fault::exited);
    }
    scanned = buffer_.size();
    buffer_.append(chunk, static_cast<std::size_t>(got));
  }
}

void ProcessCandidate::write_requests(std::string_view lines, std::span<const std::size_t> ends,
                                      std::uint64_t first_id) {
  const std::size_t total = lines.size();
  while (!lines.empty()) {
    const ssize_t wrote = write(to_child_, lines.data(), lines.size());
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote < 0 && errno != EPIPE) throw BrokenCandidate(system_error("cannot write to the candidate"));
    if (wrote < 0) {
      throw_if_interrupted();
      // Its input is closed: most likely it exited (then say how, as when its output ends), else it closed it.
      // The request named is the one being written: the first not wholly written.
      const std::size_t at = total - lines.size();
      const std::uint64_t id = first_id + static_cast<std::uint64_t>(
                                              std::upper_bound(ends.begin(), ends.end(), at) - ends.begin());
      const auto give_up = std::chrono::steady_clock::now() + deadline_;
      std::string status;
      while ((status = exit_status(false)).empty() && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      if (status.empty()) throw BrokenCandidate(name() + " closed its input at request " + std::to_string(id),
                            Fault::exited);
      throw BrokenCandidate(name() + " " + status + " before answering request " + std::to_string(id),
                            Fault::exited);
    }
    lines.remove_prefix(static_cast<std::size_t>(wrote));
  }
}

std::size_t ProcessCandidate::longest_answer(std::size_t circles) {
  constexpr std::size_t most = std::numeric_limits<std::size_t>::max();
  return circles > (most - kAnswerSlack) / kCircleBytes ? most : kAnswerSlack + circles * kCircleBytes;
}

Circles ProcessCandidate::read_answer(const Circles& world, std::uint64_t id) {
  std::string text = read_line(id, deadlines_->for_world(world.size()), longest_answer(world.size()));
  if (log_) log_->write(copy_, '<', text);
  const auto now = std::chrono::steady_clock::now();
  deadlines_->answered(world.size(), now - asked_);
  asked_ = now;
  ++lines_;
  Line line;
  try {
    // A plain line, as most answers are, by the trace reader's fast path; anything else (a fault to name, a
    // NaN, an unknown key) by parse_line, which reads the same line to the same values (formats/plain_line.hpp).
    if (auto plain = plain_.read(text, kId)) line = std::move(*plain);
    else line = parse_line(text, lines_, kId, Reading::answer);
  } catch (const ProtocolError& e) {
    throw BrokenCandidate(name() + " wrote a malformed answer to request " + std::to_string(id) + ": " + e.what(),
                            Fault::malformed);
  }
  if (line.number != id)
    throw BrokenCandidate(name() + " answered request " + std::to_string(id) + " with id " + std::to_string(line.number),
                            Fault::malformed);
  if (line.circles.size() != world.size())
    throw BrokenCandidate(name() + " answered request " + std::to_string(id) + " (" + std::to_string(world.size()) +
                          " circles) with " + std::to_string(line.circles.size()) + " circles",
                            Fault::malformed);
  return std::move(line.circles);
}

std::vector<Circles> Answers::all() && {
  if (broken) throw *broken;
  return std::move(answers);
}

Answers Candidate::answer_all(std::span<const Circles> worlds, std::uint64_t first_id, std::span<const Spelling>) {
  throw_if_interrupted();
  Answers read;
  read.answers.reserve(worlds.size());
  try {
    for (const Circles& world : worlds) read.answers.push_back(answer(world, first_id++));
  } catch (const BrokenCandidate& e) {
    read.broken = e;
  }
  return read;
}

Answers ProcessCandidate::answer_all(std::span<const Circles> worlds, std::uint64_t first_id,
                                     std::span<const Spelling> spellings) {
  // After a fault, what the program wrote to earlier requests may still be on its way: a fresh program, so that
  // no answer is ever taken for another request's. Then a program that crashed, hung or broke the protocol
  // on one world is asked about the next from a clean start (as shrinking asks).
  if (unanswered_ > 0 || pid_ <= 0) restart();
  Answers read;
  read.answers.reserve(worlds.size());
  try {
    answer_batches(worlds, first_id, spellings, read.answers);
  } catch (const BrokenCandidate& e) {
    read.broken = e;
  }
  return read;
}

void ProcessCandidate::answer_batches(std::span<const Circles> worlds, std::uint64_t first_id,
                                      std::span<const Spelling> spellings, std::vector<Circles>& answers) {
  std::string lines;
  std::vector<std::size_t> ends;  // the offset just past each request line in `lines`
  for (std::size_t first = 0; first < worlds.size();) {
    // The batch: requests first … last − 1, at least one, at most kBatchBytes unless the first alone is more.
    lines.clear();
    ends.clear();
    std::size_t last = first;
    for (; last < worlds.size(); ++last) {
      const std::size_t before = lines.size();
      if (!spellings.empty() && spellings[last] == Spelling::every_form)
        formats::append_spelled_line(lines, kId, first_id + last, worlds[last]);
      else
        formats::append_line(lines, kId, first_id + last, worlds[last]);
      lines += '\n';
      if (last > first && lines.size() > kBatchBytes) {
        lines.resize(before);
        break;
      }
      ends.push_back(lines.size());
    }
    unanswered_ += last - first;
    if (log_) log_->write(copy_, '>', std::string_view(lines).substr(0, lines.size() - 1));
    asked_ = std::chrono::steady_clock::now();
    write_requests(lines, ends, first_id + first);
    for (; first < last; ++first) {
      answers.push_back(read_answer(worlds[first], first_id + first));
      --unanswered_;
    }
  }
}

Circles ProcessCandidate::answer(const Circles& world, std::uint64_t id) {
  return std::move(answer_all(std::span(&world, 1), id).all().front());
}

void ProcessCandidate::finish() {
  // A program whose answer a stage's cut left unread is still working on it: a fresh one is what ends at the end
  // of its input, as every program must.
  if (unanswered_ > 0) restart();
  if (to_child_ >= 0) {
    close(to_child_);
    to_child_ = -1;
  }
  const auto give_up = std::chrono::steady_clock::now() + deadline_;
  std::string status;
  while ((status = exit_status(false)).empty() && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (status.empty()) {
    kill_group();
    throw BrokenCandidate(name() + " did not exit within " + seconds(deadline_) +
                          " of the end of its input (it was stopped)");
  }
  if (status != "exited with status 0")
    throw BrokenCandidate(name() + " " + status + " at the end of its input (a candidate exits 0)");
}

}  // namespace circles::conform
