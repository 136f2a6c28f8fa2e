// A count and its noun in the number the count asks for: "1 step", "0 steps", "2 steps"; with its plural given,
// "1 try", "2 tries".
#pragma once

#include <cstdint>
#include <string>

namespace circles::formats {

inline std::string counted(std::uint64_t n, const std::string& noun, const std::string& plural = "") {
  return std::to_string(n) + " " + (n == 1 ? noun : plural.empty() ? noun + "s" : plural);
}

}  // namespace circles::formats
