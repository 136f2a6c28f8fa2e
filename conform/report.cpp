#include "conform/report.hpp"

#include "conform/json_reader.hpp"
#include "conform/verdict_text.hpp"
#include "formats/json_number.hpp"
#include "formats/json_world.hpp"
#include "formats/protocol.hpp"  // shortened_token

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace circles::conform {
namespace {

using formats::json_string;
using formats::Numbers;
namespace json_number = formats::json_number;
using ReportReader = JsonReader<ReportError>;

// ── Writing ───────────────────────────────────────────────────────────────────────────────────────────

// A world of a report: any numbers, as an answer received can hold (formats/json_world.hpp).
void append_world(std::string& out, const Circles& w) { formats::append_world(out, w, Numbers::any); }

std::string counterexample_json(const Counterexample& c, const std::string& text) {
  const properties::Difference& d = c.difference;
  std::string out = "{\"family\": " + json_string(c.family) + ", \"case\": " +
                    (c.case_index ? std::to_string(*c.case_index) : "null") +
                    ", \"stored\": " + (c.stored.empty() ? "null" : json_string(c.stored.string())) +
                    ", \"step\": " + std::to_string(c.step) + ", \"steps\": " + std::to_string(c.steps) +
                    ",\n    \"world\": ";
  append_world(out, c.input);
  out += ",\n    \"expected\": ";
  append_world(out, c.expected);
  out += ",\n    \"received\": ";
  append_world(out, c.actual);
  out += ",\n    \"difference\": {\"circle\": " + std::to_string(d.circle) + ", \"field\": " +
         json_string(spec::name(d.field)) + ", \"expected\": ";
  json_number::append_or_string(out, d.expected);
  out += ", \"received\": ";
  json_number::append_or_string(out, d.actual);
  out += ", \"decision\": " + json_string(d.decision) + "},\n    \"shrink_path\": [";
  for (std::size_t k = 0; k < c.shrink_path.size(); ++k) {
    if (k) out += ", ";
    append_world(out, c.shrink_path[k]);
  }
  out += "],\n    \"replay\": " + json_string(c.replay) + ",\n    \"text\": " + json_string(text) + "}";
  return out;
}

// Every counterexample of the verdict, each with its text, in the order of the --keep-going table: a stored one
// of no family of the profile first, then each family's that has one, in the profile's order. The run's
// counterexample has `text`, the others counterexample_summary.
std::vector<std::pair<const Counterexample*, std::string>> every_counterexample(const Verdict& v, const std::string& text) {
  std::vector<std::pair<const Counterexample*, std::string>> all;
  if (v.counterexample && v.counterexample->family.empty()) all.emplace_back(&*v.counterexample, text);
  for (const FamilyResult& f : v.families) {
    if (f.has_counterexample && v.counterexample) all.emplace_back(&*v.counterexample, text);
    else if (f.counterexample) all.emplace_back(&*f.counterexample, counterexample_summary(*f.counterexample));
  }
  return all;
}

// ── Reading ───────────────────────────────────────────────────────────────────────────────────────────

[[noreturn]] void refuse(const nlohmann::json& r, const std::string& name, const std::string& key,
                         const std::string& expected) {
  throw ReportError(name + ": \"" + key + "\": expected " + expected + ", found " +
                    (r.contains(key) ? formats::shortened_token(r.at(key).dump()) : std::string("nothing")));
}

// The keys of the report as a whole, each of the type json_report writes it, so that a report cut short or edited
// by hand is refused naming its file and key, rather than ending the program with a JSON library's exception.
void check_report(const nlohmann::json& r, const std::string& name) {
  const auto has = [&](const char* key, bool (nlohmann::json::*is)() const noexcept) {
    return r.contains(key) && (r.at(key).*is)();
  };
  for (const char* key : {"candidate", "level", "profile", "shard", "verdict"})
    if (!has(key, &nlohmann::json::is_string)) refuse(r, name, key, "a string");
  for (const char* key : {"seed", "steps", "cases", "skipped", "cut_short", "replayed"})
    if (!has(key, &nlohmann::json::is_number_unsigned)) refuse(r, name, key, "an integer >= 0");
  if (!has("elapsed_seconds", &nlohmann::json::is_number)) refuse(r, name, "elapsed_seconds", "a number");
  if (!parse_outcome(r.at("verdict").get<std::string>()))
    refuse(r, name, "verdict", "\"conforms\", \"does not conform\", \"cannot check\" or \"interrupted\"");
  if (!has("error", &nlohmann::json::is_null) && !has("error", &nlohmann::json::is_string))
    refuse(r, name, "error", "null or a string");
  if (!has("families", &nlohmann::json::is_object) ||
      std::any_of(r.at("families").begin(), r.at("families").end(), [](const nlohmann::json& n) { return !n.is_number_unsigned(); }))
    refuse(r, name, "families", "an object of case counts, integers >= 0");
  if (!has("family_status", &nlohmann::json::is_object)) refuse(r, name, "family_status", "an object of statuses");
  const bool no_counterexample = has("counterexample", &nlohmann::json::is_null);
  if (!no_counterexample && !(has("counterexample", &nlohmann::json::is_object) && r.at("counterexample").contains("case") &&
                              (r.at("counterexample").at("case").is_null() || r.at("counterexample").at("case").is_number_unsigned())))
    refuse(r, name, "counterexample", "null or an object whose \"case\" is null or an integer >= 0");
  if (r.contains("counterexamples") &&
      (!r.at("counterexamples").is_array() ||
       std::any_of(r.at("counterexamples").begin(), r.at("counterexamples").end(), [](const nlohmann::json& c) { return !c.is_object(); })))
    refuse(r, name, "counterexamples", "an array of counterexamples");
}

// What was checked: seed, steps, level, profile and shard.
Options options_of(const nlohmann::json& r, const std::string& name) {
  Options o;
  o.seed = r.at("seed").get<std::uint64_t>();
  o.steps = r.at("steps").get<std::uint64_t>();
  try {
    o.level = properties::parse_level(r.at("level").get<std::string>());
  } catch (const std::invalid_argument&) {
    refuse(r, name, "level", "exact, faithful or ulps:K");
  }
  try {
    o.profile = properties::parse_profile(r.at("profile").get<std::string>());
  } catch (const std::invalid_argument&) {
    refuse(r, name, "profile", "\"resolved\" or \"literal\"");
  }
  const std::string shard = r.at("shard").get<std::string>();
  try {
    std::tie(o.shard, o.shards) = parse_shard(shard);
  } catch (const std::invalid_argument&) {
    throw ReportError(name + ": \"shard\": expected i/n, found \"" + shard + "\" (a merged report is not merged again)");
  }
  return o;
}

// A counterexample, as counterexample_json writes it; a key left out or null keeps its default, so that a report
// made by hand may give only "family" and "case". `text`, if given, gets its "text".
Counterexample counterexample_of(const nlohmann::json& c, const ReportReader& read, std::string* text = nullptr) {
  const auto given = [&](const char* key) { return c.contains(key) && !c.at(key).is_null(); };
  Counterexample out;
  if (given("family")) out.family = read.string(c.at("family"), "family");
  if (given("case")) out.case_index = read.integer(c.at("case"), "case");
  if (given("stored")) out.stored = read.string(c.at("stored"), "stored");
  if (given("step")) out.step = read.integer(c.at("step"), "step");
  if (given("steps")) out.steps = read.integer(c.at("steps"), "steps");
  const std::pair<const char*, Circles*> worlds[] = {{"world", &out.input}, {"expected", &out.expected}, {"received", &out.actual}};
  for (const auto& [key, world] : worlds)
    if (given(key)) *world = read.world(c.at(key), key, Numbers::any);
  if (given("shrink_path")) {
    if (!c.at("shrink_path").is_array()) read.fail("key \"shrink_path\": expected an array of worlds");
    for (const nlohmann::json& w : c.at("shrink_path")) out.shrink_path.push_back(read.world(w, "shrink_path", Numbers::any));
  }
  if (given("difference")) {
    const nlohmann::json& d = c.at("difference");
    if (!d.is_object()) read.fail("key \"difference\": expected an object, found " + std::string(d.type_name()));
    properties::Difference& diff = out.difference;
    if (d.contains("circle")) diff.circle = read.integer(d.at("circle"), "circle");
    if (d.contains("field")) diff.field = read.field(d.at("field"), "key \"difference\"");
    if (d.contains("expected")) diff.expected = read.number(d.at("expected"), "key \"difference\": expected", Numbers::any);
    if (d.contains("received")) diff.actual = read.number(d.at("received"), "key \"difference\": received", Numbers::any);
    if (d.contains("decision")) diff.decision = read.string(d.at("decision"), "decision");
  }
  if (given("replay")) out.replay = read.string(c.at("replay"), "replay");
  if (text && given("text")) *text = read.string(c.at("text"), "text");
  return out;
}

// The families, in the profile's order, each with its cases checked, its status and its counterexample.
std::vector<FamilyResult> families_of(const nlohmann::json& r, Profile profile, const std::string& name) {
  std::map<properties::Family, FamilyResult> read;
  for (const auto& [family, count] : r.at("families").items()) {
    const std::optional<properties::Family> f = parse_family(family, profile);
    if (!f)
      throw ReportError(name + ": \"families\": " + family + " is not a family of the " + properties::name(profile) +
                        " profile");
    read[*f] = {*f, 0, count.get<std::uint64_t>(), FamilyStatus::passed, false, std::nullopt};
  }
  for (const auto& [family, s] : r.at("family_status").items()) {
    const std::optional<FamilyStatus> status = parse_family_status(s.is_string() ? s.get<std::string>() : "");
    if (!status)
      throw ReportError(name + ": \"family_status\": " + family + " is " + s.dump() + ", not a status of a family");
    const std::optional<properties::Family> f = parse_family(family, profile);
    if (!f || !read.contains(*f))
      throw ReportError(name + ": \"family_status\": " + family + " is not one of the \"families\"");
    read[*f].status = *status;
  }
  if (r.at("family_status").size() != read.size())
    throw ReportError(name + ": \"family_status\": expected a status for each of the \"families\"");
  const ReportReader reader(name + ": \"counterexamples\"");
  for (const nlohmann::json& c : r.value("counterexamples", nlohmann::json::array())) {
    Counterexample counterexample = counterexample_of(c, reader);
    const std::optional<properties::Family> f = parse_family(counterexample.family, profile);
    if (f && read.contains(*f)) read[*f].counterexample = std::move(counterexample);
  }
  std::vector<FamilyResult> families;
  for (const properties::Family f : properties::families(profile))
    if (read.contains(f)) families.push_back(std::move(read[f]));
  return families;
}

}  // namespace

std::string json_report(const Verdict& v, const std::string& text) {
  const Options& o = v.options;
  std::string out = std::string("{\n  \"format\": \"") + kReportFormat + "\",\n  \"verdict\": " + json_string(name(v.outcome)) +
                    ",\n  \"error\": " + (v.error.empty() ? "null" : json_string(v.error)) +
                    ",\n  \"candidate\": " + json_string(v.candidate) + ",\n  \"seed\": " + std::to_string(o.seed) +
                    ", \"shard\": " + json_string(shard_text(v)) + ", \"level\": " + json_string(o.level.text()) +
                    ", \"profile\": " + json_string(properties::name(o.profile)) +
                    ", \"steps\": " + std::to_string(o.steps) + ",\n  \"cases\": " + std::to_string(v.cases) +
                    ", \"skipped\": " + std::to_string(v.skipped) + ", \"cut_short\": " + std::to_string(v.cut_short) +
                    ", \"replayed\": " + std::to_string(v.replayed) + ",\n  \"families\": {";
  std::string status = "{";
  for (std::size_t f = 0; f < v.families.size(); ++f) {
    const std::string family = json_string(properties::name(v.families[f].family));
    out += (f ? ", " : "") + family + ": " + std::to_string(v.families[f].checked);
    status += (f ? ", " : "") + family + ": " + json_string(name(v.families[f].status));
  }
  std::string all = "[";
  for (const auto& [c, its_text] : every_counterexample(v, text))
    all += (all.size() > 1 ? ",\n  " : "") + counterexample_json(*c, its_text);
  out += "},\n  \"family_status\": " + status + "},\n  \"counterexample\": " +
         (v.counterexample ? counterexample_json(*v.counterexample, text) : "null") + ",\n  \"counterexamples\": " + all +
         "],\n  \"elapsed_seconds\": " + elapsed_text(v) + "\n}\n";
  return out;
}

Report read_report(std::string_view text, const std::string& name) {
  nlohmann::json r;
  try {
    r = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    throw ReportError(name + ": malformed JSON: " + e.what());
  }
  if (!r.is_object() || !r.contains("format") || r["format"] != kReportFormat)
    throw ReportError(name + ": not a report of circles conform (\"format\": \"" + kReportFormat + "\")");
  check_report(r, name);
  Report report;
  Verdict& v = report.verdict;
  v.outcome = *parse_outcome(r.at("verdict").get<std::string>());
  if (r.at("error").is_string()) v.error = r.at("error").get<std::string>();
  v.candidate = r.at("candidate").get<std::string>();
  v.options = options_of(r, name);
  v.cases = r.at("cases").get<std::uint64_t>();
  v.skipped = r.at("skipped").get<std::uint64_t>();
  v.cut_short = r.at("cut_short").get<std::uint64_t>();
  v.replayed = r.at("replayed").get<std::uint64_t>();
  v.families = families_of(r, v.options.profile, name);
  if (r.at("counterexample").is_object())
    v.counterexample = counterexample_of(r.at("counterexample"), ReportReader(name + ": \"counterexample\""), &report.text);
  mark_counterexample_family(v);
  v.elapsed = std::chrono::duration<double>(r.at("elapsed_seconds").get<double>());
  return report;
}

}  // namespace circles::conform
