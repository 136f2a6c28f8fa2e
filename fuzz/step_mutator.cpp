// libFuzzer's custom mutator and cross-over for the step fuzzers (fuzz/step_fuzzer.cpp, fuzz/step_harness.cpp):
// decode the bytes into a world, change the world (fuzz::mutate, fuzz::cross_over), encode it again. Random
// byte flips almost never make a tangency or a tie; these mutations make them on purpose.
//
// One time in four the bytes are left to libFuzzer's own mutations (LLVMFuzzerMutate), which reach values no
// structured mutation makes; an encoding longer than libFuzzer's max_size does the same. With the environment
// variable CIRCLES_STEP_FUZZER_BYTES=1 every mutation is libFuzzer's own and there is no cross-over: the
// baseline of docs/hardening.md's coverage figures. This file lives in a static library, and libFuzzer refers
// to these functions weakly, so a fuzzer links it with -Wl,--undefined for both (fuzz/CMakeLists.txt).
#include "fuzz/step_input.hpp"

#include <algorithm>
#include <cstdlib>
#include <span>
#include <string_view>

// libFuzzer's own mutation, available to a custom mutator (linked from libFuzzer with -fsanitize=fuzzer).
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

using namespace circles;

std::size_t written(const std::vector<std::uint8_t>& bytes, std::uint8_t* out, std::size_t max_size) {
  if (bytes.size() > max_size) return 0;
  std::copy(bytes.begin(), bytes.end(), out);
  return bytes.size();
}

bool bytes_only() {
  static const bool only = [] {
    const char* v = std::getenv("CIRCLES_STEP_FUZZER_BYTES");
    return v != nullptr && std::string_view(v) == "1";
  }();
  return only;
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned seed) {
  if (bytes_only() || seed % 4 == 0) return LLVMFuzzerMutate(data, size, max_size);
  const fuzz::StepInput input = fuzz::decode(std::span<const std::uint8_t>(data, size));
  const std::size_t n = written(fuzz::encode(fuzz::mutate(input, seed)), data, max_size);
  return n != 0 ? n : LLVMFuzzerMutate(data, size, max_size);
}

extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* a, std::size_t a_size, const std::uint8_t* b,
                                                 std::size_t b_size, std::uint8_t* out, std::size_t max_out_size,
                                                 unsigned seed) {
  if (bytes_only()) return 0;
  const fuzz::StepInput child = fuzz::cross_over(fuzz::decode(std::span<const std::uint8_t>(a, a_size)),
                                                 fuzz::decode(std::span<const std::uint8_t>(b, b_size)), seed);
  return written(fuzz::encode(child), out, max_out_size);
}
