// A candidate implementation under test: anything that answers the step protocol (docs/protocol.md).
//
//   EngineCandidate   one of our engines, in process (cli/engines.hpp).
//   ProcessCandidate  any program: started once with `/bin/sh -c COMMAND`, fed one request line at a time on
//                     its stdin, read one answer line at a time from its stdout, with a deadline per request.
//                     It runs in a process group of its own, which is killed when the candidate is destroyed,
//                     so no process outlives the check, whatever the program does.
#pragma once

#include "cli/engines.hpp"
#include "cli/protocol.hpp"

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <sys/types.h>

namespace circles::cli {

// The candidate cannot be checked: it crashed, exited, hung past its deadline, wrote a malformed line, a wrong
// id or a wrong number of circles. what() says which, for which request.
class BrokenCandidate : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Candidate {
 public:
  virtual ~Candidate() = default;
  // The candidate's w_1 for w_0 = `world`, asked as request `id`. Throws BrokenCandidate; an answer that is
  // only wrong (a different world of the right shape) is returned for the caller to judge.
  virtual Circles answer(const Circles& world, std::uint64_t id) = 0;
  // The end of the input: the candidate must exit 0 (a process) or simply stop. Throws BrokenCandidate.
  virtual void finish() {}
  // "the double engine", "the program `python3 step.py`": for messages.
  virtual std::string name() const = 0;
};

class EngineCandidate : public Candidate {
 public:
  EngineCandidate(const EngineEntry& engine, unsigned threads) : engine_(engine), threads_(threads) {}
  // A position beyond the double range is an answer the protocol cannot carry: BrokenCandidate.
  Circles answer(const Circles& world, std::uint64_t id) override;
  std::string name() const override;

 private:
  const EngineEntry& engine_;
  unsigned threads_;
};

class ProcessCandidate : public Candidate {
 public:
  // Starts the program. Throws BrokenCandidate if it cannot be started. Ignores SIGPIPE in this process from
  // then on (a write to a candidate that exited must be an error to report, not a signal that kills us).
  ProcessCandidate(std::string command, std::chrono::milliseconds deadline);
  ~ProcessCandidate() override;
  ProcessCandidate(const ProcessCandidate&) = delete;
  ProcessCandidate& operator=(const ProcessCandidate&) = delete;

  Circles answer(const Circles& world, std::uint64_t id) override;
  // Closes the program's stdin and waits, up to the deadline, for it to exit 0.
  void finish() override;
  std::string name() const override { return "the program `" + command_ + "`"; }

 private:
  // The next line the program writes, without its newline, or BrokenCandidate at the deadline or at EOF.
  std::string read_line(std::uint64_t id);
  // "exited with status 3", "was killed by signal 11", or "" while it runs.
  std::string exit_status(bool wait);
  void kill_group() noexcept;

  std::string command_;
  std::chrono::milliseconds deadline_;
  pid_t pid_ = -1;
  int to_child_ = -1, from_child_ = -1;
  std::string buffer_;
  std::size_t lines_ = 0;
  std::string status_;  // set once the program is reaped
};

}  // namespace circles::cli
