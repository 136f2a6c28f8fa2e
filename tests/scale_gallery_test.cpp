// The scale gallery (tests/scale_gallery.hpp): `circles conform` with its default options rejects every wrong
// optimized step through a big family, on every seed tried, and shrinks its counterexample by delta debugging to
// a world near the fewest circles its bug needs; the correct optimized step conforms. Checked in process here, and
// through the program by the scale_gallery_program ctests (tests/CMakeLists.txt).
#include "conform/candidate.hpp"
#include "conform/conform.hpp"
#include "tests/scale_gallery.hpp"

#include <gtest/gtest.h>

#include <string>

namespace circles::conform {
namespace {

using testing::ScaleEntry;

// An entry in process, keeping its state between requests as a program would.
class Optimized : public Candidate {
 public:
  explicit Optimized(const ScaleEntry& entry) : entry_(entry) {}
  Circles answer(const Circles& world, std::uint64_t) override {
    return testing::optimized_step(world, entry_.bugs, state_);
  }
  std::string name() const override { return "the scale gallery entry `" + entry_.name + "`"; }

 private:
  const ScaleEntry& entry_;
  testing::ScaleState state_;
};

Verdict verdict(const ScaleEntry& entry, std::uint64_t seed, std::vector<properties::Family> skip = {}) {
  Optimized candidate(entry);
  Options options;  // the defaults: 1000 cases, one step, level exact, resolved profile, 4097 circles at most
  options.seed = seed;
  options.skip = std::move(skip);
  return check(candidate, options);
}

constexpr std::uint64_t kSeeds = 10;

TEST(scale_gallery, the_correct_optimized_step_conforms_by_default) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Verdict v = verdict(*testing::find_scale_entry("optimized"), seed);
    EXPECT_EQ(v.outcome, Outcome::conforms) << "seed " << seed << ": " << v.error;
  }
}

TEST(scale_gallery, every_entry_fails_by_default_on_10_seeds_in_a_big_family_shrunk_near_what_its_bug_needs) {
  for (const ScaleEntry& entry : testing::scale_gallery())
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
      const Verdict v = verdict(entry, seed);
      ASSERT_EQ(v.outcome, Outcome::does_not_conform) << entry.name << ", seed " << seed << ": " << v.error;
      const Counterexample& c = *v.counterexample;
      const std::size_t shrunk = c.shrink_path.back().size();
      EXPECT_GE(shrunk, entry.needs) << entry.name << ", seed " << seed;
      EXPECT_LE(shrunk, entry.needs + 4) << entry.name << ", seed " << seed << ", family " << c.family << ": shrunk from "
                                         << c.circles_before << " to " << shrunk << " circles";
    }
}

// The small families, of at most 8 circles, cannot show these bugs: the big ones are what catches them.
TEST(scale_gallery, no_entry_fails_on_the_small_families) {
  std::vector<properties::Family> big;
  for (const properties::Family f : properties::families(Profile::resolved))
    if (properties::is_big(f)) big.push_back(f);
  for (const auto* gallery : {&testing::scale_gallery(), &testing::swarm_gallery()})
    for (const ScaleEntry& entry : *gallery) {
      const Verdict v = verdict(entry, 1, big);
      EXPECT_EQ(v.outcome, Outcome::conforms) << entry.name;
    }
}

}  // namespace
}  // namespace circles::conform
