// `circles oracle`: run the exact oracle in both profiles on a scene and say what it did.
#pragma once

#include "spec/circle.hpp"

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace circles::cli {

void report_oracle(const std::vector<spec::Circle>& scene, const std::string& scene_name, std::size_t steps,
                   std::ostream& out);

}  // namespace circles::cli
