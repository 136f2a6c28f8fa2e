// Candidates under test (conform/candidate.hpp): our engines in process, and programs over the step protocol,
// sent batches of requests, refused with what they did when they break it, and never left running.
#include "conform/candidate.hpp"

#include "conform/interrupt.hpp"
#include "engines/registry.hpp"
#include "properties/boundaries.hpp"
#include "spec/oracle.hpp"
#include "tests/repository.hpp"
#include "tests/step_worlds.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
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

// Whether process `pid` runs: not when there is no such process, nor when it is a zombie waiting for its new
// parent (init or a subreaper such as ctest) to reap it, state Z in /proc/PID/stat ("pid (comm) S ...").
bool runs(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto paren = line.rfind(')');
  return paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] != 'Z';
}

// Whether the process whose id a program wrote to `file` has ended, given a moment for a kill to land.
bool ended(const std::filesystem::path& file) {
  pid_t pid = 0;
  for (int tries = 0; tries < 200 && !(std::ifstream(file) >> pid); ++tries) std::this_thread::sleep_for(10ms);
  std::filesystem::remove(file);
  if (pid <= 0) return false;
  for (int tries = 0; tries < 100 && runs(pid); ++tries) std::this_thread::sleep_for(10ms);
  return !runs(pid);
}

std::filesystem::path pid_file(const char* name) {
  return std::filesystem::temp_directory_path() /
         ("circles-conform-" + std::to_string(::getpid()) + "-" + name + ".pid");
}

TEST(candidate, leaves_no_process_behind_even_when_the_program_starts_others) {
  const std::filesystem::path file = pid_file("background");
  {
    // The shell starts sleep in the background (same process group) and then hangs itself.
    ProcessCandidate candidate("sleep 60 & echo $! > " + file.string() + "; sleep 60", 100ms);
    EXPECT_TRUE(thrown<BrokenCandidate>([&] { candidate.answer({}, 1); }));
  }
  EXPECT_TRUE(ended(file)) << "the background sleep outlived the check";
}

// interrupt(), as a signal handler calls it, kills every running program's group at once, before the check
// gets back to its candidate; the candidate then answers nothing more, with Interrupted, not BrokenCandidate
// (the program did nothing wrong). The first signal recorded is the one reported.
TEST(candidate, an_interruption_kills_the_programs_at_once_and_ends_their_requests) {
  const std::filesystem::path first = pid_file("first"), second = pid_file("second");
  ProcessCandidate a("sleep 60 & echo $! > " + first.string() + "; exec cat", 10s);
  ProcessCandidate b("sleep 60 & echo $! > " + second.string() + "; exec cat", 10s);
  EXPECT_EQ(a.answer({{0, 0, 1, 0, 1}}, 1), (Circles{{0, 0, 1, 0, 1}}));  // cat echoes: both are running
  EXPECT_EQ(b.answer({}, 1), Circles{});
  interrupt(SIGTERM);
  interrupt(SIGINT);
  EXPECT_EQ(interruption(), SIGTERM);
  EXPECT_TRUE(ended(first)) << "interrupt() left a program's group running";
  EXPECT_TRUE(ended(second)) << "interrupt() left a program's group running";
  const auto e = thrown<Interrupted>([&] { a.answer({}, 2); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->signal(), SIGTERM);
  EXPECT_EQ(std::string(e->what()), "interrupted by SIGTERM");
  // No program starts once the check is ending.
  EXPECT_TRUE(thrown<Interrupted>([] { ProcessCandidate("exec cat", 10s); }));
  clear_interruption();
  EXPECT_EQ(interruption(), 0);
}

// An answer is refused as soon as it is longer than any answer to its world could be
// (ProcessCandidate::longest_answer), so that what conform holds of a line is bounded by the world, not by what
// a program writes: here 20 MB of spaces, of which conform reads about the first 71 KB.
TEST(candidate, refuses_an_answer_longer_than_its_world_could_need_as_soon_as_it_passes_the_bound) {
  // 64 KiB, and 5,600 bytes a circle: five numbers of up to 1,100 bytes, and 100 of brackets, commas, spaces.
  EXPECT_EQ(ProcessCandidate::longest_answer(1), 65536u + 5600u);
  EXPECT_EQ(ProcessCandidate::longest_answer(1000), 65536u + 5'600'000u);
  EXPECT_EQ(ProcessCandidate::longest_answer(std::size_t(-1)), std::size_t(-1));  // no overflow
  const std::string command = "read x; printf '{\"id\": 4, \"circles\": ['; head -c 20000000 /dev/zero | tr '\\0' ' '";
  ProcessCandidate candidate(command, 10s);
  const auto e = thrown<BrokenCandidate>([&] { candidate.answer({{0, 0, 1, 0, 1}}, 4); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "the program `" + command +
                                        "` wrote a malformed answer to request 4: the line is longer than 71136 "
                                        "bytes, more than any answer to its world needs (docs/protocol.md, Limits)");
}

// docs/protocol.md's Limits, as conform holds them: the longest request line of n circles (every number and the
// id at their longest; a radius has no sign) is 126n + 39 bytes, and the longest answer read is longest_answer(n).
TEST(candidate, protocol_md_states_the_longest_request_and_answer_conform_sends_and_reads) {
  const std::string limits = circles::testing::text_of("docs/protocol.md");
  for (const std::size_t n : {std::size_t{8}, properties::kDefaultMaxCircles}) {
    const Circles widest(n, {-0x1.fffffffffffffp+1023, -0x1.fffffffffffffp+1023, -0x1.fffffffffffffp+1023,
                             -0x1.fffffffffffffp+1023, 0x1.ffffffffffffep+1023});
    EXPECT_EQ(format_line(kId, std::uint64_t(-1), widest).size(), 126 * n + 39);
  }
  for (const char* stated : {"126n + 39 bytes", "1,047 for 8 circles", "516,261 for 4,097", "4,097 by default",
                             "65,536 + 5,600n bytes", "at most 1,077 characters"})
    EXPECT_NE(limits.find(stated), std::string::npos) << "docs/protocol.md does not say " << stated;
  EXPECT_EQ(properties::kDefaultMaxCircles, 4097u);
  EXPECT_EQ(126 * 4097 + 39, 516'261);
  EXPECT_EQ(ProcessCandidate::longest_answer(0), 65'536u);
  EXPECT_EQ(ProcessCandidate::longest_answer(1) - ProcessCandidate::longest_answer(0), 5'600u);
}

// The bound leaves room for every number spelled as long as a double's exact decimal value can be: 200 circles
// whose every number is a subnormal written out in full, 1,077 bytes or so each, are read, and read right.
TEST(candidate, reads_an_answer_that_spells_every_number_in_full) {
  const double largest_subnormal = 0x0.fffffffffffffp-1022, smallest = 0x0.0000000000001p-1022;
  const Circles world(200, {-largest_subnormal, largest_subnormal, -0x0.aaaaaaaaaaaabp-1022, 0x0.5555555555555p-1022,
                            smallest});
  // Each number's exact value, written without an exponent by Python's Decimal.
  const std::filesystem::path script = pid_file("spell").replace_extension("py");
  std::ofstream(script) << "import sys, json, decimal\n"
                           "for line in sys.stdin:\n"
                           "    r = json.loads(line)\n"
                           "    spell = lambda x: format(decimal.Decimal(x), 'f')\n"
                           "    circles = ','.join('[' + ','.join(map(spell, c)) + ']' for c in r['circles'])\n"
                           "    print('{\"id\": %d, \"circles\": [%s]}' % (r['id'], circles), flush=True)\n";
  ProcessCandidate candidate("exec python3 " + script.string(), 10s);
  EXPECT_EQ(candidate.answer(world, 1), world);
  candidate.finish();
  std::filesystem::remove(script);
}

}  // namespace
}  // namespace circles::conform
