#include "properties/conformance.hpp"

#include "properties/chain.hpp"

#include "impl/engine.hpp"
#include "impl/predicate.hpp"
#include "spec/oracle.hpp"

#include <rapidcheck.h>
#include <rapidcheck/detail/Results.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace circles::properties {
namespace {

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

// The two decisions of a step, each with its section of docs/math.md.
const std::string kIntersect = "the intersect test (3) (docs/math.md#3-intersect--specintersect): ";
const std::string kLeastContact = "the least-contact rule e (8) (docs/math.md#8-e--spece): ";

// Which decision of circle k's step differs (at `field`, the first that does): its contacts by (3), exactly, on
// the input doubles. A radius is judged only when the position and velocity before it are right, and no decision
// touches it.
std::string decision(const Circles& in, std::size_t k, spec::Field field, const Circles& expected,
                     const Circles& actual) {
  if (field == spec::Field::r)
    return "none: the position and velocity are right, but the radius changed, which no step does";
  const auto same_velocity = [](const spec::CircleDoubles& a, const spec::CircleDoubles& b) {
    return a[2] == b[2] && a[3] == b[3];
  };
  if (same_velocity(expected[k], actual[k])) return "none: the velocity is right, the position is not the nearest double";
  std::vector<std::size_t> contacts;
  for (std::size_t j = 0; j < in.size(); ++j)
    if (j != k && impl::intersect_exact(in[k][0], in[k][1], in[k][4], in[j][0], in[j][1], in[j][4]))
      contacts.push_back(j);
  const std::string circle = "circle " + std::to_string(k);
  if (contacts.empty()) return kIntersect + circle + " touches no circle, yet its velocity changed";
  // The velocity of a contact that is not the least is e (8)'s fault, even where it equals the circle's own: the
  // contacts were found (a program that keeps only some of them takes the least of those it kept).
  for (const std::size_t j : contacts)
    if (same_velocity(actual[k], in[j]))
      return kLeastContact + circle + " took the velocity of circle " + std::to_string(j) +
             ", a contact but not the least one" +
             (same_velocity(actual[k], in[k]) ? " (the same as its own)" : "");
  if (same_velocity(actual[k], in[k]))
    return kIntersect + circle + " touches circle " + std::to_string(contacts.front()) +
           (contacts.size() > 1 ? " and others" : "") + " but kept its own velocity";
  return kLeastContact + circle + " took a velocity that none of its contacts has";
}

std::string hex(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%a", x);
  return text;
}

// The shortest decimal that reads back as x ("0.1", "-0", "5e-324"), which C++ and JSON read alike.
std::string shortest(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

// "{px, py, vx, vy, r}" and "{{...}, {...}}": a circle and a world as C++ initializers of CircleDoubles and Circles.
std::string circle_text(const spec::CircleDoubles& c) {
  std::string text = "{";
  for (std::size_t f = 0; f < c.size(); ++f) text += (f == 0 ? "" : ", ") + shortest(c[f]);
  return text + "}";
}
std::string world_text(const Circles& w) {
  std::string text = "{";
  for (std::size_t k = 0; k < w.size(); ++k) text += (k == 0 ? "" : ", ") + circle_text(w[k]);
  return text + "}";
}

// A failure of the property with `message` alone as its description (RC_FAIL would add our file, line and
// source text).
[[noreturn]] void fail(std::string message) {
  throw rc::detail::CaseResult(rc::detail::CaseResult::Type::Failure, std::move(message));
}

}  // namespace

// A case of step_conforms, which RapidCheck shows in a counterexample under this type's name: its own form of a
// double has 6 significant digits, which cannot reproduce a world of ulps.
struct StepConformsCase {
  Family family;
  Circles world;
};
void showValue(const StepConformsCase& c, std::ostream& os) {
  os << name(c.family) << ", w_0 = " << world_text(c.world);
}

namespace {

// The most circles expected_step steps with step_all_pairs; above, with the double engine, whose set-up costs
// more than testing the 2016 pairs of 64 circles.
constexpr std::size_t kAllPairsUpTo = 64;

bool finite(const Circles& w) {
  for (const auto& c : w)
    for (const double x : c)
      if (!std::isfinite(x)) return false;
  return true;
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

std::variant<Circles, NoAnswer> expected_step(const Circles& w, Profile profile) {
  if (profile == Profile::resolved) {
    // Small worlds: impl::step_all_pairs, the exact step with every pair tested (intersect_exact,
    // advance_rounded), 50-100 times faster than the oracle. Big worlds: the double engine's one step
    // (its broad phase, one list for one step), O(n log n + contacts) where step_all_pairs is O(n²); both are
    // held equal to the oracle (tests/engine_test.cpp), so that conform's time per case stays small next to
    // the program's, even at 10^6 circles.
    try {
      if (w.size() <= kAllPairsUpTo) return impl::step_all_pairs(impl::World{w}).circles();
      impl::DoubleEngine engine(impl::World{w}, impl::EngineOptions{.threads = 0, .keep_pairs = false, .horizon = 0});
      engine.step();
      return engine.world().circles();
    } catch (const impl::PositionOverflow&) {
      return NoAnswer::overflow;
    }
  }
  if (outside_literal_domain(w)) return NoAnswer::outside_literal_domain;
  // The literal oracle itself: f (4) of each circle in the set W, which inside the domain is defined and
  // one-to-one, so the image of circle k is answer k.
  std::vector<spec::Circle> list;
  list.reserve(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) list.push_back(spec::from_doubles(w[k], k, spec::Radii::positive));
  const spec::LiteralWorld W = spec::literal_world(list);
  Circles out;
  out.reserve(w.size());
  for (const spec::Circle& c : list) {
    const std::optional<spec::Circle> image = spec::f(c, W);
    if (!image) throw std::logic_error("expected_step: (8) undefined inside the literal domain, which cannot happen");
    out.push_back(spec::nearest_doubles(*image));
  }
  if (!finite(out)) return NoAnswer::overflow;
  return out;
}

std::optional<Difference> compare(const Circles& input, const Circles& expected, const Circles& actual, Level level) {
  for (std::size_t k = 0; k < expected.size(); ++k)
    for (std::size_t f = 0; f < expected[k].size(); ++f) {
      const double e = expected[k][f], a = actual[k][f];
      const spec::Field field = spec::Field(f);
      // Velocities and radii are copied, never computed: exact at every level. Positions within the level.
      const bool position = field == spec::Field::px || field == spec::Field::py;
      const bool equal = position ? std::isfinite(a) && ulps_between(e, a) <= level.ulps : e == a;
      if (!equal) return Difference{k, field, e, a, decision(input, k, field, expected, actual)};
    }
  return std::nullopt;
}

void step_conforms(const Step& step, const Options& options) {
  const StepConformsCase drawn = *rc::gen::map(gen::boundary_case(options.profile), [](std::pair<Family, Circles> c) {
    return StepConformsCase{c.first, std::move(c.second)};
  });
  const Family family = drawn.family;  // a variable, not a structured binding: the lambdas below capture it
  RC_TAG(name(family));
  Chain chain(drawn.world, std::max(options.steps, steps_to_decide(family)), options.level);
  // "step 2 of 3 (family tangency, resolved profile, level exact)"
  const auto which = [&](std::uint64_t s) {
    return "step " + std::to_string(s) + " of " + std::to_string(chain.steps()) + " (family " + name(family) + ", " +
           name(options.profile) + " profile, level " + options.level.text() + ")";
  };
  const auto asked = [](std::uint64_t s, const Circles& w) {
    return "the world asked at step " + std::to_string(s) + ", w_" + std::to_string(s - 1) + " = " + world_text(w);
  };
  while (chain.going()) {
    auto expected = expected_step(chain.input(), options.profile);
    if (!std::holds_alternative<Circles>(expected)) return;
    Circles actual = step(chain.input());
    if (actual.size() != chain.input().size())
      fail(which(chain.step() + 1) + ": asked " + std::to_string(chain.input().size()) + " circles, answered " +
              std::to_string(actual.size()) + "\n" + asked(chain.step() + 1, chain.input()));
    if (!chain.judge(std::move(actual), std::move(std::get<Circles>(expected)))) {
      const ChainFailure& f = *chain.failure();
      const Difference& d = f.difference;
      fail(which(f.step) + ": circle " + std::to_string(d.circle) + ", field " + spec::name(d.field) + ": expected " +
              hex(d.expected) + " (" + shortest(d.expected) + "), got " + hex(d.actual) + " (" + shortest(d.actual) +
              "); which decision: " + d.decision + "\n" + asked(f.step, f.input) + "\ncircle " +
              std::to_string(d.circle) + ": expected " + circle_text(f.expected[d.circle]) + ", got " +
              circle_text(f.actual[d.circle]));
    }
  }
}

std::optional<std::string> find_counterexample(const Step& step, const Options& options) {
  const rc::detail::TestResult result = rc::detail::checkTestable([&] { step_conforms(step, options); });
  std::ostringstream report;
  rc::detail::FailureResult failure;
  if (result.match(failure)) {
    rc::detail::printResultMessage(failure, report);
    return report.str();
  }
  if (rc::detail::SuccessResult success; result.match(success)) return std::nullopt;
  rc::detail::printResultMessage(result, report);
  throw std::runtime_error("find_counterexample: RapidCheck did not finish the property: " + report.str());
}

}  // namespace circles::properties
