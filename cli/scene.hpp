// Scenes for the `circles` command: the protocol's compact form {"circles": [[px, py, vx, vy, r], ...]}.
#pragma once

#include "spec/circle.hpp"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace circles::cli {

// Any scene that cannot be used: the message names the source, the place and the reason.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The circles of a compact-form scene, each the exact value of its five doubles. `source` names the text in
// messages (a file name, or "<embedded default>"). Throws SceneError for malformed JSON, a wrong shape or type,
// a number that is not a double (an integer beyond 2^53 that would round, a value beyond the double range),
// and a circle outside C in the resolved profile (r < 0).
std::vector<spec::Circle> parse_scene(std::string_view text, const std::string& source);

// The same, from a file.
std::vector<spec::Circle> load_scene(const std::string& path);

// The embedded default scene (scenes/default.json, built into the binary).
std::vector<spec::Circle> default_scene();

}  // namespace circles::cli
