#include "conform/merge.hpp"

#include "formats/json_world.hpp"  // json_string

#include <algorithm>
#include <optional>
#include <set>
#include <utility>

namespace circles::conform {
namespace {

// A family's status over shards: it failed if it failed in any (unexpectedly, then as expected), else it
// passed unexpectedly if it did in any, else passed if it passed in one; not reached and skipped rank last.
int status_rank(FamilyStatus status) {
  switch (status) {
    case FamilyStatus::skipped: return 1;
    case FamilyStatus::not_reached: return 2;
    case FamilyStatus::passed: return 3;
    case FamilyStatus::unexpected_pass: return 4;
    case FamilyStatus::expected_failure: return 5;
    case FamilyStatus::failed: return 6;
  }
  return 0;
}

// What makes reports the shards of one run, each as the report writes it: its key and value.
std::vector<std::pair<const char*, std::string>> run_of(const Verdict& v) {
  const Options& o = v.options;
  return {{"candidate", formats::json_string(v.candidate)},
          {"seed", std::to_string(o.seed)},
          {"level", formats::json_string(o.level.text())},
          {"profile", formats::json_string(properties::name(o.profile))},
          {"steps", std::to_string(o.steps)}};
}

// The reports, each read, and all of them shards of one run. Throws ReportError.
std::vector<Report> read_reports(const std::vector<std::string>& texts, const std::vector<std::string>& names) {
  if (texts.empty()) throw ReportError("report merge: no reports to merge");
  std::vector<Report> reports;
  for (std::size_t k = 0; k < texts.size(); ++k) reports.push_back(read_report(texts[k], names[k]));
  const Verdict& first = reports.front().verdict;
  const auto first_run = run_of(first);
  const std::uint64_t n = first.options.shards;
  std::set<std::uint64_t> shards;
  for (std::size_t k = 0; k < reports.size(); ++k) {
    const Verdict& v = reports[k].verdict;
    const auto run = run_of(v);
    for (std::size_t j = 0; j < run.size(); ++j)
      if (run[j].second != first_run[j].second)
        throw ReportError(names[k] + ": \"" + run[j].first + "\" is " + run[j].second + ", but " + names[0] +
                          "'s is " + first_run[j].second + ": only the shards of one run merge");
    const std::uint64_t i = v.options.shard, count = v.options.shards;
    if (count != n) throw ReportError(names[k] + ": shard " + std::to_string(i) + "/" + std::to_string(count) +
                                      " is not one of " + std::to_string(n) + " shards, as " + names[0] + "'s is");
    if (!shards.insert(i).second) throw ReportError(names[k] + ": shard " + std::to_string(i) + "/" + std::to_string(n) + " twice");
  }
  return reports;
}

// `found`'s counterexample into `kept` where it was found first (a tie keeps `kept`'s); true when it was taken.
bool take_first_found(std::optional<Counterexample>& kept, std::optional<Counterexample>& found) {
  if (!found || (kept && !found_before(*found, *kept))) return false;
  kept = std::move(found);
  return true;
}

// One shard's record of a family into the merged one: the cases add up, the status ranks, the counterexample found
// first stays.
void merge_family(std::vector<FamilyResult>& merged, FamilyResult& shard) {
  const auto at = std::find_if(merged.begin(), merged.end(), [&](const FamilyResult& f) { return f.family == shard.family; });
  if (at == merged.end()) {
    merged.push_back(std::move(shard));
    return;
  }
  at->checked += shard.checked;
  if (status_rank(shard.status) > status_rank(at->status)) at->status = shard.status;
  take_first_found(at->counterexample, shard.counterexample);
}

}  // namespace

Report merged_report(const std::vector<std::string>& texts, const std::vector<std::string>& names) {
  std::vector<Report> reports = read_reports(texts, names);
  Report merged = std::move(reports.front());
  Verdict& m = merged.verdict;
  // Not judged: a shard that could not check makes the merged run so, else one that a signal interrupted.
  std::optional<Outcome> unjudged;
  if (!judged(m.outcome)) unjudged = m.outcome;
  else m.error.clear();
  m.merged_shards = {m.options.shard};
  for (std::size_t k = 1; k < reports.size(); ++k) {
    Verdict& v = reports[k].verdict;
    m.merged_shards.push_back(v.options.shard);
    m.cases += v.cases;
    m.skipped += v.skipped;
    m.cut_short += v.cut_short;
    m.replayed = std::max(m.replayed, v.replayed);  // each shard replays the same corpus
    m.elapsed += v.elapsed;
    if (!judged(v.outcome) && (!unjudged || (*unjudged == Outcome::interrupted && v.outcome == Outcome::cannot_check))) {
      unjudged = v.outcome;
      m.error = v.error;
    }
    if (take_first_found(m.counterexample, v.counterexample)) merged.text = std::move(reports[k].text);
    for (FamilyResult& f : v.families) merge_family(m.families, f);
  }
  std::sort(m.merged_shards.begin(), m.merged_shards.end());
  mark_counterexample_family(m);
  m.outcome = unjudged ? *unjudged : checked_outcome(m);
  return merged;
}

}  // namespace circles::conform
