#include "cli/run.hpp"

#include "cli/json_number.hpp"
#include "cli/protocol.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <utility>

namespace circles::cli {

Circles doubles_of(const std::vector<spec::Circle>& scene) {
  Circles w;
  w.reserve(scene.size());
  for (const spec::Circle& c : scene) w.push_back(spec::nearest_doubles(c));
  return w;
}

namespace {

std::string system_error(const std::string& what) { return what + ": " + std::strerror(errno); }

// A trace being written: lines go to a temporary file beside `path` (the same directory, so that the final
// rename is atomic), which commit() renames to `path`. Until then `path` is untouched; a trace dropped
// without commit() is removed, so no reader ever sees a half-written trace.
class TraceFile {
 public:
  explicit TraceFile(std::string path) : path_(std::move(path)), temp_(path_ + ".partial-XXXXXX") {
    const int fd = mkstemp(temp_.data());
    if (fd < 0) throw TraceError(system_error("trace " + path_ + ": cannot create " + temp_));
    // mkstemp makes the file private (0600); a trace is an ordinary output file, so give it the mode a
    // plain fopen would: 0666 less the umask (which can only be read by setting it).
    const mode_t mask = umask(0);
    umask(mask);
    file_ = fdopen(fd, "w");
    if (!file_ || fchmod(fd, 0666 & ~mask) != 0) {
      const std::string reason = system_error("trace " + path_ + ": cannot open " + temp_);
      if (!file_) close(fd);
      discard();
      throw TraceError(reason);
    }
  }
  TraceFile(const TraceFile&) = delete;
  TraceFile& operator=(const TraceFile&) = delete;
  ~TraceFile() { discard(); }

  void write(std::uint64_t step, const Circles& world) {
    line_.clear();
    append_line(line_, kStep, step, world);
    line_ += '\n';
    if (std::fwrite(line_.data(), 1, line_.size(), file_) != line_.size())
      throw TraceError(system_error("trace " + path_ + ": cannot write to " + temp_));
  }

  void commit() {
    std::FILE* f = std::exchange(file_, nullptr);
    if (std::fclose(f) != 0) throw TraceError(system_error("trace " + path_ + ": cannot write to " + temp_));
    if (std::rename(temp_.c_str(), path_.c_str()) != 0)
      throw TraceError(system_error("trace " + path_ + ": cannot rename " + temp_ + " to it"));
    temp_.clear();
  }

 private:
  void discard() noexcept {
    if (file_) std::fclose(std::exchange(file_, nullptr));
    if (!temp_.empty()) std::remove(temp_.c_str());
    temp_.clear();
  }

  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  std::string line_;
};

// The shortest decimal that reads back as x, and its hexadecimal form, for messages: "0.1 (0x1.999999999999ap-4)".
std::string show(double x) {
  std::string text;
  json_number::append(text, x);
  char hex[32];  // "%a" of a double: at most "-0x1.fffffffffffffp-1022" (24 characters)
  std::snprintf(hex, sizeof hex, "%a", x);
  return text + " (" + hex + ")";
}

}  // namespace

RunResult run(const Circles& world, const RunOptions& options) {
  std::optional<TraceFile> trace;
  if (!options.trace.empty()) trace.emplace(options.trace);
  const auto stepper = options.engine->start(world, options.threads);
  if (trace) trace->write(0, world);
  RunResult result;
  while (result.steps < options.steps) {
    const auto start = std::chrono::steady_clock::now();
    try {
      stepper->step();
    } catch (const StepOverflow& e) {
      result.overflow = e;
      break;
    }
    result.stepping += std::chrono::steady_clock::now() - start;
    result.steps = stepper->steps();
    if (trace) trace->write(result.steps, stepper->circles());
  }
  if (trace) trace->commit();
  return result;
}

void print_summary(const RunResult& result, std::size_t circles, const RunOptions& options, std::ostream& out) {
  out << result.steps << " steps of " << circles << " circles with the " << options.engine->name << " engine ("
      << (!options.engine->threaded || options.threads == 1 ? std::string("1 thread")
          : options.threads == 0                            ? std::string("all cores")
                                                            : std::to_string(options.threads) + " threads")
      << "): " << result.stepping.count() << " s stepping";
  const double circle_steps = static_cast<double>(result.steps) * static_cast<double>(circles);
  if (circle_steps > 0) out << ", " << result.stepping.count() * 1e9 / circle_steps << " ns per circle-step";
  out << "\n";
  if (!options.trace.empty())
    out << "trace: " << options.trace << " (w_0 to w_" << result.steps << ", " << result.steps + 1 << " lines)\n";
}

Comparison compare_with_oracle(const EngineEntry& engine, const Circles& world, std::uint64_t steps, unsigned threads) {
  const auto oracle = reference(engine, world);
  const auto candidate = engine.start(world, threads);
  Comparison c;
  for (; c.steps < steps; ++c.steps) {
    const std::uint64_t step = c.steps + 1;
    std::optional<StepOverflow> expected, actual;
    try {
      oracle->step();
    } catch (const StepOverflow& e) {
      expected = e;
    }
    try {
      candidate->step();
    } catch (const StepOverflow& e) {
      actual = e;
    }
    if (expected || actual) {
      if (expected && actual && expected->index == actual->index && expected->field == actual->field) {
        c.overflow = expected;
      } else {
        c.difference = "step " + std::to_string(step) + ": " +
                       (expected ? "the oracle stops at " + overflow_reason(expected->index, expected->field)
                                 : std::string("the oracle does not overflow")) +
                       ", the engine " +
                       (actual ? "stops at " + overflow_reason(actual->index, actual->field) : "does not");
      }
      return c;
    }
    const Circles want = oracle->circles(), got = candidate->circles();
    if (want.size() != got.size()) {
      c.difference = "step " + std::to_string(step) + ": the oracle has " + std::to_string(want.size()) +
                     " circles, the engine " + std::to_string(got.size());
      return c;
    }
    for (std::size_t k = 0; k < want.size(); ++k)
      for (std::size_t f = 0; f < want[k].size(); ++f)
        if (want[k][f] != got[k][f]) {  // by value: -0 == +0
          c.difference = "step " + std::to_string(step) + ", circle " + std::to_string(k) + ", field " +
                         spec::name(spec::Field(f)) + ": oracle " + show(want[k][f]) + ", engine " + show(got[k][f]);
          return c;
        }
  }
  return c;
}

void print_comparison(const EngineEntry& engine, const Comparison& c, std::ostream& out) {
  out << engine.name << " engine: ";
  const char* oracle = engine.exact ? "the oracle's exact sequence, rounded," : "the correctly rounded oracle";
  if (c.difference) {
    out << "DIFFERS from " << oracle << " at " << *c.difference << "\n";
    return;
  }
  out << "agrees with " << oracle << " at each of the " << c.steps << " steps";
  if (c.overflow) out << ", after which both stop: " << c.overflow->what();
  out << "\n";
}

}  // namespace circles::cli
