// The oracle's public face: worlds of both profiles built from plain circle lists, and their steps.
// The equations themselves are in spec/equations.hpp.
#pragma once

#include "spec/equations.hpp"

#include <vector>

namespace circles::spec {

// ── Literal profile: the seed to the letter ──────────────────────────────────────────────────────────

using LiteralWorld = World<Circle>;

// The set of the given circles: equal circles are one element. Throws OutsideC for r ≤ 0.
LiteralWorld literal_world(const std::vector<Circle>& circles);

// One step of (1), or the circles at which (8) has no value.
std::variant<LiteralWorld, Undefined<Circle>> literal_step(const LiteralWorld& w);

// ── Resolved profile: what implementations follow, and every tool's default ──────────────────────────

// A resolved world is a sequence; circle k of the result is the image of circle k of the input.
using Sequence = std::vector<Circle>;

// The tagged set {(k, c_k)} of a sequence. Throws OutsideC for r < 0.
World<Indexed> resolved_world(const Sequence& circles);
Sequence sequence(const World<Indexed>& w);

// One step of (1) in the resolved profile. Always defined: the lexicographic m is a total order.
// Throws OutsideC for r < 0.
Sequence resolved_step(const Sequence& w);

// The same step from doubles [px, py, vx, vy, r], with the exact result rounded to nearest, ties to even
// (the "correctly rounded oracle step" that the double engines are held to). Throws OutsideC for NaN,
// infinities and r < 0.
Circles resolved_step_rounded(const Circles& w);

}  // namespace circles::spec
