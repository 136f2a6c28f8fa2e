#include "cli/interrupt.hpp"

#include "formats/output_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>

namespace circles::cli {
namespace {

// The signals handled, and each one's message, made when the handler is installed: a handler may not allocate.
constexpr std::array<std::pair<int, const char*>, 3> kSignals{{{SIGINT, "SIGINT"}, {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"}}};
std::array<std::string, kSignals.size()> messages;
std::atomic_flag ending = ATOMIC_FLAG_INIT;
std::atomic_flag winding_down = ATOMIC_FLAG_INIT;
void (*wind_down_on_first)(int) noexcept = nullptr;

void end(int signal) {
  if (wind_down_on_first && !winding_down.test_and_set()) {
    wind_down_on_first(signal);
    return;
  }
  if (ending.test_and_set()) return;  // a second signal, maybe on another thread: the first ends the program
  formats::remove_temporary_files();
  for (std::size_t k = 0; k < kSignals.size(); ++k)
    if (kSignals[k].first == signal) {
      const std::string& message = messages[k];
      if (::write(STDERR_FILENO, message.data(), message.size()) < 0) {
        // Nothing more can be said.
      }
    }
  _exit(128 + signal);
}

}  // namespace

void end_cleanly_on_interrupt(const std::string& command, void (*wind_down)(int) noexcept) {
  wind_down_on_first = wind_down;
  // "\r" and ESC [K, erase to the end of the line: a progress line (or the ^C a terminal echoes) goes first. On a
  // terminal only: a file or a pipe gets the message alone.
  const std::string erase = isatty(STDERR_FILENO) ? "\r\x1b[K" : "";
  struct sigaction action{};
  action.sa_handler = end;
  sigemptyset(&action.sa_mask);
  for (const auto& [signal, name] : kSignals) sigaddset(&action.sa_mask, signal);
  for (std::size_t k = 0; k < kSignals.size(); ++k) {
    const auto [signal, name] = kSignals[k];
    messages[k] = erase + command + ": interrupted by " + name + "\n";
    struct sigaction before{};
    if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
}

}  // namespace circles::cli
