// The conformance property: any step function over doubles, yours or ours, checked against the spec on worlds
// that reach its boundaries (properties/boundaries.hpp). Run it from your own GoogleTest with RapidCheck:
//
//   #include "properties/conformance.hpp"
//   #include <rapidcheck/gtest.h>
//   circles::properties::Circles my_step(const circles::properties::Circles& w);
//   RC_GTEST_PROP(my_engine, steps_as_the_spec_says, ()) { circles::properties::step_conforms(my_step); }
//
// and link circles::properties and rapidcheck_gtest. docs/properties.md works through an example, a right and
// a wrong step function, which tests/properties_example_test.cpp compiles and runs.
#pragma once

#include "properties/boundaries.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace circles::properties {

// A step function: w_1 for w_0, circle k of the answer the image of circle k of w_0 (the step protocol's
// contract, docs/protocol.md).
using Step = std::function<Circles(const Circles&)>;

// How close an answer must be. Decisions (velocities, and radii, which never change) must be exact at every
// level; positions must be the double nearest to the exact value (ulps = 0, "exact"), or within `ulps` units
// in the last place of it (1: "faithful"). Compared by value: −0 == +0.
struct Level {
  std::uint64_t ulps = 0;
  std::string text() const;  // "exact", "faithful", "ulps:K"
};
// "exact", "faithful" or "ulps:K". Throws std::invalid_argument with a message for --level.
Level parse_level(std::string_view text);

// What a conforming step answers for w: the exact step rounded to nearest, each coordinate (resolved:
// impl::step_all_pairs up to 64 circles, the double engine's step above, both of which tests/engine_test.cpp
// holds equal to the oracle; literal: the oracle's literal
// f (4) for each circle). No answer when a position leaves the double range (the protocol cannot carry it),
// or, in the literal profile, when w is outside its domain (outside_literal_domain).
enum class NoAnswer { overflow, outside_literal_domain };
std::variant<Circles, NoAnswer> expected_step(const Circles& w, Profile profile);

// The first coordinate at which `actual` differs from `expected` (the answer for `input`) at `level`.
struct Difference {
  std::size_t circle;
  spec::Field field;  // printed with spec::name: "px" … "r"
  double expected, actual;
  // Which decision differs, in words, with its section of docs/math.md: "the intersect test (3)
  // (docs/math.md#3-intersect--specintersect): circle 0 touches circle 1 but kept its own velocity", "the
  // least-contact rule e (8) (docs/math.md#8-e--spece): …", "none: the velocity is right, the position is not the
  // nearest double", or, for a radius (which no step changes), "none: the position and velocity are right, but
  // the radius changed, which no step does".
  std::string decision;
};
std::optional<Difference> compare(const Circles& input, const Circles& expected, const Circles& actual, Level level);

struct Options {
  Profile profile = Profile::resolved;
  Level level{};
  std::uint64_t steps = 1;  // chained: each step from the step function's own last answer (at least
                            // steps_to_decide of the world's family)
};

// The property body: draws a family of `options.profile` and a world of it (gen::boundary_case), tags the case
// with the family's name (RC_TAG), steps it `options.steps` times with `step` (steps_to_decide(family) times
// if more: twice for tangent-after-step, whose tangency is in w_1) and fails (RC_FAIL) at the first answer of
// the wrong length or that differs from expected_step of its input at `options.level`. A world whose next step
// has no answer ends the chain there. RapidCheck's report of a failure shows the case as
//   tangency, w_0 = {{0, 0, 60, 0, 1}, {2, 0, -60, 0, 1}}
// (the family, and w_0 with every number in the shortest form that reads back as the same double), and the
// failure as
//   step 1 of 1 (family tangency, resolved profile, level exact): circle 0, field vx: expected -0x1.ep+5 (-60),
//   got 0x1.ep+5 (60); which decision: the intersect test (3) (...): circle 0 touches circle 1 but kept its own
//   velocity
//   the world asked at step 1, w_0 = {{0, 0, 60, 0, 1}, {2, 0, -60, 0, 1}}
//   circle 0: expected {1, 0, -60, 0, 1}, got {1, 0, 60, 0, 1}
// where the world asked is the one of the step that failed: w_1 at step 2 of a chain.
void step_conforms(const Step& step, const Options& options = {});

// Runs step_conforms(step, options) as a RapidCheck property, as RC_GTEST_PROP would (RapidCheck's configuration,
// RC_PARAMS), and returns RapidCheck's report of the shrunk counterexample if it fails (the report above, after
// how many cases passed), or nothing if every case passes: for a test that requires a wrong step to be caught,
// instead of failing. Throws std::runtime_error if RapidCheck gives up or cannot run the property.
std::optional<std::string> find_counterexample(const Step& step, const Options& options = {});

}  // namespace circles::properties
