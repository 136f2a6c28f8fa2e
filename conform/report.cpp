#include "conform/report.hpp"

#include "formats/json_number.hpp"
#include "formats/json_world.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace circles::conform {
namespace {

using formats::json_string;
using formats::Numbers;
namespace json_number = formats::json_number;

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

}  // namespace

std::string difference_line(const Counterexample& c) {
  const properties::Difference& d = c.difference;
  return "step " + std::to_string(c.step) + " of " + std::to_string(c.steps) + ", circle " + std::to_string(d.circle) +
         ", field " + spec::name(d.field) + ": expected " + json_number::decimal_and_hex(d.expected) +
         ", got " + json_number::decimal_and_hex(d.actual);
}

std::string counterexample_summary(const Counterexample& c) {
  return difference_line(c) + "\nwhich decision: " + c.difference.decision + "\nreplay: " + c.replay + "\n";
}

std::string shard_text(const Verdict& v) {
  return std::to_string(v.options.shard) + "/" + std::to_string(v.options.shards);
}

std::string elapsed_text(const Verdict& v) {
  std::string text;
  json_number::append(text, std::max(0.0, v.elapsed.count()));
  return text;
}

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

}  // namespace circles::conform
