#include "conform/replay.hpp"

#include "properties/boundaries.hpp"

#include <algorithm>

namespace circles::conform {

std::string shell_quoted(std::string_view word) {
  const auto plain = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view("_-./:,=+@%").find(c) != std::string_view::npos;
  };
  if (!word.empty() && std::all_of(word.begin(), word.end(), plain)) return std::string(word);
  std::string quoted = "'";
  for (const char c : word) {
    if (c == '\'') quoted.append("'\\''");
    else quoted.push_back(c);
  }
  quoted.push_back('\'');
  return quoted;
}

std::string replay_command(std::string_view candidate, const Options& options, std::optional<std::uint64_t> case_index,
                           std::optional<std::size_t> circles) {
  std::string command = "circles conform";
  const auto add = [&command](std::string_view option, std::string_view value) {
    command.append(" ").append(option);
    if (!value.empty()) command.append(" ").append(value);
  };
  if (!candidate.empty()) add(candidate, "");
  if (case_index) {
    add("--seed", std::to_string(options.seed));
    add("--case", std::to_string(*case_index));
    if (circles) add("--circles", std::to_string(*circles));
  } else {
    add("--save", shell_quoted(options.save.string()));
    add("--cases", "0");
  }
  add("--level", shell_quoted(options.level.text()));
  if (options.steps > 1) add("--steps", std::to_string(options.steps));
  if (options.profile == Profile::literal) add("--profile", "literal");
  if (!options.budget && options.max_circles != properties::kDefaultMaxCircles) add("--max-circles", std::to_string(options.max_circles));
  if (!options.skip.empty()) {
    std::string checked, skipped;
    for (const properties::Family f : properties::families(options.profile)) {
      const bool skip = std::find(options.skip.begin(), options.skip.end(), f) != options.skip.end();
      std::string& list = skip ? skipped : checked;
      if (!list.empty()) list.push_back(',');
      list.append(properties::name(f));
    }
    if (!checked.empty() && checked.size() <= skipped.size()) add("--families", checked);
    else add("--skip-families", skipped);
  }
  return command;
}

}  // namespace circles::conform
