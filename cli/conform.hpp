// `circles conform`: checks a candidate (cli/candidate.hpp) against the spec on generated worlds, and reports
// the first counterexample, shrunk to a minimal world, with a picture (cli/counterexample_svg.hpp) and, on
// request, as a data file that later runs replay first (cli/corpus.hpp).
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
#pragma once

#include "cli/candidate.hpp"
#include "cli/protocol.hpp"
#include "properties/conformance.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace circles::cli {

using properties::compare;
using properties::Difference;
using properties::Level;
using properties::parse_level;
using properties::Profile;

struct ConformOptions {
  Level level;
  std::uint64_t cases = 1000;
  std::uint64_t seed = 1;
  std::uint64_t steps = 1;  // steps chained per case (at least properties::steps_to_decide of its family)
  std::uint64_t shard = 0, shards = 1;  // this run checks the rounds q with q mod shards == shard
  std::optional<std::uint64_t> only_case;  // replay one case
  Profile profile = Profile::resolved;
  // The corpus: every *.json file here is replayed first, and a new counterexample is saved here (with its
  // picture beside it). Empty: none. Created if missing.
  std::filesystem::path save{};
  // Where to draw the counterexample's picture; empty: beside the saved file if `save` is set, else nowhere
  // (a picture is drawn only when asked for, so that runs in a loop leave nothing behind).
  std::filesystem::path svg{};
};

// "i/n" → shard i of n (0 ≤ i < n). Throws std::invalid_argument with a message for --shard.
std::pair<std::uint64_t, std::uint64_t> parse_shard(std::string_view text);

// A run that cannot give a verdict: a corpus file that cannot be read, a --save or --svg path that cannot be
// written, or a family of which no case was checked (too few cases for a round of every family, or every one
// of its worlds skipped). what() says which and what to do; `circles conform` exits 2.
class ConformError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The worlds of cases 0 … cases − 1 of `seed` in `profile`, each as conform draws it (before any shrinking),
// whatever the shard: for tools that hand out conform's worlds (cli/vectors.hpp).
std::vector<Circles> case_worlds(std::uint64_t seed, std::uint64_t cases, Profile profile = Profile::resolved);

// Runs the check, printing a summary with the number of cases checked per family (and the counterexample, if
// any) on `out`. Returns 0 when every case conforms, 1 for a counterexample. Throws BrokenCandidate and
// ConformError.
int conform(Candidate& candidate, const ConformOptions& options, std::ostream& out);

}  // namespace circles::cli
