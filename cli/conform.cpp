#include "cli/conform.hpp"

#include "cli/corpus.hpp"
#include "cli/counterexample_svg.hpp"
#include "cli/json_number.hpp"
#include "properties/boundaries.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <charconv>
#include <span>
#include <variant>
#include <vector>

namespace circles::cli {
namespace {

using properties::NoAnswer;

// Shrinking asks the candidate at most this many worlds: enough for worlds of 8 circles, bounded for a slow one.
constexpr int kMaxShrinkQueries = 2000;

// A failure of one case: the step of the chain (1-based) of how many, its input, the two answers and what
// differs.
struct Failure {
  std::uint64_t step, steps;
  Circles input, expected, actual;
  Difference difference;
};

// How a chain that did not fail ended: every step checked; no step checked, because w_0 has no expected answer
// (its next world leaves the double range, or, replayed in the literal profile, it is outside the domain);
// or checked up to a world with no expected answer.
enum class Ending { checked, skipped, cut_short };

// One case's chain of steps, as Checker::run_all runs it.
struct Chain {
  Chain(Circles w_0, std::uint64_t steps_to_chain) : now(std::move(w_0)), steps(steps_to_chain) {}
  Circles now;                    // the world to ask next: w_0, then the candidate's last answer
  std::uint64_t steps, step = 0;  // the steps to chain, and the steps asked so far
  Ending ending = Ending::checked;
  std::optional<Failure> failure;
};

// The most cases conform asks the candidate about in one Checker::run_all, which sends every request whose
// world is known before reading their answers (ProcessCandidate also bounds the bytes in flight), so that they
// share one round trip through the pipes. A batch of requests ends sooner, at a case that chains another step:
// by default at each tangent-after-step case, one in 17, so about 14 requests a batch (docs/benchmarks.md);
// with --steps 2 or more, at every case, so 2. The bound matters when no case chains, and bounds the requests
// a failing run asks beyond the case-by-case run's.
constexpr std::size_t kBatchCases = 64;

class Checker {
 public:
  Checker(Candidate& candidate, const ConformOptions& options) : candidate_(candidate), options_(options) {}

  // Chains `steps` steps from w.
  std::optional<Failure> run(const Circles& w, std::uint64_t steps, Ending& ending) {
    Chain chain(w, steps);
    run_all(std::span(&chain, 1));
    ending = chain.ending;
    return std::move(chain.failure);
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
        if (chain.step >= chain.steps) continue;
        auto reference = properties::expected_step(chain.now, options_.profile);
        if (!std::holds_alternative<Circles>(reference)) {
          chain.ending = chain.step == 0 ? Ending::skipped : Ending::cut_short;
          continue;
        }
        asked.push_back(chain.now);
        expected.push_back(std::move(std::get<Circles>(reference)));
        whose.push_back(k);
        if (chain.step + 1 < chain.steps) {  // its next request waits for this answer
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
        Chain& chain = chains[whose[i]];
        ++chain.step;
        if (auto d = compare(asked[i], expected[i], answers[i], options_.level)) {
          chain.failure = Failure{chain.step, chain.steps, std::move(asked[i]), std::move(expected[i]),
                                  std::move(answers[i]), *d};
          return whose[i];
        }
        chain.now = std::move(answers[i]);
      }
      if (read.broken) throw *read.broken;
      first = next;
    }
    return chains.size();
  }

 private:
  Candidate& candidate_;
  const ConformOptions& options_;
  std::uint64_t next_id_ = 1;
};

void print_world(std::ostream& out, const std::string& title, const Circles& w) {
  out << "  " << title << ":\n";
  for (std::size_t k = 0; k < w.size(); ++k) {
    std::string line = "    #" + std::to_string(k) + " [";
    for (std::size_t f = 0; f < 5; ++f) {
      if (f) line += ", ";
      json_number::append_any(line, w[k][f]);
    }
    out << line << "]\n";
  }
}

std::filesystem::path picture_path(const ConformOptions& options, const std::string& stem) {
  if (!options.svg.empty()) return options.svg;
  if (!options.save.empty()) return options.save / (stem + ".svg");
  return {};
}

// Prints the counterexample, draws its picture and, for a new one, saves it. `found` says where it came from
// ("case 9 of seed 3 (family tangency), shrunk …" or "stored in DIR/F.json …"), `replay` how to see it again.
void report(std::ostream& out, const Candidate& candidate, const ConformOptions& options, const Failure& failure,
            const std::string& found, const std::string& replay, StoredCounterexample* to_save,
            const std::string& stem) {
  const Difference& d = failure.difference;
  const std::string profile = properties::name(options.profile);
  std::vector<std::string> head{
      "circles conform: " + candidate.name() + " does not conform (level " + options.level.text() + ", " + profile +
          " profile)",
      "counterexample: " + found,
      "  step " + std::to_string(failure.step) + " of " + std::to_string(failure.steps) + ", circle " +
          std::to_string(d.circle) + ", field " + properties::field_name(d.field) + ": expected " +
          json_number::decimal_and_hex(d.expected) + ", got " + json_number::decimal_and_hex(d.actual),
      "  which decision: " + d.decision,
  };
  for (const std::string& line : head) out << line << "\n";
  print_world(out, failure.step == 1 ? "the world asked (w_0)" : "the world asked (the candidate's own last answer)",
              failure.input);
  print_world(out,
              options.profile == Profile::literal ? "expected (the literal oracle's step, rounded to nearest)"
                                                  : "expected (the correctly rounded oracle step)",
              failure.expected);
  print_world(out, "answered", failure.actual);

  if (to_save && !options.save.empty()) {
    try {
      out << "saved: " << save(options.save, *to_save).string() << "\n";
    } catch (const CorpusError& e) {
      out << "saved: not saved: " << e.what() << "\n";
    }
  }
  if (const std::filesystem::path svg = picture_path(options, stem); !svg.empty()) {
    try {
      write_atomically(svg, counterexample_svg({failure.input, failure.expected, failure.actual, d.circle,
                                                options.profile, head}));
      out << "picture: " << svg.string() << "\n";
    } catch (const std::exception& e) {
      out << "picture: not drawn: " << e.what() << "\n";
    }
  }
  out << "replay: " << replay << "\n";
}

// "lattice 59, random-doubles 59, …", wrapped before 110 columns, each line indented.
void print_families(std::ostream& out, std::span<const properties::Family> families,
                    const std::vector<std::uint64_t>& checked) {
  std::string line = "  cases checked per family:";
  for (std::size_t f = 0; f < families.size(); ++f) {
    const std::string item =
        std::string(" ") + properties::name(families[f]) + " " + std::to_string(checked[f]) + (f + 1 < families.size() ? "," : "");
    if (line.size() + item.size() > 110) {
      out << line << "\n";
      line = "   ";
    }
    line += item;
  }
  out << line << "\n";
}

// Case c's family and generator: the families of the profile in turn.
class Cases {
 public:
  explicit Cases(Profile profile) : families_(properties::families(profile)) {
    for (const properties::Family f : families_) gens_.push_back(properties::gen::boundary_world(f, profile));
  }
  std::span<const properties::Family> families() const { return families_; }
  std::size_t family(std::uint64_t c) const { return static_cast<std::size_t>(c % families_.size()); }
  // Case c's world from its random stream. RapidCheck's sizes cycle 0 … 99 over a run (the families'
  // generators ignore it).
  rc::Shrinkable<Circles> world(std::uint64_t c, const rc::Random& random) const {
    return gens_[family(c)](random, static_cast<int>(c % rc::kNominalSize));
  }

 private:
  std::span<const properties::Family> families_;
  std::vector<rc::Gen<Circles>> gens_;
};

}  // namespace

std::vector<Circles> case_worlds(std::uint64_t seed, std::uint64_t cases, Profile profile) {
  const Cases all(profile);
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

int conform(Candidate& candidate, const ConformOptions& options, std::ostream& out) {
  // Paths first: a --save or --svg that cannot be used is a usage error, found before any case runs.
  if (!options.save.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.save, error);
    if (error || !std::filesystem::is_directory(options.save))
      throw ConformError("--save: cannot use the directory " + options.save.string() +
                         (error ? ": " + error.message() : ": it is not a directory"));
  }
  if (!options.svg.empty()) {
    const std::filesystem::path parent = options.svg.parent_path().empty() ? "." : options.svg.parent_path();
    if (!std::filesystem::is_directory(parent))
      throw ConformError("--svg: cannot write " + options.svg.string() + ": the directory " + parent.string() +
                         " does not exist");
  }
  const std::string profile = properties::name(options.profile);
  const std::string replay_options = " --level " + options.level.text() +
                                     (options.steps > 1 ? " --steps " + std::to_string(options.steps) : "") +
                                     (options.profile == Profile::literal ? " --profile literal" : "");
  Checker checker(candidate, options);

  // 1. The corpus, replayed first.
  std::uint64_t replayed = 0, not_replayed = 0;
  if (!options.save.empty()) {
    std::vector<std::pair<std::filesystem::path, StoredCounterexample>> corpus;
    try {
      corpus = load_corpus(options.save);
    } catch (const CorpusError& e) {
      throw ConformError(std::string("--save: ") + e.what());
    }
    for (const auto& [file, stored] : corpus) {
      Ending ending = Ending::checked;
      const std::optional<Failure> failure = checker.run(stored.world, options.steps, ending);
      if (ending == Ending::skipped) {
        ++not_replayed;
        continue;
      }
      ++replayed;
      if (!failure) continue;
      std::string found = "stored in " + file.string() + ", replayed first";
      if (stored.seed && stored.case_index)
        found += " (found as case " + std::to_string(*stored.case_index) + " of seed " + std::to_string(*stored.seed) +
                 (stored.family.empty() ? "" : ", family " + stored.family) + ")";
      report(out, candidate, options, *failure, found,
             "--save " + options.save.string() + replay_options + " (the corpus is replayed first)", nullptr,
             file.stem().string());
      return 1;
    }
  }

  // 2. The generated cases, in rounds of one case per family.
  const Cases all(options.profile);
  const std::span<const properties::Family> families = all.families();
  const std::uint64_t F = families.size();
  std::vector<std::uint64_t> drawn(F, 0), checked(F, 0);
  std::uint64_t cases = 0, skipped = 0, cut_short = 0;
  rc::Random stream(options.seed);
  // The cases of this run, checked kBatchCases at a time (Checker::run_all), then counted and, for the first
  // that fails, shrunk and reported, in order: the verdict is the sequential run's.
  struct Case {
    std::uint64_t index;
    std::size_t family;
    rc::Shrinkable<Circles> world;
  };
  std::vector<Case> batch;
  std::vector<Chain> chains;
  // Checks the batch; returns the index of its failing case, if one fails.
  const auto check_batch = [&]() -> std::optional<std::size_t> {
    const std::size_t failed = checker.run_all(chains);
    for (std::size_t k = 0; k < chains.size() && k <= failed; ++k) {
      ++cases;
      ++drawn[batch[k].family];
      if (chains[k].ending == Ending::skipped) ++skipped;
      else ++checked[batch[k].family];
      cut_short += chains[k].ending == Ending::cut_short;
    }
    if (failed < chains.size()) return failed;
    batch.clear();
    chains.clear();
    return std::nullopt;
  };
  // --case I replays case I whatever --cases says: the replay line of a report does not repeat it.
  const std::uint64_t end = options.only_case ? *options.only_case + 1 : options.cases;
  std::optional<std::size_t> failed;
  for (std::uint64_t c = 0; c < end && !failed; ++c) {
    const rc::Random random = stream.split();  // case c's stream, whichever cases this run checks
    if (options.only_case ? c != *options.only_case : (c / F) % options.shards != options.shard) continue;
    const std::size_t family = all.family(c);
    // At least as far as the family's boundary: tangent-after-step's tangency is decided at the second step.
    const std::uint64_t steps = std::max(options.steps, properties::steps_to_decide(families[family]));
    batch.push_back(Case{c, family, all.world(c, random)});
    chains.emplace_back(batch.back().world.value(), steps);
    if (batch.size() == kBatchCases) failed = check_batch();
  }
  if (!failed && !batch.empty()) failed = check_batch();
  if (failed) {
    const auto& [c, family, drawn_world] = batch[*failed];
    rc::Shrinkable<Circles> world = drawn_world;
    const std::uint64_t steps = chains[*failed].steps;
    std::optional<Failure> failure = std::move(chains[*failed].failure);
    // Shrink: take the first simpler world that still fails, until none does (or the budget is spent).
    const std::size_t circles_before = world.value().size();
    int shrinks = 0, queries = 0;
    for (bool progress = true; progress && queries < kMaxShrinkQueries;) {
      progress = false;
      auto candidates = world.shrinks();
      while (auto next = candidates.next()) {
        if (++queries > kMaxShrinkQueries) break;
        Ending e = Ending::checked;
        std::optional<Failure> f;
        try {
          f = checker.run(next->value(), steps, e);
        } catch (const BrokenCandidate&) {
          // A simpler world on which the candidate breaks (crashes, hangs, writes a malformed line) does not
          // show the wrong answer being shrunk; the next is asked of the program started afresh.
          continue;
        }
        if (f) {
          world = *next;
          failure = std::move(f);
          ++shrinks;
          progress = true;
          break;
        }
      }
    }
    const std::string family_name = properties::name(families[family]);
    StoredCounterexample stored{options.profile, failure->input, options.level.text(), family_name, candidate.name(),
                                options.seed, c, steps, failure->step, failure->expected, failure->actual,
                                failure->difference};
    report(out, candidate, options, *failure,
           "case " + std::to_string(c) + " of seed " + std::to_string(options.seed) + " (family " + family_name +
               "), shrunk from " + std::to_string(circles_before) + " to " + std::to_string(world.value().size()) +
               " circles in " + std::to_string(shrinks) + " steps",
           "--seed " + std::to_string(options.seed) + " --case " + std::to_string(c) + replay_options, &stored,
           stem(stored));
    return 1;
  }
  candidate.finish();

  // 3. Every family must have been checked: a family with no case is a gap in the check, not a pass.
  if (!options.only_case && options.cases > 0)
    for (std::size_t f = 0; f < F; ++f) {
      if (checked[f] > 0) continue;
      const std::string family = properties::name(families[f]);
      if (drawn[f] == 0)
        throw ConformError("no case of the family " + family + " was checked: each round of " + std::to_string(F) +
                           " cases draws every family of the " + profile + " profile once, and this run " +
                           (options.shards > 1 ? "(shard " + std::to_string(options.shard) + "/" +
                                                     std::to_string(options.shards) + ") "
                                               : std::string()) +
                           "checked " + std::to_string(cases) + "; raise --cases to at least " +
                           std::to_string(F * options.shards));
      throw ConformError("no case of the family " + family + " was checked: all " + std::to_string(drawn[f]) +
                         " of its worlds were skipped (their next world leaves the double range)");
    }

  out << "circles conform: " << candidate.name() << " conforms: " << cases << " cases";
  if (skipped) out << " (" << skipped << " skipped: their next world leaves the double range)";
  out << ", " << options.steps << " step" << (options.steps == 1 ? "" : "s") << " each";
  std::string longer;  // "tangent-after-step 2": the families chained further, to the step that decides them
  for (std::size_t f = 0; f < F; ++f)
    if (checked[f] > 0 && properties::steps_to_decide(families[f]) > options.steps)
      longer += (longer.empty() ? "" : ", ") + std::string(properties::name(families[f])) + " " +
                std::to_string(properties::steps_to_decide(families[f]));
  if (!longer.empty()) out << " (" << longer << ": chained to the step that decides its boundary)";
  out << ", level " << options.level.text() << ", seed " << options.seed << ", " << profile << " profile";
  if (options.shards > 1) out << ", shard " << options.shard << "/" << options.shards;
  out << "\n";
  if (cases > 0) print_families(out, families, checked);
  if (cut_short)
    out << "  " << cut_short << " chains ended early: their next world leaves the double range"
        << (options.profile == Profile::literal ? " or the literal domain" : "") << "\n";
  if (!options.save.empty()) {
    out << "  corpus: " << replayed << " stored counterexample" << (replayed == 1 ? "" : "s") << " replayed from "
        << options.save.string();
    if (not_replayed)
      out << " (" << not_replayed << " not: no expected answer"
          << (options.profile == Profile::literal ? ", outside the literal domain or beyond the double range" : ", beyond the double range")
          << ")";
    out << "\n";
  }
  return 0;
}

}  // namespace circles::cli
