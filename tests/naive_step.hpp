// The naive step of examples/python/step_naive.py and the verdicts on it, for the tests of --keep-going
// (tests/keep_going_test.cpp) and of expectation files (tests/expect_test.cpp).
#pragma once

#include "conform/conform.hpp"
#include "tests/gallery.hpp"

#include <cstdint>
#include <set>
#include <string>

namespace circles::testing {

// Hypot distance and p + v·(1/60).
inline spec::Circles naive_step(const spec::Circles& w) {
  Mistakes m;
  m.contact = Mistakes::Contact::hypot;
  m.naive_update = true;
  return mistaken_step(w, m);
}

inline spec::Circles exact_step(const spec::Circles& w) { return mistaken_step(w, Mistakes{}); }

// conform's default options with --seed `seed` --keep-going.
inline conform::Options keep_going(std::uint64_t seed) {
  conform::Options o;
  o.seed = seed;
  o.keep_going = true;
  return o;
}

// The names of the families of `v` whose status is `status`.
inline std::set<std::string> with_status(const conform::Verdict& v, conform::FamilyStatus status) {
  std::set<std::string> names;
  for (const conform::FamilyResult& f : v.families)
    if (f.status == status) names.insert(properties::name(f.family));
  return names;
}

// The 23 families the naive step's two mistakes reach in seed 1's 1000 cases: every one but tangent-after-step,
// signed-zeros and long-rows, on whose worlds there its answers are the nearest doubles.
inline const std::set<std::string> kNaiveFails = {"lattice",    "random-doubles", "tangency",        "ulp-nudge",
                                                  "tie-px",     "tie-p",          "tie-p-vx",        "tie-p-v",
                                                  "duplicates", "incomparable",   "mutual-contacts", "square-overflow",
                                                  "subnormals", "cancellation",   "zero-radius",     "wire",
                                                  "sizes",      "crowds",         "cell-crowds",     "radius-spread",
                                                  "index-bits", "order-borders",  "big-chains"};

}  // namespace circles::testing
