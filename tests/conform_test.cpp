// `circles conform` in process: the comparison and its levels, the verdicts on right and wrong candidates, the
// shrunk counterexample, and candidate programs that crash, hang, or answer out of protocol.
#include "cli/candidate.hpp"
#include "cli/conform.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>

#include <signal.h>
#include <unistd.h>

#include "impl/rounding.hpp"
#include "spec/oracle.hpp"
#include "tests/thrown.hpp"

namespace circles::cli {
namespace {

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

// The oracle with (3) decided by < instead of <=: wrong exactly at tangency.
Circles strict_intersect_step(const Circles& w) {
  Circles out = w;
  for (std::size_t k = 0; k < w.size(); ++k) {
    std::size_t least = k;
    for (std::size_t j = 0; j < w.size(); ++j) {
      if (j == k) continue;
      const spec::Q dx = spec::exact(w[j][0]) - spec::exact(w[k][0]), dy = spec::exact(w[j][1]) - spec::exact(w[k][1]);
      const spec::Q s = spec::exact(w[k][4]) + spec::exact(w[j][4]);
      if (s * s > dx * dx + dy * dy && (least == k || std::make_pair(w[j], j) < std::make_pair(w[least], least)))
        least = j;
    }
    out[k][2] = w[least][2];
    out[k][3] = w[least][3];
    out[k][0] = impl::advance_rounded(w[k][0], out[k][2]);
    out[k][1] = impl::advance_rounded(w[k][1], out[k][3]);
  }
  return out;
}

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

TEST(conform, shards_split_the_cases_without_overlap) {
  // Each shard sees every case index once between them: a candidate that fails only case 5 fails in shard 1/2.
  int status = -1;
  std::uint64_t asked = 0;
  FunctionCandidate counting([&](const Circles& w) {
    ++asked;
    return spec::resolved_step_rounded(w);
  });
  run(counting, ConformOptions{{0}, 100, 3, 1, 0, 2, {}}, status);
  const std::uint64_t first = asked;
  run(counting, ConformOptions{{0}, 100, 3, 1, 1, 2, {}}, status);
  EXPECT_EQ(first, 50u);
  EXPECT_EQ(asked, 100u);
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
