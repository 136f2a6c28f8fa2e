// What every fuzz target asserts beyond "no crash": a failed check prints what failed and aborts, which
// libFuzzer reports as a crash and saves the input (docs/hardening.md).
#pragma once

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace circles::fuzz {

inline void require(bool holds, const char* what, std::string_view detail = {}) {
  if (holds) return;
  std::fprintf(stderr, "fuzz check failed: %s: %.*s\n", what, static_cast<int>(detail.size()), detail.data());
  std::abort();
}

// A reader's message is one line of printable ASCII (cli::printable escapes every other byte it quotes), so
// hostile input cannot write control characters or invalid UTF-8 to a terminal or a log through it.
inline bool is_one_printable_line(std::string_view message) {
  if (message.empty()) return false;
  for (const char c : message)
    if (c < 0x20 || c > 0x7E) return false;
  return true;
}

// Two worlds (sequences of circles, each a sequence of doubles) with the same doubles bit for bit: a round trip
// must keep -0 and every payload, which == would not see.
template <class World>
bool same_bits(const World& a, const World& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].size() != b[k].size()) return false;
    for (std::size_t j = 0; j < a[k].size(); ++j)
      if (std::bit_cast<std::uint64_t>(a[k][j]) != std::bit_cast<std::uint64_t>(b[k][j])) return false;
  }
  return true;
}

}  // namespace circles::fuzz
