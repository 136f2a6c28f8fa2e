#include "cli/report.hpp"

#include "formats/json_number.hpp"
#include "formats/json_world.hpp"
#include "formats/output_file.hpp"
#include "formats/protocol.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <limits>
#include <map>
#include <set>

namespace circles::cli {
namespace {

using conform::Counterexample;
using conform::FamilyResult;
using conform::FamilyStatus;
using conform::Verdict;
using spec::Circles;
using formats::json_string;
namespace json_number = formats::json_number;

using conform::kReportFormat;

// A world of a report: any numbers, as an answer received can hold (formats/json_world.hpp).
void append_world(std::string& out, const Circles& w) { formats::append_world(out, w, formats::Numbers::any); }

std::string shard_text(const conform::Options& o) { return std::to_string(o.shard) + "/" + std::to_string(o.shards); }

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

// "step 1 of 1, circle 0, field px: expected 0.5 (0x1p-1), got 0.25 (0x1p-2)": the JUnit failure's message.
std::string difference_message(const Counterexample& c) {
  const properties::Difference& d = c.difference;
  return "step " + std::to_string(c.step) + " of " + std::to_string(c.steps) + ", circle " + std::to_string(d.circle) +
         ", field " + spec::name(d.field) + ": expected " + json_number::decimal_and_hex(d.expected) +
         ", got " + json_number::decimal_and_hex(d.actual);
}

// The text of a counterexample other than the run's (which is printed whole): its difference, which decision
// differs, and its replay line.
std::string short_text(const Counterexample& c) {
  return difference_message(c) + "\nwhich decision: " + c.difference.decision + "\nreplay: " + c.replay + "\n";
}

// Every counterexample of the verdict, each with its text, in the order of the --keep-going table: a stored one
// of no family of the profile first, then each family's that has one, in the profile's order. The run's
// counterexample has `text`, the others short_text.
std::vector<std::pair<const Counterexample*, std::string>> every_counterexample(const Verdict& v, const std::string& text) {
  std::vector<std::pair<const Counterexample*, std::string>> all;
  if (v.counterexample && v.counterexample->family.empty()) all.emplace_back(&*v.counterexample, text);
  for (const FamilyResult& f : v.families) {
    if (f.has_counterexample && v.counterexample) all.emplace_back(&*v.counterexample, text);
    else if (f.counterexample) all.emplace_back(&*f.counterexample, short_text(*f.counterexample));
  }
  return all;
}

// XML text: the five special characters escaped, and the bytes XML 1.0 cannot hold (control characters but
// tab, newline and carriage return) as U+FFFD. Other bytes pass as they are (UTF-8 in, UTF-8 out).
std::string xml(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += "\xEF\xBF\xBD";
        else out += c;
    }
  }
  return out;
}

std::string seconds(double s) {
  std::string text;
  json_number::append(text, std::max(0.0, s));
  return text;
}

}  // namespace

std::string json_report(const Verdict& v, const std::string& text) {
  const conform::Options& o = v.options;
  std::string out = std::string("{\n  \"format\": \"") + kReportFormat + "\",\n  \"verdict\": " + json_string(name(v.outcome)) +
                    ",\n  \"error\": " + (v.error.empty() ? "null" : json_string(v.error)) +
                    ",\n  \"candidate\": " + json_string(v.candidate) + ",\n  \"seed\": " + std::to_string(o.seed) +
                    ", \"shard\": " + json_string(shard_text(o)) + ", \"level\": " + json_string(o.level.text()) +
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
         "],\n  \"elapsed_seconds\": " + seconds(v.elapsed.count()) + "\n}\n";
  return out;
}

std::string junit_report(const Verdict& v, const std::string& text) {
  std::size_t failures = 0, errors = 0, skipped = 0;
  std::string cases;
  for (const FamilyResult& f : v.families) {
    const std::string family = properties::name(f.family);
    cases += "    <testcase classname=\"circles.conform\" name=\"" + xml(family) + "\" time=\"0\">\n";
    // The family's counterexample: the run's (printed in full, `text`), or with --keep-going its own.
    const Counterexample* c = f.has_counterexample && v.counterexample ? &*v.counterexample
                              : f.counterexample                       ? &*f.counterexample
                                                                       : nullptr;
    const auto message = difference_message;
    if (f.status == FamilyStatus::failed && c) {
      ++failures;
      const std::string body = f.has_counterexample ? text : short_text(*c);
      cases += "      <failure type=\"does not conform\" message=\"" + xml(message(*c)) + "\">" + xml(body) + "</failure>\n";
    } else if (f.status == FamilyStatus::unexpected_pass) {
      ++failures;
      const std::string why = "unexpected pass: the expectation file lists " + family +
                              " as failing, and it passed; delete its line";
      cases += "      <failure type=\"unexpected pass\" message=\"" + xml(why) + "\">" + xml(why) + "</failure>\n";
    } else if (f.status == FamilyStatus::expected_failure) {
      ++skipped;
      cases += "      <skipped message=\"" + xml("expected failure" + (c ? ": " + message(*c) : std::string())) + "\"/>\n";
    } else if (f.status == FamilyStatus::skipped) {
      ++skipped;
      cases += "      <skipped message=\"skipped: left out by --families or --skip-families\"/>\n";
    } else if (v.outcome == conform::Outcome::cannot_check && f.checked == 0) {
      ++errors;
      cases += "      <error type=\"cannot check\" message=\"" + xml(v.error) + "\">" + xml(v.error) + "</error>\n";
    } else if (f.status == conform::FamilyStatus::not_reached) {
      ++skipped;
      cases += "      <skipped message=\"not reached: the run stopped at its counterexample\"/>\n";
    }
    cases += "      <system-out>" + std::to_string(f.checked) + " cases checked</system-out>\n    </testcase>\n";
  }
  const conform::Options& o = v.options;
  const std::string counts = "tests=\"" + std::to_string(v.families.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\" skipped=\"" + std::to_string(skipped) +
                             "\" time=\"" + seconds(v.elapsed.count()) + "\"";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"circles conform\" " + counts + ">\n" +
         "  <testsuite name=\"" + xml("circles conform: " + v.candidate) + "\" " + counts + ">\n    <properties>\n" +
         "      <property name=\"verdict\" value=\"" + xml(name(v.outcome)) + "\"/>\n" +
         "      <property name=\"seed\" value=\"" + std::to_string(o.seed) + "\"/>\n" +
         "      <property name=\"shard\" value=\"" + shard_text(o) + "\"/>\n" +
         "      <property name=\"level\" value=\"" + xml(o.level.text()) + "\"/>\n" +
         "      <property name=\"profile\" value=\"" + properties::name(o.profile) + "\"/>\n" +
         "      <property name=\"cases\" value=\"" + std::to_string(v.cases) + "\"/>\n    </properties>\n" + cases +
         "  </testsuite>\n</testsuites>\n";
}

void write_report(const std::string& path, const std::string& what, const std::string& text) {
  formats::OutputFile file(path, what + " " + path);
  file.write(text);
  file.commit();
}

}  // namespace circles::cli
