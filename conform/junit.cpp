#include "conform/junit.hpp"

#include "conform/verdict_text.hpp"
#include "formats/counted.hpp"
#include "formats/xml_text.hpp"

namespace circles::conform {
namespace {

using formats::counted;

std::string xml(const std::string& s) { return formats::xml_text(s); }

}  // namespace

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
    if (f.status == FamilyStatus::failed && c) {
      ++failures;
      const std::string body = f.has_counterexample ? text : counterexample_summary(*c);
      cases += "      <failure type=\"does not conform\" message=\"" + xml(difference_line(*c)) + "\">" + xml(body) + "</failure>\n";
    } else if (f.status == FamilyStatus::unexpected_pass) {
      ++failures;
      const std::string why = "unexpected pass: the expectation file lists " + family +
                              " as failing, and it passed; delete its line";
      cases += "      <failure type=\"unexpected pass\" message=\"" + xml(why) + "\">" + xml(why) + "</failure>\n";
    } else if (f.status == FamilyStatus::expected_failure) {
      ++skipped;
      cases += "      <skipped message=\"" + xml("expected failure" + (c ? ": " + difference_line(*c) : std::string())) + "\"/>\n";
    } else if (f.status == FamilyStatus::skipped) {
      ++skipped;
      cases += "      <skipped message=\"skipped: left out by --families or --skip-families\"/>\n";
    } else if ((v.outcome == Outcome::cannot_check && f.checked == 0) || v.outcome == Outcome::interrupted) {
      // A run that could not check: an error in each family it did not check. A run that a signal interrupted
      // checked no family to its share of the cases: an error in each that did not fail.
      ++errors;
      cases += "      <error type=\"" + std::string(name(v.outcome)) + "\" message=\"" + xml(v.error) + "\">" + xml(v.error) +
               "</error>\n";
    } else if (f.status == FamilyStatus::not_reached) {
      ++skipped;
      cases += "      <skipped message=\"not reached: the run stopped at its counterexample\"/>\n";
    }
    cases += "      <system-out>" + counted(f.checked, "case") + " checked</system-out>\n    </testcase>\n";
  }
  const Options& o = v.options;
  const std::string counts = "tests=\"" + std::to_string(v.families.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\" skipped=\"" + std::to_string(skipped) +
                             "\" time=\"" + elapsed_text(v) + "\"";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"circles conform\" " + counts + ">\n" +
         "  <testsuite name=\"" + xml("circles conform: " + v.candidate) + "\" " + counts + ">\n    <properties>\n" +
         "      <property name=\"verdict\" value=\"" + xml(name(v.outcome)) + "\"/>\n" +
         "      <property name=\"seed\" value=\"" + std::to_string(o.seed) + "\"/>\n" +
         "      <property name=\"shard\" value=\"" + shard_text(v) + "\"/>\n" +
         "      <property name=\"level\" value=\"" + xml(o.level.text()) + "\"/>\n" +
         "      <property name=\"profile\" value=\"" + properties::name(o.profile) + "\"/>\n" +
         "      <property name=\"cases\" value=\"" + std::to_string(v.cases) + "\"/>\n    </properties>\n" + cases +
         "  </testsuite>\n</testsuites>\n";
}

}  // namespace circles::conform
