#include "conform/conform.hpp"

#include "conform/checker.hpp"
#include "conform/corpus.hpp"
#include "conform/deadline.hpp"
#include "conform/ladder.hpp"
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
// Shrinking a hang asks at most this many worlds, each of which may cost the program's whole deadline.
constexpr int kMaxHangShrinkQueries = 8;
// Shrinking one counterexample stops after this long, whatever its budget of queries: a program that crashes is
// started afresh for each world asked, and a slow one takes its time on each.
constexpr std::chrono::seconds kMaxShrinkTime{60};
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
using Failure = properties::ChainFailure;
using Ending = Chain::Ending;

// Whether two failures received the same kind of wrong value: both NaN, the same infinity, or both finite. Shrinking
// and simplifying keep a failure's kind, so that a candidate that answers NaN on one world and a finite wrong
// value on a simpler one is shown with its NaN, the fault it was caught by, rather than slipping to another.
bool same_kind(const Failure& a, const Failure& b) {
  if (a.fault != b.fault) return false;
  if (!a.fault.empty()) return true;  // the same fault: a crash shrinks to a crash, a hang to a hang
  const double x = a.difference.actual, y = b.difference.actual;
  if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
  return std::isfinite(x) == std::isfinite(y) && (std::isfinite(x) || x == y);
}

// How the requests of a family's cases spell their numbers (the wire family's every way, the others' shortest).
Spelling spelling_of(properties::Family family) {
  return properties::row(family).spelled ? Spelling::every_form : Spelling::shortest;
}

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
  // removes its circles by delta debugging instead; with `circles`, it is the ladder's world of that size (the
  // family's largest with at most that many circles).
  rc::Shrinkable<Circles> world(std::uint64_t c, const rc::Random& random,
                                std::optional<std::size_t> circles = std::nullopt) const {
    const properties::Family f = families_[family(c)];
    if (properties::is_big(f))
      return rc::shrinkable::just(properties::gen::big_world(f, c / families_.size(), circles.value_or(max_circles_),
                                                             random, circles.has_value()));
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
      : candidate_(candidate), options_(options), verdict_(verdict), jobs_(candidate, options, options.jobs) {}

  void operator()() {
    replay_corpus();
    if (verdict_.counterexample && !options_.keep_going) return;
    check_cases();
    if (verdict_.counterexample && !options_.keep_going) return;
    candidate_.finish();
    jobs_.finish();
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
    c.fault = std::move(failure.fault);
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
      std::optional<Failure> failure = jobs_.first().run(
          stored.world, options_.steps, ending, result ? spelling_of(result->family) : Spelling::shortest);
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

  // 2. The generated cases, in rounds of one case per family: a fixed schedule of `cases` (--cases, --shard,
  // --case), or the budget's (--budget): rounds of the small families, then the ladder's big worlds. Each is
  // asked in stages (run_stage), and the first failing case of each failing family (the first only, without
  // --keep-going) is shrunk, in case order.
  void check_cases() {
    if (options_.budget && !options_.only_case) budget_cases();
    else fixed_cases();
    for (Failing& f : failing_) shrink(std::move(f.drawn.world), f.drawn.index, f.drawn.family, f.drawn.circles,
                                       f.steps, std::move(f.failure));
  }

  // One case to ask: its index, its family's index in the profile, the size of a ladder's world (none: the
  // fixed schedule's) and its world.
  struct Case {
    std::uint64_t index;
    std::size_t family;
    std::optional<std::size_t> circles;
    rc::Shrinkable<Circles> world;
  };
  struct Failing {
    Case drawn;
    std::uint64_t steps;
    Failure failure;
  };

  // Case c's random stream: the c-th split of the seed's, whichever cases this run asks.
  const rc::Random& random_of(std::uint64_t c) {
    while (randoms_.size() <= c) randoms_.push_back(stream_.split());
    return randoms_[c];
  }

  // Whether a case of the family with index `family` is asked: not a skipped family, nor, with --keep-going,
  // one that failed already (here or in the corpus).
  bool asked(std::size_t family) const {
    return !skipped(cases_.families()[family]) && verdict_.families[family].status != FamilyStatus::failed;
  }

  Case draw(std::uint64_t c, const rc::Random& random, std::optional<std::size_t> circles) const {
    return Case{c, cases_.family(c), circles, cases_.world(c, random, circles)};
  }

  // Counts a case asked, unless its family failed earlier.
  void count(const Case& c, const Chain& chain) {
    FamilyResult& family = verdict_.families[c.family];
    if (family.status == FamilyStatus::failed) return;
    ++verdict_.cases;
    ++family.drawn;
    if (chain.ending() == Ending::no_reference_at_w0) ++verdict_.skipped;
    else ++family.checked;
    verdict_.cut_short += chain.ending() == Ending::no_reference_later;
    if (properties::is_big(family.family))
      verdict_.largest_world = std::max(verdict_.largest_world, c.world.value().size());
  }

  // Asks a stage of cases, its units on every job at once (Jobs), then counts them in case order up to the
  // first that fails, or with --keep-going all of them, as a run of one case after another counts them: a case
  // of a family that failed earlier is asked, but neither counted nor shrunk, so that a failing family's count
  // is its cases up to its first failure. Returns false when the run stops there (a failure, without
  // --keep-going). A candidate that broke is reported after the cases before it are counted.
  bool run_stage(std::vector<Case>& stage) {
    std::vector<Chain> chains;
    std::vector<Spelling> spellings;
    chains.reserve(stage.size());
    for (const Case& c : stage) {
      // At least as far as the family's boundary: tangent-after-step's tangency is decided at the second step.
      chains.emplace_back(c.world.value(),
                          std::max(options_.steps, properties::steps_to_decide(cases_.families()[c.family])),
                          options_.level);
      spellings.push_back(spelling_of(cases_.families()[c.family]));
    }
    const auto units = jobs_.units(chains.size());
    std::vector<UnitOutcome> outcomes = jobs_.run(chains, units, options_.keep_going, spellings);
    for (std::size_t u = 0; u < units.size(); ++u) {
      const auto [from, to] = units[u];
      std::size_t k = from;
      for (const std::size_t f : outcomes[u].failed) {
        // A program that breaks on the first world of a run, before any answer, cannot be checked at all; on the
        // one case of --case, it breaks on that case's world, as its replay line says.
        const Failure& failure = *chains[from + f].failure();
        if (!failure.fault.empty() && failure.step == 1 && from + f == 0 && verdict_.cases == 0 &&
            verdict_.replayed == 0 && !options_.only_case)
          throw BrokenCandidate(failure.difference.decision.substr(std::string_view("none: ").size()));
        for (; k <= from + f; ++k) count(stage[k], chains[k]);
        FamilyResult& family = verdict_.families[stage[from + f].family];
        if (family.status != FamilyStatus::failed) {
          family.status = FamilyStatus::failed;
          failing_.push_back({stage[from + f], chains[from + f].steps(), std::move(*chains[from + f].failure())});
        }
        if (!options_.keep_going) return false;
      }
      if (outcomes[u].broken) std::rethrow_exception(outcomes[u].broken);
      for (; k < to; ++k) count(stage[k], chains[k]);
    }
    if (options_.progress) options_.progress(verdict_);
    return true;
  }

  // The cases a stage holds: kBatchCases for each job.
  std::size_t stage_size() const { return Jobs::kBatchCases * std::max(options_.jobs, 1u); }

  // The fixed schedule: cases 0 … cases − 1 of the shard's rounds, or the one case of --case (whatever --cases
  // says: the replay line of a report does not repeat it), with its ladder size if it has one.
  void fixed_cases() {
    const std::uint64_t F = cases_.families().size();
    std::vector<Case> stage;
    const std::uint64_t end = options_.only_case ? *options_.only_case + 1 : options_.cases;
    for (std::uint64_t c = 0; c < end; ++c) {
      throw_if_interrupted();  // between cases too: an engine in process has no request to notice it at
      const rc::Random random = stream_.split();  // case c's stream, whichever cases this run checks
      if (options_.only_case ? c != *options_.only_case : (c / F) % options_.shards != options_.shard) continue;
      if (!asked(cases_.family(c))) continue;
      stage.push_back(draw(c, random, options_.only_case ? options_.circles : std::nullopt));
      if (stage.size() == stage_size()) {
        if (!run_stage(stage)) return;
        stage.clear();
      }
    }
    if (!stage.empty()) run_stage(stage);
  }

  // The budget's schedule: rounds 0, 1, … of the small families, up to kSmallRounds of them or kSmallShare of the
  // budget; then the ladder (conform/ladder.hpp): stage k asks round k of the big families, each at the size the
  // ladder gives for the time left. The first stage of each part runs whatever the budget, so that every family
  // is checked.
  void budget_cases() {
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const double budget = *options_.budget;
    const std::uint64_t F = cases_.families().size();
    const auto round = [&](std::uint64_t q, bool big, std::optional<std::size_t> circles, std::vector<Case>& stage) {
      throw_if_interrupted();
      for (std::size_t f = 0; f < F; ++f)
        if (properties::is_big(cases_.families()[f]) == big && asked(f))
          stage.push_back(draw(q * F + f, random_of(q * F + f), circles));
    };
    std::vector<Case> stage;
    for (std::uint64_t q = 0; q < kSmallRounds; ++q) {
      round(q, false, std::nullopt, stage);
      if (stage.size() < stage_size() && q + 1 < kSmallRounds) continue;
      const bool first = verdict_.cases == 0;
      if (!first && elapsed() > kSmallShare * budget) break;
      if (!stage.empty() && !run_stage(stage)) return;
      stage.clear();
    }
    Ladder ladder(options_.max_circles);
    const auto cut_at = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                    std::chrono::duration<double>(budget * (1 + kCutGrace)));
    for (std::uint64_t q = 0;; ++q) {
      const std::optional<std::size_t> size = ladder.next(budget - elapsed());
      if (!size) break;
      stage.clear();
      round(q, true, size, stage);
      if (stage.empty()) break;
      const double before = elapsed();
      // The first stage runs whatever it takes; a later one is cut at the budget's end (conform/deadline.hpp),
      // its cases uncounted but for those before the cut that a failure in case order needs (run_stage).
      try {
        std::optional<StageCut> cut;
        if (q > 0) cut.emplace(cut_at);
        if (!run_stage(stage)) return;
      } catch (const StageCutOff&) {
        verdict_.cut_world = *size;
        return;
      }
      ladder.took(*size, elapsed() - before);
    }
  }

  // The budget's rounds of the small families: as many as the fixed schedule's default of 1000 cases has.
  static constexpr std::uint64_t kSmallRounds = 40;
  // The share of the budget after which no further round of the small families starts, leaving the rest to the
  // ladder's big worlds.
  static constexpr double kSmallShare = 0.25;
  // A ladder stage still running this share of the budget after its end is cut (conform/deadline.hpp): the
  // ladder plans each stage to end with time to spare (Ladder::kMargin), so this is for a world far slower than
  // the ones before it of its size, and a default run ends within 66 s.
  static constexpr double kCutGrace = 0.1;

  // Shrinks case c's failure (of the family with index `family`) and records it as the family's counterexample.
  void shrink(rc::Shrinkable<Circles> world, std::uint64_t c, std::size_t family, std::optional<std::size_t> circles,
              std::uint64_t steps, Failure failure) {
    const std::span<const properties::Family> families = cases_.families();
    shrink_spelling_ = spelling_of(families[family]);
    Counterexample counterexample;
    counterexample.shrink_path = {world.value()};
    counterexample.circles_before = world.value().size();
    // Each world on which a program hangs costs its deadline: a hang is shrunk a few worlds at most (the queries
    // count up to kMaxShrinkQueries from further on).
    int queries = failure.fault == name(Fault::hung) ? kMaxShrinkQueries - kMaxHangShrinkQueries : 0;
    shrink_until_ = std::chrono::steady_clock::now() + kMaxShrinkTime;
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
    if (options_.simplify && failure.fault.empty()) simplify(world.value(), steps, failure, counterexample);
    counterexample.family = properties::name(families[family]);
    counterexample.case_index = c;
    counterexample.replay = replay_command(candidate_.option(), options_, c, circles);
    if (!options_.save.empty()) {
      const StoredCounterexample stored{options_.profile, failure.input,   options_.level.text(), counterexample.family,
                                        candidate_.name(), options_.seed,   c,
                                        steps,             failure.step,    failure.expected,
                                        failure.actual,    failure.difference, failure.fault};
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
  // asked of the program started afresh). Once a signal has interrupted the check, or the shrinking's time is
  // spent, no world is asked: the counterexample is the world shrunk so far. `tries` counts the worlds asked.
  std::optional<Failure> still_fails(const Circles& w, std::uint64_t steps, const Failure& failure,
                                     std::uint64_t& tries) {
    if (interruption() || std::chrono::steady_clock::now() > shrink_until_) return std::nullopt;
    ++tries;
    Ending e = Ending::checked;
    std::optional<Failure> f;
    try {
      f = jobs_.first().run(w, steps, e, shrink_spelling_);
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
  Jobs jobs_;
  const Cases cases_{options_.profile, options_.max_circles};
  rc::Random stream_{options_.seed};
  std::vector<rc::Random> randoms_;
  std::vector<Failing> failing_;  // the first failing case of each family that fails, in case order
  std::chrono::steady_clock::time_point shrink_until_{};  // when shrinking the counterexample at hand stops
  Spelling shrink_spelling_ = Spelling::shortest;         // how the requests of the case being shrunk are spelled
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
  } catch (const Interrupted&) {
    // Recorded below, with a signal that came while a counterexample was shrunk.
  } catch (const BrokenCandidate& e) {
    // A fault that a signal caused (interrupt() killed the program) is the interruption, not the program's.
    if (!interruption()) {
      could_check = false;
      verdict.error = e.what();
    }
  } catch (const ConformError& e) {
    could_check = false;
    verdict.error = e.what();
  } catch (const spec::OutsideC& e) {  // a generated world conform's reference refuses: a bug of conform's own
    could_check = false;
    verdict.error = std::string("conform drew a world its reference refuses: ") + e.what();
  }
  // A signal ends the run as interrupted, whether it stopped a request, a case, or the shrinking of a
  // counterexample (which then reports the world shrunk so far).
  if (const int signal = interruption()) {
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
