// Counterexamples as data files (conform/corpus.hpp): each round-trips through its file bit for bit, is named by
// a hash of its profile and world, and a file that cannot be replayed is refused naming the file and the place,
// before a run with --save asks any case.
#include "conform/corpus.hpp"

#include "conform/conform.hpp"
#include "tests/function_candidate.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>

namespace circles::conform {
namespace {

using circles::testing::FunctionCandidate;
using circles::testing::TempDir;
using circles::testing::thrown;

TEST(corpus, round_trips_a_counterexample_through_its_file_bit_for_bit) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  StoredCounterexample c;
  c.profile = Profile::literal;
  c.world = {{-0.0, 0.1, 1e300, -tiny, 2.5}, {1.0 / 3, -2, 0, 60, tiny}};
  c.level = "ulps:3";
  c.family = "subnormals";
  c.candidate = "the program `a \"quoted\" name`";
  c.seed = 18446744073709551615u;
  c.case_index = 12;
  c.steps = 4;
  c.step = 2;
  c.expected = c.world;
  c.actual = {{0, 0, 0, 0, 0}, {1, 1, 1, 1, 1}};
  c.difference = Difference{1, spec::Field::r, tiny, -0.0, "none: \"quoted\""};
  const StoredCounterexample back = from_json(to_json(c), "x.json");
  EXPECT_EQ(back.profile, c.profile);
  ASSERT_EQ(back.world.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t f = 0; f < 5; ++f)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(back.world[k][f]), std::bit_cast<std::uint64_t>(c.world[k][f]));
  EXPECT_EQ(back.level, c.level);
  EXPECT_EQ(back.family, c.family);
  EXPECT_EQ(back.candidate, c.candidate);
  EXPECT_EQ(back.seed, c.seed);
  EXPECT_EQ(back.case_index, c.case_index);
  EXPECT_EQ(back.steps, c.steps);
  EXPECT_EQ(back.step, c.step);
  EXPECT_EQ(back.actual, c.actual);
  ASSERT_TRUE(back.difference);
  EXPECT_EQ(back.difference->field, spec::Field::r);
  EXPECT_TRUE(std::signbit(back.difference->actual));
  EXPECT_EQ(back.difference->decision, c.difference->decision);
  // Equal worlds in one profile are one file; the other profile is another.
  StoredCounterexample other = c;
  other.seed = 1;
  EXPECT_EQ(stem(other), stem(c));
  other.profile = Profile::resolved;
  EXPECT_NE(stem(other), stem(c));
  EXPECT_EQ(stem(c).size(), std::string("counterexample-").size() + 16);
}

TEST(corpus, refuses_corpus_files_it_cannot_replay_naming_the_file_and_the_place) {
  const auto error = [](const std::string& text) {
    const auto e = thrown<CorpusError>([&] { from_json(text, "F.json"); });
    return e ? std::string(e->what()) : std::string("nothing thrown");
  };
  const std::string head = R"({"format": "circles-counterexample/1", "profile": "resolved", )";
  EXPECT_EQ(error("{"), "F.json: malformed JSON: [json.exception.parse_error.101] parse error at line 1, column 2: "
                        "syntax error while parsing object key - unexpected end of input; expected string literal");
  EXPECT_EQ(error("[]"), "F.json: expected an object {\"format\": ..., \"profile\": ..., \"world\": ...}");
  EXPECT_EQ(error(R"({"format": "circles-counterexample/1", "world": []})"), "F.json: missing key \"profile\"");
  EXPECT_EQ(error(R"({"format": "other", "profile": "resolved", "world": []})"),
            "F.json: key \"format\": expected \"circles-counterexample/1\", found \"other\"");
  EXPECT_EQ(error(head + R"("world": [], "note": 1})"),
            "F.json: unknown key \"note\" (a counterexample has the keys format, profile, world, level, seed, case, "
            "family, steps, step, candidate, fault, expected, actual and difference)");
  EXPECT_EQ(error(R"({"format": "circles-counterexample/1", "profile": "exact", "world": []})"),
            "F.json: key \"profile\": expected \"resolved\" or \"literal\", found \"exact\"");
  EXPECT_EQ(error(head + R"("world": [[0, 0, 0, 0, -2]]})"),
            "F.json: key \"world\": circle 0, field r: radius -2 is negative (r >= 0, the resolved profile) (not an "
            "element of C)");
  EXPECT_EQ(error(head + R"("world": [[0, 0, 0, 0]]})"),
            "F.json: key \"world\": circle 0: expected 5 numbers [px, py, vx, vy, r]");
  EXPECT_EQ(error(head + R"("world": [[0, 0, "1", 0, 1]]})"),
            "F.json: key \"world\": circle 0, field vx: expected a number, found \"1\"");
  EXPECT_EQ(error(head + R"("world": [[0, 0, 0, 0, 1e999]]})"),
            "F.json: malformed JSON: [json.exception.out_of_range.406] number overflow parsing '1e999'");
  // A number means the double nearest to it (formats/json_number.hpp): 2^53 + 1 is 2^53.
  EXPECT_EQ(from_json(head + R"("world": [[9007199254740993, 0, 0, 0, 1]]})", "F.json").world[0][0], 0x1p53);
  EXPECT_EQ(error(head + R"("world": [], "seed": -1})"), "F.json: key \"seed\": expected an integer >= 0, found -1");

  // In a directory, the file is named by its path, and a run with --save stops before any case.
  const TempDir corpus;
  corpus.write("bad.json", "{");
  std::uint64_t asked = 0;
  FunctionCandidate counting([&](const Circles& w) {
    ++asked;
    return w;
  });
  Options options{{0}, 100, 1, 1, 0, 1, {}};
  options.save = corpus.path;
  const Verdict v = check(counting, options);
  EXPECT_EQ(v.outcome, Outcome::cannot_check);
  EXPECT_TRUE(v.error.starts_with("--save: " + (corpus.path / "bad.json").string() + ": malformed JSON")) << v.error;
  EXPECT_EQ(asked, 0u);
}

// The committed corpus (tests/corpus/conform): read in order of name, each file named by the stem of what it
// holds, so that finding one of them again (save) writes the same file rather than a second one.
TEST(corpus, loads_a_directory_in_order_of_name_and_saves_each_counterexample_under_its_stem) {
  const auto committed = load_corpus(std::filesystem::path(CIRCLES_SOURCE_DIR) / "tests" / "corpus" / "conform");
  ASSERT_GE(committed.size(), 2u);
  for (std::size_t k = 1; k < committed.size(); ++k) EXPECT_LT(committed[k - 1].first, committed[k].first);
  const TempDir dir;
  for (const auto& [file, c] : committed) {
    EXPECT_EQ(file.stem().string(), stem(c)) << file;
    EXPECT_EQ(save(dir.path / "copy", c), dir.path / "copy" / file.filename());
    EXPECT_EQ(save(dir.path / "copy", c), dir.path / "copy" / file.filename()) << "saved again under another name";
  }
  const auto copied = load_corpus(dir.path / "copy");
  ASSERT_EQ(copied.size(), committed.size());
  for (std::size_t k = 0; k < copied.size(); ++k) {
    EXPECT_EQ(copied[k].first.filename(), committed[k].first.filename());
    EXPECT_EQ(to_json(copied[k].second), to_json(committed[k].second));
  }
}

}  // namespace
}  // namespace circles::conform
