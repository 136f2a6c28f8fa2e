// The gallery of deliberately wrong implementations (tests/gallery.hpp), each of which `circles conform` with its
// default budget (1000 cases, one step, level exact, resolved profile) must reject, checked in process, and the
// committed corpus of their counterexamples. (Through the program over the step protocol: the gallery_program
// ctests, tests/CMakeLists.txt.)
#include "conform/candidate.hpp"
#include "conform/conform.hpp"
#include "conform/corpus.hpp"
#include "tests/gallery.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <variant>

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

// The gallery_program ctests (tests/CMakeLists.txt) run `circles conform` on gallery_candidate NAME for each
// name of their own list, which must be this gallery's, name for name: an entry added here and not there would
// go unchecked through the program.
TEST(gallery, every_entry_runs_through_the_program_as_a_ctest_of_its_own) {
  std::ifstream in(std::filesystem::path(CIRCLES_SOURCE_DIR) / "tests" / "CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  const std::string cmake = text.str();
  std::smatch list;
  ASSERT_TRUE(std::regex_search(cmake, list, std::regex(R"(foreach\(gallery_entry ([^)]*)\))")));
  std::istringstream names(list[1].str());
  std::set<std::string> in_cmake, entries;
  for (std::string name; names >> name;) in_cmake.insert(name);
  for (const GalleryEntry& e : gallery()) entries.insert(e.name);
  EXPECT_EQ(in_cmake, entries);
  EXPECT_EQ(entries.size(), gallery().size()) << "two entries share a name";
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

// The committed corpus (tests/corpus/conform), which CI also replays with `circles conform --save` against our
// engines: each file names the gallery entry that made it, which its world still catches, and the step with no
// mistake passes it.
TEST(gallery, each_committed_counterexample_still_catches_the_mistake_that_made_it) {
  const auto corpus = load_corpus(std::filesystem::path(CIRCLES_SOURCE_DIR) / "tests" / "corpus" / "conform");
  EXPECT_GE(corpus.size(), 4u);
  for (const auto& [file, c] : corpus) {
    const auto entry = std::find_if(gallery().begin(), gallery().end(), [&](const GalleryEntry& e) {
      return c.candidate == "the gallery entry `" + e.description + "`";
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
