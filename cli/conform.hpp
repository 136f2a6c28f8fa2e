// `circles conform`: checks a candidate (cli/candidate.hpp) against the correctly rounded oracle step on
// generated worlds, and reports the first counterexample, shrunk to a minimal world.
//
// Each case is a world drawn from the property suite's generators (properties/generators.hpp) with its own
// random stream, split in order from the seed, so case i of a seed is the same world on every run, shard and
// machine. A case chains `steps` steps: the candidate is fed its own outputs, and each answer is checked
// against the oracle applied to the candidate's input. A world whose oracle step leaves the double range
// cannot be asked (the protocol carries finite doubles) and is skipped, and counted.
#pragma once

#include "cli/candidate.hpp"
#include "cli/protocol.hpp"

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace circles::cli {

// How close an answer must be. Decisions (velocities, and radii, which never change) must be exact at every
// level; positions must equal the nearest double (exact), or be within `ulps` units in the last place.
struct Level {
  std::uint64_t ulps = 0;  // 0: exact; 1: faithful
  std::string text() const;
};
// "exact", "faithful" (ulps:1) or "ulps:K". Throws std::invalid_argument with a message for --level.
Level parse_level(std::string_view text);

struct ConformOptions {
  Level level;
  std::uint64_t cases = 1000;
  std::uint64_t seed = 1;
  std::uint64_t steps = 1;  // steps chained per case
  std::uint64_t shard = 0, shards = 1;  // this run checks the cases c with c mod shards == shard
  std::optional<std::uint64_t> only_case;  // replay one case
};

// "i/n" → shard i of n (0 ≤ i < n). Throws std::invalid_argument with a message for --shard.
std::pair<std::uint64_t, std::uint64_t> parse_shard(std::string_view text);

// What differs in one answer.
struct Difference {
  std::size_t circle;
  int field;  // 0 px … 4 r
  double expected, actual;
  std::string decision;  // which decision differs, or that none does (then only the position)
};

// The first difference between `actual` and `expected`, the oracle's answer for `input`, at `level`.
std::optional<Difference> compare(const Circles& input, const Circles& expected, const Circles& actual, Level level);

// Runs the check, printing a summary (and the counterexample, if any) on `out`. Returns 0 when every case
// conforms, 1 for a counterexample. Throws BrokenCandidate.
int conform(Candidate& candidate, const ConformOptions& options, std::ostream& out);

}  // namespace circles::cli
