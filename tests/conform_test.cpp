// `circles conform` in process: the comparison and its levels, the verdicts on right and wrong candidates, the
// shrunk counterexample, rounds of every family and shards, the literal profile, counterexamples saved with
// --save and replayed first, and the verdicts on programs that answer NaN or break off inside a batch. The
// candidates themselves are tests/candidate_test.cpp's, the corpus files tests/corpus_test.cpp's.
#include "conform/candidate.hpp"
#include "conform/conform.hpp"
#include "conform/corpus.hpp"
#include "pictures/counterexample_svg.hpp"

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
#include "tests/function_candidate.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

namespace circles::conform {

using namespace circles::formats;
using engines::engine;
namespace {

using circles::testing::TempDir;
using circles::testing::thrown;
using namespace std::chrono_literals;

using circles::testing::FunctionCandidate;

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

// A verdict in a line, for the messages of failed expectations.
std::string describe(const Verdict& v) {
  std::string text = std::string(name(v.outcome)) + " after " + std::to_string(v.cases) + " cases";
  if (!v.error.empty()) text += ": " + v.error;
  if (v.counterexample) {
    const Counterexample& c = *v.counterexample;
    text += ": family " + c.family + ", step " + std::to_string(c.step) + " of " + std::to_string(c.steps) +
            ", circle " + std::to_string(c.difference.circle) + ", field " + spec::name(c.difference.field) +
            ", " + c.difference.decision + ", replay " + c.replay;
  }
  return text;
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
            "the intersect test (3) (docs/math.md#3-intersect--specintersect): circle 0 touches circle 1 but kept "
            "its own velocity");
  Circles phantom = expected;
  phantom[2][2] = 7;
  EXPECT_EQ(compare(in, expected, phantom, Level{1000})->decision,
            "the intersect test (3) (docs/math.md#3-intersect--specintersect): circle 2 touches no circle, yet its "
            "velocity changed");
  const Circles three{{0, 0, 1, 0, 1}, {1, 0, 2, 0, 1}, {-1, 0, 3, 0, 1}};
  Circles chose = spec::resolved_step_rounded(three);
  chose[0][2] = 2;  // circle 1's velocity; the least contact of circle 0 is circle 2 (px −1 < 1)
  EXPECT_EQ(compare(three, spec::resolved_step_rounded(three), chose, Level{1000})->decision,
            "the least-contact rule e (8) (docs/math.md#8-e--spece): circle 0 took the velocity of circle 1, a "
            "contact but not the least one");
  // A contact's velocity that is also the circle's own: the contacts were found, and the least was not taken
  // (a program that keeps only its first contacts). Circle 0's least contact is circle 2 (px -1); circle 1 moves
  // as circle 0 does, and circle 0 answers that velocity.
  const Circles same{{0, 0, 1, 0, 1}, {1, 0, 1, 0, 1}, {-1, 0, 3, 0, 1}};
  Circles kept_first = spec::resolved_step_rounded(same);
  kept_first[0][2] = 1;
  EXPECT_EQ(compare(same, spec::resolved_step_rounded(same), kept_first, Level{1000})->decision,
            "the least-contact rule e (8) (docs/math.md#8-e--spece): circle 0 took the velocity of circle 1, a "
            "contact but not the least one (the same as its own)");
}

// NaN and the infinities differ from every expected value, in every field, at every level: never "equal" from
// a NaN comparison, nor from the rank of NaN's bits. The difference names the field and holds the value received.
TEST(conform, judges_nan_and_infinities_in_every_field_as_differences_at_every_level) {
  const Circles in{{0, 0, 1, 0, 1}, {1, 0, 2, 0, 1}};
  const Circles expected = spec::resolved_step_rounded(in);
  for (const double odd : {double{NAN}, -double{NAN}, double{INFINITY}, -double{INFINITY}})
    for (std::size_t field = 0; field < 5; ++field)
      for (const std::uint64_t ulps : {std::uint64_t{0}, std::uint64_t{1}, std::numeric_limits<std::uint64_t>::max()}) {
        Circles answer = expected;
        answer[1][field] = odd;
        const auto d = compare(in, expected, answer, Level{ulps});
        ASSERT_TRUE(d) << odd << " in field " << field << " at ulps " << ulps;
        EXPECT_EQ(d->circle, 1u);
        EXPECT_EQ(d->field, spec::Field(field));
        EXPECT_EQ(d->expected, expected[1][field]);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(d->actual), std::bit_cast<std::uint64_t>(odd));
      }
}

// −0 and +0 are one value (docs/conform.md, --level): in every field, at every level, either way round.
TEST(conform, judges_minus_0_and_plus_0_as_one_value_in_every_field_both_ways) {
  const Circles in{{0, 0, 0, 0, 0}, {-0.0, -0.0, -0.0, -0.0, -0.0}};
  const Circles expected = spec::resolved_step_rounded(in);
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t field = 0; field < 5; ++field) {
      ASSERT_EQ(expected[k][field], 0.0);
      for (const std::uint64_t ulps : {std::uint64_t{0}, std::uint64_t{1}}) {
        Circles flipped = expected;
        flipped[k][field] = std::copysign(0.0, std::signbit(expected[k][field]) ? 1.0 : -1.0);
        EXPECT_FALSE(compare(in, expected, flipped, Level{ulps})) << "circle " << k << ", field " << field;
      }
    }
}

// A radius is copied by every step: a wrong one is no decision, and the message does not blame the position.
TEST(conform, names_a_changed_radius_as_no_decision_rather_than_a_wrong_position) {
  const Circles in{{0, 0, 1, 0, 1}, {10, 0, 2, 0, 1}};
  const Circles expected = spec::resolved_step_rounded(in);
  for (const double r : {double{NAN}, double{INFINITY}, 2.0, -1.0}) {
    Circles answer = expected;
    answer[0][4] = r;
    const auto d = compare(in, expected, answer, Level{0});
    ASSERT_TRUE(d) << r;
    EXPECT_EQ(d->field, spec::Field::r);
    EXPECT_EQ(d->decision, "none: the position and velocity are right, but the radius changed, which no step does");
  }
}

TEST(conform, the_double_engine_conforms_over_chained_steps) {
  EngineCandidate engine_candidate(engine("double"), 1);
  const Verdict v = check(engine_candidate, Options{{0}, 400, 11, 2, 0, 1, {}});
  EXPECT_EQ(v.outcome, Outcome::conforms) << describe(v);
  EXPECT_EQ(v.cases, 400u);
  EXPECT_EQ(v.options.steps, 2u);
  EXPECT_EQ(v.options.seed, 11u);
  EXPECT_FALSE(v.counterexample);
}

TEST(conform, its_fast_reference_agrees_with_the_oracle_on_the_worlds_it_draws) {
  // conform compares answers with impl::step_all_pairs, not with the oracle itself (50-100 times slower): with
  // the oracle as the candidate, every case must conform, over chained steps too.
  // The big families' worlds, of thousands of circles, would take the oracle hours: the small ones here, and the
  // big ones against every pair tested, below.
  EngineCandidate oracle(engine("oracle"), 1);
  Options options{{0}, 3000, 21, 2, 0, 1, {}};
  options.skip = testing::big_families();
  const Verdict v = check(oracle, options);
  EXPECT_EQ(v.outcome, Outcome::conforms) << describe(v);
}

TEST(conform, its_fast_reference_for_big_worlds_agrees_with_every_pair_tested) {
  // Above 64 circles conform's expected answer is the double engine's step, not step_all_pairs: with
  // step_all_pairs as the candidate, every case of the big families must conform, over chained steps too.
  FunctionCandidate all_pairs(testing::right_step);
  Options options{{0}, 520, 22, 2, 0, 1, {}};  // 20 rounds of the 26 families, 8 of them big
  for (const properties::Family f : properties::families(Profile::resolved))
    if (!properties::is_big(f)) options.skip.push_back(f);
  const Verdict v = check(all_pairs, options);
  EXPECT_EQ(v.outcome, Outcome::conforms) << describe(v);
  std::uint64_t big = 0;
  for (const FamilyResult& f : v.families) big += properties::is_big(f.family) ? f.checked : 0;
  EXPECT_EQ(big, 160u);
}

TEST(conform, rejects_a_strict_intersect_with_a_counterexample_shrunk_to_two_tangent_circles) {
  FunctionCandidate wrong(strict_intersect_step);
  const Verdict v = check(wrong, Options{{0}, 1000, 7, 1, 0, 1, {}});
  ASSERT_EQ(v.outcome, Outcome::does_not_conform) << describe(v);
  const Counterexample& c = *v.counterexample;
  EXPECT_EQ(c.input.size(), 2u);
  EXPECT_EQ(c.shrink_path.front().size(), c.circles_before);
  EXPECT_EQ(c.shrink_path.back(), c.input);  // one step: the world asked is the shrunk w_0
  EXPECT_TRUE(c.difference.decision.starts_with("the intersect test (3) (docs/math.md#3-intersect--specintersect): circle"))
      << c.difference.decision;
  EXPECT_TRUE(c.difference.decision.ends_with("but kept its own velocity")) << c.difference.decision;
  ASSERT_TRUE(c.case_index);
  // A function in process: no option selects it on the command line.
  EXPECT_EQ(c.replay, "circles conform --seed 7 --case " + std::to_string(*c.case_index) + " --level exact");
  EXPECT_EQ(c.expected, spec::resolved_step_rounded(c.input));
  EXPECT_EQ(c.actual, strict_intersect_step(c.input));
  // The counterexample is attached to its family, whose status is failed.
  std::size_t with_counterexample = 0;
  for (const FamilyResult& f : v.families)
    if (f.has_counterexample) {
      ++with_counterexample;
      EXPECT_EQ(properties::name(f.family), c.family);
      EXPECT_EQ(f.status, FamilyStatus::failed);
    }
  EXPECT_EQ(with_counterexample, 1u);
}

// The tangent-after-step family's circles become tangent in w_1, so its tangency is decided at the second step:
// its cases are chained two steps even when one is asked for (the default), and a step that is wrong only there
// is caught at the default budget, in that family.
TEST(conform, chains_the_tangent_after_step_family_to_the_step_that_decides_its_tangency) {
  StaleContacts stale;
  Options defaults;  // 1000 cases, one step, level exact, resolved profile
  defaults.seed = 5;
  const Verdict v = check(stale, defaults);
  ASSERT_EQ(v.outcome, Outcome::does_not_conform) << describe(v);
  const Counterexample& c = *v.counterexample;
  EXPECT_EQ(c.family, "tangent-after-step");
  EXPECT_EQ(c.step, 2u);
  EXPECT_EQ(c.steps, 2u);
  EXPECT_TRUE(c.difference.decision.starts_with("the intersect test (3) (docs/math.md#3-intersect--specintersect): circle"))
      << c.difference.decision;
  EXPECT_TRUE(c.difference.decision.ends_with("but kept its own velocity")) << c.difference.decision;
  EXPECT_NE(c.input, c.shrink_path.back());  // the world asked is the candidate's own first answer
  // Its first steps are right: the cases of every other family chained one step pass (big-chains, chained three
  // steps, catches it too).
  const auto families = properties::families(Profile::resolved);
  const std::uint64_t F = families.size();
  Options one_case = defaults;
  for (std::uint64_t k = 0; k < 10 * F; ++k) {
    if (properties::steps_to_decide(families[k % F]) > 1) continue;
    one_case.only_case = k;
    const Verdict one = check(stale, one_case);
    EXPECT_EQ(one.outcome, Outcome::conforms) << describe(one);
  }
}

TEST(conform, shards_take_whole_rounds_of_every_family_without_overlap) {
  // Cases come in rounds of one per family; shard i/n takes the rounds q with q mod n = i. With the 26
  // families of the resolved profile, 110 cases are rounds 0 … 3 (26 each) and 6 cases of round 4: shard
  // 0/2 asks rounds 0, 2 and the partial 4, shard 1/2 rounds 1 and 3.
  ASSERT_EQ(properties::families(Profile::resolved).size(), 26u);
  std::uint64_t asked = 0;
  FunctionCandidate counting([&](const Circles& w) {
    ++asked;
    return testing::right_step(w);
  });
  const Verdict first_verdict = check(counting, Options{{0}, 110, 3, 1, 0, 2, {}});
  const std::uint64_t first = asked;
  const Verdict second_verdict = check(counting, Options{{0}, 110, 3, 1, 1, 2, {}});
  EXPECT_EQ(first_verdict.cases + second_verdict.cases, 110u);
  // One request per case, a second for each case of tangent-after-step (family 11, chained two steps) and nine
  // more for each of big-chains (family 25, chained ten): 2 and 2 in shard 0, 2 and 2 in shard 1.
  EXPECT_EQ(first, 58u + 2 + 2 * 9);
  EXPECT_EQ(asked, 110u + 4 + 4 * 9);
  // Each shard saw every family: two or three cases of each in shard 0 (the partial round's first 6 families).
  for (const FamilyResult& f : first_verdict.families)
    EXPECT_EQ(f.checked, f.family < properties::Family::tie_p_vx ? 3u : 2u) << properties::name(f.family);
}

TEST(conform, refuses_a_run_too_short_to_reach_every_family) {
  EngineCandidate engine_candidate(engine("double"), 1);
  const Verdict short_run = check(engine_candidate, Options{{0}, 10, 3, 1, 0, 1, {}});
  EXPECT_EQ(short_run.outcome, Outcome::cannot_check);
  EXPECT_EQ(short_run.error,
            "no case of the family mutual-contacts was checked: each round of 26 cases draws every family of the resolved "
            "profile once, and this run checked 10; raise --cases to at least 26");
  const Verdict sharded = check(engine_candidate, Options{{0}, 28, 3, 1, 1, 2, {}});
  EXPECT_EQ(sharded.outcome, Outcome::cannot_check);
  EXPECT_EQ(sharded.error,
            "no case of the family tangency was checked: each round of 26 cases draws every family of the resolved "
            "profile once, and this run (shard 1/2) checked 2; raise --cases to at least 52");
  // Replaying one case is not a run over the families; nor need --cases reach it.
  const Verdict one = check(engine_candidate, Options{{0}, 1000, 3, 1, 0, 1, 1500});
  EXPECT_EQ(one.outcome, Outcome::conforms) << describe(one);
  EXPECT_EQ(one.cases, 1u);
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
  Options options{{0}, 1500, 5, 3, 0, 1, {}};
  options.profile = Profile::literal;
  const Verdict v = check(literal, options);
  EXPECT_EQ(v.outcome, Outcome::conforms) << describe(v);
  EXPECT_EQ(outside, 0u);
  EXPECT_GT(with_contacts, asked / 3);  // not only worlds where nothing meets
  EXPECT_EQ(v.families.size(), properties::families(Profile::literal).size());
  EngineCandidate double_engine(engine("double"), 1);
  EXPECT_EQ(check(double_engine, options).outcome, Outcome::conforms);
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
  Options options{{0}, 1000, 5, 1, 0, 1, {}};
  options.profile = Profile::literal;
  const Verdict v = check(greatest, options);
  ASSERT_EQ(v.outcome, Outcome::does_not_conform) << describe(v);
  EXPECT_TRUE(v.counterexample->difference.decision.starts_with("the least-contact rule e (8)"));
  EXPECT_TRUE(v.counterexample->replay.ends_with(" --profile literal")) << v.counterexample->replay;
}

// ── Counterexamples as files: --save and --svg ─────────────────────────────────────────────────────────

std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir, const std::string& extension) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(dir))
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == extension) files.push_back(entry.path());
  return files;
}

TEST(conform, saves_a_counterexample_and_replays_it_first_on_every_run) {
  const TempDir dir;
  const std::filesystem::path corpus = dir.path / "corpus";  // --save makes it
  FunctionCandidate wrong(strict_intersect_step);
  Options options{{0}, 1000, 7, 1, 0, 1, {}};
  options.save = corpus;
  const Verdict first = check(wrong, options);
  ASSERT_EQ(first.outcome, Outcome::does_not_conform) << describe(first);
  const auto saved = files_in(corpus, ".json");
  ASSERT_EQ(saved.size(), 1u) << describe(first);
  EXPECT_EQ(first.counterexample->saved, saved[0]);

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
  const Verdict second = check(wrong, options);
  ASSERT_EQ(second.outcome, Outcome::does_not_conform) << describe(second);
  EXPECT_EQ(second.counterexample->stored, saved[0]);
  EXPECT_EQ(second.counterexample->found_case, c.case_index);
  EXPECT_EQ(second.counterexample->found_seed, 7u);
  EXPECT_EQ(second.counterexample->family, c.family);
  EXPECT_EQ(second.counterexample->replay, "circles conform --save " + corpus.string() + " --cases 0 --level exact");
  EXPECT_EQ(files_in(corpus, ".json").size(), 1u);  // not saved twice

  // A right step passes it, and says so.
  FunctionCandidate right([](const Circles& w) { return testing::right_step(w); });
  const Verdict third = check(right, options);
  EXPECT_EQ(third.outcome, Outcome::conforms) << describe(third);
  EXPECT_EQ(third.replayed, 1u);
}

TEST(conform, refuses_a_save_directory_it_cannot_use_before_any_case) {
  const TempDir dir;
  dir.write("file", "x");
  std::uint64_t asked = 0;
  FunctionCandidate counting([&](const Circles& w) {
    ++asked;
    return w;
  });
  Options options{{0}, 100, 1, 1, 0, 1, {}};
  options.save = dir.path / "file";
  const auto e = thrown<ConformError>([&] { check(counting, options); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "--save: cannot use the directory " + (dir.path / "file").string() + ": " +
                                        std::make_error_code(std::errc::not_a_directory).message());
  EXPECT_EQ(asked, 0u);
}

// A program that crashes right after its first wrong answer, before answering the rest of its batch: the
// strict (3) step, with answer_all stopping at the first answer that differs from the resolved step. Conform
// judges the answers it has before the fault, so the verdict is the counterexample, exit 1, as a case-by-case
// run gives; reporting the crash, exit 2, would hide a wrong answer behind a fault it provoked.
class CrashesAfterItsFirstWrongAnswer : public FunctionCandidate {
 public:
  CrashesAfterItsFirstWrongAnswer() : FunctionCandidate(strict_intersect_step) {}
  Answers answer_all(std::span<const Circles> worlds, std::uint64_t first_id,
                     std::span<const Spelling> spellings = {}) override {
    Answers read = Candidate::answer_all(worlds, first_id, spellings);
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
  const Verdict v = check(candidate, Options{});
  EXPECT_EQ(v.outcome, Outcome::does_not_conform) << describe(v);
  EXPECT_GE(candidate.crashes, 1);  // the fault happened, inside a batch
}

// tests/faulty_candidate.cpp MODE, through the program and conform's defaults at seed 1 (a batch of requests at a
// time, as `circles conform --exec` asks).
Verdict check_faulty(const std::string& mode) {
  ProcessCandidate candidate(std::string(CIRCLES_FAULTY_CANDIDATE) + " " + mode, 10s);
  Options options;
  options.seed = 1;
  return check(candidate, options);
}

// Python's json writes NaN, Infinity and -Infinity for floats that are not finite: each is read as the value it
// means and judged like any number, a counterexample (exit 1) shrunk to the two circles that make the
// candidate write it, naming the field, the expected value and the token received.
TEST(conform, reads_nan_and_infinity_in_an_answer_as_values_and_reports_a_counterexample) {
  for (const std::string token : {"NaN", "Infinity", "-Infinity"}) {
    const Verdict v = check_faulty(token);
    ASSERT_EQ(v.outcome, Outcome::does_not_conform) << token << ": " << describe(v);
    const Counterexample& c = *v.counterexample;
    EXPECT_EQ(c.input.size(), 2u) << describe(v);
    EXPECT_EQ(c.difference.circle, 0u);
    EXPECT_EQ(c.difference.field, spec::Field::px);
    EXPECT_EQ(c.difference.expected, c.expected[0][0]);
    EXPECT_TRUE(std::isfinite(c.difference.expected));
    EXPECT_EQ(std::isnan(c.difference.actual), token == "NaN");
    if (token != "NaN") {
      EXPECT_EQ(c.difference.actual, token == "Infinity" ? INFINITY : -INFINITY);
    }
  }
}

// Shrinking and simplifying keep the kind of the wrong value: a step that answers NaN for circle 0's px on a
// world of two or more circles whose circle 0 has px != 0, and one ulp too far on every other world, is shown
// with its NaN on two circles, not slipped to the simpler one-circle world or px = 0 that fails with a number.
TEST(conform, keeps_a_nan_answer_through_shrinking_and_simplifying) {
  FunctionCandidate nan_on_pairs([](const Circles& w) {
    Circles out = spec::resolved_step_rounded(w);
    if (!out.empty()) out[0][0] = w.size() >= 2 && w[0][0] != 0 ? NAN : std::nextafter(out[0][0], INFINITY);
    return out;
  });
  Options options;
  options.seed = 1;
  const Verdict v = check(nan_on_pairs, options);
  ASSERT_EQ(v.outcome, Outcome::does_not_conform) << describe(v);
  const Counterexample& c = *v.counterexample;
  EXPECT_TRUE(std::isnan(c.difference.actual)) << describe(v) << ", got " << c.difference.actual;
  EXPECT_TRUE(std::isnan(c.actual[0][0]));
  EXPECT_EQ(c.input.size(), 2u);
  EXPECT_NE(c.input[0][0], 0.0);
  EXPECT_GE(c.shrinks(), 1u);
  for (const Circles& w : c.shrink_path) EXPECT_TRUE(w.size() >= 2 && w[0][0] != 0) << "a world on the path has no NaN";
}

// A program that answers one request wrong and then breaks (a line that is not JSON, or an exit) on the next,
// inside a batch: the answers to the rest of the batch are still in its pipe when conform reads the fault. The
// program is started afresh before the next request, so shrinking gets the answers to its own requests, never
// "answered request 13 with id 6", and the verdict is the shrunk counterexample, exit 1.
TEST(conform, never_takes_an_answer_for_another_request_after_a_fault_in_a_batch) {
  for (const std::string mode : {"wrong-then-malformed", "wrong-then-crash"}) {
    const Verdict v = check_faulty(mode);
    ASSERT_EQ(v.outcome, Outcome::does_not_conform) << mode << ": " << describe(v);
    const Counterexample& c = *v.counterexample;
    EXPECT_EQ(c.input.size(), 2u) << describe(v);
    EXPECT_GE(c.shrinks(), 1u);
    EXPECT_EQ(c.difference.circle, 0u);
    EXPECT_EQ(c.difference.actual, std::nextafter(c.difference.expected, INFINITY));  // the one mistake
  }
}

// Unknown keys in an answer are ignored, whatever their values (NaN and a "}" in a string included), for
// forward compatibility: an exact candidate that adds a timing to each answer conforms.
TEST(conform, ignores_unknown_keys_in_an_answer) {
  const Verdict v = check_faulty("extra-key");
  EXPECT_EQ(v.outcome, Outcome::conforms) << describe(v);
  EXPECT_EQ(v.cases, 1000u);
}

}  // namespace
}  // namespace circles::conform
