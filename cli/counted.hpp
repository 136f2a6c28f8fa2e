// A count and its noun in the number the count asks for: "1 step", "0 steps", "2 steps".
#pragma once

#include <cstdint>
#include <string>

namespace circles::cli {

inline std::string counted(std::uint64_t n, const std::string& noun) {
  return std::to_string(n).append(" ").append(noun).append(n == 1 ? "" : "s");
}

}  // namespace circles::cli
