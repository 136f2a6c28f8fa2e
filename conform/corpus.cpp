#include "conform/corpus.hpp"

#include "conform/json_reader.hpp"
#include "formats/input_file.hpp"
#include "formats/json_number.hpp"
#include "formats/json_world.hpp"
#include "formats/output_file.hpp"
#include "spec/outside_c.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace circles::conform {

namespace json_number = formats::json_number;
using formats::OutputError;
namespace {

constexpr std::string_view kFormat = "circles-counterexample/1";
constexpr std::string_view kKeys[] = {"format", "profile", "world",  "level",    "seed",     "case",      "family",
                                      "steps",  "step",    "candidate", "expected", "actual", "difference",
                                      "fault"};
constexpr std::string_view kDifferenceKeys[] = {"circle", "field", "expected", "actual", "decision"};


// The world asked and the expected answer are worlds of C (Numbers::finite); what the candidate answered is any
// numbers (Numbers::any), those that are not finite stored as the strings "NaN", "Infinity" and "-Infinity".
using formats::Numbers;

// A world one row a line, indented under its key.
void append_listed_world(std::string& out, const Circles& w, Numbers numbers = Numbers::finite) {
  formats::append_world(out, w, numbers, {.row = "\n    ", .field = ", ", .close = "\n  "});
}

using CorpusReader = JsonReader<CorpusError>;

}  // namespace

std::string to_json(const StoredCounterexample& c) {
  const auto string = [](const std::string& s) { return nlohmann::json(s).dump(); };
  const auto number = [](double x) {
    std::string text;
    json_number::append(text, x);
    return text;
  };
  const auto answered = [](double x) {
    std::string text;
    json_number::append_or_string(text, x);
    return text;
  };
  std::string out = "{\n  \"format\": " + string(std::string(kFormat)) + ",\n";
  out += "  \"profile\": " + string(properties::name(c.profile)) + ",\n";
  out += "  \"world\": ";
  append_listed_world(out, c.world);
  out += ",\n";
  if (!c.level.empty()) out += "  \"level\": " + string(c.level) + ",\n";
  if (c.seed) out += "  \"seed\": " + std::to_string(*c.seed) + ",\n";
  if (c.case_index) out += "  \"case\": " + std::to_string(*c.case_index) + ",\n";
  if (!c.family.empty()) out += "  \"family\": " + string(c.family) + ",\n";
  if (c.steps) out += "  \"steps\": " + std::to_string(*c.steps) + ",\n";
  if (c.step) out += "  \"step\": " + std::to_string(*c.step) + ",\n";
  if (!c.candidate.empty()) out += "  \"candidate\": " + string(c.candidate) + ",\n";
  if (!c.fault.empty()) out += "  \"fault\": " + string(c.fault) + ",\n";
  if (c.difference) {
    const properties::Difference& d = *c.difference;
    out += "  \"difference\": {\"circle\": " + std::to_string(d.circle) + ", \"field\": " +
           string(spec::name(d.field)) + ", \"expected\": " + number(d.expected) +
           ", \"actual\": " + answered(d.actual) + ",\n                 \"decision\": " + string(d.decision) + "},\n";
  }
  if (!c.expected.empty()) {
    out += "  \"expected\": ";
    append_listed_world(out, c.expected);
    out += ",\n";
  }
  if (!c.actual.empty()) {
    out += "  \"actual\": ";
    append_listed_world(out, c.actual, Numbers::any);
    out += ",\n";
  }
  out.erase(out.size() - 2);  // the last ",\n"
  out += "\n}\n";
  return out;
}

StoredCounterexample from_json(std::string_view text, const std::string& source) {
  const CorpusReader read(source);
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    read.fail(std::string("malformed JSON: ") + e.what());
  }
  if (!root.is_object()) read.fail("expected an object {\"format\": ..., \"profile\": ..., \"world\": ...}");
  for (const auto& [key, value] : root.items())
    if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys))
      read.fail("unknown key " + in_quotes(key) + " (a counterexample has the keys format, profile, world, level, "
                "seed, case, family, steps, step, candidate, fault, expected, actual and difference)");
  for (const char* key : {"format", "profile", "world"})
    if (!root.contains(key)) read.fail("missing key " + in_quotes(key));
  if (read.string(root["format"], "format") != kFormat)
    read.fail("key \"format\": expected \"" + std::string(kFormat) + "\", found " + root["format"].dump());

  StoredCounterexample c;
  try {
    c.profile = properties::parse_profile(read.string(root["profile"], "profile"));
  } catch (const std::invalid_argument&) {
    read.fail("key \"profile\": expected \"resolved\" or \"literal\", found " + root["profile"].dump());
  }
  c.world = read.world(root["world"], "world");
  if (root.contains("level")) c.level = read.string(root["level"], "level");
  if (root.contains("family")) c.family = read.string(root["family"], "family");
  if (root.contains("candidate")) c.candidate = read.string(root["candidate"], "candidate");
  if (root.contains("fault")) c.fault = read.string(root["fault"], "fault");
  if (root.contains("seed")) c.seed = read.integer(root["seed"], "seed");
  if (root.contains("case")) c.case_index = read.integer(root["case"], "case");
  if (root.contains("steps")) c.steps = read.integer(root["steps"], "steps");
  if (root.contains("step")) c.step = read.integer(root["step"], "step");
  if (root.contains("expected")) c.expected = read.world(root["expected"], "expected");
  if (root.contains("actual")) c.actual = read.world(root["actual"], "actual", Numbers::any);
  if (root.contains("difference")) {
    const nlohmann::json& d = root["difference"];
    if (!d.is_object()) read.fail("key \"difference\": expected an object, found " + std::string(d.type_name()));
    for (const auto& [key, value] : d.items())
      if (std::find(std::begin(kDifferenceKeys), std::end(kDifferenceKeys), key) == std::end(kDifferenceKeys))
        read.fail("key \"difference\": unknown key " + in_quotes(key));
    for (const std::string_view key : kDifferenceKeys)
      if (!d.contains(std::string(key))) read.fail("key \"difference\": missing key " + in_quotes(key));
    properties::Difference diff{};
    diff.circle = read.integer(d["circle"], "circle");
    diff.field = read.field(d["field"], "key \"difference\"");
    diff.expected = read.number(d["expected"], "key \"difference\": expected");
    diff.actual = read.number(d["actual"], "key \"difference\": actual", Numbers::any);
    diff.decision = read.string(d["decision"], "decision");
    c.difference = diff;
  }
  return c;
}

std::string stem(const StoredCounterexample& c) {
  // FNV-1a (64 bits) of the profile and the world's protocol line: the same world found twice is one file.
  std::uint64_t hash = 14695981039346656037ull;
  const std::string key = std::string(properties::name(c.profile)) + " " + format_line(kId, 0, c.world);
  for (const unsigned char byte : key) hash = (hash ^ byte) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return "counterexample-" + std::string(hex);
}

std::filesystem::path save(const std::filesystem::path& dir, const StoredCounterexample& c) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw CorpusError("cannot create the directory " + dir.string() + ": " + error.message());
  const std::filesystem::path file = dir / (stem(c) + ".json");
  try {
    formats::write_file(file.string(), file.string(), to_json(c));
  } catch (const OutputError& e) {
    throw CorpusError(e.what());
  }
  return file;
}

std::vector<std::pair<std::filesystem::path, StoredCounterexample>> load_corpus(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (std::filesystem::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
    if (it->path().extension() == ".json") files.push_back(it->path());
  if (error) throw CorpusError("cannot read the directory " + dir.string() + ": " + error.message());
  std::sort(files.begin(), files.end());
  std::vector<std::pair<std::filesystem::path, StoredCounterexample>> corpus;
  for (const std::filesystem::path& file : files) {
    std::string text;
    try {
      text = formats::read_input(file.string());
    } catch (const formats::InputError& e) {
      throw CorpusError(file.string() + ": " + e.what());
    }
    corpus.emplace_back(file, from_json(text, file.string()));
  }
  return corpus;
}

}  // namespace circles::conform
