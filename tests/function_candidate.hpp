// FunctionCandidate: a step function as a conform::Candidate, in process, for deliberately wrong implementations
// in the tests of conform (tests/conform_test.cpp) and of its reports (tests/report_test.cpp).
#pragma once

#include "conform/candidate.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>

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

}  // namespace circles::testing
