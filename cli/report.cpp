#include "cli/report.hpp"

#include "formats/json_number.hpp"
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
using formats::Circles;
namespace json_number = formats::json_number;

constexpr const char* kFormat = "circles-conform-report/1";

void append_world(std::string& out, const Circles& w) {
  out += '[';
  for (std::size_t k = 0; k < w.size(); ++k) {
    out += k ? ",[" : "[";
    for (std::size_t f = 0; f < 5; ++f) {
      if (f) out += ',';
      json_number::append_or_string(out, w[k][f]);
    }
    out += ']';
  }
  out += ']';
}

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
         json_string(properties::field_name(d.field)) + ", \"expected\": ";
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
         ", field " + properties::field_name(d.field) + ": expected " + json_number::decimal_and_hex(d.expected) +
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

// A family's status over shards: it failed if it failed in any (unexpectedly, then as expected), else it
// passed unexpectedly if it did in any, else passed if it passed in one; not reached and skipped rank last.
int status_rank(const std::string& status) {
  static const char* const order[] = {"", "skipped", "not reached", "passed", "unexpected pass", "expected failure",
                                      "failed"};
  return static_cast<int>(std::find(std::begin(order), std::end(order), status) - std::begin(order));
}

// The keys merge_reports reads, each of the type conform writes it, so that a report cut short or edited by hand
// is refused naming its file and key, rather than ending the program with a JSON library's exception.
void check_report(const nlohmann::json& r, const std::string& name) {
  const auto refuse = [&](const std::string& key, const std::string& expected) {
    throw ReportError(name + ": \"" + key + "\": expected " + expected + ", found " +
                      (r.contains(key) ? formats::shortened_token(r.at(key).dump()) : std::string("nothing")));
  };
  const auto has = [&](const char* key, bool (nlohmann::json::*is)() const noexcept) {
    return r.contains(key) && (r.at(key).*is)();
  };
  for (const char* key : {"candidate", "level", "profile", "shard", "verdict"})
    if (!has(key, &nlohmann::json::is_string)) refuse(key, "a string");
  for (const char* key : {"seed", "steps", "cases", "skipped", "cut_short", "replayed"})
    if (!has(key, &nlohmann::json::is_number_unsigned)) refuse(key, "an integer >= 0");
  if (!has("elapsed_seconds", &nlohmann::json::is_number)) refuse("elapsed_seconds", "a number");
  const std::string verdict = r.at("verdict");
  if (verdict != "conforms" && verdict != "does not conform" && verdict != "cannot check")
    refuse("verdict", "\"conforms\", \"does not conform\" or \"cannot check\"");
  if (!has("error", &nlohmann::json::is_null) && !has("error", &nlohmann::json::is_string)) refuse("error", "null or a string");
  if (!has("families", &nlohmann::json::is_object) ||
      std::any_of(r.at("families").begin(), r.at("families").end(), [](const nlohmann::json& n) { return !n.is_number_unsigned(); }))
    refuse("families", "an object of case counts, integers >= 0");
  if (!has("family_status", &nlohmann::json::is_object)) refuse("family_status", "an object of statuses");
  const bool no_counterexample = has("counterexample", &nlohmann::json::is_null);
  if (!no_counterexample && !(has("counterexample", &nlohmann::json::is_object) && r.at("counterexample").contains("case") &&
                              (r.at("counterexample").at("case").is_null() || r.at("counterexample").at("case").is_number_unsigned())))
    refuse("counterexample", "null or an object whose \"case\" is null or an integer >= 0");
}

}  // namespace

std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string json_report(const Verdict& v, const std::string& text) {
  const conform::Options& o = v.options;
  std::string out = std::string("{\n  \"format\": \"") + kFormat + "\",\n  \"verdict\": " + json_string(name(v.outcome)) +
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

std::string merge_reports(const std::vector<std::string>& texts, const std::vector<std::string>& names) {
  if (texts.empty()) throw ReportError("report merge: no reports to merge");
  std::vector<nlohmann::json> reports;
  for (std::size_t k = 0; k < texts.size(); ++k) {
    nlohmann::json r;
    try {
      r = nlohmann::json::parse(texts[k]);
    } catch (const nlohmann::json::exception& e) {
      throw ReportError(names[k] + ": malformed JSON: " + e.what());
    }
    if (!r.is_object() || !r.contains("format") || r["format"] != kFormat)
      throw ReportError(names[k] + ": not a report of circles conform (\"format\": \"" + kFormat + "\")");
    check_report(r, names[k]);
    reports.push_back(std::move(r));
  }
  const nlohmann::json& first = reports.front();
  const auto shard_of = [&](std::size_t k) {
    const std::string s = reports[k].value("shard", "");
    const auto slash = s.find('/');
    try {
      if (slash == std::string::npos || s.find(',') != std::string::npos) throw std::invalid_argument(s);
      return std::pair{std::stoull(s.substr(0, slash)), std::stoull(s.substr(slash + 1))};
    } catch (const std::exception&) {
      throw ReportError(names[k] + ": \"shard\": expected i/n, found \"" + s + "\" (a merged report is not merged again)");
    }
  };
  std::set<unsigned long long> shards;
  const unsigned long long n = shard_of(0).second;
  for (std::size_t k = 0; k < reports.size(); ++k) {
    for (const char* key : {"candidate", "seed", "level", "profile", "steps"})
      if (reports[k][key] != first[key])
        throw ReportError(names[k] + ": \"" + key + "\" is " + reports[k][key].dump() + ", but " + names[0] + "'s is " +
                          first[key].dump() + ": only the shards of one run merge");
    const auto [i, count] = shard_of(k);
    if (count != n) throw ReportError(names[k] + ": shard " + std::to_string(i) + "/" + std::to_string(count) +
                                      " is not one of " + std::to_string(n) + " shards, as " + names[0] + "'s is");
    if (!shards.insert(i).second) throw ReportError(names[k] + ": shard " + std::to_string(i) + "/" + std::to_string(n) + " twice");
  }

  nlohmann::ordered_json out;
  std::string verdict = "conforms";
  nlohmann::json error = nullptr, counterexample = nullptr;
  std::uint64_t cases = 0, skipped = 0, cut_short = 0, replayed = 0;
  double elapsed = 0;
  std::vector<std::pair<std::string, std::uint64_t>> families;  // in the first report's order
  std::map<std::string, std::string> status;
  std::map<std::string, nlohmann::json> of_family;  // the counterexample of the lowest case of each family
  const auto rank = [](const nlohmann::json& c) {  // a stored counterexample (no case) was replayed first
    return c["case"].is_null() ? -1.0 : c["case"].get<double>();
  };
  for (const nlohmann::json& r : reports) {
    cases += r.value("cases", 0ull);
    skipped += r.value("skipped", 0ull);
    cut_short += r.value("cut_short", 0ull);
    replayed = std::max<std::uint64_t>(replayed, r.value("replayed", 0ull));  // each shard replays the same corpus
    elapsed += r.value("elapsed_seconds", 0.0);
    if (r["verdict"] == "cannot check" && error.is_null()) error = r["error"];
    if (!r["counterexample"].is_null() && (counterexample.is_null() || rank(r["counterexample"]) < rank(counterexample)))
      counterexample = r["counterexample"];
    for (const nlohmann::json& c : r.value("counterexamples", nlohmann::json::array())) {
      nlohmann::json& kept = of_family[c.value("family", "")];
      if (kept.is_null() || rank(c) < rank(kept)) kept = c;
    }
    for (const auto& [family, count] : r["families"].items()) {
      // [&name = family]: Clang 14 cannot capture a structured binding (the sanitizer and fuzz build is Clang's).
      const auto named = [&name = family](const auto& p) { return p.first == name; };
      auto at = std::find_if(families.begin(), families.end(), named);
      if (at == families.end()) families.emplace_back(family, count.get<std::uint64_t>());
      else at->second += count.get<std::uint64_t>();
    }
    for (const auto& [family, s] : r["family_status"].items()) {
      const std::string one = s.is_string() ? s.get<std::string>() : "";
      if (!conform::parse_family_status(one))
        throw ReportError(names[&r - reports.data()] + ": \"family_status\": " + family + " is " + s.dump() +
                          ", not a status of a family");
      std::string& merged = status[family];
      if (status_rank(one) > status_rank(merged)) merged = one;
    }
  }
  bool family_fails = false;
  for (const auto& [family, s] : status) family_fails = family_fails || s == "failed" || s == "unexpected pass";
  if (!error.is_null()) verdict = "cannot check";
  else if (!counterexample.is_null() || family_fails) verdict = "does not conform";
  std::string shard_list;
  for (const unsigned long long i : shards) shard_list += (shard_list.empty() ? "" : ",") + std::to_string(i);
  out["format"] = kFormat;
  out["verdict"] = verdict;
  out["error"] = error;
  for (const char* key : {"candidate", "seed"}) out[key] = first[key];
  out["shard"] = shard_list + "/" + std::to_string(n);
  for (const char* key : {"level", "profile", "steps"}) out[key] = first[key];
  out["cases"] = cases;
  out["skipped"] = skipped;
  out["cut_short"] = cut_short;
  out["replayed"] = replayed;
  nlohmann::ordered_json by_family = nlohmann::ordered_json::object(), by_status = nlohmann::ordered_json::object();
  for (const auto& [family, count] : families) {
    by_family[family] = count;
    by_status[family] = status[family];
  }
  out["families"] = by_family;
  out["family_status"] = by_status;
  out["counterexample"] = counterexample;
  nlohmann::json all = nlohmann::json::array();
  if (of_family.contains("")) all.push_back(of_family[""]);
  for (const auto& [family, count] : families)
    if (of_family.contains(family)) all.push_back(of_family[family]);
  out["counterexamples"] = all;
  out["elapsed_seconds"] = elapsed;
  return out.dump(2) + "\n";
}

int merge_command(const std::string& out, const std::vector<std::string>& reports, std::ostream& said,
                  std::ostream& err) {
  std::vector<std::string> texts;
  for (const std::string& file : reports) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) {
      err << "circles report merge: " << file << ": cannot read it\n";
      return 2;
    }
    texts.push_back(text.str());
  }
  try {
    const std::string merged = merge_reports(texts, reports);
    write_report(out, "report", merged);
    const nlohmann::json m = nlohmann::json::parse(merged);
    const std::string verdict = m["verdict"];
    said << "circles report merge: " << out << ": " << m["candidate"].get<std::string>() << " " << verdict << ": "
         << m["cases"].get<std::uint64_t>() << (m["cases"] == 1 ? " case" : " cases") << " of seed "
         << m["seed"].get<std::uint64_t>() << " in " << reports.size() << (reports.size() == 1 ? " report" : " reports");
    if (m["counterexample"].is_object() && m["counterexample"].contains("replay"))
      said << "; replay: " << m["counterexample"]["replay"].get<std::string>();
    if (m["error"].is_string()) said << "; " << m["error"].get<std::string>();
    said << "\n";
    return verdict == "conforms" ? 0 : verdict == "does not conform" ? 1 : 2;
  } catch (const ReportError& e) {
    err << "circles report merge: " << e.what() << "\n";
  } catch (const formats::OutputError& e) {
    err << "circles report merge: " << e.what() << "\n";
  }
  return 2;
}

void write_report(const std::string& path, const std::string& what, const std::string& text) {
  formats::OutputFile file(path, what + " " + path);
  file.write(text);
  file.commit();
}

}  // namespace circles::cli
