// How conform asks a candidate about its cases: Checker runs chains of steps (properties/chain.hpp) against one
// candidate, in batches that share a round trip through the pipes; Jobs runs the units of a stage of cases on
// several copies of the candidate at once (`circles conform --jobs N`), each copy answering its own units, and
// hands back each unit's outcome for the caller to count in case order, so that the verdict is the one a single
// copy gives.
#pragma once

#include "conform/candidate.hpp"
#include "conform/conform.hpp"
#include "properties/chain.hpp"

#include <cstddef>
#include <exception>
#include <memory>
#include <span>
#include <vector>

namespace circles::conform {

using properties::Chain;

class Checker {
 public:
  Checker(Candidate& candidate, const Options& options) : candidate_(candidate), options_(options) {}

  // Chains `steps` steps from w, each request spelled as `spelling` says; `ending` says how the chain ended.
  // Throws BrokenCandidate.
  std::optional<properties::ChainFailure> run(const Circles& w, std::uint64_t steps, Chain::Ending& ending,
                                              Spelling spelling = Spelling::shortest);

  // Runs the chains as run() would run them one after another, up to the first that fails: returns its index
  // (its `failure` set), or chains.size() if none does. The candidate is asked in batches
  // (Candidate::answer_all): every request whose world is known, in the order of the sequential run, up to
  // and including the first whose answer a later request needs (a step of a chain that goes on). So the
  // candidate gets the sequential run's requests in the same order, with the same ids (a step that carries
  // state from one request to the next is caught as before), plus, after a failing request, the rest of its
  // batch, whose answers are read and not judged. Throws BrokenCandidate after judging the answers before it.
  // `spellings`, empty or one per chain, says how each chain's requests are spelled (Candidate::answer_all).
  std::size_t run_all(std::span<Chain> chains, std::span<const Spelling> spellings = {});

 private:
  Candidate& candidate_;
  const Options& options_;
  std::uint64_t next_id_ = 1;
};

// What one unit of chains gave: the indices (in the unit) of its failing chains, in order, the first only
// unless every one was asked for; and, if the candidate broke, what it threw (the chains after the last failure
// are then not all judged).
struct UnitOutcome {
  std::vector<std::size_t> failed;
  std::exception_ptr broken;
};

// The candidate and `jobs` − 1 copies of it (Candidate::copy; a candidate that cannot be copied runs alone), each
// with its own Checker. Copies are started when a stage first has work for them, and finished with the run.
class Jobs {
 public:
  Jobs(Candidate& candidate, const Options& options, unsigned jobs);
  ~Jobs();
  Jobs(const Jobs&) = delete;
  Jobs& operator=(const Jobs&) = delete;

  // The first job's checker: the candidate itself (for shrinking, which asks one world at a time).
  Checker& first() { return *checkers_.front(); }
  // The units into which a stage of n chains is cut: at most kBatchCases each, and as many as the jobs when
  // they are fewer than n, so that every job has one.
  std::vector<std::pair<std::size_t, std::size_t>> units(std::size_t n) const;
  // Runs each unit [from, to) of `chains` on one job, the jobs at once; `all`: every failing chain of a unit
  // (--keep-going), else its first; `spellings` as Checker::run_all takes them. Returns the units' outcomes, in
  // order.
  std::vector<UnitOutcome> run(std::span<Chain> chains, std::span<const std::pair<std::size_t, std::size_t>> units,
                               bool all, std::span<const Spelling> spellings = {});
  // Each copy's Candidate::finish (the candidate's own is the caller's). Throws BrokenCandidate.
  void finish();

  // The most cases conform asks one candidate about in one Checker::run_all, which sends every request whose world
  // is known before reading their answers (ProcessCandidate also bounds the bytes in flight), so that they share
  // one round trip through the pipes. A batch of requests ends sooner, at a case that chains another step: by
  // default at each tangent-after-step case, one in 17, so about 14 requests a batch (docs/benchmarks.md); with
  // --steps 2 or more, at every case, so 2. The bound matters when no case chains, and bounds the requests a
  // failing run asks beyond the case-by-case run's.
  static constexpr std::size_t kBatchCases = 64;

 private:
  Candidate& candidate_;
  const Options& options_;
  unsigned jobs_;
  std::vector<std::unique_ptr<Candidate>> copies_;
  std::vector<std::unique_ptr<Checker>> checkers_;
};

}  // namespace circles::conform
