// Sentences of README.md and docs/ checked against what they speak of: the program's output, the default scene,
// scripts/setup, the benchmarks' figures of record, and the files of the repository that the text names.
#include "formats/scene.hpp"
#include "properties/boundaries.hpp"
#include "tests/repository.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace circles::testing;

// Each match of `pattern` in a file: where ("FILE:LINE") and what (its first group, or the whole match).
struct Place {
  std::string where, what;
};
std::vector<Place> places(const std::filesystem::path& file, const std::regex& pattern) {
  std::vector<Place> found;
  const std::vector<std::string> lines = lines_of(file);
  for (std::size_t n = 0; n < lines.size(); ++n)
    for (std::sregex_iterator m(lines[n].begin(), lines[n].end(), pattern), end; m != end; ++m)
      found.push_back({file.string() + ":" + std::to_string(n + 1), m->size() > 1 ? (*m)[1].str() : m->str()});
  return found;
}

// The literal profile has no step from w_30 to w_31 of the default scene; the docs that mention it write it as
// the program does, so that a reader finds the same numbers in both.
TEST(docs_claims, the_cradles_undefined_step_is_written_as_the_program_prints_it) {
  const Output oracle = output_of(std::string("'") + CIRCLES_PROGRAM + "' oracle");
  ASSERT_EQ(oracle.status, 0);
  std::smatch printed;
  ASSERT_TRUE(std::regex_search(oracle.text, printed, std::regex(R"(undefined at (step \d+ → \d+))"))) << oracle.text;
  for (const char* doc : {"docs/scenes.md", "docs/accuracy.md"})
    EXPECT_NE(text_of(doc).find(printed[1].str()), std::string::npos)
        << doc << " does not name the cradle's undefined step as the program does: " << printed[1];
}

// scenes.md describes the default scene in the frame of the pictures, where y points down (docs/run.md): a
// circle with v_y > 0 falls, and one at a smaller y is above.
TEST(docs_claims, scenes_md_describes_the_default_scene_with_y_pointing_down) {
  const auto w = circles::formats::default_scene().circles;
  ASSERT_EQ(w.size(), 10u);
  const std::string doc = text_of("docs/scenes.md");
  ASSERT_TRUE(w[4].v.x() == 0 && w[4].v.y() > 0);
  EXPECT_NE(doc.find("circle 4 falls"), std::string::npos);
  // The side of circle 6 that circle k comes from, and that it moves towards circle 6.
  const auto side = [&](std::size_t k) -> std::string {
    const auto d = w[k].p - w[6].p;
    EXPECT_LT(d.dot(w[k].v), 0) << "circle " << k << " does not move towards circle 6";
    if (d.x() == 0) return d.y() < 0 ? "above" : "below";
    if (d.y() == 0) return d.x() > 0 ? "the right" : "the left";
    ADD_FAILURE() << "circle " << k << " comes from neither an axis of circle 6";
    return "";
  };
  const std::string sentence = "circles 7 and 8 close on circle 6 from " + side(7) + " and from " + side(8);
  EXPECT_NE(doc.find(sentence), std::string::npos) << "docs/scenes.md does not say: " << sentence;
}

// A doc that says a package is not one of the suite's dependencies, while scripts/setup installs it, misleads:
// the setup is the list of what the suite needs.
TEST(docs_claims, no_doc_calls_a_package_scripts_setup_installs_no_dependency) {
  std::set<std::string> installed;  // the words of the lines of `packages=( ... )`, less their comments
  bool listed = false;
  for (const std::string& line : lines_of("scripts/setup")) {
    if (line == ")") listed = false;
    if (listed) {
      std::istringstream names(line.substr(0, line.find('#')));
      for (std::string name; names >> name;) installed.insert(name);
    }
    if (line == "packages=(") listed = true;
  }
  ASSERT_TRUE(installed.contains("ffmpeg") && installed.contains("libcairo2-dev")) << installed.size();
  const std::regex denial(R"((\w[\w.+-]*) is not one of the suite's dependencies)");
  for (const std::filesystem::path& doc : markdown_docs())
    for (const Place& place : places(doc, denial))
      EXPECT_FALSE(installed.contains(place.what)) << place.where << " says " << place.what
                                                   << " is no dependency, but scripts/setup installs it";
  EXPECT_NE(text_of("docs/run.md").find("`scripts/setup` installs it"), std::string::npos)
      << "docs/run.md does not say that scripts/setup installs ffmpeg";
}

// conform's speed is measured by scripts/benchmarks and recorded in benchmarks.md, one run for every figure;
// another doc that gave its own would disagree with it after the next run.
TEST(docs_claims, only_benchmarks_md_gives_conforms_worlds_per_second) {
  const std::regex figure(R"(\d[\d,.]* (?:[a-z]+ )?worlds(?: per second|/s| a second))");
  for (const std::filesystem::path& doc : markdown_docs()) {
    if (doc == "docs/benchmarks.md") continue;
    for (const Place& place : places(doc, figure))
      ADD_FAILURE() << place.where << ": " << place.what << ": the figure of record is in docs/benchmarks.md; link it instead";
  }
  EXPECT_FALSE(places("docs/benchmarks.md", figure).empty());
}

// Every path of the repository a file names, in a comment or a doc ("formats/scene.hpp"), exists.
TEST(docs_claims, every_file_of_the_repository_a_file_names_exists) {
  const std::regex path(
      R"((?:^|[^\w/.-])((?:bench|cli|cmake|conform|docs|examples|formats|fuzz|impl|pictures|properties|scenes|scripts|spec|tests)/[\w./-]*\w\.(?:cpp|hpp|in|md|json|sh|py|txt|cmake|yml|yaml))\b)");
  std::size_t named = 0;
  for (const std::filesystem::path& file : repository_files()) {
    if (file.extension() == ".png") continue;
    for (const Place& place : places(file, path)) {
      ++named;
      // cli/version.hpp is written into the build tree at each build (cli/CMakeLists.txt), from git.
      if (place.what == "cli/version.hpp") continue;
      EXPECT_TRUE(std::filesystem::exists(root / place.what)) << place.where << " names " << place.what
                                                              << ", which is no file of the repository";
    }
  }
  EXPECT_GT(named, 300u);
}

// docs/vectors.md shows the summary of the command it gives, run from the repository's root: the same cases, the
// same count of the big families' cases left out, the same features.
TEST(docs_claims, vectors_md_shows_the_summary_its_command_prints) {
  const Output summary = output_of("cd " + quoted(root) + " && '" + CIRCLES_PROGRAM + "' vectors --out - 2>&1 >/dev/null");
  ASSERT_EQ(summary.status, 0) << summary.text;
  // --out vectors names its file vectors/vectors.jsonl where --out - says standard output.
  const std::string printed =
      std::regex_replace(summary.text, std::regex("^circles vectors: standard output: "), "circles vectors: vectors/vectors.jsonl: ");
  const std::string doc = text_of("docs/vectors.md");
  EXPECT_NE(doc.find("./build/circles vectors --out vectors "), std::string::npos);
  EXPECT_NE(doc.find("```\n" + printed + "```\n"), std::string::npos)
      << "docs/vectors.md does not show the summary the command prints:\n" << printed;
  EXPECT_NE(printed.find("left out: "), std::string::npos) << printed;
}

// How many cases a family gets of RapidCheck's default 100, as docs/properties.md says it in more than one place:
// 100 over the resolved profile's families.
TEST(docs_claims, properties_md_gives_one_count_of_cases_a_family_of_a_default_run) {
  const auto families = circles::properties::families(circles::properties::Profile::resolved).size();
  const std::string text = std::regex_replace(text_of("docs/properties.md"), std::regex("\n"), " ");
  const std::regex count(R"(100 cases[^.]*? gets about (\d+))");
  std::size_t said = 0;
  for (std::sregex_iterator m(text.begin(), text.end(), count), end; m != end; ++m, ++said)
    EXPECT_EQ(std::stoul((*m)[1]), (100 + families / 2) / families) << m->str();
  EXPECT_GE(said, 2u);
}

}  // namespace
