// The gallery of deliberately wrong implementations (tests/gallery.hpp), each of which `circles conform` with its
// default budget (1000 cases, one step, level exact, resolved profile) must reject, checked in process, and the
// committed corpus of their counterexamples. (Through the program over the step protocol: the gallery_program
// ctests, tests/CMakeLists.txt.)
#include "conform/candidate.hpp"
#include "conform/conform.hpp"
#include "conform/corpus.hpp"
#include "tests/gallery.hpp"
#include "tests/scale_gallery.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace circles::conform {

using namespace circles::formats;
namespace {

using testing::find_entry;
using testing::gallery;
using testing::GalleryEntry;
using testing::mistaken_step;
using testing::Mistakes;

// An entry in process, named by its description (which the corpus files record).
class Gallery : public Candidate {
 public:
  explicit Gallery(const GalleryEntry& entry) : entry_(entry) {}
  Circles answer(const Circles& world, std::uint64_t) override { return mistaken_step(world, entry_.mistakes); }
  std::string name() const override { return "the gallery entry `" + entry_.description + "`"; }

 private:
  const GalleryEntry& entry_;
};

// conform's verdict with its default budget; counterexamples are saved in `save` if given.
Verdict verdict(const GalleryEntry& entry, const std::filesystem::path& save = {}) {
  Gallery candidate(entry);
  Options options;  // the defaults: 1000 cases, one step, level exact, resolved profile
  options.seed = 1;
  options.save = save;
  return check(candidate, options);
}

TEST(gallery, the_step_with_no_mistake_conforms) {
  const Verdict v = verdict(*find_entry("none"));
  EXPECT_EQ(v.outcome, Outcome::conforms) << v.error;
}

// The gallery_program, scale_gallery_program and swarm_gallery_program ctests (tests/CMakeLists.txt) run `circles conform` on
// gallery_candidate NAME for each name of their own list, which must be the gallery's and the scale gallery's,
// name for name: an entry added here and not there would go unchecked through the program.
// The names the gallery_ctests(PREFIX …) call of tests/CMakeLists.txt lists.
std::set<std::string> ctest_names(const std::string& prefix) {
  std::ifstream in(std::filesystem::path(CIRCLES_SOURCE_DIR) / "tests" / "CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  const std::string cmake = text.str();
  std::smatch list;
  if (!std::regex_search(cmake, list, std::regex("gallery_ctests\\(" + prefix + R"( \d+ ([^)]*)\))"))) return {};
  std::istringstream names(list[1].str());
  std::set<std::string> in_cmake;
  for (std::string name; names >> name;) in_cmake.insert(name);
  return in_cmake;
}

TEST(gallery, every_entry_runs_through_the_program_as_a_ctest_of_its_own) {
  std::set<std::string> entries;
  for (const GalleryEntry& e : gallery()) entries.insert(e.name);
  EXPECT_EQ(ctest_names("gallery_program"), entries);
  EXPECT_EQ(entries.size(), gallery().size()) << "two entries share a name";
  std::set<std::string> scale;
  for (const testing::ScaleEntry& e : testing::scale_gallery()) scale.insert(e.name);
  EXPECT_EQ(ctest_names("scale_gallery_program"), scale);
  EXPECT_EQ(scale.size(), testing::scale_gallery().size()) << "two scale entries share a name";
  std::set<std::string> swarm;
  for (const testing::ScaleEntry& e : testing::swarm_gallery()) swarm.insert(e.name);
  EXPECT_EQ(ctest_names("swarm_gallery_program"), swarm);
  EXPECT_EQ(swarm.size(), testing::swarm_gallery().size()) << "two swarm entries share a name";
  EXPECT_GE(swarm.size(), 10u);
}

// Each counterexample is also saved, and the saved world still catches the mistake. With the environment
// variable CIRCLES_GALLERY_SAVE=DIR the files are kept, entry k's in DIR/k: that is how tests/corpus/conform
// was made.
TEST(gallery, every_wrong_implementation_is_rejected_by_the_default_budget) {
  const char* keep = std::getenv("CIRCLES_GALLERY_SAVE");
  const std::filesystem::path save =
      keep ? std::filesystem::path(keep)
           : std::filesystem::temp_directory_path() / ("circles-gallery-" + std::to_string(::getpid()));
  for (std::size_t entry = 0; entry < gallery().size(); ++entry) {
    const std::string& mistake = gallery()[entry].description;
    // A directory of its own: a corpus shared with the entries before would catch most mistakes by replay.
    const Verdict v = verdict(gallery()[entry], save / std::to_string(entry));
    ASSERT_EQ(v.outcome, Outcome::does_not_conform) << mistake << " was not caught: " << v.error;
    std::printf("[ gallery ] %-55s which decision: %s\n", mistake.c_str(), v.counterexample->difference.decision.c_str());
    const std::string file = v.counterexample->saved.string();
    ASSERT_FALSE(file.empty()) << v.counterexample->not_saved;
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const StoredCounterexample c = from_json(text.str(), file);
    const auto expected = properties::expected_step(c.world, c.profile);
    ASSERT_TRUE(std::holds_alternative<Circles>(expected)) << file;
    EXPECT_TRUE(compare(c.world, std::get<Circles>(expected), mistaken_step(c.world, gallery()[entry].mistakes),
                        Level{0}))
        << file;
  }
  if (!keep) std::filesystem::remove_all(save);
}

// Significant digits of x: those of the shortest decimal that reads back as x, in scientific form ("6.5e-02"
// has 2, 0 and 60 have 1).
int significant_digits(double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x, std::chars_format::scientific).ptr;
  const std::string_view s(text, static_cast<std::size_t>(end - text));
  return static_cast<int>(std::count_if(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(s.find('e')),
                                        [](char c) { return c >= '0' && c <= '9'; }));
}

double median(std::vector<int> xs) {
  std::sort(xs.begin(), xs.end());
  const std::size_t n = xs.size();
  return n % 2 ? xs[n / 2] : (xs[n / 2 - 1] + xs[n / 2]) / 2.0;
}

// Counterexamples a person can read: after shrinking, each number is simplified while the case still fails. Over
// the gallery and seeds 1 … 5, no counterexample's world has more significant digits than before, and all of
// them fewer (docs/conform.md reports the median and mean per number, printed here); every simplified world
// still catches its mistake and only it.
TEST(gallery, simplified_counterexamples_have_fewer_significant_digits_and_still_fail) {
  std::vector<int> before, after;
  for (const GalleryEntry& entry : gallery())
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      int digits[2] = {0, 0};
      for (const bool simplify : {false, true}) {
        Gallery candidate(entry);
        Options options;
        options.seed = seed;
        options.simplify = simplify;
        const Verdict v = check(candidate, options);
        ASSERT_EQ(v.outcome, Outcome::does_not_conform) << entry.name << " seed " << seed;
        const Circles& w = v.counterexample->shrink_path.back();
        for (const auto& c : w)
          for (const double x : c) {
            (simplify ? after : before).push_back(significant_digits(x));
            digits[simplify] += significant_digits(x);
          }
        const auto expected = properties::expected_step(w, Profile::resolved);
        ASSERT_TRUE(std::holds_alternative<Circles>(expected));
        if (v.counterexample->steps == 1) {
          EXPECT_TRUE(compare(w, std::get<Circles>(expected), mistaken_step(w, entry.mistakes), Level{0})) << entry.name;
          EXPECT_FALSE(compare(w, std::get<Circles>(expected), mistaken_step(w, Mistakes{}), Level{0})) << entry.name;
        }
      }
      EXPECT_LE(digits[1], digits[0]) << entry.name << " seed " << seed;
    }
  const auto mean = [](const std::vector<int>& xs) {
    return std::accumulate(xs.begin(), xs.end(), 0.0) / static_cast<double>(xs.size());
  };
  std::printf("[ gallery ] significant digits per number of the counterexamples: median %.1f before, %.1f after "
              "simplifying; mean %.2f before, %.2f after (%zu numbers before, %zu after)\n",
              median(before), median(after), mean(before), mean(after), before.size(), after.size());
  EXPECT_LT(std::accumulate(after.begin(), after.end(), 0), std::accumulate(before.begin(), before.end(), 0));
}

// The committed corpus (tests/corpus/conform), which CI also replays with `circles conform --save` against our
// engines: each file names the gallery entry that made it, which its world still catches, and the step with no
// mistake passes it.
TEST(gallery, each_committed_counterexample_still_catches_the_mistake_that_made_it) {
  const auto corpus = load_corpus(std::filesystem::path(CIRCLES_SOURCE_DIR) / "tests" / "corpus" / "conform");
  EXPECT_GE(corpus.size(), 4u);
  for (const auto& [file, c] : corpus) {
    const std::string& candidate = c.candidate;  // Clang 14 cannot capture the structured binding c itself
    const auto entry = std::find_if(gallery().begin(), gallery().end(), [&](const GalleryEntry& e) {
      return candidate == "the gallery entry `" + e.description + "`";
    });
    ASSERT_NE(entry, gallery().end()) << file << " names " << c.candidate;
    const auto expected = properties::expected_step(c.world, c.profile);
    ASSERT_TRUE(std::holds_alternative<Circles>(expected)) << file;
    EXPECT_TRUE(compare(c.world, std::get<Circles>(expected), mistaken_step(c.world, entry->mistakes), Level{0}))
        << file << " no longer catches " << entry->description;
    EXPECT_FALSE(compare(c.world, std::get<Circles>(expected), mistaken_step(c.world, Mistakes{}), Level{0})) << file;
  }
}

}  // namespace
}  // namespace circles::conform
