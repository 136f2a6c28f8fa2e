// Candidates under test (conform/candidate.hpp): our engines in process, and programs over the step protocol,
// sent batches of requests, refused with what they did when they break it, and never left running.
#include "conform/candidate.hpp"

#include "engines/registry.hpp"
#include "spec/oracle.hpp"
#include "tests/step_worlds.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

namespace circles::conform {
namespace {

using circles::testing::kOverflowsAtStep4;
using circles::testing::kTouching;
using circles::testing::thrown;
using namespace std::chrono_literals;

// The name messages give a candidate, and the option that selects it on the command line, quoted for sh.
TEST(candidate, names_itself_and_the_option_that_selects_it) {
  const EngineCandidate exact(engines::engine("exact"), 2);
  EXPECT_EQ(exact.name(), "the exact engine");
  EXPECT_EQ(exact.option(), "--engine exact");
  const ProcessCandidate plain("cat", 1s);
  EXPECT_EQ(plain.name(), "the program `cat`");
  EXPECT_EQ(plain.option(), "--exec cat");
  const ProcessCandidate quoted("exec cat # it's here", 1s);
  EXPECT_EQ(quoted.name(), "the program `exec cat # it's here`");
  EXPECT_EQ(quoted.option(), R"(--exec 'exec cat # it'\''s here')");
}

// An engine's answer with a position beyond the double range cannot be sent: the candidate is broken at that
// request, named with the step's own message.
TEST(candidate, an_engine_is_broken_by_an_answer_beyond_the_double_range) {
  EngineCandidate candidate(engines::engine("double"), 1);
  EXPECT_EQ(candidate.answer(kTouching, 1), spec::resolved_step_rounded(kTouching));
  const Circles w3 = circles::testing::oracle_worlds(kOverflowsAtStep4, 3).back();
  const auto e = thrown<BrokenCandidate>([&] { candidate.answer(w3, 6); });
  ASSERT_TRUE(e);
  EXPECT_STREQ(e->what(), "request 6: step 1, circle 1, field px: the position p + v/60 overflows to infinity");
}

// Before any answer, the deadline grows as an O(n²) step's time beyond kFirstCircles, by (n / 512)², not by
// whole multiples of 512: 4097 circles are 64.03… times 512², not 64 times.
TEST(deadlines, before_any_answer_grow_with_the_square_of_the_circles_beyond_512) {
  using std::chrono::milliseconds;
  const Deadlines ten(10s), short_one(300ms);
  EXPECT_EQ(ten.for_world(0), 10s);
  EXPECT_EQ(ten.for_world(512), 10s);
  EXPECT_EQ(ten.for_world(513), milliseconds(10039));  // 10000 · (513/512)² = 10039.10…
  EXPECT_EQ(ten.for_world(1024), 40s);
  EXPECT_EQ(ten.for_world(4097), milliseconds(640312));  // 10000 · 64.0312538…
  EXPECT_EQ(short_one.for_world(1024), 1200ms);
}

// After answers, from the largest world answered: kFactor times its time, times (n/m)² above it and n/m below,
// never less than the floor; the slowest answer to that world counts, and a larger world replaces it.
TEST(deadlines, after_answers_follow_the_programs_own_speed_with_a_factor_and_a_floor) {
  using std::chrono::milliseconds;
  Deadlines d(1s);
  d.answered(100, 0.25s);
  EXPECT_EQ(d.for_world(100), 5s);
  EXPECT_EQ(d.for_world(200), 20s);
  EXPECT_EQ(d.for_world(50), 2500ms);
  EXPECT_EQ(d.for_world(2), 1s);  // the floor
  d.answered(100, 0.1s);          // a faster answer to the same size: the slowest still counts
  EXPECT_EQ(d.for_world(100), 5s);
  d.answered(400, 0.1s);          // a larger world: its time is the measure now
  EXPECT_EQ(d.for_world(800), 8s);
  EXPECT_EQ(d.for_world(10), 1s);
  d.answered(0, 100s);            // an empty world tells nothing
  EXPECT_EQ(d.for_world(800), 8s);
  // The floor grows as the square root of the circles beyond 512: 4 times at 8192.
  d.answered(8192, 0.001s);
  EXPECT_EQ(d.for_world(8192), 4s);
}

// Programs that break the protocol: each is refused with what it did, and nothing of it outlives the check.
TEST(candidate, refuses_broken_programs_with_what_they_did) {
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
TEST(candidate, sends_a_program_several_requests_before_reading_their_answers) {
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
TEST(candidate, splits_requests_into_batches_a_program_echoing_them_answers_in_order) {
  std::vector<Circles> worlds;
  for (int k = 0; k < 2000; ++k) worlds.push_back(Circles(1 + k % 8, {k * 0.1, -k * 1e-300, 1.0 / (k + 1), 3.5, 1}));
  ProcessCandidate cat("exec cat", 10s);
  const std::vector<Circles> echoed = cat.answer_all(worlds, 1).all();
  EXPECT_EQ(echoed, worlds);
  EXPECT_EQ(cat.answer(worlds[5], 2001), worlds[5]);  // ids go on where the batches left them
  cat.finish();
}

TEST(candidate, leaves_no_process_behind_even_when_the_program_starts_others) {
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
}  // namespace circles::conform
