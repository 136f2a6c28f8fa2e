#include "cli/options.hpp"

#include "engines/registry.hpp"
#include "formats/input_file.hpp"
#include "formats/output_file.hpp"
#include "formats/scene.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace circles::cli {
namespace {

// `option` takes `metavariable`, checked by `check`, whose description is what it wants.
CLI::Option* takes_checked(CLI::Option* option, const std::string& metavariable, const std::string& wants,
                           std::function<std::string(const std::string&)> check) {
  return option->type_name(metavariable)->check(CLI::Validator(
      [check = std::move(check)](std::string& value) { return check(value); }, wants));
}

// The message of a value refused, in the voice of the other checks (--level, --profile, --shard):
// "\"abc\" is not a whole number from 0 to 100".
std::string found(const std::string& wants, const std::string& value) { return "\"" + value + "\" is not " + wants; }

// "The engine, one of: double (the double engine ...); oracle (...)", from the registry.
std::string engine_help() {
  std::string help;
  for (const engines::EngineEntry& e : engines::engines())
    help += (help.empty() ? "The engine, one of: " : "; ") + std::string(e.name) + " (" + std::string(e.summary) + ")";
  return help;
}

}  // namespace

CLI::Option* takes_whole_number(CLI::Option* option, const std::string& metavariable, std::uint64_t least,
                                std::uint64_t most) {
  const std::string wants = "a whole number from " + std::to_string(least) + " to " + std::to_string(most);
  return takes_checked(option, metavariable, wants, [=](const std::string& value) {
    // Digits alone: CLI11 reads "-1" with strtoull as 2^64 - 1, and "0x10" as 16.
    std::uint64_t n = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), n);
    const bool whole = !value.empty() && error == std::errc{} && end == value.data() + value.size();
    return whole && n >= least && n <= most ? std::string() : found(wants, value);
  });
}

CLI::Option* takes_number(CLI::Option* option, const std::string& metavariable, const std::string& wants,
                          bool (*in_range)(double)) {
  return takes_checked(option, metavariable, wants, [=](const std::string& value) {
    double x = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), x);
    const bool number = !value.empty() && error == std::errc{} && end == value.data() + value.size();
    return number && std::isfinite(x) && in_range(x) ? std::string() : found(wants, value);
  });
}

CLI::Option* takes(CLI::Option* option, const std::string& metavariable, const std::string& wants) {
  return takes_checked(option, metavariable, wants, [](const std::string&) { return std::string(); });
}

CLI::Option* takes_directory(CLI::Option* option, const std::string& wants) {
  return takes_checked(option, "DIR", wants,
                       [=](const std::string& value) { return value == "-" ? found(wants, value) : std::string(); });
}

CLI::Option* takes_output_file(CLI::Option* option) { return takes(option, "FILE", "a file to write, or - for stdout"); }

CLI::Option* takes_input_file(CLI::Option* option) { return takes(option, "FILE", "a file to read, or - for stdin"); }

CLI::Option* takes_one_of(CLI::Option* option, const std::string& metavariable, const std::vector<std::string>& names) {
  std::string wants;
  for (std::size_t k = 0; k < names.size(); ++k)
    wants += (k == 0 ? "" : k + 1 == names.size() ? (names.size() > 2 ? ", or " : " or ") : ", ") + names[k];
  return takes_checked(option, metavariable, wants, [=](const std::string& value) {
    return std::find(names.begin(), names.end(), value) != names.end() ? std::string() : found(wants, value);
  });
}

void add_report_options(CLI::App* command, conform::ReportFiles& files, const conform::ReportFormat* except) {
  for (const conform::ReportFormat& format : conform::report_formats())
    if (&format != except)
      takes_output_file(command->add_option(format.option, files[format.option],
                                            std::string("Also write the verdict as ") + format.name + " to FILE" +
                                                format.about));
}

std::string two_on_stdout(const std::vector<std::pair<std::string, std::string>>& given) {
  std::vector<std::string> on_stdout;
  for (const auto& [option, path] : given)
    if (formats::is_standard_output(path)) on_stdout.push_back(option);
  if (on_stdout.size() < 2) return "";
  return on_stdout[0] + " and " + on_stdout[1] + " both go to stdout; give - to one of them";
}

bool any_on_stdout(const std::vector<std::pair<std::string, std::string>>& given) {
  return std::any_of(given.begin(), given.end(), [](const auto& output) { return formats::is_standard_output(output.second); });
}

Takes takes_of(const CLI::Option& option) {
  if (option.get_expected_max() == 0) return {};  // a flag
  // CLI11 gives the type name and each check's description after a colon: "N:a whole number from 0 to 100".
  const std::string type = option.get_type_name();
  const std::size_t colon = type.find(':');
  if (colon == std::string::npos) return {type, type};
  return {type.substr(0, colon), type.substr(colon + 1)};
}

void add_engine_options(CLI::App* command, std::string& engine_name, unsigned& threads) {
  std::string names;
  for (const engines::EngineEntry& e : engines::engines()) names += (names.empty() ? "" : ", ") + std::string(e.name);
  takes_checked(command->add_option("--engine", engine_name, engine_help())->capture_default_str(), "NAME",
                "an engine: " + names, [](const std::string& name) {
                  return engines::find_engine(name) ? std::string() : std::string(engines::UnknownEngine(name).what());
                });
  takes_whole_number(command->add_option("--threads", threads, "Threads (0: one per core that other programs leave free)")->capture_default_str(), "N",
                     0, engines::max_threads());
}

SceneOptions::Source SceneOptions::source() const {
  if (random.circles > 0) return Source::random;
  return path.empty() ? Source::embedded : Source::file;
}

std::string SceneOptions::name() const {
  switch (source()) {
    case Source::random: return formats::random_scene_name(random.circles, random.coverage, random.seed);
    case Source::file: return formats::input_name(path);
    case Source::embedded: break;
  }
  return "the embedded default scene";
}

CLI::Option* add_scene_file(CLI::App* command, SceneOptions& scene) {
  // No CLI::ExistingFile on the scene: a missing file or a directory is reported by the scene loader, as every
  // other bad scene is (docs/scenes.md).
  return takes(command->add_option("scene", scene.path,
                                   "The scene, a file (scenes.md in the docs) or - for stdin; default: the embedded "
                                   "default scene"),
               "SCENE", "a scene file to read, or - for stdin");
}

void add_random_options(CLI::App* command, CLI::Option* file, SceneOptions& scene) {
  RandomOptions& random = scene.random;
  // Up to 2^63 - 1, which refuses "-5" (read as 2^64 - 5); a count beyond memory is refused with its bytes.
  CLI::Option* n = takes_whole_number(
      command
          ->add_option("--random", random.circles,
                       "Instead of a scene file, N random circles like the benchmarks' (r 2-6, |v| <= 100)")
          ->excludes(file),
      "N", 1, std::numeric_limits<std::int64_t>::max());
  takes_number(command->add_option("--coverage", random.coverage, "With --random: the circles' area over their square's")
                   ->capture_default_str()
                   ->needs(n),
               "FRACTION", "a number in (0, 1]", [](double x) { return x > 0 && x <= 1; });
  takes_whole_number(command->add_option("--seed", random.seed, "With --random: the seed")->capture_default_str()->needs(n),
                     "N", 0, std::numeric_limits<std::uint64_t>::max());
}

}  // namespace circles::cli
