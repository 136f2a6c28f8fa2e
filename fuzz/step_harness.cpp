// The step fuzzer for anyone's step (docs/hardening.md, "Your own step"): the libFuzzer entry points around a
// circles_step of <circles/step.h>, which the user's object defines. Each input, a world and K chained steps
// (fuzz/step_input.hpp), is stepped K times by circles_step, each step from its own previous answer, and held
// to the exact engine's rounded steps, themselves held to impl::step_all_pairs and, on the oracle's sample of
// inputs, to the oracle's rounded steps (fuzz::judged_reference). A difference aborts with the world as a scene (fuzz::fail). Installed as libcircles_step_harness.a;
// circles_add_step_fuzzer (cmake/circlesStepFuzzer.cmake) links it with libFuzzer and the user's sources.
#include "fuzz/step.h"
#include "fuzz/step_input.hpp"
#include "fuzz/step_judge.hpp"

#include <cmath>
#include <vector>

using namespace circles;

namespace {

// circles_step's chain: `steps` calls, each on the previous answer, to its first overflow or refusal.
fuzz::Chain candidate_chain(const fuzz::StepInput& input, std::uint64_t steps) {
  fuzz::Chain chain;
  std::vector<double> in, out(5 * input.circles.size());
  for (const auto& c : input.circles) in.insert(in.end(), c.begin(), c.end());
  for (std::uint64_t t = 1; t <= steps; ++t) {
    const int code = circles_step(input.circles.size(), in.data(), out.data());
    if (code == CIRCLES_STEP_OVERFLOW) {
      chain.overflow = fuzz::Overflow{t, fuzz::Overflow::kUnknown, spec::Field::px};
      break;
    }
    if (code != CIRCLES_STEP_OK)
      fuzz::fail(input, "circles_step", "step " + std::to_string(t) + ": returned " + std::to_string(code));
    fuzz::Circles w(input.circles.size());
    for (std::size_t k = 0; k < w.size(); ++k)
      for (std::size_t f = 0; f < 5; ++f) w[k][f] = out[5 * k + f];
    for (const double x : out)
      if (!std::isfinite(x))
        fuzz::fail(input, "circles_step", "step " + std::to_string(t) + ": a value that is not finite, with OK");
    chain.worlds.push_back(std::move(w));
    in.swap(out);
  }
  return chain;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::StepInput input = fuzz::decode(std::span<const std::uint8_t>(data, size));
  const std::uint64_t steps = fuzz::judged_steps(input);
  if (auto d = fuzz::difference(fuzz::judged_reference(input, steps), candidate_chain(input, steps)))
    fuzz::fail(input, "circles_step", *d);
  return 0;
}
