#include "conform/checker.hpp"

#include "conform/deadline.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
#include <variant>

namespace circles::conform {

std::optional<properties::ChainFailure> Checker::run(const Circles& w, std::uint64_t steps, Chain::Ending& ending,
                                                     Spelling spelling) {
  Chain chain(w, steps, options_.level);
  run_all(std::span(&chain, 1), std::span(&spelling, 1));
  ending = chain.ending();
  return std::move(chain.failure());
}

std::size_t Checker::run_all(std::span<Chain> chains, std::span<const Spelling> spellings) {
  std::vector<Circles> asked, expected;
  std::vector<Spelling> spelled;
  std::vector<std::size_t> whose;  // asked[i] is the next step of chains[whose[i]]
  for (std::size_t first = 0; first < chains.size();) {
    asked.clear();
    expected.clear();
    spelled.clear();
    whose.clear();
    std::size_t next = chains.size();  // where the next batch starts: the chain that goes on, if any
    for (std::size_t k = first; k < chains.size(); ++k) {
      Chain& chain = chains[k];
      if (!chain.going()) continue;
      throw_if_cut();
      auto reference = properties::expected_step(chain.input(), options_.profile);
      if (!std::holds_alternative<Circles>(reference)) {
        chain.end();
        continue;
      }
      asked.push_back(chain.input());
      spelled.push_back(spellings.empty() ? Spelling::shortest : spellings[k]);
      expected.push_back(std::move(std::get<Circles>(reference)));
      whose.push_back(k);
      if (chain.goes_on_after_next()) {  // its next request waits for this answer
        next = k;
        break;
      }
    }
    if (asked.empty()) break;
    Answers read = candidate_.answer_all(asked, next_id_, spelled);
    std::vector<Circles>& answers = read.answers;
    next_id_ += asked.size();
    // The answers before a fault are judged first: a wrong one is the counterexample the sequential run
    // reports, even when the candidate then breaks on a request the sequential run would not have sent.
    for (std::size_t i = 0; i < answers.size(); ++i) {
      if (!chains[whose[i]].judge(std::move(answers[i]), std::move(expected[i]))) return whose[i];
    }
    // A fault on a world (a crash, a hang, a malformed line) fails the chain asked, as a wrong answer would; the
    // caller decides whether a fault before any answer means the program cannot be checked at all.
    if (read.broken && read.broken->fault() != Fault::other) {
      const std::size_t at = answers.size();
      chains[whose[at]].broke(std::move(expected[at]), name(read.broken->fault()), read.broken->what());
      return whose[at];
    }
    if (read.broken) throw *read.broken;
    first = next;
  }
  return chains.size();
}

Jobs::Jobs(Candidate& candidate, const Options& options, unsigned jobs)
    : candidate_(candidate), options_(options), jobs_(std::max(jobs, 1u)) {
  checkers_.push_back(std::make_unique<Checker>(candidate, options));
}

Jobs::~Jobs() = default;

std::vector<std::pair<std::size_t, std::size_t>> Jobs::units(std::size_t n) const {
  const std::size_t size = std::clamp<std::size_t>((n + jobs_ - 1) / jobs_, 1, kBatchCases);
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t from = 0; from < n; from += size) out.emplace_back(from, std::min(n, from + size));
  return out;
}

namespace {

// One unit's chains on one checker: up to the first failing chain, or with `all`, every one.
UnitOutcome run_unit(Checker& checker, std::span<Chain> chains, bool all, std::span<const Spelling> spellings) {
  UnitOutcome outcome;
  try {
    for (std::size_t from = 0; from < chains.size();) {
      const std::size_t failed =
          from + checker.run_all(chains.subspan(from), spellings.empty() ? spellings : spellings.subspan(from));
      if (failed == chains.size()) break;
      outcome.failed.push_back(failed);
      if (!all) break;
      from = failed + 1;
    }
  } catch (...) {
    outcome.broken = std::current_exception();
  }
  return outcome;
}

}  // namespace

std::vector<UnitOutcome> Jobs::run(std::span<Chain> chains, std::span<const std::pair<std::size_t, std::size_t>> units,
                                   bool all, std::span<const Spelling> spellings) {
  std::vector<UnitOutcome> outcomes(units.size());
  // The copies this stage needs, started once; a candidate that cannot be copied keeps to one job.
  const std::size_t wanted = std::min<std::size_t>(jobs_, units.size());
  while (checkers_.size() < wanted) {
    std::unique_ptr<Candidate> copy = candidate_.copy();
    if (!copy) break;
    checkers_.push_back(std::make_unique<Checker>(*copy, options_));
    copies_.push_back(std::move(copy));
  }
  const std::size_t workers = std::min(wanted, checkers_.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&](Checker& checker) {
    for (std::size_t u; (u = next++) < units.size();) {
      const auto [from, to] = units[u];
      outcomes[u] = run_unit(checker, chains.subspan(from, to - from), all,
                             spellings.empty() ? spellings : spellings.subspan(from, to - from));
    }
  };
  if (workers <= 1) {
    work(first());
    return outcomes;
  }
  std::vector<std::jthread> threads;
  for (std::size_t w = 1; w < workers; ++w) threads.emplace_back([&work, this, w] { work(*checkers_[w]); });
  work(first());
  threads.clear();  // joins
  return outcomes;
}

void Jobs::finish() {
  for (const std::unique_ptr<Candidate>& copy : copies_) copy->finish();
}

}  // namespace circles::conform
