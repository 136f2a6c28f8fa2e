#include "conform/merge.hpp"

#include "conform/conform.hpp"  // FamilyStatus
#include "formats/protocol.hpp"  // shortened_token

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <optional>
#include <set>

namespace circles::conform {
namespace {

// A family's status over shards: it failed if it failed in any (unexpectedly, then as expected), else it
// passed unexpectedly if it did in any, else passed if it passed in one; not reached and skipped rank last.
int status_rank(std::optional<FamilyStatus> status) {
  if (!status) return 0;  // not yet seen in any shard
  switch (*status) {
    case FamilyStatus::skipped: return 1;
    case FamilyStatus::not_reached: return 2;
    case FamilyStatus::passed: return 3;
    case FamilyStatus::unexpected_pass: return 4;
    case FamilyStatus::expected_failure: return 5;
    case FamilyStatus::failed: return 6;
  }
  return 0;
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

// The reports, each read and checked, and all of shards of one run, the shards' indices in `shards` and their
// count in `n`. Throws ReportError.
std::vector<nlohmann::json> read_reports(const std::vector<std::string>& texts, const std::vector<std::string>& names,
                                         std::set<unsigned long long>& shards, unsigned long long& n) {
  if (texts.empty()) throw ReportError("report merge: no reports to merge");
  std::vector<nlohmann::json> reports;
  for (std::size_t k = 0; k < texts.size(); ++k) {
    nlohmann::json r;
    try {
      r = nlohmann::json::parse(texts[k]);
    } catch (const nlohmann::json::exception& e) {
      throw ReportError(names[k] + ": malformed JSON: " + e.what());
    }
    if (!r.is_object() || !r.contains("format") || r["format"] != kReportFormat)
      throw ReportError(names[k] + ": not a report of circles conform (\"format\": \"" + kReportFormat + "\")");
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
  n = shard_of(0).second;
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

  return reports;
}

}  // namespace

std::string merge_reports(const std::vector<std::string>& texts, const std::vector<std::string>& names) {
  std::set<unsigned long long> shards;
  unsigned long long n = 0;
  const std::vector<nlohmann::json> reports = read_reports(texts, names, shards, n);
  const nlohmann::json& first = reports.front();
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
      const std::optional<FamilyStatus> status_of_one = parse_family_status(one);
      if (!status_of_one)
        throw ReportError(names[&r - reports.data()] + ": \"family_status\": " + family + " is " + s.dump() +
                          ", not a status of a family");
      std::string& merged = status[family];
      if (status_rank(status_of_one) > status_rank(parse_family_status(merged))) merged = one;
    }
  }
  bool family_fails = false;
  for (const auto& [family, s] : status)
    family_fails = family_fails || s == name(FamilyStatus::failed) || s == name(FamilyStatus::unexpected_pass);
  if (!error.is_null()) verdict = "cannot check";
  else if (!counterexample.is_null() || family_fails) verdict = "does not conform";
  nlohmann::ordered_json out;
  std::string shard_list;
  for (const unsigned long long i : shards) shard_list += (shard_list.empty() ? "" : ",") + std::to_string(i);
  out["format"] = kReportFormat;
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

}  // namespace circles::conform
