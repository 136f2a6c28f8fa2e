#include "conform/expect.hpp"

#include "formats/input_file.hpp"
#include "formats/json_number.hpp"

#include <algorithm>

namespace circles::conform {
namespace {

std::string where(const std::filesystem::path& file, std::size_t line) {
  return file.string() + ":" + std::to_string(line) + ": ";
}

// The line's words: the first two, and the rest with its leading blanks removed.
struct Words {
  std::string_view first, second, rest;
};

Words split(std::string_view line) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  const auto skip = [&](std::string_view s) {
    std::size_t k = 0;
    while (k < s.size() && blank(s[k])) ++k;
    return s.substr(k);
  };
  const auto word = [&](std::string_view& s) {
    s = skip(s);
    std::size_t k = 0;
    while (k < s.size() && !blank(s[k])) ++k;
    const std::string_view w = s.substr(0, k);
    s = s.substr(k);
    return w;
  };
  Words w;
  w.first = word(line);
  w.second = word(line);
  w.rest = skip(line);
  while (!w.rest.empty() && blank(w.rest.back())) w.rest.remove_suffix(1);
  return w;
}

}  // namespace

const Expectation* Expectations::find(properties::Family family) const {
  const auto at = std::find_if(entries.begin(), entries.end(), [&](const Expectation& e) { return e.family == family; });
  return at == entries.end() ? nullptr : &*at;
}

Expectations parse_expectations(std::string_view text, const std::filesystem::path& file, Profile profile) {
  Expectations out;
  out.file = file;
  std::size_t number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const Words w = split(line);
    if (w.first.empty() || w.first.front() == '#') continue;
    const std::string at = where(file, number);
    if (w.first == "fail")
      throw ExpectError(at + "the entry names no family: expected FAMILY fail REASON");
    std::vector<properties::Family> family;
    try {
      family = parse_families("family", w.first, profile);
    } catch (const std::invalid_argument& e) {
      throw ExpectError(at + e.what());
    }
    if (w.second != "fail")
      throw ExpectError(at + "expected \"fail\" after the family " + std::string(w.first) + ", found \"" +
                        std::string(w.second) + "\": FAMILY fail REASON");
    if (w.rest.empty()) throw ExpectError(at + "the entry for " + std::string(w.first) + " gives no reason: FAMILY fail REASON");
    if (const Expectation* before = out.find(family.front()))
      throw ExpectError(at + "the family " + std::string(w.first) + " is listed already, on line " +
                        std::to_string(before->line));
    out.entries.push_back({family.front(), std::string(w.rest), number});
  }
  return out;
}

Expectations read_expectations(const std::filesystem::path& file, Profile profile) {
  const std::string name = formats::input_name(file.string());
  std::string text;
  try {
    text = formats::read_input(file.string());
  } catch (const formats::InputError& e) {
    throw ExpectError(name + ": " + e.what());
  }
  return parse_expectations(text, name, profile);
}

void apply(Verdict& verdict, const Expectations& expectations) {
  const Counterexample* first = nullptr;
  for (FamilyResult& f : verdict.families) {
    const bool listed = expectations.find(f.family) != nullptr;
    if (listed && f.status == FamilyStatus::failed) f.status = FamilyStatus::expected_failure;
    else if (listed && f.status == FamilyStatus::passed) f.status = FamilyStatus::unexpected_pass;
    if (f.status == FamilyStatus::failed && f.counterexample && (!first || found_before(*f.counterexample, *first)))
      first = &*f.counterexample;
  }
  // A stored counterexample of no family of the profile fails the run whatever the file says.
  if (verdict.counterexample && verdict.counterexample->family.empty()) first = &*verdict.counterexample;
  std::optional<Counterexample> reported;
  if (first) reported = *first;
  verdict.counterexample = std::move(reported);
  mark_counterexample_family(verdict);
  if (judged(verdict.outcome)) verdict.outcome = checked_outcome(verdict);
}

std::vector<std::string> unexpected_passes(const Verdict& verdict, const Expectations& expectations) {
  std::vector<std::string> lines;
  for (const FamilyResult& f : verdict.families)
    if (f.status == FamilyStatus::unexpected_pass)
      lines.push_back(std::string(properties::name(f.family)) + ": unexpected pass (" + std::to_string(f.checked) +
                      (f.checked == 1 ? " case" : " cases") + " checked): delete its line, " + expectations.file.string() + ":" +
                      std::to_string(expectations.find(f.family)->line));
  return lines;
}

std::string expectations_text(const Verdict& verdict) {
  const Options& o = verdict.options;
  std::string text =
      "# circles conform expectations: FAMILY fail REASON, one a line (docs/conform.md, \"Expectation files\").\n"
      "# Written by --write-expect for " + verdict.candidate + ", seed " + std::to_string(o.seed) + ", level " +
      o.level.text() + ", " + properties::name(o.profile) + " profile: fill in each reason, and delete a line\n"
      "# when its family passes.\n";
  for (const FamilyResult& f : verdict.families) {
    if (f.status != FamilyStatus::failed && f.status != FamilyStatus::expected_failure) continue;
    if (f.counterexample) {
      const properties::Difference& d = f.counterexample->difference;
      text += "# field " + std::string(spec::name(d.field)) + " of circle " + std::to_string(d.circle) +
              ": expected " + formats::json_number::decimal_and_hex(d.expected) + ", got " +
              formats::json_number::decimal_and_hex(d.actual) + " (" + d.decision + "); replay: " +
              f.counterexample->replay + "\n";
    }
    text += std::string(properties::name(f.family)) + " fail TODO: why it fails\n";
  }
  return text;
}

}  // namespace circles::conform
