// The run-time-against-error benchmark (docs/accuracy.md) and the stability stress (docs/stability.md):
// engines that differ in their arithmetic, each run beside the exact trajectory, which is impl::ExactEngine's
// exact state (tests/exact_engine_test.cpp and tests/accuracy_test.cpp hold it to the oracle).
//
// Definitions, for a variant after step t (world t; step t makes world t from world t − 1):
//   error     max over circles k and both coordinates of |p_k − p*_k|, p* the exact position, a rational.
//             Computed exactly; reported as its nearest double.
//   ulps      max of |p_k − p*_k| / ulp(p*_k), with ulp(x) = 2^(max(⌊log2 |x|⌋, −1022) − 52), the spacing of
//             the doubles in x's binade (2^-1074 for x = 0): a world of correctly rounded positions is within
//             0.5 of it, a world of floats within about 2^28.
//   decision  at step t, each circle k takes the least circle it intersects in world t − 1 (the order of (7)
//             and (8) in the resolved profile), or none. A variant departs at the first step at which some
//             circle's decision differs from the exact run's; from then on the two worlds are different
//             trajectories, not the same one rounded differently.
// Every variant is stepped in the resolved profile (worlds are sequences, circle k stays circle k).
#pragma once

#include "impl/engine.hpp"
#include "spec/oracle.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace circles::bench::accuracy {

using spec::Circles;
// decisions[k]: the circle that circle k takes its velocity from at the next step; k itself when none.
using Decisions = std::vector<std::uint32_t>;

// ── The variants ─────────────────────────────────────────────────────────────────────────────────────

// The double variants are impl::BasicEngine over an arithmetic policy (impl/arithmetic.hpp), one thread, so
// that the stepping code, the layout and the broad phase are the same and only the arithmetic differs.
enum class Kind {
  float_naive,      // BasicEngine<FloatNaiveArithmetic>: √ test and p + v·(1/60) in float, input rounded to float
  naive_sqrt,       // BasicEngine<NaiveSqrtArithmetic>: √(dx² + dy²) ≤ ra + rb and p + v·RN(1/60), doubles
  naive_squares,    // impl::NaiveEngine: (ra + rb)² ≥ dx² + dy² and p + v·RN(1/60), doubles
  exact_decisions,  // BasicEngine<ExactDecisionArithmetic>: the exact test, the naive update
  double_engine,    // impl::DoubleEngine: the exact test, RN(p + v/60) (the correctly rounded oracle step)
  exact,            // impl::ExactEngine: no rounding in the state
  oracle,           // spec::resolved_step: the oracle's transcription of (1)-(9), rationals, O(n²) sets
};
inline constexpr Kind kKinds[] = {Kind::float_naive, Kind::naive_sqrt,   Kind::naive_squares, Kind::exact_decisions,
                                  Kind::double_engine, Kind::exact,        Kind::oracle};

// "float_naive", "naive_sqrt", ...: the CSV's variant column.
std::string_view id_of(Kind kind);

class Variant {
 public:
  virtual ~Variant() = default;
  // One step; throws impl::PositionOverflow (state unchanged) where the variant reports one.
  virtual void step() = 0;
  // The decisions of the next step, computed as the variant's own step computes them: for the double
  // engines, the engine's candidate pairs (BasicEngine::candidates), the policy's intersect and
  // World::precedes; for the exact ones, spec::intersect and the lexicographic order on the exact state.
  virtual Decisions decisions() const = 0;
  // The current world: doubles for the double engines, rationals for the exact ones.
  virtual std::variant<impl::World, spec::Sequence> state() const = 0;
};

// The variant on `scene` (exact doubles). float_naive first rounds every field to float; a field beyond the
// float range becomes ±infinity and impl::World refuses it with spec::OutsideC, which this passes on.
std::unique_ptr<Variant> make_variant(Kind kind, const Circles& scene);

// How many fields of `scene` change when rounded to float (what float_naive starts from instead).
std::size_t float_changes(const Circles& scene);

// The exact run's decisions on a world of rationals: candidate pairs from boxes that contain the exact ones,
// then spec::intersect, the least by spec::lex_compare and then by index.
Decisions exact_decisions(const spec::Sequence& w);

// One step of the resolved profile on rationals, (4) with i(c, W) found through the boxes of exact_decisions
// instead of over all of W: an exact stepper that shares no code with impl::ExactEngine and costs
// O(n log n + pairs) rationals a step instead of the oracle's O(n²), for checking the exact engine over long runs.
spec::Sequence swept_step(const spec::Sequence& w);

// ── Following a variant beside the exact run ─────────────────────────────────────────────────────────

// The largest error seen, by the definitions at the top of this file.
struct Error {
  spec::Q abs = 0;
  double ulps = 0;
  // Adds world w (doubles) against the exact world and its rounding (ExactEngine::world()).
  void add(const impl::World& w, const spec::Sequence& exact, const impl::World& rounded);
  // Adds a world of rationals.
  void add(const spec::Sequence& w, const spec::Sequence& exact);
  void add(const Error& other);

 private:
  double abs_below_ = 0;  // a double ≤ abs, for the filter
  void add_one(double p, const spec::Q& exact, double rounded);
};

// The first decision that differs: at step `step`, circle `circle` took `took` where the exact run took
// `exact_took` (each the circle's own index for none).
struct Departure {
  std::uint64_t step = 0;
  std::uint32_t circle = 0, took = 0, exact_took = 0;
  // "circle 3 took none where the exact run took circle 4" and the like.
  std::string describe() const;
};

struct Outcome {
  Kind kind = Kind::exact;
  std::uint64_t steps = 0;               // worlds 1 … steps were compared with the exact run
  std::optional<Departure> departure;
  Error error;                           // over worlds 0 … steps
  Error error_before;                    // over worlds before the departure's step (all of them if none)
  std::string input;                     // how the variant's input differs from the scene ("" if it does not)
  std::string end;                       // why it stopped before the steps asked ("" if it did not)
  bool non_finite = false;               // a NaN or ±infinity was seen in a world (the engines must throw)
};

// Steps `kinds` beside the exact run for `steps` steps (the oracle for at most `oracle_steps`), comparing
// every world and every step's decisions. A variant stops at its own exception (recorded in `end`); all stop
// where the exact run throws PositionOverflow (its exact positions leave the doubles), after taking that step
// themselves to show what they do there (throw, or go on, with or without a NaN or infinity). Throws
// std::logic_error if a variant's velocities after a step are not those its decisions() predicted, or if
// the exact or oracle variant ever differs from the exact run: the report relies on both.
std::vector<Outcome> follow(const Circles& scene, std::uint64_t steps, std::span<const Kind> kinds,
                            std::uint64_t oracle_steps);

// Median wall-clock nanoseconds per circle-step of `repetitions` runs of `steps` steps from a fresh variant
// (construction untimed). Returns nothing when the variant cannot take the scene or throws on the way.
std::optional<double> ns_per_circle_step(Kind kind, const Circles& scene, std::uint64_t steps, int repetitions);

// ── Scenes ───────────────────────────────────────────────────────────────────────────────────────────

// A pair of circles designed to touch: in the exact run, at step `step` |p_b − p_a| = r_a + r_b + gap exactly
// and at step − 1 the two are farther apart than that. gap = 0 is a tangency; gap > 0 a near miss by a dyadic
// gap, where the exact run has no contact and a rounding one may.
struct Designed {
  std::uint32_t a = 0, b = 0;
  std::uint64_t step = 0;
  double gap = 0;
};

struct Scene {
  std::string id;    // file name without .json for the bundled ones
  std::string name;  // the scene's "name"
  std::uint64_t steps = 0;
  Circles circles;
  std::vector<std::string> circle_names;  // empty, or one per circle ("" for none)
  std::vector<Designed> designed;
};

// The bundled scenes of scenes/: cradle, dense, random, tangency_exact, tangency_sixtieths (the last).
std::vector<Scene> bundled_scenes();
// The stress scenes of docs/stability.md; the long run has `long_steps` steps.
std::vector<Scene> stress_scenes(std::uint64_t long_steps);
// The scene as a file of the agreed format (docs/scenes.md): "name", "steps", "circles", one circle a line.
std::string scene_json(const Scene& scene);

// What each variant decides for circle a of each designed pair at step `step` + 1, the step that acts on the
// designed world: the exact run takes b at a tangency and none at a near miss.
struct Contact {
  Designed pair;
  Kind kind = Kind::exact;
  std::optional<std::uint32_t> took;  // circle a's decision; nothing if the variant stopped before
  std::uint32_t exact_took = 0;
  std::string end;                    // why the variant stopped before, if it did
};
std::vector<Contact> designed_contacts(const Scene& scene, std::span<const Kind> kinds);

// Steps the exact engine to each designed pair's step and checks the design, as rationals. Throws
// std::logic_error naming the scene and the pair otherwise.
void check_designed(const Scene& scene);

}  // namespace circles::bench::accuracy
