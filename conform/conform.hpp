// circles::conform: checks a candidate (conform/candidate.hpp) against the spec on generated worlds, and returns
// its verdict as data (Verdict): conforms, does not conform (with the first counterexample, shrunk to a minimal
// world, and its shrink path) or cannot check (and why), the cases per family, the replay line and the timing.
// `circles conform` prints it (cli/conform_report.hpp), draws its picture and writes it as a report for CI.
//
// Cases come in rounds of one case per family of the profile (properties/boundaries.hpp): case c is drawn from
// family c mod F, F the number of families, with its own random stream split in order from the seed, so case c
// of a seed is the same world on every run, shard and machine. A shard takes whole rounds, so each shard sees
// every family. A case chains `steps` steps, or as many as its family needs to decide its boundary if more
// (properties::steps_to_decide: 2 for tangent-after-step): the candidate is fed its own outputs, and each
// answer is checked against the expected answer for the candidate's input (properties::expected_step). A world
// whose expected answer leaves the double range cannot be asked (the protocol carries finite doubles) and is
// skipped, and counted; in the literal profile a chain also stops at a world outside the literal domain.
// The candidate is asked about up to 64 cases at a time (Candidate::answer_all), in the order and with the ids a
// case-by-case run would use, so that a candidate program gets several requests per round trip; the verdict,
// the counterexample and its shrinking are those of the case-by-case run.
// With Options::keep_going the run goes on past a counterexample: a family stops being asked at its first failing
// case, the others run to their share of the cases, and each failing family's first case is shrunk, in case
// order; the verdict is the same for the same seed. Options::skip leaves families out without moving any case.
#pragma once

#include "conform/candidate.hpp"
#include "formats/protocol.hpp"
#include "properties/boundaries.hpp"
#include "properties/conformance.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace circles::conform {

using spec::Circles;
using properties::compare;
using properties::Difference;
using properties::Level;
using properties::parse_level;
using properties::Profile;

struct Verdict;

// The most circles of a big world in a budget run, unless told otherwise (--max-circles): past the thresholds
// at which programs commonly start threads (10^4 to 3·10^4), up to where a fast program gets in a minute.
inline constexpr std::size_t kBudgetMaxCircles = 1'000'000;
// The seconds of a run with no fixed schedule (`circles conform` without --cases, --shard or --case).
inline constexpr double kDefaultBudget = 60;

struct Options {
  Level level;
  std::uint64_t cases = 1000;
  std::uint64_t seed = 1;
  std::uint64_t steps = 1;  // steps chained per case (at least properties::steps_to_decide of its family)
  std::uint64_t shard = 0, shards = 1;  // this run checks the rounds q with q mod shards == shard
  std::optional<std::uint64_t> only_case;  // replay one case
  Profile profile = Profile::resolved;
  // The corpus: every *.json file here is replayed first, and a new counterexample is saved here. Empty:
  // none. Created if missing.
  std::filesystem::path save{};
  // After shrinking, simplify each number of the counterexample while it still fails: toward 0, integers and
  // short binary fractions (docs/conform.md, "Counterexamples a person can read"). Off only to measure it.
  bool simplify = true;
  // Go on after a counterexample (--keep-going): every family is checked up to its share of the cases, and one
  // counterexample is shrunk per failing family (FamilyResult::counterexample). A family stops being asked at
  // its first failing case. Off: the run stops at its first counterexample.
  bool keep_going = false;
  // Families not checked (--families, --skip-families): their cases are neither drawn nor asked, their stored
  // counterexamples not replayed, and their status is `skipped`. The other cases keep their worlds.
  std::vector<properties::Family> skip{};
  // The most circles of a big family's world (--max-circles; properties::gen::big_world): the default crosses
  // every power of two up to 4096; a fast program can be taken to 10^5 or 10^6 circles.
  std::size_t max_circles = properties::kDefaultMaxCircles;
  // The time budget in seconds (--budget; docs/conform.md, "The time budget"): rounds of the small families,
  // then big worlds on a ladder of sizes up to max_circles, as far as the candidate's measured speed allows.
  // None: the fixed schedule of `cases` rounds.
  std::optional<double> budget{};
  // With only_case: the case's world is the ladder's world of this many circles (--circles), as a budget run's
  // replay line asks.
  std::optional<std::size_t> circles{};
  // Copies of the candidate asked at once (--jobs), each its own cases; the verdict is the same for every count.
  unsigned jobs = 1;
  // Called after each batch of generated cases with the verdict so far (its cases, its families' statuses), for
  // a progress line; none by default.
  std::function<void(const Verdict&)> progress{};
};

// The family of `profile` of that name; nothing for another text.
std::optional<properties::Family> parse_family(std::string_view name, Profile profile);

// "A,B,..." → those families of `profile`, for --families and --skip-families. Throws std::invalid_argument
// naming `option`, the unknown name and the known families.
std::vector<properties::Family> parse_families(std::string_view option, std::string_view list, Profile profile);

// "i/n" → shard i of n (0 ≤ i < n). Throws std::invalid_argument with a message for --shard.
std::pair<std::uint64_t, std::uint64_t> parse_shard(std::string_view text);

// A run that cannot give a verdict, found before any case runs: a --save directory that cannot be used. what()
// says which and what to do; `circles conform` exits 2. (Faults found while checking are a Verdict whose
// outcome is cannot_check.)
class ConformError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The verdicts, as the report names them: "conforms", "does not conform", "cannot check" (exit 0, 1, 2), and
// "interrupted" (exit 128 + the signal): a signal ended the check (conform/interrupt.hpp) before its last case.
enum class Outcome { conforms, does_not_conform, cannot_check, interrupted };
const char* name(Outcome outcome);
// Whether the run judged the candidate: conforms or does not conform. Expectations and the families' table
// apply to such a verdict only.
bool judged(Outcome outcome);
// The outcome of that name; nothing for another text.
std::optional<Outcome> parse_outcome(std::string_view text);

// How one family fared: passed or failed; against an expectation file (conform/expect.hpp), a listed family
// that failed is an expected_failure and one that passed an unexpected_pass; a family left out by
// Options::skip is skipped; a run that stops at its first counterexample marks the families it did not reach
// `not_reached`.
enum class FamilyStatus { passed, failed, expected_failure, unexpected_pass, skipped, not_reached };
// "passed", "failed", "expected failure", "unexpected pass", "skipped", "not reached"
const char* name(FamilyStatus status);
// The status of that name; nothing for another text.
std::optional<FamilyStatus> parse_family_status(std::string_view text);

// The first answer that differs, with how it was found and how to see it again.
struct Counterexample {
  std::string family;                          // its family, "" for a stored file without one
  std::optional<std::uint64_t> case_index;     // the generated case; nothing for a stored file
  std::filesystem::path stored;                // the corpus file it was replayed from, if it was
  std::optional<std::uint64_t> found_seed, found_case;  // a stored file's record of where it was found
  std::uint64_t step = 1, steps = 1;           // the failing step of the chain (1-based) and the chain's length
  Circles input, expected, actual;             // the world asked at that step, and the two answers
  Difference difference;
  // Not a wrong answer but none: how the program broke instead of answering ("crashed or exited", "hung", "wrote
  // a malformed answer"; conform::Fault), `actual` empty and difference.decision the whole message. "" for a
  // wrong answer.
  std::string fault;
  // Shrinking: the world drawn, then each simpler w_0 that still failed, in order (the last the one reported):
  // first fewer circles (RapidCheck's shrinks), then numbers simplified one at a time.
  std::vector<Circles> shrink_path;
  std::size_t circles_before = 0;              // circles of the world drawn
  std::uint64_t tries = 0;                     // simpler worlds asked while shrinking, kept or not
  // The command that replays it (conform/replay.hpp): "circles conform --exec 'python3 step.py' --seed 3 --case 3
  // --level exact".
  std::string replay;
  std::filesystem::path saved;                 // where --save stored it, if it did
  std::string not_saved;                       // why it could not be stored, if it could not
  std::uint64_t shrinks() const { return shrink_path.empty() ? 0 : shrink_path.size() - 1; }
};

// Whether counterexample a was found before b: the lower case first, and a stored one (no case: the corpus is
// replayed before any case) before every generated one.
bool found_before(const Counterexample& a, const Counterexample& b);

// One family's record: its cases drawn and checked (a drawn case is skipped when its first world has no
// expected answer), its status, and its counterexample, if it failed.
struct FamilyResult {
  properties::Family family;
  std::uint64_t drawn = 0, checked = 0;
  FamilyStatus status = FamilyStatus::passed;
  bool has_counterexample = false;  // Verdict::counterexample is this family's
  std::optional<Counterexample> counterexample;  // this family's shrunk counterexample, if it failed
};

struct Verdict {
  Outcome outcome = Outcome::conforms;
  std::string candidate;  // "the program `python3 step.py`"
  Options options;        // what was checked: seed, shard, level, profile, steps, …
  std::uint64_t cases = 0;       // generated cases run (up to and including a failing one)
  std::uint64_t skipped = 0;     // of those, cases whose w_0 has no expected answer
  std::uint64_t cut_short = 0;   // chains that ended early at a world with no expected answer
  std::uint64_t replayed = 0, not_replayed = 0;  // corpus files replayed, and those outside the profile's domain
  std::vector<FamilyResult> families;  // every family of the profile, in order
  // The run's first counterexample (the lowest case; a stored one first), set when a family failed. With
  // --keep-going each failing family has its own in FamilyResult::counterexample.
  std::optional<Counterexample> counterexample;
  std::string error;                             // why, when the outcome is cannot_check or interrupted
  int signal = 0;                                // the signal, when the outcome is interrupted
  // When the outcome is interrupted, the command that checks the same cases again (conform/replay.hpp).
  std::string rerun{};
  std::chrono::duration<double> elapsed{};       // wall time of the check
  std::size_t largest_world = 0;                 // the most circles of a big family's world checked
  std::size_t cut_world = 0;  // the circles of the worlds of a ladder stage cut at the budget's end, 0: none was
  // The shards a verdict merged from their reports combines (conform/merge.hpp), in order; empty for a run's
  // own verdict, whose shard is options.shard.
  std::vector<std::uint64_t> merged_shards{};
  std::uint64_t checked() const { return cases - skipped; }
};

// conform's rule for the outcome of a verdict that could check, from the rest of it: does not conform when it has
// a counterexample, or a family failed or passed unexpectedly; else conforms. A run (check), a run judged against
// an expectation file (conform/expect.hpp) and the shards of a run merged (conform/merge.hpp) each decide by it.
Outcome checked_outcome(const Verdict& verdict);

// Sets FamilyResult::has_counterexample on the family Verdict::counterexample names, and on no other.
void mark_counterexample_family(Verdict& verdict);

// The worlds of cases 0 … cases − 1 of `seed` in `profile`, each as conform draws it (before any shrinking),
// whatever the shard: for tools that hand out conform's worlds (cli/vectors_command.hpp).
std::vector<Circles> case_worlds(std::uint64_t seed, std::uint64_t cases, Profile profile = Profile::resolved,
                                 std::size_t max_circles = properties::kDefaultMaxCircles);

// The verdict cannot_check, for `error`, of a candidate not checked at all (a program that cannot start): no
// case run, every family not reached.
Verdict unchecked(std::string candidate, const Options& options, std::string error);

// Checks `candidate`. A candidate that breaks (BrokenCandidate), a corpus file that cannot be replayed and a
// family of which no case was checked give the verdict cannot_check, with the reason in `error`. A signal
// recorded by interrupt() (conform/interrupt.hpp) stops the check at its next request or case with the verdict
// interrupted: the cases counted are those checked, the families not reached are marked so, and `rerun` says
// how to check the same cases again. Throws
// ConformError only for a --save directory that cannot be used, before any case runs.
Verdict check(Candidate& candidate, const Options& options);

}  // namespace circles::conform
