// Steering for the step fuzzer (docs/hardening.md, "Steering to the boundary"): a decision made by comparing a
// computed value with its certified error bound is reported to libFuzzer as a comparison of two integers, so
// that its value profile (-use_value_profile=1) keeps inputs that bring the two closer. A world in the sliver
// between a lowered bound and the true one takes the same branches as its neighbours, and coverage alone gives
// the fuzzer nothing to steer by; the distance between the two sides of the comparison does.
//
// Compiled in only where the libraries are instrumented for libFuzzer (CIRCLES_SANITIZE holds "fuzzer":
// cmake/sanitizers.cmake defines CIRCLES_FUZZ_STEERING); elsewhere steer() is empty and costs nothing.
#pragma once

#include <bit>
#include <cstdint>

#if defined(CIRCLES_FUZZ_STEERING)
extern "C" void __sanitizer_cov_trace_cmp8(std::uint64_t a, std::uint64_t b);
#endif

namespace circles::impl::detail {

// The bits of a double ≥ 0 (or NaN) as an integer in the same order: for non-negative doubles the IEEE
// encoding is already monotone, so nearby values share their high bits.
inline std::uint64_t ordered_bits(double x) noexcept { return std::bit_cast<std::uint64_t>(x); }

// Reports the comparison of `value` with `bound` (both ≥ 0, the magnitudes a filter compares). Inlined, so
// that each call site is a comparison of its own in the value profile (libFuzzer keys it by the caller's PC).
[[gnu::always_inline]] inline void steer([[maybe_unused]] double value, [[maybe_unused]] double bound) noexcept {
#if defined(CIRCLES_FUZZ_STEERING)
  __sanitizer_cov_trace_cmp8(ordered_bits(value), ordered_bits(bound));
#endif
}

}  // namespace circles::impl::detail
