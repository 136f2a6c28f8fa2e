#include "conform/conform.hpp"

#include "conform/corpus.hpp"
#include "conform/replay.hpp"
#include "formats/json_number.hpp"
#include "properties/boundaries.hpp"
#include "properties/chain.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <tuple>
#include <span>
#include <variant>
#include <vector>

namespace circles::conform {
namespace {

using properties::NoAnswer;

// Shrinking asks the candidate at most this many worlds: enough for worlds of 8 circles, and for delta debugging
// a world of 10^5 circles down to a dozen (about k log2(n/k) + k queries for k circles, then one per circle
// left to show that none can go), bounded for a slow program.
constexpr int kMaxShrinkQueries = 2000;
// The most circles of a small family's world (properties/boundaries.hpp): bigger worlds shrink by delta
// debugging over their circles before anything else.
constexpr std::size_t kSmallWorld = 8;
// Simplifying the numbers of the shrunk world asks at most this many more: 8 circles × 5 fields × the up to 71
// values of simpler_values is 2840, but a field stops at its first simpler value that still fails, most at 0 or
// an integer, and a number that is already simple has few simpler values.
constexpr int kMaxSimplifyQueries = 1000;

// How simple a number reads, smaller first: zero; then integers before fractions; then fewer significant
// decimal digits (those of the shortest decimal that reads back as it: 0.5 has 1, 0.0625 3); then fewer bits
// in its significand (the shorter binary fraction); then the smaller magnitude.
std::tuple<bool, bool, int, int, double> simplicity(double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x, std::chars_format::scientific).ptr;
  const std::string_view s(text, static_cast<std::size_t>(end - text));
  const int digits = static_cast<int>(std::count_if(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(s.find('e')),
                                                    [](char c) { return c >= '0' && c <= '9'; }));
  int e = 0;
  const double m = std::frexp(std::fabs(x), &e);  // |x| = m · 2^e, 1/2 <= m < 1
  int bits = 0;
  for (double rest = m; rest != 0; rest = rest * 2 - std::trunc(rest * 2)) ++bits;
  return {x != 0, std::trunc(x) != x, digits, bits, std::fabs(x)};
}

// Values simpler than x (by simplicity), simplest first, as Hypothesis shrinks a number: toward 0, toward the
// integers (toward zero and nearest), toward short binary fractions (x's significand cut to 1, 2, …, 52 bits
// toward zero) and short decimals (x rounded to 1, 2, …, 16 significant digits). Each is a finite double.
std::vector<double> simpler_values(double x) {
  std::vector<double> out{0.0, std::trunc(x), std::nearbyint(x)};
  int e = 0;
  std::frexp(x, &e);
  for (int bits = 1; bits < 53; ++bits) out.push_back(std::ldexp(std::trunc(std::ldexp(x, bits - e)), e - bits));
  for (int digits = 1; digits <= 16; ++digits) {
    char text[40];
    const auto end = std::to_chars(text, text + sizeof text - 1, x, std::chars_format::scientific, digits - 1).ptr;
    *end = '\0';
    out.push_back(std::strtod(text, nullptr));
  }
  const auto key = simplicity(x);
  std::erase_if(out, [&](double y) { return !std::isfinite(y) || !(simplicity(y) < key); });
  std::sort(out.begin(), out.end(), [](double a, double b) { return simplicity(a) < simplicity(b); });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// One case's chain of steps (properties/chain.hpp), its failure, and how it ended: every step checked; no step
// checked, because w_0 has no expected answer (its next world leaves the double range, or, replayed in the
// literal profile, it is outside the domain): skipped; or checked up to a world with no expected answer.
using properties::Chain;
using Failure = properties::ChainFailure;
using Ending = Chain::Ending;

// Whether two failures received the same kind of wrong value: both NaN, the same infinity, or both finite. Shrinking
// and simplifying keep a failure's kind, so that a candidate that answers NaN on one world and a finite wrong
// value on a simpler one is shown with its NaN, the fault it was caught by, rather than slipping to another.
bool same_kind(const Failure& a, const Failure& b) {
  const double x = a.difference.actual, y = b.difference.actual;
  if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
  return std::isfinite(x) == std::isfinite(y) && (std::isfinite(x) || x == y);
}

// The most cases conform asks the candidate about in one Checker::run_all, which sends every request whose
// world is known before reading their answers (ProcessCandidate also bounds the bytes in flight), so that they
// share one round trip through the pipes. A batch of requests ends sooner, at a case that chains another step:
// by default at each tangent-after-step case, one in 17, so about 14 requests a batch (docs/benchmarks.md);
// with --steps 2 or more, at every case, so 2. The bound matters when no case chains, and bounds the requests
// a failing run asks beyond the case-by-case run's.
constexpr std::size_t kBatchCases = 64;

class Checker {
 public:
  Checker(Candidate& candidate, const Options& options) : candidate_(candidate), options_(options) {}

  // Chains `steps` steps from w.
  std::optional<Failure> run(const Circles& w, std::uint64_t steps, Ending& ending) {
    Chain chain(w, steps, options_.level);
    run_all(std::span(&chain, 1));
    ending = chain.ending();
    return std::move(chain.failure());
  }

  // Runs the chains as run() would run them one after another, up to the first that fails: returns its index
  // (its `failure` set), or chains.size() if none does. The candidate is asked in batches
  // (Candidate::answer_all): every request whose world is known, in the order of the sequential run, up to
  // and including the first whose answer a later request needs (a step of a chain that goes on). So the
  // candidate gets the sequential run's requests in the same order, with the same ids (a step that carries
  // state from one request to the next is caught as before), plus, after a failing request, the rest of its
  // batch, whose answers are read and not judged.
  std::size_t run_all(std::span<Chain> chains) {
    std::vector<Circles> asked, expected;
    std::vector<std::size_t> whose;  // asked[i] is the next step of chains[whose[i]]
    for (std::size_t first = 0; first < chains.size();) {
      asked.clear();
      expected.clear();
      whose.clear();
      std::size_t next = chains.size();  // where the next batch starts: the chain that goes on, if any
      for (std::size_t k = first; k < chains.size(); ++k) {
        Chain& chain = chains[k];
        if (!chain.going()) continue;
        auto reference = properties::expected_step(chain.input(), options_.profile);
        if (!std::holds_alternative<Circles>(reference)) {
          chain.end();
          continue;
        }
        asked.push_back(chain.input());
        expected.push_back(std::move(std::get<Circles>(reference)));
        whose.push_back(k);
        if (chain.goes_on_after_next()) {  // its next request waits for this answer
          next = k;
          break;
        }
      }
      if (asked.empty()) break;
      Answers read = candidate_.answer_all(asked, next_id_);
      std::vector<Circles>& answers = read.answers;
      next_id_ += asked.size();
      // The answers before a fault are judged first: a wrong one is the counterexample the sequential run
      // reports, even when the candidate then breaks on a request the sequential run would not have sent.
      for (std::size_t i = 0; i < answers.size(); ++i) {
        if (!chains[whose[i]].judge(std::move(answers[i]), std::move(expected[i]))) return whose[i];
      }
      if (read.broken) throw *read.broken;
      first = next;
    }
    return chains.size();
  }

 private:
  Candidate& candidate_;
  const Options& options_;
  std::uint64_t next_id_ = 1;
};

// Case c's family and generator: the families of the profile in turn.
class Cases {
 public:
  explicit Cases(Profile profile, std::size_t max_circles = properties::kDefaultMaxCircles)
      : families_(properties::families(profile)), max_circles_(max_circles) {
    for (const properties::Family f : families_) gens_.push_back(properties::gen::boundary_world(f, profile));
  }
  std::span<const properties::Family> families() const { return families_; }
  std::size_t family(std::uint64_t c) const { return static_cast<std::size_t>(c % families_.size()); }
  // Case c's world from its random stream. RapidCheck's sizes cycle 0 … 99 over a run (the families'
  // generators ignore it). A big family's world is its round's (c / F), which does not shrink: Run::shrink
  // removes its circles by delta debugging instead.
  rc::Shrinkable<Circles> world(std::uint64_t c, const rc::Random& random) const {
    const properties::Family f = families_[family(c)];
    if (properties::is_big(f))
      return rc::shrinkable::just(properties::gen::big_world(f, c / families_.size(), max_circles_, random));
    return gens_[family(c)](random, static_cast<int>(c % rc::kNominalSize));
  }

 private:
  std::span<const properties::Family> families_;
  std::size_t max_circles_;
  std::vector<rc::Gen<Circles>> gens_;
};

}  // namespace

std::vector<Circles> case_worlds(std::uint64_t seed, std::uint64_t cases, Profile profile, std::size_t max_circles) {
  const Cases all(profile, max_circles);
  rc::Random stream(seed);
  std::vector<Circles> worlds;
  for (std::uint64_t c = 0; c < cases; ++c) worlds.push_back(all.world(c, stream.split()).value());
  return worlds;
}

std::pair<std::uint64_t, std::uint64_t> parse_shard(std::string_view text) {
  const auto slash = text.find('/');
  std::uint64_t i = 0, n = 0;
  const auto number = [](std::string_view digits, std::uint64_t& v) {
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    return !digits.empty() && error == std::errc{} && end == digits.data() + digits.size();
  };
  if (slash == std::string_view::npos || !number(text.substr(0, slash), i) || !number(text.substr(slash + 1), n) ||
      n == 0 || i >= n)
    throw std::invalid_argument("--shard: \"" + std::string(text) + "\" is not i/n with 0 <= i < n");
  return {i, n};
}

const char* name(Outcome outcome) {
  switch (outcome) {
    case Outcome::conforms: return "conforms";
    case Outcome::does_not_conform: return "does not conform";
    case Outcome::interrupted: return "interrupted";
    case Outcome::cannot_check: break;
  }
  return "cannot check";
}

std::optional<Outcome> parse_outcome(std::string_view text) {
  for (const Outcome o : {Outcome::conforms, Outcome::does_not_conform, Outcome::cannot_check, Outcome::interrupted})
    if (text == name(o)) return o;
  return std::nullopt;
}

bool judged(Outcome outcome) { return outcome == Outcome::conforms || outcome == Outcome::does_not_conform; }

namespace {
constexpr FamilyStatus kStatuses[] = {FamilyStatus::passed,         FamilyStatus::failed,  FamilyStatus::expected_failure,
                                      FamilyStatus::unexpected_pass, FamilyStatus::skipped, FamilyStatus::not_reached};
}  // namespace

const char* name(FamilyStatus status) {
  switch (status) {
    case FamilyStatus::passed: return "passed";
    case FamilyStatus::failed: return "failed";
    case FamilyStatus::expected_failure: return "expected failure";
    case FamilyStatus::unexpected_pass: return "unexpected pass";
    case FamilyStatus::skipped: return "skipped";
    case FamilyStatus::not_reached: break;
  }
  return "not reached";
}

std::optional<FamilyStatus> parse_family_status(std::string_view text) {
  for (const FamilyStatus s : kStatuses)
    if (text == name(s)) return s;
  return std::nullopt;
}

std::optional<properties::Family> parse_family(std::string_view name, Profile profile) {
  for (const properties::Family f : properties::families(profile))
    if (name == properties::name(f)) return f;
  return std::nullopt;
}

std::vector<properties::Family> parse_families(std::string_view option, std::string_view list, Profile profile) {
  std::vector<properties::Family> out;
  for (std::size_t start = 0; start <= list.size();) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view item = list.substr(start, comma - start);
    const std::optional<properties::Family> family = parse_family(item, profile);
    if (!family) {
      std::string names;
      for (const properties::Family f : properties::families(profile))
        names += (names.empty() ? "" : ", ") + std::string(properties::name(f));
      throw std::invalid_argument(std::string(option) + ": unknown family \"" + std::string(item) + "\"; the families of the " +
                                  properties::name(profile) + " profile are " + names);
    }
    if (std::find(out.begin(), out.end(), *family) == out.end()) out.push_back(*family);
    start = comma + 1;
  }
  return out;
}

bool found_before(const Counterexample& a, const Counterexample& b) {
  const auto order = [](const Counterexample& c) { return c.case_index ? *c.case_index + 1 : 0; };
  return order(a) < order(b);
}

Outcome checked_outcome(const Verdict& verdict) {
  const bool fails = verdict.counterexample ||
                     std::any_of(verdict.families.begin(), verdict.families.end(), [](const FamilyResult& f) {
                       return f.status == FamilyStatus::failed || f.status == FamilyStatus::unexpected_pass;
                     });
  return fails ? Outcome::does_not_conform : Outcome::conforms;
}

void mark_counterexample_family(Verdict& verdict) {
  for (FamilyResult& f : verdict.families)
    f.has_counterexample = verdict.counterexample && properties::name(f.family) == verdict.counterexample->family;
}

namespace {

// check()'s work, which throws BrokenCandidate and ConformError for check() to turn into a verdict.
class Run {
 public:
  Run(Candidate& candidate, const Options& options, Verdict& verdict)
      : candidate_(candidate), options_(options), verdict_(verdict), checker_(candidate, options) {}

  void operator()() {
    replay_corpus();
    if (verdict_.counterexample && !options_.keep_going) return;
    check_cases();
    if (verdict_.counterexample && !options_.keep_going) return;
    candidate_.finish();
    require_every_family();
  }

 private:
  bool skipped(properties::Family family) const {
    return std::find(options_.skip.begin(), options_.skip.end(), family) != options_.skip.end();
  }

  // Records the counterexample of the family `result` (none: a stored file of no known family); the run's
  // counterexample is its first.
  void fail(Failure failure, Counterexample c, FamilyResult* result) {
    c.step = failure.step;
    c.steps = failure.steps;
    c.input = std::move(failure.input);
    c.expected = std::move(failure.expected);
    c.actual = std::move(failure.actual);
    c.difference = std::move(failure.difference);
    const bool first = !verdict_.counterexample;
    if (result) {
      result->status = FamilyStatus::failed;
      result->has_counterexample = first;
      result->counterexample = c;
    }
    if (first) verdict_.counterexample = std::move(c);
  }

  FamilyResult* result_of(const std::string& family) {
    for (FamilyResult& f : verdict_.families)
      if (properties::name(f.family) == family) return &f;
    return nullptr;
  }

  // 1. The corpus, replayed first.
  void replay_corpus() {
    if (options_.save.empty()) return;
    std::vector<std::pair<std::filesystem::path, StoredCounterexample>> corpus;
    try {
      corpus = load_corpus(options_.save);
    } catch (const CorpusError& e) {
      throw ConformError(std::string("--save: ") + e.what());
    }
    for (const auto& [file, stored] : corpus) {
      FamilyResult* result = result_of(stored.family);
      if (result && (skipped(result->family) || result->status == FamilyStatus::failed)) continue;
      Ending ending = Ending::checked;
      std::optional<Failure> failure = checker_.run(stored.world, options_.steps, ending);
      if (ending == Ending::no_reference_at_w0) {
        ++verdict_.not_replayed;
        continue;
      }
      ++verdict_.replayed;
      if (!failure) continue;
      Counterexample c;
      c.family = stored.family;
      c.stored = file;
      c.found_seed = stored.seed;
      c.found_case = stored.case_index;
      c.circles_before = stored.world.size();
      c.shrink_path = {stored.world};
      c.replay = replay_command(candidate_.option(), options_, std::nullopt);
      fail(std::move(*failure), std::move(c), result);
      if (!options_.keep_going) return;
    }
  }

  // 2. The generated cases, in rounds of one case per family.
  void check_cases() {
    const std::span<const properties::Family> families = cases_.families();
    const std::uint64_t F = families.size();
    rc::Random stream(options_.seed);
    // The cases of this run, checked kBatchCases at a time (Checker::run_all), then counted and, for the first
    // that fails (with --keep-going, of each family), shrunk, in order: the verdict is the sequential run's.
    struct Case {
      std::uint64_t index;
      std::size_t family;
      rc::Shrinkable<Circles> world;
    };
    struct Failing {
      Case drawn;
      std::uint64_t steps;
      Failure failure;
    };
    std::vector<Case> batch;
    std::vector<Chain> chains;
    std::vector<Failing> failing;  // the first failing case of each family that fails, in case order
    // Checks the batch, counting its cases up to the first that fails, or with --keep-going all of them: a case
    // of a family that failed earlier in the batch is asked, but neither counted nor shrunk, so that a failing
    // family's count is its cases up to its first failure.
    const auto check_batch = [&]() {
      for (std::size_t from = 0; from < chains.size();) {
        const std::size_t failed = from + checker_.run_all(std::span(chains).subspan(from));
        for (std::size_t k = from; k < chains.size() && k <= failed; ++k) {
          FamilyResult& family = verdict_.families[batch[k].family];
          if (family.status == FamilyStatus::failed) continue;
          ++verdict_.cases;
          ++family.drawn;
          if (chains[k].ending() == Ending::no_reference_at_w0) ++verdict_.skipped;
          else ++family.checked;
          verdict_.cut_short += chains[k].ending() == Ending::no_reference_later;
        }
        if (failed == chains.size()) break;
        FamilyResult& family = verdict_.families[batch[failed].family];
        if (family.status != FamilyStatus::failed) {
          family.status = FamilyStatus::failed;
          failing.push_back({batch[failed], chains[failed].steps(), std::move(*chains[failed].failure())});
        }
        if (!options_.keep_going) return;
        from = failed + 1;
      }
      batch.clear();
      chains.clear();
      if (options_.progress) options_.progress(verdict_);
    };
    // --case I replays case I whatever --cases says: the replay line of a report does not repeat it.
    const std::uint64_t end = options_.only_case ? *options_.only_case + 1 : options_.cases;
    for (std::uint64_t c = 0; c < end && (failing.empty() || options_.keep_going); ++c) {
      throw_if_interrupted();  // between cases too: an engine in process has no request to notice it at
      const rc::Random random = stream.split();  // case c's stream, whichever cases this run checks
      if (options_.only_case ? c != *options_.only_case : (c / F) % options_.shards != options_.shard) continue;
      const std::size_t family = cases_.family(c);
      // A skipped family, and with --keep-going one that failed already (here or in the corpus), is not asked.
      if (skipped(families[family]) || verdict_.families[family].status == FamilyStatus::failed) continue;
      // At least as far as the family's boundary: tangent-after-step's tangency is decided at the second step.
      const std::uint64_t steps = std::max(options_.steps, properties::steps_to_decide(families[family]));
      batch.push_back(Case{c, family, cases_.world(c, random)});
      chains.emplace_back(batch.back().world.value(), steps, options_.level);
      if (batch.size() == kBatchCases) check_batch();
    }
    if (!batch.empty() && (failing.empty() || options_.keep_going)) check_batch();
    for (Failing& f : failing) shrink(std::move(f.drawn.world), f.drawn.index, f.drawn.family, f.steps, std::move(f.failure));
  }

  // Shrinks case c's failure (of the family with index `family`) and records it as the family's counterexample.
  void shrink(rc::Shrinkable<Circles> world, std::uint64_t c, std::size_t family, std::uint64_t steps, Failure failure) {
    const std::span<const properties::Family> families = cases_.families();
    Counterexample counterexample;
    counterexample.shrink_path = {world.value()};
    counterexample.circles_before = world.value().size();
    int queries = 0;
    // A world bigger than the small families' loses its circles by delta debugging first; a small family's
    // world then shrinks through its generator's shrinks (RapidCheck's), which drop circles one at a time and
    // simplify the family's integers.
    if (world.value().size() > kSmallWorld) {
      Circles smaller = world.value();
      remove_circles(smaller, steps, failure, counterexample, queries);
      world = rc::shrinkable::just(std::move(smaller));
    }
    // Shrink: take the first simpler world that still fails with the same kind of value (same_kind), until none
    // does (or the budget is spent).
    for (bool progress = true; progress && queries < kMaxShrinkQueries;) {
      progress = false;
      auto candidates = world.shrinks();
      while (auto next = candidates.next()) {
        if (++queries > kMaxShrinkQueries) break;
        std::optional<Failure> f = still_fails(next->value(), steps, failure, counterexample.tries);
        if (f) {
          world = *next;
          failure = std::move(*f);
          counterexample.shrink_path.push_back(world.value());
          progress = true;
          break;
        }
      }
    }
    if (options_.simplify) simplify(world.value(), steps, failure, counterexample);
    counterexample.family = properties::name(families[family]);
    counterexample.case_index = c;
    counterexample.replay = replay_command(candidate_.option(), options_, c);
    if (!options_.save.empty()) {
      const StoredCounterexample stored{options_.profile, failure.input, options_.level.text(), counterexample.family,
                                        candidate_.name(), options_.seed, c, steps, failure.step, failure.expected,
                                        failure.actual, failure.difference};
      try {
        counterexample.saved = save(options_.save, stored);
      } catch (const CorpusError& e) {
        counterexample.not_saved = e.what();
      }
    }
    fail(std::move(failure), std::move(counterexample), &verdict_.families[family]);
  }

  // The failure of the case chained `steps` steps from w, if it fails with the same kind of value as `failure`
  // (same_kind); nothing if it passes, fails otherwise, or breaks the candidate (a world on which the candidate
  // crashes, hangs or writes a malformed line does not show the wrong answer being shrunk; the next world is
  // asked of the program started afresh). Once a signal has interrupted the check, no world is asked: the
  // counterexample is the world shrunk so far, reported with the interruption. `tries` counts the worlds asked.
  std::optional<Failure> still_fails(const Circles& w, std::uint64_t steps, const Failure& failure,
                                     std::uint64_t& tries) {
    if (interruption()) return std::nullopt;
    ++tries;
    Ending e = Ending::checked;
    std::optional<Failure> f;
    try {
      f = checker_.run(w, steps, e);
    } catch (const BrokenCandidate&) {
      return std::nullopt;
    } catch (const Interrupted&) {
      return std::nullopt;
    }
    if (f && same_kind(*f, failure)) return f;
    return std::nullopt;
  }

  // Delta debugging (Zeller and Hildebrandt's ddmin) over the circles of `world`, in their order: remove a
  // chunk of them, of n chunks, while the case still fails; when no chunk can go, split finer (n doubles) down
  // to single circles. It ends 1-minimal, a world from which no single circle can be removed while it still
  // fails, unless the budget of queries runs out first. A failure that needs k circles of a world of n takes
  // about k log2(n/k) + k queries of ever smaller worlds.
  void remove_circles(Circles& world, std::uint64_t steps, Failure& failure, Counterexample& counterexample,
                      int& queries) {
    for (std::size_t chunks = 2; world.size() > 1 && queries < kMaxShrinkQueries;) {
      chunks = std::min(chunks, world.size());
      bool removed = false;
      for (std::size_t k = 0; k < chunks && queries < kMaxShrinkQueries; ++k) {
        const std::size_t from = world.size() * k / chunks, to = world.size() * (k + 1) / chunks;
        Circles rest(world.begin(), world.begin() + static_cast<std::ptrdiff_t>(from));
        rest.insert(rest.end(), world.begin() + static_cast<std::ptrdiff_t>(to), world.end());
        ++queries;
        if (auto f = still_fails(rest, steps, failure, counterexample.tries)) {
          world = std::move(rest);
          failure = std::move(*f);
          counterexample.shrink_path.push_back(world);
          removed = true;
          break;
        }
      }
      if (removed) chunks = std::max<std::size_t>(chunks - 1, 2);
      else if (chunks == world.size()) break;
      else chunks *= 2;
    }
  }

  // After shrinking: each number of the world, in turn, replaced by its simplest value (simpler_values) with
  // which the case still fails, pass after pass until no number changes or the budget is spent. A world on
  // which the candidate breaks is passed over, as in shrinking.
  void simplify(Circles world, std::uint64_t steps, Failure& failure, Counterexample& counterexample) {
    int queries = 0;
    for (bool progress = true; progress && queries < kMaxSimplifyQueries;) {
      progress = false;
      for (std::size_t k = 0; k < world.size(); ++k)
        for (std::size_t f = 0; f < 5; ++f)
          for (const double y : simpler_values(world[k][f])) {
            if (++queries > kMaxSimplifyQueries) return;
            Circles simpler = world;
            simpler[k][f] = y;
            // The same failure, made simpler: at the same step, in the same field (a stateful candidate may
            // fail otherwise on a world that happens to equal one of its earlier answers), of the same kind.
            std::optional<Failure> still = still_fails(simpler, steps, failure, counterexample.tries);
            if (!still || still->step != failure.step || still->difference.field != failure.difference.field)
              continue;
            world = std::move(simpler);
            failure = std::move(*still);
            counterexample.shrink_path.push_back(world);
            progress = true;
            break;
          }
    }
  }

  // 3. Every family must have been checked: a family with no case is a gap in the check, not a pass.
  void require_every_family() {
    if (options_.only_case || options_.cases == 0) return;
    const std::uint64_t F = verdict_.families.size();
    for (const FamilyResult& f : verdict_.families) {
      if (f.checked > 0 || skipped(f.family) || f.status == FamilyStatus::failed) continue;
      const std::string family = properties::name(f.family);
      if (f.drawn == 0)
        throw ConformError("no case of the family " + family + " was checked: each round of " + std::to_string(F) +
                           " cases draws every family of the " + properties::name(options_.profile) +
                           " profile once, and this run " +
                           (options_.shards > 1 ? "(shard " + std::to_string(options_.shard) + "/" +
                                                      std::to_string(options_.shards) + ") "
                                                : std::string()) +
                           "checked " + std::to_string(verdict_.cases) + "; raise --cases to at least " +
                           std::to_string(F * options_.shards));
      throw ConformError("no case of the family " + family + " was checked: all " + std::to_string(f.drawn) +
                         " of its worlds were skipped (their next world leaves the double range)");
    }
  }

  Candidate& candidate_;
  const Options& options_;
  Verdict& verdict_;
  Checker checker_;
  const Cases cases_{options_.profile, options_.max_circles};
};

}  // namespace

Verdict unchecked(std::string candidate, const Options& options, std::string error) {
  Verdict verdict;
  verdict.outcome = Outcome::cannot_check;
  verdict.candidate = std::move(candidate);
  verdict.options = options;
  verdict.error = std::move(error);
  for (const properties::Family f : properties::families(options.profile))
    verdict.families.push_back({f, 0, 0, FamilyStatus::not_reached, false, std::nullopt});
  return verdict;
}

Verdict check(Candidate& candidate, const Options& options) {
  // A --save directory that cannot be used is a usage error, found before any case runs.
  if (!options.save.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.save, error);
    if (error || !std::filesystem::is_directory(options.save))
      throw ConformError("--save: cannot use the directory " + options.save.string() +
                         (error ? ": " + error.message() : ": it is not a directory"));
  }
  const auto start = std::chrono::steady_clock::now();
  Verdict verdict = unchecked(candidate.name(), options, "");
  bool could_check = true;
  try {
    Run(candidate, options, verdict)();
  } catch (const Interrupted& e) {
    verdict.signal = e.signal();
    verdict.error = e.what();
  } catch (const BrokenCandidate& e) {
    // A fault that a signal caused (interrupt() killed the program) is the interruption, not the program's.
    if (const int signal = interruption()) {
      verdict.signal = signal;
      verdict.error = Interrupted(signal).what();
    } else {
      could_check = false;
      verdict.error = e.what();
    }
  } catch (const ConformError& e) {
    could_check = false;
    verdict.error = e.what();
  }
  // A signal while a counterexample was shrunk ends the shrinking, not the run: the run is interrupted all the same.
  if (const int signal = interruption(); signal && !verdict.signal) {
    verdict.signal = signal;
    verdict.error = Interrupted(signal).what();
  }
  // A family with no checked case did not pass: the run stopped (a counterexample, a fault) before it, or
  // replayed one case or the corpus alone.
  for (FamilyResult& f : verdict.families)
    if (std::find(options.skip.begin(), options.skip.end(), f.family) != options.skip.end()) f.status = FamilyStatus::skipped;
    else if (f.status != FamilyStatus::failed) f.status = f.checked > 0 ? FamilyStatus::passed : FamilyStatus::not_reached;
  verdict.outcome = verdict.signal ? Outcome::interrupted : could_check ? checked_outcome(verdict) : Outcome::cannot_check;
  if (verdict.signal) verdict.rerun = rerun_command(candidate.option(), options);
  verdict.elapsed = std::chrono::steady_clock::now() - start;
  return verdict;
}

}  // namespace circles::conform
