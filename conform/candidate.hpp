// A candidate implementation under test: anything that answers the step protocol (docs/protocol.md).
//
//   EngineCandidate   one of our engines, in process (engines/registry.hpp).
//   ProcessCandidate  any program: started once with `/bin/sh -c COMMAND`, fed request lines on its stdin (a
//                     batch of them at a time, so that a batch shares one round trip through the pipes), read
//                     one answer line at a time from its stdout, in order, with a deadline per request.
//                     It runs in a process group of its own, which is killed when the candidate is destroyed,
//                     so no process outlives the check, whatever the program does; a signal that interrupts
//                     the check kills it at once (conform/interrupt.hpp). After a fault (a crash, a
//                     hang, a malformed line, a wrong id or count), the next answer_all starts the program
//                     afresh, so that no answer it wrote to an earlier request is read as another's.
#pragma once

#include "conform/deadline.hpp"
#include "engines/registry.hpp"
#include "formats/plain_line.hpp"
#include "formats/protocol.hpp"
#include "formats/spelling.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <sys/types.h>

namespace circles::conform {

using spec::Circles;
using formats::ProtocolError;
using formats::Line;
using formats::Reading;
using formats::parse_line;
using formats::format_line;
using formats::kId;
using formats::Spelling;

// What a candidate did instead of answering a request: it exited or was killed (exited), gave no answer within
// its deadline (hung), or wrote a malformed line, a wrong id or a wrong number of circles (malformed); or
// something that no world explains (other: a pipe that cannot be made, a program that cannot start).
enum class Fault { other, exited, hung, malformed };
// "crashed or exited", "hung", "wrote a malformed answer", "" for other.
const char* name(Fault fault);

// The candidate broke instead of answering: what() says how, for which request; fault() is its kind. conform
// reports a fault on a world as a counterexample (conform/conform.hpp), and one before the program's first
// answer, or of kind other, as a candidate it cannot check.
class BrokenCandidate : public std::runtime_error {
 public:
  explicit BrokenCandidate(const std::string& what, Fault fault = Fault::other)
      : std::runtime_error(what), fault_(fault) {}
  Fault fault() const noexcept { return fault_; }

 private:
  Fault fault_;
};

// Where `circles conform --log FILE` writes every request line sent and every answer line read, as they go, each
// prefixed by the copy of the program (--jobs) that it went to or came from: "1> " for a request to copy 1,
// "1< " for an answer from it. Shared by the copies.
class RequestLog {
 public:
  explicit RequestLog(std::string path);
  ~RequestLog();
  RequestLog(const RequestLog&) = delete;
  RequestLog& operator=(const RequestLog&) = delete;
  // The lines of `text`, each prefixed. Throws formats::OutputError.
  void write(unsigned copy, char direction, std::string_view text);
  // Closes the file, in place or renamed over its path. Throws formats::OutputError.
  void commit();

 private:
  struct File;
  std::unique_ptr<File> file_;
};

// What Candidate::answer_all read: the answers to its first answers.size() requests, in order, and, when that is
// not all of them, why the next one has none (what answer() would have thrown for it). A caller judges the
// answers it has before it reports the candidate broken: a wrong answer ahead of the fault is a counterexample.
struct Answers {
  std::vector<Circles> answers;
  std::optional<BrokenCandidate> broken;
  // All the answers, or throws `broken`.
  std::vector<Circles> all() &&;
};

class Candidate {
 public:
  virtual ~Candidate() = default;
  // The candidate's w_1 for w_0 = `world`, asked as request `id`. Throws BrokenCandidate; an answer that is
  // only wrong (a different world of the right shape) is returned for the caller to judge.
  virtual Circles answer(const Circles& world, std::uint64_t id) = 0;
  // The answers to worlds[k] asked as request first_id + k, in order: what answer() gives for each in turn,
  // but a candidate may be sent several requests before it answers the first (ProcessCandidate is). Stops at
  // the first request it cannot answer, with the BrokenCandidate in `broken`; this loop of answer() asks none
  // after it. `spellings`, empty or one per world, says how a request line spells each world's numbers
  // (formats/spelling.hpp; empty: every one the shortest way); a candidate in process reads no text and
  // ignores it.
  virtual Answers answer_all(std::span<const Circles> worlds, std::uint64_t first_id,
                             std::span<const Spelling> spellings = {});
  // The end of the input: the candidate must exit 0 (a process) or simply stop. Throws BrokenCandidate.
  virtual void finish() {}
  // "the double engine", "the program `python3 step.py`": for messages.
  virtual std::string name() const = 0;
  // Another candidate like this one, to ask other cases at the same time (--jobs); none for one that cannot be
  // copied, which then answers every case itself. Throws BrokenCandidate.
  virtual std::unique_ptr<Candidate> copy() const { return nullptr; }
  // The option of `circles conform` that selects this candidate, quoted for sh: "--engine double", "--exec
  // 'python3 step.py'"; "" for one that no command line selects (a function in a test). Replay lines start
  // with it (conform/replay.hpp).
  virtual std::string option() const { return ""; }
};

class EngineCandidate : public Candidate {
 public:
  EngineCandidate(const engines::EngineEntry& engine, unsigned threads) : engine_(engine), threads_(threads) {}
  // A position beyond the double range is an answer the protocol cannot carry: BrokenCandidate.
  Circles answer(const Circles& world, std::uint64_t id) override;
  std::string name() const override;
  std::string option() const override;
  std::unique_ptr<Candidate> copy() const override { return std::make_unique<EngineCandidate>(engine_, threads_); }

 private:
  const engines::EngineEntry& engine_;
  unsigned threads_;
};

class ProcessCandidate : public Candidate {
 public:
  // Starts the program. Throws BrokenCandidate if it cannot be started. Ignores SIGPIPE in this process from
  // then on (a write to a candidate that exited must be an error to report, not a signal that kills us).
  // `deadline` is the floor of each answer's deadline, which grows with the program's measured speed
  // (conform/deadline.hpp); copies share that measure.
  ProcessCandidate(std::string command, std::chrono::milliseconds deadline,
                   std::shared_ptr<Deadlines> deadlines = nullptr);
  ~ProcessCandidate() override;
  ProcessCandidate(const ProcessCandidate&) = delete;
  ProcessCandidate& operator=(const ProcessCandidate&) = delete;

  Circles answer(const Circles& world, std::uint64_t id) override;
  // Writes the requests in batches of at most kBatchBytes (a larger request goes alone) and reads each batch's
  // answers, each within the deadline of the previous answer (or of the batch's last write). Answers are read
  // as Reading::answer reads them (formats/protocol.hpp): unknown keys ignored, NaN and infinities as values.
  // Restarts the program first if it stopped or a request before has no answer read (a fault in a batch).
  Answers answer_all(std::span<const Circles> worlds, std::uint64_t first_id,
                     std::span<const Spelling> spellings = {}) override;
  // Closes the program's stdin and waits, up to the deadline, for it to exit 0.
  void finish() override;
  std::string name() const override { return "the program `" + command_ + "`"; }
  std::unique_ptr<Candidate> copy() const override;
  // Writes every request and answer line to `log` from now on.
  void log_to(std::shared_ptr<RequestLog> log) { log_ = std::move(log); }
  std::string option() const override;

  // The most bytes of request lines written before their answers are read. Why a bound, and why this one: we
  // write a whole batch before reading any answer, while the candidate may answer each line as it reads it, so
  // its answers pile up in its stdout pipe until we read them; if they filled that pipe, it would block
  // writing, stop reading, and our write would block in turn, for ever. Pipes hold 64 KiB on Linux (pipe(7)).
  // A batch of at most 16 KiB goes into a stdin pipe that the batches before left empty (the candidate read
  // each of their requests before answering it), so our write completes even if the candidate reads nothing
  // meanwhile; and its answers to it, the same worlds in the same format, fill its stdout pipe only if they
  // are four times as long as the requests. A request longer than the bound goes alone, as it always did.
  static constexpr std::size_t kBatchBytes = 16 * 1024;

  // The longest answer line read for a world of n circles, kAnswerSlack + n · kCircleBytes bytes; a longer one is
  // malformed as soon as it passes the bound, so conform holds at most that much of a line, whatever a program
  // writes (docs/protocol.md, Limits).
  //   kNumberBytes: the longest spelling of a double without an exponent or a superfluous digit is its exact
  //     decimal value written out, at most a sign, "0.", and the 1,074 places of a subnormal (2^-1074 =
  //     5^1074 / 10^1074): 1,077 bytes. 1,100 leaves room for an exponent or a few trailing zeros.
  //   kCircleBytes: five numbers, plus 100 bytes for the brackets, the four commas, the comma between circles
  //     and the whitespace around them.
  //   kAnswerSlack: the id (at most 20 digits), the keys, and the unknown keys a newer program may add.
  static constexpr std::size_t kNumberBytes = 1100;
  static constexpr std::size_t kCircleBytes = 5 * kNumberBytes + 100;
  static constexpr std::size_t kAnswerSlack = 64 * 1024;
  static std::size_t longest_answer(std::size_t circles);

 private:
  // Starts the program (throws BrokenCandidate if it cannot); stops it, and closes its pipes; both.
  void start();
  void stop() noexcept;
  void restart();
  // answer_all's work: appends the answer to each of worlds, in batches of at most kBatchBytes; throws
  // BrokenCandidate at the first request without an answer.
  void answer_batches(std::span<const Circles> worlds, std::uint64_t first_id, std::span<const Spelling> spellings,
                      std::vector<Circles>& answers);
  // The next line the program writes, without its newline, or BrokenCandidate at the deadline, at EOF or as
  // soon as the line is longer than `longest` bytes.
  std::string read_line(std::uint64_t id, std::chrono::milliseconds deadline, std::size_t longest);
  // "exited with status 3", "was killed by signal 11", or "" while it runs.
  std::string exit_status(bool wait);
  // Writes all of `lines`, the requests first_id, first_id + 1, … (`ends` holds the offset just past each).
  void write_requests(std::string_view lines, std::span<const std::size_t> ends, std::uint64_t first_id);
  // Reads the answer to request `id` about `world` and checks its id and length.
  Circles read_answer(const Circles& world, std::uint64_t id);
  void kill_group() noexcept;
  // The program's exit status once it has exited (waiting for that if `wait`), its group untracked and killed
  // first; nothing while it runs.
  std::optional<int> reap(bool wait) noexcept;

  std::string command_;
  std::chrono::milliseconds deadline_;
  std::shared_ptr<Deadlines> deadlines_;
  std::shared_ptr<RequestLog> log_;
  unsigned copy_ = 1;  // which copy of the program this is, from 1, for the log
  mutable unsigned copies_made_ = 0;
  std::chrono::steady_clock::time_point asked_{};  // when the answer being read was asked for: its request's
                                                   // write, or the previous answer in a batch
  pid_t pid_ = -1;
  int to_child_ = -1, from_child_ = -1;
  std::string buffer_;
  formats::PlainLineReader plain_;
  std::size_t lines_ = 0;
  std::size_t unanswered_ = 0;  // requests written whose answers were not read
  std::string status_;  // set once the program is reaped
};

}  // namespace circles::conform
