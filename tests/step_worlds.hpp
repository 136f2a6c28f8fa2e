// Worlds the tests of the engine registry, candidates, `circles serve` and `circles run` step, and the oracle's
// worlds of a run from them (tests/registry_test.cpp, tests/candidate_test.cpp, tests/serve_test.cpp,
// tests/cli_run_test.cpp, tests/render_test.cpp).
#pragma once

#include "formats/protocol.hpp"
#include "spec/oracle.hpp"

#include <cfloat>
#include <cstddef>
#include <vector>

namespace circles::testing {

// Two circles that touch (distance 2 = 1 + 1) and exchange velocities, and one alone.
inline const spec::Circles kTouching{{0, 0, 1, 0, 1}, {2, 0, -1, 0, 1}, {10, 10, 0, 60, 0}};

// Circle 1 moves by exactly 2^1017 per step (v = 60 · 2^1017, so v/60 is exact) from DBL_MAX − 3 · 2^1017:
// w_3 puts it at DBL_MAX exactly, and step 4 would take it to DBL_MAX + 2^1017, beyond the rounding boundary
// DBL_MAX + 2^970 (half an ulp of DBL_MAX), so to infinity. Every sum before is exact (multiples of 2^971).
inline const spec::Circles kOverflowsAtStep4{{0, 0, 0, 0, 1}, {DBL_MAX - 3 * 0x1p1017, -5, 60 * 0x1p1017, 0, 1}};

// w_0, w_1, ..., w_n by the oracle, each step from the previous rounded world.
inline std::vector<spec::Circles> oracle_worlds(const spec::Circles& w0, std::size_t n) {
  std::vector<spec::Circles> worlds{w0};
  for (std::size_t t = 0; t < n; ++t) worlds.push_back(spec::resolved_step_rounded(worlds.back()));
  return worlds;
}

}  // namespace circles::testing
