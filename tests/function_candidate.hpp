// FunctionCandidate: a step function as a conform::Candidate, in process, for deliberately wrong implementations
// in the tests of conform (tests/conform_test.cpp) and of its reports (tests/report_test.cpp).
#pragma once

#include "conform/candidate.hpp"
#include "impl/engine.hpp"
#include "properties/boundaries.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace circles::testing {

class FunctionCandidate : public conform::Candidate {
 public:
  using Step = std::function<formats::Circles(const formats::Circles&)>;
  explicit FunctionCandidate(Step step, std::string name = "the function")
      : step_(std::move(step)), name_(std::move(name)) {}
  formats::Circles answer(const formats::Circles& world, std::uint64_t) override { return step_(world); }
  std::string name() const override { return name_; }

 private:
  Step step_;
  std::string name_;
};

// The right step, fast enough for the big families' worlds of thousands of circles: impl::step_all_pairs, which
// tests/engine_test.cpp holds equal to the oracle. (The oracle itself, O(n²) in rationals, takes minutes over
// one of them.)
inline formats::Circles right_step(const formats::Circles& w) { return impl::step_all_pairs(impl::World{w}).circles(); }

// The big families of the resolved profile, for Options::skip in a test whose candidate is the oracle: such a
// test checks the small families.
inline std::vector<properties::Family> big_families() {
  std::vector<properties::Family> big;
  for (const properties::Family f : properties::families(properties::Profile::resolved))
    if (properties::is_big(f)) big.push_back(f);
  return big;
}

}  // namespace circles::testing
