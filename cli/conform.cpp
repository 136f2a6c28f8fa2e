#include "cli/conform.hpp"

#include "cli/json_number.hpp"
#include "impl/engine.hpp"
#include "impl/predicate.hpp"
#include "properties/generators.hpp"
#include "spec/circle.hpp"
#include "spec/oracle.hpp"

#include <rapidcheck.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace circles::cli {
namespace {

constexpr const char* kFieldName[] = {"px", "py", "vx", "vy", "r"};
// Shrinking asks the candidate at most this many worlds: enough for worlds of 8 circles, bounded for a slow one.
constexpr int kMaxShrinkQueries = 2000;

// The distance in units in the last place between two finite doubles: their rank among the doubles, with
// −0 and +0 one rank (bit patterns of negatives reflected below zero).
std::uint64_t ulps_between(double a, double b) {
  const auto rank = [](double x) {
    const auto i = std::bit_cast<std::int64_t>(x);
    return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
  };
  const std::int64_t ra = rank(a), rb = rank(b);
  return ra >= rb ? static_cast<std::uint64_t>(ra) - static_cast<std::uint64_t>(rb)
                  : static_cast<std::uint64_t>(rb) - static_cast<std::uint64_t>(ra);
}

std::string decimal_and_hex(double x) {
  std::string text;
  json_number::append(text, x);
  char hex[64];
  std::snprintf(hex, sizeof hex, "%a", x);
  return text + " (" + hex + ")";
}

// Which decision of circle k's step differs: its contacts by (3), exactly, on the input doubles.
std::string decision(const Circles& in, std::size_t k, const Circles& expected, const Circles& actual) {
  const auto same_velocity = [](const std::array<double, 5>& a, const std::array<double, 5>& b) {
    return a[2] == b[2] && a[3] == b[3];
  };
  if (same_velocity(expected[k], actual[k])) return "none: the velocity is right, the position is not the nearest double";
  std::vector<std::size_t> contacts;
  for (std::size_t j = 0; j < in.size(); ++j)
    if (j != k && impl::intersect_exact(in[k][0], in[k][1], in[k][4], in[j][0], in[j][1], in[j][4]))
      contacts.push_back(j);
  const std::string circle = "circle " + std::to_string(k);
  if (contacts.empty()) return "intersect (3): " + circle + " touches no circle, yet its velocity changed";
  if (same_velocity(actual[k], in[k]))
    return "intersect (3): " + circle + " touches circle " + std::to_string(contacts.front()) +
           (contacts.size() > 1 ? " and others" : "") + " but kept its own velocity";
  for (const std::size_t j : contacts)
    if (same_velocity(actual[k], in[j]))
      return "the choice of e (8): " + circle + " took the velocity of circle " + std::to_string(j) +
             ", a contact but not the least one";
  return "the choice of e (8): " + circle + " took a velocity that none of its contacts has";
}

rc::Gen<Circles> worlds() {
  // Half the cases from the suite's exact worlds (copies, ties, exact tangencies), rounded to doubles; half
  // with every field from finite_double (every binade, subnormals, ±0, near DBL_MAX).
  const auto rounded = rc::gen::map(properties::gen::world(spec::Radii::non_negative, 8),
                                    [](const std::vector<spec::Circle>& w) {
                                      Circles out;
                                      for (const spec::Circle& c : w) out.push_back(spec::nearest_doubles(c));
                                      return out;
                                    });
  const auto finite = [](const Circles& w) {
    for (const auto& c : w)
      for (const double x : c)
        if (!std::isfinite(x)) return false;
    return true;
  };
  return rc::gen::oneOf(rc::gen::suchThat(rounded, finite),
                        properties::gen::double_world(8, properties::gen::finite_double()));
}

// The expected answer: impl::step_all_pairs, the exact step with every pair tested (intersect_exact,
// advance_rounded), which tests/engine_test.cpp holds equal to spec::resolved_step_rounded on every world the
// property suite generates; 50-100 times faster than the oracle on these small worlds. Nothing when a position
// leaves the double range.
std::optional<Circles> expected_step(const Circles& w) {
  try {
    return impl::step_all_pairs(impl::World{w}).circles();
  } catch (const impl::PositionOverflow&) {
    return std::nullopt;
  }
}

// A failure of one case: the step of the chain (1-based), its input, the two answers and what differs.
struct Failure {
  std::uint64_t step;
  Circles input, expected, actual;
  Difference difference;
};

class Checker {
 public:
  Checker(Candidate& candidate, const ConformOptions& options) : candidate_(candidate), options_(options) {}

  // Runs the chain from w; nullopt when it conforms. `skipped` is set when the oracle leaves the double range
  // first (the protocol cannot carry the question).
  std::optional<Failure> run(const Circles& w, bool& skipped) {
    skipped = false;
    Circles now = w;
    for (std::uint64_t step = 1; step <= options_.steps; ++step) {
      const std::optional<Circles> reference = expected_step(now);
      if (!reference) {
        skipped = true;
        return std::nullopt;
      }
      const Circles& expected = *reference;
      const Circles actual = candidate_.answer(now, next_id_++);
      if (auto d = compare(now, expected, actual, options_.level)) return Failure{step, now, expected, actual, *d};
      now = actual;
    }
    return std::nullopt;
  }

  std::uint64_t queries() const { return next_id_; }

 private:
  Candidate& candidate_;
  const ConformOptions& options_;
  std::uint64_t next_id_ = 1;
};

void print_world(std::ostream& out, const char* title, const Circles& w) {
  out << "  " << title << ":\n";
  for (std::size_t k = 0; k < w.size(); ++k) {
    std::string line = "    #" + std::to_string(k) + " [";
    for (std::size_t f = 0; f < 5; ++f) {
      if (f) line += ", ";
      json_number::append(line, w[k][f]);
    }
    out << line << "]\n";
  }
}

}  // namespace

std::string Level::text() const {
  if (ulps == 0) return "exact";
  if (ulps == 1) return "faithful";
  return "ulps:" + std::to_string(ulps);
}

Level parse_level(std::string_view text) {
  if (text == "exact") return Level{0};
  if (text == "faithful") return Level{1};
  if (text.starts_with("ulps:")) {
    std::uint64_t k = 0;
    const std::string_view digits = text.substr(5);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), k);
    if (error == std::errc{} && end == digits.data() + digits.size() && !digits.empty()) return Level{k};
  }
  throw std::invalid_argument("--level: \"" + std::string(text) + "\" is not exact, faithful or ulps:K (K an integer)");
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

std::optional<Difference> compare(const Circles& input, const Circles& expected, const Circles& actual, Level level) {
  for (std::size_t k = 0; k < expected.size(); ++k)
    for (int f = 0; f < 5; ++f) {
      const double e = expected[k][static_cast<std::size_t>(f)], a = actual[k][static_cast<std::size_t>(f)];
      // Velocities and radii are copied, never computed: exact at every level. Positions within the level.
      const bool position = f < 2;
      const bool equal = position ? ulps_between(e, a) <= level.ulps : e == a;
      if (!equal) return Difference{k, f, e, a, decision(input, k, expected, actual)};
    }
  return std::nullopt;
}

int conform(Candidate& candidate, const ConformOptions& options, std::ostream& out) {
  Checker checker(candidate, options);
  const rc::Gen<Circles> gen = worlds();
  rc::Random stream(options.seed);
  std::uint64_t checked = 0, skipped = 0;
  for (std::uint64_t c = 0; c < options.cases; ++c) {
    const rc::Random random = stream.split();  // case c's stream, whichever cases this run checks
    if (options.only_case ? c != *options.only_case : c % options.shards != options.shard) continue;
    // RapidCheck's sizes cycle 0 … 99 over a run: small worlds first, then larger ones.
    rc::Shrinkable<Circles> world = gen(random, static_cast<int>(c % rc::kNominalSize));
    bool skip = false;
    std::optional<Failure> failure = checker.run(world.value(), skip);
    ++checked;
    skipped += skip;
    if (!failure) continue;
    // Shrink: take the first simpler world that still fails, until none does (or the budget is spent).
    const std::size_t circles_before = world.value().size();
    int shrinks = 0, queries = 0;
    for (bool progress = true; progress && queries < kMaxShrinkQueries;) {
      progress = false;
      auto candidates = world.shrinks();
      while (auto next = candidates.next()) {
        if (++queries > kMaxShrinkQueries) break;
        bool s = false;
        if (auto f = checker.run(next->value(), s)) {
          world = *next;
          failure = std::move(f);
          ++shrinks;
          progress = true;
          break;
        }
      }
    }
    const Difference& d = failure->difference;
    out << "circles conform: " << candidate.name() << " does not conform (level " << options.level.text()
        << ", resolved profile)\n";
    out << "counterexample: case " << c << " of seed " << options.seed << ", shrunk from " << circles_before
        << " to " << world.value().size() << " circles in " << shrinks << " steps\n";
    out << "  step " << failure->step << " of " << options.steps << ", circle " << d.circle << ", field "
        << kFieldName[d.field] << ": expected " << decimal_and_hex(d.expected) << ", got "
        << decimal_and_hex(d.actual) << "\n";
    out << "  which decision: " << d.decision << "\n";
    print_world(out, failure->step == 1 ? "the world asked (w_0)" : "the world asked (the candidate's own last answer)",
                failure->input);
    print_world(out, "expected (the correctly rounded oracle step)", failure->expected);
    print_world(out, "answered", failure->actual);
    out << "replay: --seed " << options.seed << " --case " << c << (options.steps > 1 ? " --steps " + std::to_string(options.steps) : "")
        << " --level " << options.level.text() << "\n";
    return 1;
  }
  candidate.finish();
  out << "circles conform: " << candidate.name() << " conforms: " << checked << " cases";
  if (skipped) out << " (" << skipped << " skipped: their next world leaves the double range)";
  out << ", " << options.steps << " step" << (options.steps == 1 ? "" : "s") << " each, level "
      << options.level.text() << ", seed " << options.seed;
  if (options.shards > 1) out << ", shard " << options.shard << "/" << options.shards;
  out << "\n";
  return 0;
}

}  // namespace circles::cli
