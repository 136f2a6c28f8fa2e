// `circles conform` in process: the comparison and its levels, the verdicts on right and wrong candidates, the
// shrunk counterexample, rounds of every family and shards, the literal profile, counterexamples saved and
// replayed (cli/corpus.hpp) and drawn (cli/counterexample_svg.hpp), and candidate programs that crash, hang, or
// answer out of protocol.
#include "cli/candidate.hpp"
#include "cli/conform.hpp"
#include "cli/corpus.hpp"
#include "cli/counterexample_svg.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <signal.h>
#include <unistd.h>

#include "impl/predicate.hpp"
#include "impl/rounding.hpp"
#include "properties/boundaries.hpp"
#include "spec/oracle.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

namespace circles::cli {
namespace {

using circles::testing::TempDir;
using circles::testing::thrown;
using namespace std::chrono_literals;

// An in-process candidate from a step function, for deliberately wrong implementations.
class FunctionCandidate : public Candidate {
 public:
  explicit FunctionCandidate(std::function<Circles(const Circles&)> step) : step_(std::move(step)) {}
  Circles answer(const Circles& world, std::uint64_t) override { return step_(world); }
  std::string name() const override { return "the function"; }

 private:
  std::function<Circles(const Circles&)> step_;
};

// The resolved step with the contacts `touches(k, j)` decides: each circle takes the velocity of the least.
Circles step_with_contacts(const Circles& w, const std::function<bool(std::size_t, std::size_t)>& touches) {
  Circles out = w;
  for (std::size_t k = 0; k < w.size(); ++k) {
    std::size_t least = k;
    for (std::size_t j = 0; j < w.size(); ++j)
      if (j != k && touches(k, j) && (least == k || std::make_pair(w[j], j) < std::make_pair(w[least], least)))
        least = j;
    out[k][2] = w[least][2];
    out[k][3] = w[least][3];
    out[k][0] = impl::advance_rounded(w[k][0], out[k][2]);
    out[k][1] = impl::advance_rounded(w[k][1], out[k][3]);
  }
  return out;
}

// The oracle with (3) decided by < instead of <=: wrong exactly at tangency.
Circles strict_intersect_step(const Circles& w) {
  return step_with_contacts(w, [&](std::size_t k, std::size_t j) {
    const spec::Q dx = spec::exact(w[j][0]) - spec::exact(w[k][0]), dy = spec::exact(w[j][1]) - spec::exact(w[k][1]);
    const spec::Q s = spec::exact(w[k][4]) + spec::exact(w[j][4]);
    return s * s > dx * dx + dy * dy;
  });
}

// A step that keeps its contact list from one request to the next, as a neighbour list that is never rebuilt:
// asked its own last answer back (the next step of a chain), it tests only the pairs that touched in the world
// before; asked any other world, it finds the pairs anew. So it is right at the first step of every chain, and
// wrong where two circles come into contact after a move: two circles that become tangent in w_1.
class StaleContacts : public Candidate {
 public:
  Circles answer(const Circles& w, std::uint64_t) override {
    const auto touch = [&](std::size_t k, std::size_t j) {
      return impl::intersect_exact(w[k][0], w[k][1], w[k][4], w[j][0], w[j][1], w[j][4]);
    };
    if (w != last_answer_) {
      pairs_.clear();
      for (std::size_t k = 0; k < w.size(); ++k)
        for (std::size_t j = 0; j < w.size(); ++j)
          if (j != k && touch(k, j)) pairs_.emplace(k, j);
    }
    last_answer_ =
        step_with_contacts(w, [&](std::size_t k, std::size_t j) { return pairs_.contains({k, j}) && touch(k, j); });
    return last_answer_;
  }
  std::string name() const override { return "the step with a stale contact list"; }

 private:
  Circles last_answer_;
  std::set<std::pair<std::size_t, std::size_t>> pairs_;
};

std::string run(Candidate& candidate, ConformOptions options, int& status) {
  std::ostringstream out;
  status = conform(candidate, options, out);
  return out.str();
}

TEST(conform, parses_levels_and_shards_and_refuses_others_with_their_option_named) {
  EXPECT_EQ(parse_level("exact").ulps, 0u);
  EXPECT_EQ(parse_level("faithful").ulps, 1u);
  EXPECT_EQ(parse_level("ulps:17").ulps, 17u);
  for (const char* bad : {"exactly", "ulps:", "ulps:-1", "ulps:1x", ""}) {
    const auto e = thrown<std::invalid_argument>([&] { parse_level(bad); });
    ASSERT_TRUE(e) << bad;
    EXPECT_EQ(std::string(e->what()), "--level: \"" + std::string(bad) + "\" is not exact, faithful or ulps:K (K an integer)");
  }
  EXPECT_EQ(parse_shard("2/5"), (std::pair<std::uint64_t, std::uint64_t>{2, 5}));
  for (const char* bad : {"5/5", "1/0", "1", "a/2", "1/2/3"}) {
    const auto e = thrown<std::invalid_argument>([&] { parse_shard(bad); });
    ASSERT_TRUE(e) << bad;
    EXPECT_EQ(std::string(e->what()), "--shard: \"" + std::string(bad) + "\" is not i/n with 0 <= i < n");
  }
}

TEST(conform, compares_positions_within_the_level_and_decisions_exactly) {
  const Circles in{{0, 0, 1, 0, 1}, {1, 0, 2, 0, 1}, {10, 0, 3, 0, 1}};
  const Circles expected = spec::resolved_step_rounded(in);
  EXPECT_FALSE(compare(in, expected, expected, Level{0}));
  Circles one_ulp = expected;
  one_ulp[2][0] = std::nextafter(one_ulp[2][0], 100.0);
  Circles two_ulps = one_ulp;
  two_ulps[2][0] = std::nextafter(two_ulps[2][0], 100.0);
  ASSERT_TRUE(compare(in, expected, one_ulp, Level{0}));
  EXPECT_EQ(compare(in, expected, one_ulp, Level{0})->circle, 2u);
  EXPECT_EQ(compare(in, expected, one_ulp, Level{0})->decision, "none: the velocity is right, the position is not the nearest double");
  EXPECT_FALSE(compare(in, expected, one_ulp, Level{1}));
  EXPECT_TRUE(compare(in, expected, two_ulps, Level{1}));
  EXPECT_FALSE(compare(in, expected, two_ulps, Level{2}));
  // −0 and +0 are one value, and one rank apart from nothing.
  Circles zero{{0, 0, 0, 0, 0}}, negative_zero{{-0.0, -0.0, -0.0, -0.0, -0.0}};
  EXPECT_FALSE(compare(zero, zero, negative_zero, Level{0}));
  // Decisions: velocities must be exact at every level, and the message says which decision.
  Circles kept = expected;
  kept[0][2] = in[0][2];
  EXPECT_EQ(compare(in, expected, kept, Level{1000})->decision,
            "intersect (3): circle 0 touches circle 1 but kept its own velocity");
  Circles phantom = expected;
  phantom[2][2] = 7;
  EXPECT_EQ(compare(in, expected, phantom, Level{1000})->decision,
            "intersect (3): circle 2 touches no circle, yet its velocity changed");
  const Circles three{{0, 0, 1, 0, 1}, {1, 0, 2, 0, 1}, {-1, 0, 3, 0, 1}};
  Circles chose = spec::resolved_step_rounded(three);
  chose[0][2] = 2;  // circle 1's velocity; the least contact of circle 0 is circle 2 (px −1 < 1)
  EXPECT_EQ(compare(three, spec::resolved_step_rounded(three), chose, Level{1000})->decision,
            "the choice of e (8): circle 0 took the velocity of circle 1, a contact but not the least one");
}

TEST(conform, the_double_engine_conforms_over_chained_steps) {
  EngineCandidate engine_candidate(engine("double"), 1);
  int status = -1;
  const std::string report = run(engine_candidate, ConformOptions{{0}, 400, 11, 2, 0, 1, {}}, status);
  EXPECT_EQ(status, 0) << report;
  EXPECT_NE(report.find("conforms: 400 cases"), std::string::npos) << report;
  EXPECT_NE(report.find("2 steps each, level exact, seed 11"), std::string::npos) << report;
}

TEST(conform, its_fast_reference_agrees_with_the_oracle_on_the_worlds_it_draws) {
  // conform compares answers with impl::step_all_pairs, not with the oracle itself (50-100 times slower): with
  // the oracle as the candidate, every case must conform, over chained steps too.
  EngineCandidate oracle(engine("oracle"), 1);
  int status = -1;
  const std::string report = run(oracle, ConformOptions{{0}, 3000, 21, 2, 0, 1, {}}, status);
  EXPECT_EQ(status, 0) << report;
}

TEST(conform, rejects_a_strict_intersect_with_a_counterexample_shrunk_to_two_tangent_circles) {
  FunctionCandidate wrong(strict_intersect_step);
  int status = -1;
  const std::string report = run(wrong, ConformOptions{{0}, 1000, 7, 1, 0, 1, {}}, status);
  EXPECT_EQ(status, 1) << report;
  EXPECT_NE(report.find("to 2 circles"), std::string::npos) << report;
  EXPECT_NE(report.find("which decision: intersect (3): circle"), std::string::npos) << report;
  EXPECT_NE(report.find("but kept its own velocity"), std::string::npos) << report;
  EXPECT_NE(report.find("replay: --seed 7 --case "), std::string::npos) << report;
}

// The tangent-after-step family's circles become tangent in w_1, so its tangency is decided at the second step:
// its cases are chained two steps even when one is asked for (the default), and a step that is wrong only there
// is caught at the default budget, in that family.
TEST(conform, chains_the_tangent_after_step_family_to_the_step_that_decides_its_tangency) {
  StaleContacts stale;
  int status = -1;
  ConformOptions defaults;  // 1000 cases, one step, level exact, resolved profile
  defaults.seed = 5;
  const std::string report = run(stale, defaults, status);
  EXPECT_EQ(status, 1) << report;
  EXPECT_NE(report.find("(family tangent-after-step)"), std::string::npos) << report;
  EXPECT_NE(report.find("  step 2 of 2, circle "), std::string::npos) << report;
  EXPECT_NE(report.find("which decision: intersect (3): circle"), std::string::npos) << report;
  EXPECT_NE(report.find("but kept its own velocity"), std::string::npos) << report;
  EXPECT_NE(report.find("the world asked (the candidate's own last answer)"), std::string::npos) << report;
  // Its first steps are right: the cases of every other family, chained one step, pass.
  const auto families = properties::families(Profile::resolved);
  const std::uint64_t F = families.size();
  ConformOptions one_case = defaults;
  for (std::uint64_t c = 0; c < 10 * F; ++c) {
    if (families[c % F] == properties::Family::tangent_after_step) continue;
    one_case.only_case = c;
    const std::string one = run(stale, one_case, status);
    EXPECT_EQ(status, 0) << one;
  }
  // A run that passes says how far the family was chained.
  EngineCandidate double_engine(engine("double"), 1);
  EXPECT_NE(run(double_engine, defaults, status)
                .find(", 1 step each (tangent-after-step 2: chained to the step that decides its boundary), level exact"),
            std::string::npos);
  EXPECT_EQ(status, 0);
}

TEST(conform, shards_take_whole_rounds_of_every_family_without_overlap) {
  // Cases come in rounds of one per family; shard i/n takes the rounds q with q mod n = i. With the 17
  // families of the resolved profile, 100 cases are rounds 0 … 4 (17 each) and 15 cases of round 5: shard
  // 0/2 asks rounds 0, 2 and 4, shard 1/2 rounds 1, 3 and the partial 5.
  ASSERT_EQ(properties::families(Profile::resolved).size(), 17u);
  int status = -1;
  std::uint64_t asked = 0;
  FunctionCandidate counting([&](const Circles& w) {
    ++asked;
    return spec::resolved_step_rounded(w);
  });
  const std::string first_report = run(counting, ConformOptions{{0}, 100, 3, 1, 0, 2, {}}, status);
  const std::uint64_t first = asked;
  run(counting, ConformOptions{{0}, 100, 3, 1, 1, 2, {}}, status);
  // One request per case, and a second for each case of tangent-after-step (family 11, chained two steps):
  // 3 of them in each shard.
  EXPECT_EQ(first, 51u + 3);
  EXPECT_EQ(asked, 100u + 6);
  // Each shard saw every family: three cases of each in shard 0.
  EXPECT_NE(first_report.find("lattice 3, random-doubles 3, tangency 3,"), std::string::npos) << first_report;
}

TEST(conform, refuses_a_run_too_short_to_reach_every_family) {
  EngineCandidate engine_candidate(engine("double"), 1);
  std::ostringstream out;
  const auto e = thrown<ConformError>([&] { conform(engine_candidate, ConformOptions{{0}, 10, 3, 1, 0, 1, {}}, out); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()),
            "no case of the family mutual-contacts was checked: each round of 17 cases draws every family of the resolved "
            "profile once, and this run checked 10; raise --cases to at least 17");
  const auto sharded =
      thrown<ConformError>([&] { conform(engine_candidate, ConformOptions{{0}, 20, 3, 1, 1, 2, {}}, out); });
  ASSERT_TRUE(sharded);
  EXPECT_EQ(std::string(sharded->what()),
            "no case of the family ulp-nudge was checked: each round of 17 cases draws every family of the resolved "
            "profile once, and this run (shard 1/2) checked 3; raise --cases to at least 34");
  // Replaying one case is not a run over the families; nor need --cases reach it.
  ConformOptions one{{0}, 1000, 3, 1, 0, 1, 1500};
  int status = -1;
  EXPECT_NE(run(engine_candidate, one, status).find("conforms: 1 cases"), std::string::npos);
}

// ── The literal profile ────────────────────────────────────────────────────────────────────────────────

TEST(conform, the_literal_profile_asks_only_worlds_inside_the_seeds_domain_and_the_double_engine_passes) {
  std::uint64_t asked = 0, outside = 0, with_contacts = 0;
  FunctionCandidate literal([&](const Circles& w) {
    ++asked;
    outside += properties::outside_literal_domain(w).has_value();
    for (std::size_t a = 0; a < w.size(); ++a)
      for (std::size_t b = a + 1; b < w.size(); ++b)
        if (spec::intersect(spec::from_doubles(w[a], a, spec::Radii::positive),
                            spec::from_doubles(w[b], b, spec::Radii::positive))) {
          ++with_contacts;
          a = b = w.size();
        }
    return spec::resolved_step_rounded(w);  // inside the domain, the resolved step is the literal one
  });
  int status = -1;
  ConformOptions options{{0}, 1500, 5, 3, 0, 1, {}};
  options.profile = Profile::literal;
  const std::string report = run(literal, options, status);
  EXPECT_EQ(status, 0) << report;
  EXPECT_EQ(outside, 0u);
  EXPECT_GT(with_contacts, asked / 3);  // not only worlds where nothing meets
  EXPECT_NE(report.find("literal profile"), std::string::npos) << report;
  EngineCandidate double_engine(engine("double"), 1);
  EXPECT_EQ(conform(double_engine, options, std::cout), 0);
}

TEST(conform, the_literal_profile_refuses_a_step_that_ignores_the_product_order) {
  // The resolved and literal steps agree inside the literal domain, so a wrong decision shows in both; here a
  // step that takes the contact with the greatest key, which a world with two ordered contacts exposes.
  FunctionCandidate greatest([](const Circles& w) {
    Circles out = spec::resolved_step_rounded(w);
    for (std::size_t k = 0; k < w.size(); ++k) {
      std::optional<std::size_t> best;
      for (std::size_t j = 0; j < w.size(); ++j)
        if (j != k && spec::intersect(spec::from_doubles(w[k], k, spec::Radii::positive),
                                      spec::from_doubles(w[j], j, spec::Radii::positive)) &&
            (!best || w[*best] < w[j]))
          best = j;
      if (best) {
        out[k][2] = w[*best][2];
        out[k][3] = w[*best][3];
        out[k][0] = impl::advance_rounded(w[k][0], out[k][2]);
        out[k][1] = impl::advance_rounded(w[k][1], out[k][3]);
      }
    }
    return out;
  });
  int status = -1;
  ConformOptions options{{0}, 1000, 5, 1, 0, 1, {}};
  options.profile = Profile::literal;
  const std::string report = run(greatest, options, status);
  EXPECT_EQ(status, 1) << report;
  EXPECT_NE(report.find("the choice of e (8)"), std::string::npos) << report;
  EXPECT_NE(report.find("expected (the literal oracle's step, rounded to nearest)"), std::string::npos) << report;
  EXPECT_NE(report.find("--profile literal"), std::string::npos) << report;
}

// ── Counterexamples as files: --save and --svg ─────────────────────────────────────────────────────────

std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir, const std::string& extension) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(dir))
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == extension) files.push_back(entry.path());
  return files;
}

TEST(conform, saves_a_counterexample_with_its_picture_and_replays_it_first_on_every_run) {
  const TempDir dir;
  const std::filesystem::path corpus = dir.path / "corpus";  // --save makes it
  FunctionCandidate wrong(strict_intersect_step);
  ConformOptions options{{0}, 1000, 7, 1, 0, 1, {}};
  options.save = corpus;
  int status = -1;
  const std::string first = run(wrong, options, status);
  EXPECT_EQ(status, 1) << first;
  const auto saved = files_in(corpus, ".json");
  ASSERT_EQ(saved.size(), 1u) << first;
  EXPECT_NE(first.find("saved: " + saved[0].string()), std::string::npos) << first;
  const std::filesystem::path picture = saved[0].parent_path() / (saved[0].stem().string() + ".svg");
  EXPECT_TRUE(std::filesystem::exists(picture));
  EXPECT_NE(first.find("picture: " + picture.string()), std::string::npos) << first;

  // The file holds the shrunk world, which the wrong step still gets wrong and the right one right.
  const auto stored = load_corpus(corpus);
  ASSERT_EQ(stored.size(), 1u);
  const StoredCounterexample& c = stored[0].second;
  EXPECT_EQ(c.seed, 7u);
  ASSERT_TRUE(c.case_index);
  EXPECT_EQ(c.candidate, "the function");
  ASSERT_EQ(c.world.size(), 2u);
  EXPECT_EQ(c.expected, spec::resolved_step_rounded(c.world));
  EXPECT_EQ(c.actual, strict_intersect_step(c.world));
  ASSERT_TRUE(c.difference);
  EXPECT_NE(c.difference->decision.find("kept its own velocity"), std::string::npos);

  // The next run replays it before any generated case, even with no cases at all.
  options.cases = 0;
  const std::string second = run(wrong, options, status);
  EXPECT_EQ(status, 1) << second;
  EXPECT_NE(second.find("counterexample: stored in " + saved[0].string() + ", replayed first (found as case " +
                        std::to_string(*c.case_index) + " of seed 7, family "),
            std::string::npos)
      << second;
  EXPECT_NE(second.find("replay: --save " + corpus.string()), std::string::npos) << second;
  EXPECT_EQ(files_in(corpus, ".json").size(), 1u);  // not saved twice

  // A right step passes it, and says so.
  FunctionCandidate right([](const Circles& w) { return spec::resolved_step_rounded(w); });
  const std::string third = run(right, options, status);
  EXPECT_EQ(status, 0) << third;
  EXPECT_NE(third.find("corpus: 1 stored counterexample replayed from " + corpus.string()), std::string::npos)
      << third;
}

TEST(conform, round_trips_a_counterexample_through_its_file_bit_for_bit) {
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
  c.difference = Difference{1, 4, tiny, -0.0, "none: \"quoted\""};
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
  EXPECT_EQ(back.difference->field, 4);
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

TEST(conform, refuses_corpus_files_it_cannot_replay_naming_the_file_and_the_place) {
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
            "family, steps, step, candidate, expected, actual and difference)");
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
  // A number means the double nearest to it (cli/json_number.hpp): 2^53 + 1 is 2^53.
  EXPECT_EQ(from_json(head + R"("world": [[9007199254740993, 0, 0, 0, 1]]})", "F.json").world[0][0], 0x1p53);
  EXPECT_EQ(error(head + R"("world": [], "seed": -1})"), "F.json: key \"seed\": expected an integer >= 0, found -1");

  // In a directory, the file is named by its path, and a run with --save stops before any case.
  const TempDir corpus;
  corpus.write("bad.json", "{");
  EngineCandidate engine_candidate(engine("double"), 1);
  ConformOptions options{{0}, 100, 1, 1, 0, 1, {}};
  options.save = corpus.path;
  std::ostringstream out;
  const auto e = thrown<ConformError>([&] { conform(engine_candidate, options, out); });
  ASSERT_TRUE(e);
  EXPECT_TRUE(std::string(e->what()).starts_with("--save: " + (corpus.path / "bad.json").string() + ": malformed JSON"))
      << e->what();
}

TEST(conform, refuses_a_save_directory_or_picture_it_cannot_write_before_any_case) {
  const TempDir dir;
  dir.write("file", "x");
  std::uint64_t asked = 0;
  FunctionCandidate counting([&](const Circles& w) {
    ++asked;
    return w;
  });
  std::ostringstream out;
  ConformOptions options{{0}, 100, 1, 1, 0, 1, {}};
  options.save = dir.path / "file";
  auto e = thrown<ConformError>([&] { conform(counting, options, out); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "--save: cannot use the directory " + (dir.path / "file").string() + ": " +
                                        std::make_error_code(std::errc::not_a_directory).message());
  options.save.clear();
  options.svg = dir.path / "no" / "such" / "picture.svg";
  e = thrown<ConformError>([&] { conform(counting, options, out); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "--svg: cannot write " + options.svg.string() + ": the directory " +
                                        (dir.path / "no" / "such").string() + " does not exist");
  EXPECT_EQ(asked, 0u);
}

// Every number in the path data and positions of an SVG document.
std::vector<double> coordinates_in(const std::string& svg) {
  std::vector<double> xs;
  static const std::regex attribute(R"re((?:\sd|\sx|\sy)="([^"]*)")re");
  static const std::regex number(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf)");
  for (std::sregex_iterator a(svg.begin(), svg.end(), attribute), end; a != end; ++a) {
    const std::string text = (*a)[1];
    for (std::sregex_iterator n(text.begin(), text.end(), number); n != end; ++n) xs.push_back(std::stod(n->str()));
  }
  return xs;
}

TEST(conform, draws_worlds_from_the_subnormals_to_dbl_max_inside_the_picture) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double huge = std::numeric_limits<double>::max();
  for (const Circles& w : {Circles{{0, 0, 1, 0, 5 * tiny}, {3 * tiny, 4 * tiny, 0, 0, 0}},
                           Circles{{-huge, huge, 0, 0, huge}, {huge, -huge, 0, 0, huge}, {0, 0, 0, 0, 0}},
                           Circles{{1, 1, 0, 0, 0}}}) {
    CounterexamplePicture picture{w, w, w, 0, Profile::resolved, {"a line of text"}};
    picture.actual[0][0] = std::nextafter(w[0][0], 1.0);
    const std::string svg = counterexample_svg(picture);
    EXPECT_TRUE(svg.starts_with("<?xml")) << svg.substr(0, 100);
    EXPECT_NE(svg.find(R"(width="900pt" height="760pt")"), std::string::npos);
    const std::vector<double> xs = coordinates_in(svg);
    EXPECT_GT(xs.size(), 50u);
    for (const double x : xs) {
      ASSERT_TRUE(std::isfinite(x)) << x;
      ASSERT_GE(x, -20) << x;
      ASSERT_LE(x, 920) << x;
    }
  }
}

TEST(conform, draws_one_line_for_each_contact_and_the_expected_and_answered_positions_dashed) {
  // Contacts are orange, rgb(95%, 55%, 10%): one line for each touching pair, and one in the legend.
  const auto contact_lines = [](const Circles& w) {
    const std::string svg = counterexample_svg({w, w, w, 0, Profile::resolved, {}});
    std::size_t lines = 0;
    for (std::size_t at = 0; (at = svg.find("stroke:rgb(95%,55%,10%)", at)) != std::string::npos; ++at) ++lines;
    return lines;
  };
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 1}, {10, 0, 0, 0, 1}}), 1u);
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 1}, {2, 0, 0, 0, 1}}), 2u);  // tangent: (3) holds
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 1}, {std::nextafter(2.0, 3.0), 0, 0, 0, 1}}), 1u);
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 2}, {1, 0, 0, 0, 2}, {-1, 0, 0, 0, 2}}), 4u);  // three pairs
  const std::string svg = counterexample_svg({{{0, 0, 60, 0, 1}}, {{1, 0, 60, 0, 1}}, {{2, 0, 60, 0, 1}}, 0,
                                              Profile::resolved, {}});
  std::size_t dashed = 0;
  for (std::size_t at = 0; (at = svg.find("stroke-dasharray", at)) != std::string::npos; ++at) ++dashed;
  EXPECT_EQ(dashed, 4u);  // expected and answered, in the picture and in the legend
}

// Programs that break the protocol: each is refused with what it did, and nothing of it outlives the check.
TEST(conform, refuses_broken_programs_with_what_they_did) {
  const Circles w{{0, 0, 1, 0, 1}};
  const auto broken = [&](const std::string& command) {
    ProcessCandidate candidate(command, 300ms);
    const auto e = thrown<BrokenCandidate>([&] { candidate.answer(w, 4); });
    return e ? std::string(e->what()) : std::string("nothing thrown");
  };
  EXPECT_EQ(broken("exit 3"), "the program `exit 3` exited with status 3 before answering request 4");
  EXPECT_EQ(broken("sleep 30"), "the program `sleep 30` gave no answer to request 4 within 0.3 s (it was stopped)");
  EXPECT_EQ(broken("read x; echo '{\"id\": 5, \"circles\": [[0, 0, 1, 0, 1]]}'"),
            "the program `read x; echo '{\"id\": 5, \"circles\": [[0, 0, 1, 0, 1]]}'` answered request 4 with id 5");
  EXPECT_EQ(broken("read x; echo '{\"id\": 4, \"circles\": []}'"),
            "the program `read x; echo '{\"id\": 4, \"circles\": []}'` answered request 4 (1 circles) with 0 circles");
  EXPECT_EQ(broken("read x; echo 'hello'"),
            "the program `read x; echo 'hello'` wrote a malformed answer to request 4: line 1: malformed JSON at "
            "column 1: syntax error while parsing value - invalid literal; last read: 'h'");
  EXPECT_EQ(broken("read x; kill -SEGV $$"), "the program `read x; kill -SEGV $$` was killed by signal 11 before answering request 4");
  // A correct program that will not exit at the end of its input.
  ProcessCandidate stubborn("cat >/dev/null; sleep 30", 200ms);
  const auto e = thrown<BrokenCandidate>([&] { stubborn.finish(); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()),
            "the program `cat >/dev/null; sleep 30` did not exit within 0.2 s of the end of its input (it was stopped)");
}

// A program is sent a batch of requests before conform reads their answers: one that answers only after it has
// read two requests is answered, not waited on until the deadline (which is what asking one request at a time
// would get: "gave no answer to request 7"). Messages still name the request of the batch they concern.
// A program that crashes right after its first wrong answer, before answering the rest of its batch: the
// strict (3) step, with answer_all stopping at the first answer that differs from the resolved step. Conform
// judges the answers it has before the fault, so the verdict is the counterexample, exit 1, as a case-by-case
// run gives; reporting the crash, exit 2, would hide a wrong answer behind a fault it provoked.
class CrashesAfterItsFirstWrongAnswer : public FunctionCandidate {
 public:
  CrashesAfterItsFirstWrongAnswer() : FunctionCandidate(strict_intersect_step) {}
  Answers answer_all(std::span<const Circles> worlds, std::uint64_t first_id) override {
    Answers read = Candidate::answer_all(worlds, first_id);
    for (std::size_t i = 0; i + 1 < read.answers.size(); ++i) {
      const auto expected = properties::expected_step(worlds[i], Profile::resolved);
      if (std::holds_alternative<Circles>(expected) && std::get<Circles>(expected) != read.answers[i]) {
        read.answers.resize(i + 1);
        read.broken = BrokenCandidate("the program crashed after request " + std::to_string(first_id + i));
        ++crashes;
        break;
      }
    }
    return read;
  }
  int crashes = 0;
};

TEST(conform, judges_the_answers_before_a_fault_in_a_batch_and_reports_the_counterexample) {
  CrashesAfterItsFirstWrongAnswer candidate;
  int status = -1;
  const std::string report = run(candidate, ConformOptions{}, status);
  EXPECT_EQ(status, 1) << report;
  EXPECT_NE(report.find("does not conform"), std::string::npos) << report;
  EXPECT_GE(candidate.crashes, 1);  // the fault happened, inside a batch
}

// tests/faulty_candidate.cpp MODE, through the program and conform's defaults at seed 1 (a batch of requests at a
// time, as `circles conform --exec` asks).
std::string check_faulty(const std::string& mode, int& status) {
  ProcessCandidate candidate(std::string(CIRCLES_FAULTY_CANDIDATE) + " " + mode, 10s);
  ConformOptions options;
  options.seed = 1;
  return run(candidate, options, status);
}

// The counterexample's line naming the field: "  step 1 of 1, circle 0, field px: expected X, got Y".
std::string difference_line(const std::string& report) {
  const std::size_t at = report.find("  step ");
  return at == std::string::npos ? "" : report.substr(at, report.find('\n', at) - at);
}

// Python's json writes NaN, Infinity and -Infinity for floats that are not finite: each is read as the value it
// means and judged like any number, a counterexample (exit 1) shrunk to the two circles that make the
// candidate write it, naming the field, the expected value and the token received.
TEST(conform, reads_nan_and_infinity_in_an_answer_as_values_and_reports_a_counterexample) {
  for (const std::string token : {"NaN", "Infinity", "-Infinity"}) {
    int status = -1;
    const std::string report = check_faulty(token, status);
    EXPECT_EQ(status, 1) << token << "\n" << report;
    EXPECT_TRUE(std::regex_search(report, std::regex("shrunk from [0-9]+ to 2 circles"))) << report;
    EXPECT_TRUE(std::regex_match(difference_line(report),
                                 std::regex("  step 1 of 1, circle 0, field px: expected [-0-9.e]+ \\(0x[-0-9a-fp.+]+\\), got " +
                                            std::regex_replace(token, std::regex("[-+]"), "\\$&"))))
        << difference_line(report);
  }
}

// A program that answers one request wrong and then breaks (a line that is not JSON, or an exit) on the next,
// inside a batch: the answers to the rest of the batch are still in its pipe when conform reads the fault. The
// program is started afresh before the next request, so shrinking gets the answers to its own requests, never
// "answered request 13 with id 6", and the verdict is the shrunk counterexample, exit 1.
TEST(conform, never_takes_an_answer_for_another_request_after_a_fault_in_a_batch) {
  for (const std::string mode : {"wrong-then-malformed", "wrong-then-crash"}) {
    int status = -1;
    const std::string report = check_faulty(mode, status);
    EXPECT_EQ(status, 1) << mode << "\n" << report;
    EXPECT_TRUE(std::regex_search(report, std::regex("shrunk from [0-9]+ to 2 circles in [1-9][0-9]* steps"))) << report;
    EXPECT_NE(difference_line(report).find(", circle 0, field px: expected "), std::string::npos) << report;
  }
}

// Unknown keys in an answer are ignored, whatever their values (NaN and a "}" in a string included), for
// forward compatibility: an exact candidate that adds a timing to each answer conforms.
TEST(conform, ignores_unknown_keys_in_an_answer) {
  int status = -1;
  const std::string report = check_faulty("extra-key", status);
  EXPECT_EQ(status, 0) << report;
  EXPECT_NE(report.find("conforms: 1000 cases"), std::string::npos) << report;
}

TEST(conform, sends_a_program_several_requests_before_reading_their_answers) {
  const std::vector<Circles> worlds{{}, {{0, 0, 1, 0, 1}}};
  const auto answers = [&](const std::string& second_answer) -> std::string {
    ProcessCandidate candidate("read a; read b; echo '{\"id\": 7, \"circles\": []}'; echo '" + second_answer + "'",
                               300ms);
    try {
      return candidate.answer_all(worlds, 7).all() == std::vector<Circles>{{}, {{2, 0, 1, 0, 1}}} ? "answered" : "wrong answers";
    } catch (const BrokenCandidate& e) {
      return e.what();
    }
  };
  EXPECT_EQ(answers("{\"id\": 8, \"circles\": [[2, 0, 1, 0, 1]]}"), "answered");
  EXPECT_EQ(answers("{\"id\": 9, \"circles\": []}"),
            "the program `read a; read b; echo '{\"id\": 7, \"circles\": []}'; echo '{\"id\": 9, \"circles\": []}'` "
            "answered request 8 with id 9");
}

// More requests than a batch's bytes (ProcessCandidate::kBatchBytes) go in several batches, answered in order:
// `cat` echoes each line as it reads it, so a batch written whole, unbounded, would fill both pipes and hang.
TEST(conform, splits_requests_into_batches_a_program_echoing_them_answers_in_order) {
  std::vector<Circles> worlds;
  for (int k = 0; k < 2000; ++k) worlds.push_back(Circles(1 + k % 8, {k * 0.1, -k * 1e-300, 1.0 / (k + 1), 3.5, 1}));
  ProcessCandidate cat("exec cat", 10s);
  const std::vector<Circles> echoed = cat.answer_all(worlds, 1).all();
  EXPECT_EQ(echoed, worlds);
  EXPECT_EQ(cat.answer(worlds[5], 2001), worlds[5]);  // ids go on where the batches left them
  cat.finish();
}

TEST(conform, leaves_no_process_behind_even_when_the_program_starts_others) {
  const std::filesystem::path pid_file =
      std::filesystem::temp_directory_path() / ("circles-conform-" + std::to_string(::getpid()) + ".pid");
  {
    // The shell starts sleep in the background (same process group) and then hangs itself.
    ProcessCandidate candidate("sleep 60 & echo $! > " + pid_file.string() + "; sleep 60", 100ms);
    EXPECT_TRUE(thrown<BrokenCandidate>([&] { candidate.answer({}, 1); }));
  }
  std::ifstream in(pid_file);
  pid_t child = 0;
  ASSERT_TRUE(in >> child);
  std::filesystem::remove(pid_file);
  // Dead: no such process, or a zombie waiting for its new parent (init or a subreaper such as ctest) to reap
  // it, state Z in /proc/PID/stat ("pid (comm) S ..."). Give the kill a moment to land.
  const auto alive = [child] {
    std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
    std::string line;
    if (!std::getline(stat, line)) return false;
    const auto paren = line.rfind(')');
    return paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] != 'Z';
  };
  for (int tries = 0; tries < 100 && alive(); ++tries) std::this_thread::sleep_for(10ms);
  EXPECT_FALSE(alive()) << "the background sleep " << child << " outlived the check";
}

}  // namespace
}  // namespace circles::cli
