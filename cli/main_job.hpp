// The main job, plain `circles`: on the embedded default scene, the exact oracle's report (as `circles oracle`),
// then every engine of the registry checked against the oracle step by step (conform::compare_with_oracle).
#pragma once

#include <cstddef>
#include <ostream>

namespace circles::cli {

// Prints the report and one line per engine on `out`; returns 0 when every engine agrees, else 1.
int main_job(std::size_t steps, std::ostream& out);

}  // namespace circles::cli
