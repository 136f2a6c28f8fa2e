// thrown<E>(run): the exception of type E that run() throws, for tests that check its fields and message.
// Records a test failure and gives std::nullopt when run() returns normally; any other exception propagates
// and fails the test as GoogleTest does.
#pragma once

#include <gtest/gtest.h>

#include <optional>

namespace circles::testing {

template <class E, class F>
std::optional<E> thrown(F&& run) {
  try {
    run();
  } catch (const E& e) {
    return e;
  }
  ADD_FAILURE() << "nothing was thrown";
  return std::nullopt;
}

}  // namespace circles::testing
