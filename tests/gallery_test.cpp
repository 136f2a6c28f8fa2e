// The gallery: deliberately wrong implementations, each of which `circles conform` with its default budget
// (1000 cases, one step, level exact, resolved profile) must reject, and the committed corpus of their
// counterexamples. One step function with a knob per mistake, so that each entry differs from the correct step
// (all knobs off, which must conform) in exactly one way.
#include "cli/candidate.hpp"
#include "cli/conform.hpp"
#include "cli/corpus.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <tuple>
#include <variant>

#include "impl/predicate.hpp"
#include "impl/rounding.hpp"
#include "spec/circle.hpp"
#include "spec/equations.hpp"

namespace circles::cli {
namespace {

struct Mistakes {
  enum class Contact { exact, strict, hypot, small_grid } contact = Contact::exact;
  enum class Choice { least, y_key_first, first_in_index, literal_fold } choice = Choice::least;
  bool naive_update = false;       // p + v·(1/60): two roundings
  bool in_place = false;           // circles updated in index order, later ones reading the new values
  bool identity_by_value = false;  // i(c, W) leaves out every circle equal to c, not only c itself
  bool flush_subnormals = false;   // subnormal inputs read as zero
  bool swap_pairs = false;         // each touching pair swaps velocities, in index order, the last pair winning
};

bool touches(const std::array<double, 5>& a, const std::array<double, 5>& b, Mistakes::Contact how) {
  switch (how) {
    case Mistakes::Contact::exact: return impl::intersect_exact(a[0], a[1], a[4], b[0], b[1], b[4]);
    case Mistakes::Contact::strict: {
      const spec::Q dx = spec::exact(b[0]) - spec::exact(a[0]), dy = spec::exact(b[1]) - spec::exact(a[1]);
      const spec::Q s = spec::exact(a[4]) + spec::exact(b[4]);
      return s * s > dx * dx + dy * dy;
    }
    case Mistakes::Contact::hypot: return std::hypot(b[0] - a[0], b[1] - a[1]) <= a[4] + b[4];
    case Mistakes::Contact::small_grid:
      // Cells of side 1 and only the 3×3 around a circle's centre: misses circles whose centres are further
      // apart than a cell and a bit, however large their radii.
      return std::fabs(std::floor(a[0]) - std::floor(b[0])) <= 1 && std::fabs(std::floor(a[1]) - std::floor(b[1])) <= 1 &&
             impl::intersect_exact(a[0], a[1], a[4], b[0], b[1], b[4]);
  }
  return false;
}

// True when circle j should be taken over circle best as the contact of choice.
bool better(const Circles& w, std::size_t j, std::size_t best, Mistakes::Choice how) {
  const auto key = [&](std::size_t i) { return std::tie(w[i][0], w[i][1], w[i][2], w[i][3], w[i][4]); };
  const auto y_first = [&](std::size_t i) { return std::tie(w[i][1], w[i][0], w[i][2], w[i][3], w[i][4]); };
  switch (how) {
    case Mistakes::Choice::least: return std::make_pair(key(j), j) < std::make_pair(key(best), best);
    case Mistakes::Choice::y_key_first: return std::make_pair(y_first(j), j) < std::make_pair(y_first(best), best);
    case Mistakes::Choice::first_in_index: return false;
    case Mistakes::Choice::literal_fold: {
      // (7) folded left to right: the running minimum stays unless it is not ≤ the next one.
      const spec::Circle a = spec::from_doubles(w[best], best, spec::Radii::non_negative);
      const spec::Circle b = spec::from_doubles(w[j], j, spec::Radii::non_negative);
      return !(spec::m(a, b) == a);
    }
  }
  return false;
}

Circles mistaken_step(const Circles& input, const Mistakes& m) {
  Circles w = input;
  if (m.flush_subnormals)
    for (auto& c : w)
      for (double& x : c)
        if (std::fpclassify(x) == FP_SUBNORMAL) x = 0;
  const Circles old = w;
  Circles out = w;
  const Circles& read = m.in_place ? out : old;
  std::vector<std::array<double, 2>> velocity(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) velocity[k] = {w[k][2], w[k][3]};
  if (m.swap_pairs) {
    for (std::size_t i = 0; i < w.size(); ++i)
      for (std::size_t j = i + 1; j < w.size(); ++j)
        if (touches(old[i], old[j], m.contact)) {
          velocity[i] = {old[j][2], old[j][3]};
          velocity[j] = {old[i][2], old[i][3]};
        }
  }
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (!m.swap_pairs) {
      std::size_t best = k;
      for (std::size_t j = 0; j < w.size(); ++j) {
        if (j == k || (m.identity_by_value && read[j] == read[k])) continue;
        if (!touches(read[k], read[j], m.contact)) continue;
        if (best == k || better(read, j, best, m.choice)) best = j;
      }
      velocity[k] = {read[best][2], read[best][3]};
    }
    const auto update = [&](double p, double v) { return m.naive_update ? p + v * (1.0 / 60) : impl::advance_rounded(p, v); };
    out[k] = {update(read[k][0], velocity[k][0]), update(read[k][1], velocity[k][1]), velocity[k][0], velocity[k][1], read[k][4]};
  }
  return out;
}

class Gallery : public Candidate {
 public:
  Gallery(std::string mistake, Mistakes m) : mistake_(std::move(mistake)), m_(m) {}
  Circles answer(const Circles& world, std::uint64_t) override { return mistaken_step(world, m_); }
  std::string name() const override { return "the gallery entry `" + mistake_ + "`"; }

 private:
  std::string mistake_;
  Mistakes m_;
};

// Every entry of the gallery: a mistake and the knob that makes it.
const std::vector<std::pair<std::string, Mistakes>>& gallery() {
  using C = Mistakes::Contact;
  using H = Mistakes::Choice;
  static const std::vector<std::pair<std::string, Mistakes>> entries{
      {"< instead of <= in (3)", {.contact = C::strict}},
      {"hypot distance in doubles", {.contact = C::hypot}},
      {"a grid whose cells are too small", {.contact = C::small_grid}},
      {"p + v*(1/60)", {.naive_update = true}},
      {"in-place updates in index order", {.in_place = true}},
      {"the lexicographic key in the wrong order (py first)", {.choice = H::y_key_first}},
      {"the first intersecting circle instead of the least", {.choice = H::first_in_index}},
      {"the literal (7) folded left to right", {.choice = H::literal_fold}},
      {"velocities swapped pairwise", {.swap_pairs = true}},
      {"identity by value instead of by index", {.identity_by_value = true}},
      {"subnormals flushed to zero", {.flush_subnormals = true}},
  };
  return entries;
}

// conform's verdict with its default budget, and the report; counterexamples are saved in `save` if given.
int verdict(const std::string& mistake, Mistakes m, std::string& report, const std::filesystem::path& save = {}) {
  Gallery candidate(mistake, m);
  std::ostringstream out;
  ConformOptions options;  // the defaults: 1000 cases, one step, level exact, resolved profile
  options.seed = 1;
  options.save = save;
  const int status = conform(candidate, options, out);
  report = out.str();
  return status;
}

TEST(gallery, the_step_with_no_mistake_conforms) {
  std::string report;
  EXPECT_EQ(verdict("none", Mistakes{}, report), 0) << report;
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
    const auto& [mistake, m] = gallery()[entry];
    std::string report;
    // A directory of its own: a corpus shared with the entries before would catch most mistakes by replay.
    EXPECT_EQ(verdict(mistake, m, report, save / std::to_string(entry)), 1) << mistake << " was not caught:\n" << report;
    const auto which = report.find("which decision");
    std::printf("[ gallery ] %-55s %s", mistake.c_str(),
                which == std::string::npos ? "\n" : report.substr(which, report.find('\n', which) - which + 1).c_str());
    const auto saved = report.find("saved: ");
    ASSERT_NE(saved, std::string::npos) << report;
    const std::string file = report.substr(saved + 7, report.find('\n', saved) - saved - 7);
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const StoredCounterexample c = from_json(text.str(), file);
    const auto expected = properties::expected_step(c.world, c.profile);
    ASSERT_TRUE(std::holds_alternative<Circles>(expected)) << file;
    EXPECT_TRUE(compare(c.world, std::get<Circles>(expected), mistaken_step(c.world, m), Level{0})) << file;
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
    const auto entry = std::find_if(gallery().begin(), gallery().end(), [&](const auto& e) {
      return c.candidate == "the gallery entry `" + e.first + "`";
    });
    ASSERT_NE(entry, gallery().end()) << file << " names " << c.candidate;
    const auto expected = properties::expected_step(c.world, c.profile);
    ASSERT_TRUE(std::holds_alternative<Circles>(expected)) << file;
    EXPECT_TRUE(compare(c.world, std::get<Circles>(expected), mistaken_step(c.world, entry->second), Level{0}))
        << file << " no longer catches " << entry->first;
    EXPECT_FALSE(compare(c.world, std::get<Circles>(expected), mistaken_step(c.world, Mistakes{}), Level{0})) << file;
  }
}

}  // namespace
}  // namespace circles::cli
