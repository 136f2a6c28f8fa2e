// Golden trajectories: the engine's whole runs, hashed (formats/state_hash.hpp), against committed values.
//
// The same source is built against the default engine library (-O3 in the default Release build) and against
// variants compiled at -O0, at -O2 and with -march=x86-64-v3 (AVX2 and hardware FMA in the correctly rounded
// update): every build must give the same hashes, for every thread count (tests/CMakeLists.txt). Exact
// decisions and correct rounding make the bits a property of the spec, not of the compiler.
//
// Where the golden value comes from: for the bundled scene, the correctly rounded oracle's own trajectory,
// recomputed here; the engine must match it. For the larger random scenes the oracle is too slow, so the
// value is the engine's own, recorded once: a tripwire that any change of a bit, in any build, trips.
#include "impl/engine.hpp"
#include "formats/random_scene.hpp"
#include "formats/state_hash.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "formats/scene.hpp"
#include "spec/circle.hpp"
#include "spec/oracle.hpp"

namespace circles::impl {
namespace {

using spec::Circles;
using formats::random_scene;
using formats::state_hash;
using formats::StateHash;

std::string hex(std::uint64_t h) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// The trajectory hash of `steps` engine steps from `w` with the given options.
template <class E>
std::uint64_t engine_trajectory(const Circles& w, int steps, EngineOptions options) {
  E e{World{w}, options};
  StateHash h;
  h.add(w);
  for (int s = 0; s < steps; ++s) {
    e.step();
    h.add(e.world().circles());
  }
  return h.value();
}

TEST(state_hash, is_fnv1a_of_the_little_endian_fields_with_negative_zero_as_positive_zero) {
  // An independent reading of the definition: the bytes written out one by one, then FNV-1a over them.
  const Circles w{{1.0, -0.0, 0.1, -2.5e-310, 3.0}, {-1e300, 0.0, 0.0, 7.0, 0.0}};
  std::vector<unsigned char> bytes;
  for (const auto& c : w)
    for (const double f : c) {
      const std::uint64_t bits = f == 0 ? 0 : std::bit_cast<std::uint64_t>(f);
      for (int b = 0; b < 8; ++b) bytes.push_back(static_cast<unsigned char>(bits >> (8 * b)));
    }
  std::uint64_t h = 0xcbf29ce484222325;
  for (const unsigned char b : bytes) h = (h ^ b) * 0x100000001b3;
  EXPECT_EQ(state_hash(w), h);
  // FNV-1a of no bytes is the offset basis.
  EXPECT_EQ(state_hash(Circles{}), 0xcbf29ce484222325u);
  // −0 and +0 are one state; one ulp anywhere is another.
  Circles flipped = w;
  flipped[0][1] = 0.0;
  flipped[1][1] = -0.0;
  EXPECT_EQ(state_hash(flipped), state_hash(w));
  Circles nudged = w;
  nudged[1][4] = 0x1p-1074;
  EXPECT_NE(state_hash(nudged), state_hash(w));
  // A running hash over two worlds is the hash of their concatenated bytes.
  StateHash two;
  two.add(w);
  two.add(w);
  Circles doubled = w;
  doubled.insert(doubled.end(), w.begin(), w.end());
  EXPECT_EQ(two.value(), state_hash(doubled));
}

// The bundled default scene, 600 steps (the cradle, the glancing pair and the incomparable triple all act
// within the first 100): the oracle's trajectory, the engine's with 1, 2 and 4 threads, with and without
// skipped quiet steps, and the golden value must all be one hash.
TEST(golden, the_default_scene_follows_the_rounded_oracle_in_every_build_and_thread_count) {
  constexpr int kSteps = 600;
  constexpr std::uint64_t kGolden = 0xe273883c7cb230da;
  Circles w;
  for (const spec::Circle& c : formats::default_scene().circles) w.push_back(spec::nearest_doubles(c));
  StateHash oracle;
  oracle.add(w);
  Circles now = w;
  for (int s = 0; s < kSteps; ++s) {
    now = spec::resolved_step_rounded(now);
    oracle.add(now);
  }
  EXPECT_EQ(hex(oracle.value()), hex(kGolden)) << "the oracle's trajectory";
  for (const unsigned threads : {1u, 2u, 4u})
    for (const bool skip : {true, false})
      EXPECT_EQ(hex(engine_trajectory<DoubleEngine>(w, kSteps, {threads, skip})), hex(oracle.value()))
          << threads << " threads, skip quiet steps " << skip;
}

// Random scenes like the benchmarks' (r 2-6, |v| ≤ 100), large enough that every thread count splits the
// slots into several chunks (offers cross chunk boundaries) and the cell order is repaired every step.
TEST(golden, random_scenes_follow_their_golden_trajectories_in_every_build_and_thread_count) {
  struct Case {
    std::size_t circles;
    double coverage;
    std::uint64_t seed;
    int steps;
    std::uint64_t golden;
  };
  const Case cases[] = {
      {20000, 0.10, 1, 40, 0xbb4cfcd1a8d92980},
      {20000, 0.40, 2, 40, 0x1cba4e02799bfd92},
      {3000, 0.01, 3, 200, 0x22af5677c4c941ea},
  };
  for (const Case& c : cases) {
    const Circles w = random_scene(c.circles, c.coverage, c.seed);
    for (const unsigned threads : {1u, 2u, 4u})
      EXPECT_EQ(hex(engine_trajectory<DoubleEngine>(w, c.steps, {threads, true})), hex(c.golden))
          << c.circles << " circles, coverage " << c.coverage << ", seed " << c.seed << ", " << threads
          << " threads";
  }
}

}  // namespace
}  // namespace circles::impl
