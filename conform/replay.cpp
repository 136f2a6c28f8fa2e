#include "conform/replay.hpp"

#include "formats/json_number.hpp"
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

namespace {

void add(std::string& command, std::string_view option, std::string_view value = "") {
  command.append(" ").append(option);
  if (!value.empty()) command.append(" ").append(value);
}

// The options that choose how a world is judged and which worlds a family draws: the level, the steps, the
// profile, the largest world (with `max_circles`: a replay's case needs none in a budget run, whose ladder case
// says its size with --circles), the families checked.
void add_judging(std::string& command, const Options& options, bool max_circles) {
  add(command, "--level", shell_quoted(options.level.text()));
  if (options.steps > 1) add(command, "--steps", std::to_string(options.steps));
  if (options.profile == Profile::literal) add(command, "--profile", "literal");
  const std::size_t default_max = options.budget ? kBudgetMaxCircles : properties::kDefaultMaxCircles;
  if (max_circles && options.max_circles != default_max)
    add(command, "--max-circles", std::to_string(options.max_circles));
  if (!options.skip.empty()) {
    std::string checked, skipped;
    for (const properties::Family f : properties::families(options.profile)) {
      const bool skip = std::find(options.skip.begin(), options.skip.end(), f) != options.skip.end();
      std::string& list = skip ? skipped : checked;
      if (!list.empty()) list.push_back(',');
      list.append(properties::name(f));
    }
    if (!checked.empty() && checked.size() <= skipped.size()) add(command, "--families", checked);
    else add(command, "--skip-families", skipped);
  }
}

}  // namespace

std::string replay_command(std::string_view candidate, const Options& options, std::optional<std::uint64_t> case_index,
                           std::optional<std::size_t> circles) {
  std::string command = "circles conform";
  if (!candidate.empty()) add(command, candidate);
  if (case_index) {
    add(command, "--seed", std::to_string(options.seed));
    add(command, "--case", std::to_string(*case_index));
    if (circles) add(command, "--circles", std::to_string(*circles));
  } else {
    add(command, "--save", shell_quoted(options.save.string()));
    add(command, "--cases", "0");
  }
  add_judging(command, options, !options.budget);
  return command;
}

std::string rerun_command(std::string_view candidate, const Options& options) {
  std::string command = "circles conform";
  if (!candidate.empty()) add(command, candidate);
  add(command, "--seed", std::to_string(options.seed));
  // A budget run again (its ladder's sizes follow the program's speed, so its big worlds may differ), or the
  // fixed schedule's cases.
  if (options.only_case) add(command, "--case", std::to_string(*options.only_case));
  else if (options.budget) {
    if (*options.budget != kDefaultBudget) add(command, "--budget", formats::json_number::plain(*options.budget));
  } else {
    add(command, "--cases", std::to_string(options.cases));
  }
  if (options.only_case && options.circles) add(command, "--circles", std::to_string(*options.circles));
  if (options.shards > 1) add(command, "--shard", std::to_string(options.shard) + "/" + std::to_string(options.shards));
  if (!options.save.empty()) add(command, "--save", shell_quoted(options.save.string()));
  if (options.keep_going) add(command, "--keep-going");
  add_judging(command, options, true);
  return command;
}

}  // namespace circles::conform
