#include "cli/conform_report.hpp"

#include "conform/verdict_text.hpp"
#include "formats/counted.hpp"
#include "formats/json_number.hpp"
#include "formats/output_file.hpp"
#include "pictures/counterexample_svg.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace circles::cli {

using formats::counted;

namespace {

using conform::Counterexample;
using conform::difference_line;
using conform::head_lines;
using conform::Outcome;
using conform::Verdict;
using properties::Profile;
namespace json_number = formats::json_number;

// Draws the picture of the run's counterexample where picture_path says, if anywhere, and says where.
void draw_picture(const Verdict& v, const std::filesystem::path& svg, std::ostream& out) {
  const Counterexample& c = *v.counterexample;
  const properties::Difference& d = c.difference;
  if (!c.fault.empty()) return;  // no answer to draw
  if (const std::filesystem::path file = picture_path(v, svg); !file.empty()) {
    try {
      formats::write_file(file.string(), file.string(),
                          pictures::counterexample_svg(
                              {c.input, c.expected, c.actual, d.circle, v.options.profile, head_lines(v)}));
      out << "picture: " << file.string() << "\n";
    } catch (const std::exception& e) {
      out << "picture: not drawn: " << e.what() << "\n";
    }
  }
}

void print_counterexample(const Verdict& v, const std::filesystem::path& svg, std::ostream& out) {
  const Counterexample& c = *v.counterexample;
  out << conform::counterexample_worlds(v);
  if (!c.saved.empty()) out << "saved: " << c.saved.string() << "\n";
  if (!c.not_saved.empty()) out << "saved: not saved: " << c.not_saved << "\n";
  draw_picture(v, svg, out);
  out << "replay: " << c.replay << "\n";
}

// "lattice 59, random-doubles 59, …", wrapped before 110 columns, each line indented.
void print_families(std::ostream& out, std::span<const conform::FamilyResult> families) {
  std::string line = "  cases checked per family:";
  for (std::size_t f = 0; f < families.size(); ++f) {
    const std::string item = std::string(" ") + properties::name(families[f].family) + " " +
                             std::to_string(families[f].checked) + (f + 1 < families.size() ? "," : "");
    if (line.size() + item.size() > 110) {
      out << line << "\n";
      line = "   ";
    }
    line += item;
  }
  out << line << "\n";
}

// How far a budget run went: "big worlds up to 262,144 circles, 57 s of 60"; with a stage cut at the budget's
// end, "big worlds up to 65,536 circles, 66 s of 60 (a stage at 131,072 circles cut at the budget's end)".
std::string how_far(const Verdict& v) {
  const auto grouped = [](std::uint64_t n) {
    std::string digits = std::to_string(n);
    for (std::size_t at = digits.size(); at > 3; at -= 3) digits.insert(at - 3, ",");
    return digits;
  };
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.0f", v.elapsed.count());
  return (v.largest_world ? "big worlds up to " + grouped(v.largest_world) + " circles, " : std::string()) + elapsed +
         " s of " + json_number::plain(*v.options.budget) +
         (v.cut_world ? " (a stage at " + grouped(v.cut_world) + " circles cut at the budget's end)" : "");
}

// The first line of a run's verdict without a counterexample, or of its --keep-going table: "circles conform:
// CANDIDATE conforms: 1000 cases (2 skipped: …), 1 step each (2 for tangent-after-step, whose boundary comes
// only at step 2), level exact, seed 3, resolved profile"; against an expectation file with failures listed,
// "CANDIDATE passes with 22 expected failures, 3 families pass: 1000 cases, …".
std::string summary_line(const Verdict& v) {
  const conform::Options& o = v.options;
  // Against an expectation file, a run whose listed families failed as listed passes, but does not conform:
  // "22 expected failures, 3 families pass".
  const auto with = [&](conform::FamilyStatus status) {
    return static_cast<std::uint64_t>(
        std::count_if(v.families.begin(), v.families.end(), [&](const auto& f) { return f.status == status; }));
  };
  const std::uint64_t expected = with(conform::FamilyStatus::expected_failure);
  std::string line = "circles conform: " + v.candidate + " ";
  if (v.outcome == Outcome::conforms && expected > 0)
    line += "passes with " + counted(expected, "expected failure") + ", " +
            counted(with(conform::FamilyStatus::passed), "family", "families") + " " +
            (with(conform::FamilyStatus::passed) == 1 ? "passes" : "pass");
  else
    line += name(v.outcome);
  line += ": " + counted(v.cases, "case");
  if (v.skipped)
    line += " (" + std::to_string(v.skipped) + " skipped: " + (v.skipped == 1 ? "its" : "their") +
            " next world leaves the double range)";
  line += ", " + counted(o.steps, "step") + " each";
  std::string longer;  // "2 for tangent-after-step, whose boundary comes only at step 2": the families chained further
  for (const conform::FamilyResult& f : v.families)
    if (const std::uint64_t n = properties::steps_to_decide(f.family); f.checked > 0 && n > o.steps)
      longer += (longer.empty() ? "" : "; ") + std::to_string(n) + " for " + properties::name(f.family) +
                (f.family == properties::Family::big_chains
                     ? std::string(", so that what a program keeps between requests is used")
                     : ", whose boundary comes only at step " + std::to_string(n));
  if (!longer.empty()) line += " (" + longer + ")";
  line += ", level " + o.level.text() + ", seed " + std::to_string(o.seed) + ", " + properties::name(o.profile) +
          " profile";
  if (o.shards > 1) line += ", shard " + std::to_string(o.shard) + "/" + std::to_string(o.shards);
  if (o.budget && !o.only_case) line += "; " + how_far(v);
  return line;
}

void print_conforms(const Verdict& v, std::ostream& out) {
  const conform::Options& o = v.options;
  out << summary_line(v) << "\n";
  if (v.cases > 0) print_families(out, v.families);
  if (v.cut_short)
    out << "  " << counted(v.cut_short, "chain") << " ended early: " << (v.cut_short == 1 ? "its" : "their")
        << " next world leaves the double range"
        << (o.profile == Profile::literal ? " or the literal domain" : "") << "\n";
  if (!o.save.empty()) {
    out << "  corpus: " << counted(v.replayed, "stored counterexample") << " replayed from "
        << o.save.string();
    if (v.not_replayed)
      out << " (" << v.not_replayed << " not: no expected answer"
          << (o.profile == Profile::literal ? ", outside the literal domain or beyond the double range"
                                            : ", beyond the double range")
          << ")";
    out << "\n";
  }
}

// "1st", "2nd", "3rd", "4th", "11th", "21st".
std::string ordinal(std::uint64_t n) {
  const std::uint64_t last = n % 10;
  const char* suffix = n % 100 / 10 == 1 ? "th" : last == 1 ? "st" : last == 2 ? "nd" : last == 3 ? "rd" : "th";
  return std::to_string(n) + suffix;
}

// A family's status in the --keep-going table; for one with a counterexample, where it failed: "failed at its
// 3rd case; none asked after" (its count of cases is those up to its failure), or "failed on a stored
// counterexample; no case asked".
std::string status_cell(const conform::FamilyResult& f) {
  const std::string status = name(f.status);
  if (!f.counterexample) return status;
  if (!f.counterexample->stored.empty()) return status + " on a stored counterexample; no case asked";
  return status + " at its " + ordinal(f.checked) + " case; none asked after";
}

// --keep-going: a row per family, its cases checked, its status and, for a family that failed, its shrunk
// counterexample: a line (the field, expected, got, which decision), the world asked, and its replay line.
void print_table(const Verdict& v, std::ostream& out) {
  out << summary_line(v) << "\n";
  std::size_t width = 6;
  for (const conform::FamilyResult& f : v.families) width = std::max(width, std::string(properties::name(f.family)).size());
  const auto pad = [](std::string text, std::size_t n) { return text + std::string(n > text.size() ? n - text.size() : 0, ' '); };
  out << "  " << pad("family", width) << "  " << pad("cases", 6) << "  status\n";
  std::map<std::string, int> counts;
  for (const conform::FamilyResult& f : v.families) {
    ++counts[name(f.status)];
    out << "  " << pad(properties::name(f.family), width) << "  " << pad(std::to_string(f.checked), 6) << "  "
        << status_cell(f) << "\n";
    if (!f.counterexample) continue;
    const Counterexample& c = *f.counterexample;
    const std::string indent(width + 12, ' ');
    out << indent << difference_line(c) << "; which decision: " << c.difference.decision << "\n";
    out << conform::world_text(conform::asked_title(c), c.input, indent.substr(2));
    out << indent << "replay: " << c.replay << "\n";
    if (!c.saved.empty()) out << indent << "saved: " << c.saved.string() << "\n";
  }
  std::string summary;
  for (const auto& [status, n] : counts) {
    // "1 expected failure", "2 expected failures", "3 unexpected passes"; "passed", "skipped", ... as they are.
    std::string plural = status;
    if (n != 1 && status.ends_with("failure")) plural += "s";
    else if (n != 1 && status.ends_with("pass")) plural += "es";
    summary += (summary.empty() ? "" : ", ") + std::to_string(n) + " " + plural;
  }
  out << "  families: " << summary << "\n";
}

}  // namespace

std::filesystem::path picture_path(const Verdict& verdict, const std::filesystem::path& svg) {
  if (!svg.empty()) return svg;
  if (verdict.options.save.empty() || !verdict.counterexample) return {};
  const Counterexample& c = *verdict.counterexample;
  const std::filesystem::path& beside = !c.saved.empty() ? c.saved : c.stored;
  if (beside.empty()) return {};
  return verdict.options.save / (beside.stem().string() + ".svg");
}

int print_verdict(const Verdict& verdict, const std::filesystem::path& svg, std::ostream& out, std::ostream& err) {
  if (verdict.options.keep_going && conform::judged(verdict.outcome)) {
    print_table(verdict, out);
    if (verdict.counterexample) draw_picture(verdict, svg, out);  // of the first unexpected failure
    return verdict.outcome == Outcome::conforms ? 0 : 1;
  }
  switch (verdict.outcome) {
    case Outcome::conforms:
      print_conforms(verdict, out);
      return 0;
    case Outcome::does_not_conform:
      print_counterexample(verdict, svg, out);
      return 1;
    case Outcome::interrupted:
      // A counterexample found before the signal (shrunk as far as the signal let it), then the cases checked
      // and the seed, so that nothing is lost: the same cases can be checked again.
      if (verdict.counterexample) print_counterexample(verdict, svg, out);
      err << "circles conform: " << verdict.error << " after " << counted(verdict.checked(), "case")
          << (verdict.counterexample ? ", while shrinking its counterexample" : "") << " (seed "
          << verdict.options.seed << ")\nto check the same cases again: " << verdict.rerun << "\n";
      return 128 + verdict.signal;
    case Outcome::cannot_check:
      break;
  }
  // The seed, so that a run with a random one can be run again.
  err << "circles conform: " << verdict.error << " (seed " << verdict.options.seed << ")\n";
  return 2;
}

}  // namespace circles::cli
