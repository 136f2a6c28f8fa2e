// Box2D 2.4.1 (the Debian package) on the scenes of engine_bench, for the Box2D target (Box2D's time per step at
// least 200 times the double engine's at 10^5 circles, 10% coverage; docs/benchmarks.md, Targets) and the size and
// coverage sweeps: dynamic circle bodies with the scene's radii, positions and velocities, zero gravity,
// restitution 1 and no friction (the spec's collisions are elastic velocity exchanges), mass 1 (the spec's unit
// masses), and world steps of 1/60 with the iteration counts of Box2D's own testbed (8 velocity, 3 position).
// Box2D works in float; the scene's doubles are rounded to it. Timed like every other stepper
// (bench/harness.hpp); names follow engine_bench's, family "box2d".
#include "bench/harness.hpp"
#include "formats/random_scene.hpp"

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <array>
#include <cstdio>
#include <exception>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace circles::bench {
namespace {

// The coverage sweep at every size up to 10^5 (scripts/benchmarks runs the size sweep at 10% and the
// coverage sweep at its largest size). Not 10^6: a step would take ten seconds or more there (the time per
// circle-step grew 3.6-fold from 10^4 to 10^5 in one run, 3.7 to 13.3 µs), too long for the run of record.
constexpr std::size_t kSizes[] = {1'000, 10'000, 100'000};
constexpr double kCoverages[] = {0.001, 0.01, 0.10, 0.40};
constexpr float kDt = 1.0f / 60;
constexpr int kVelocityIterations = 8;  // b2 testbed defaults (testbed/settings.h)
constexpr int kPositionIterations = 3;
// Box2D took 598 ms per step at 10^5 bodies in one run: 5 timed steps there keep a repetition near 3 s.
std::size_t steps_for(std::size_t n) { return n < 100'000 ? kStepsPerStepper : 5; }

class Box2DScene {
 public:
  explicit Box2DScene(const spec::Circles& circles) : world_(b2Vec2(0, 0)) {
    for (const auto& c : circles) {
      b2BodyDef body;
      body.type = b2_dynamicBody;
      body.position.Set(static_cast<float>(c[0]), static_cast<float>(c[1]));
      body.linearVelocity.Set(static_cast<float>(c[2]), static_cast<float>(c[3]));
      b2CircleShape shape;
      shape.m_radius = static_cast<float>(c[4]);
      b2FixtureDef fixture;
      fixture.shape = &shape;
      fixture.density = static_cast<float>(1 / (std::numbers::pi * c[4] * c[4]));  // mass = density · π r² = 1
      fixture.friction = 0;
      fixture.restitution = 1;
      world_.CreateBody(&body)->CreateFixture(&fixture);
    }
  }
  void step() { world_.Step(kDt, kVelocityIterations, kPositionIterations); }

 private:
  b2World world_;
};

void register_one(std::size_t n, double coverage) {
  register_steps(
      configuration_name("box2d", coverage, 1, n), n, 1, steps_for(n),
      [n, coverage] { return std::make_unique<Box2DScene>(formats::random_scene(n, coverage, kSceneSeed)); },
      configuration_labels(coverage, 1));
}

void register_all() {
  for (const std::size_t n : kSizes)
    for (const double coverage : kCoverages) register_one(n, coverage);
}

}  // namespace
}  // namespace circles::bench

int main(int argc, char** argv) {
  return circles::bench::bench_main(argc, argv, "box2d_bench", [] { return true; }, circles::bench::register_all);
}
