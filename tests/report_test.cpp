// The reports of `circles conform` for CI (conform/report_formats.hpp, conform/merge.hpp): the verdict as JSON,
// read back by nlohmann; as JUnit XML, read back by pugixml as CI servers read it (one <testcase> per family, a
// <failure> with the counterexample); and the reports of shards merged into one, by `circles report merge` in
// every format.
#include "cli/conform_report.hpp"
#include "cli/merge_command.hpp"
#include "conform/junit.hpp"
#include "conform/merge.hpp"
#include "conform/report.hpp"
#include "conform/verdict_text.hpp"

#include "conform/candidate.hpp"
#include "engines/registry.hpp"
#include "conform/expect.hpp"
#include "conform/interrupt.hpp"
#include "spec/oracle.hpp"
#include "tests/function_candidate.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <cmath>
#include <fstream>
#include <csignal>
#include <sstream>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace circles::cli {
namespace {

using circles::testing::thrown;
using conform::counterexample_text;
using conform::json_report;
using conform::junit_report;
using conform::Options;
using conform::Outcome;
using conform::Verdict;
using spec::Circles;

using circles::testing::FunctionCandidate;

// The correct step, except that circle 0's px is infinite whenever a world has two circles or more.
Circles infinite_px(const Circles& w) {
  Circles out = testing::right_step(w);
  if (out.size() >= 2) out[0][0] = INFINITY;
  return out;
}

// The families of the resolved profile, and the cases of 14 rounds of them, which verdict_of checks.
const std::uint64_t kFamilies = properties::families(properties::Profile::resolved).size();
const std::uint64_t kCases = 14 * kFamilies;

Verdict verdict_of(const std::function<Circles(const Circles&)>& step, std::uint64_t shard = 0, std::uint64_t shards = 1) {
  FunctionCandidate candidate(step, "the function <&\"'>");  // a name to escape in XML
  Options options{{0}, kCases, 9, 1, shard, shards, {}};
  return conform::check(candidate, options);
}

nlohmann::json json_of(const Verdict& v) { return nlohmann::json::parse(json_report(v, counterexample_text(v))); }

// The reports `texts` merged, as the JSON report writes the merged verdict.
std::string merge_reports(const std::vector<std::string>& texts, const std::vector<std::string>& names) {
  const conform::Report merged = conform::merged_report(texts, names);
  return json_report(merged.verdict, merged.text);
}

TEST(report, writes_a_conforming_verdict_as_json_with_the_cases_of_each_family) {
  const Verdict v = verdict_of(testing::right_step);
  ASSERT_EQ(v.outcome, Outcome::conforms) << v.error;
  const nlohmann::json r = json_of(v);
  EXPECT_EQ(r["format"], "circles-conform-report/1");
  EXPECT_EQ(r["verdict"], "conforms");
  EXPECT_TRUE(r["error"].is_null());
  EXPECT_EQ(r["cases"], kCases);
  EXPECT_EQ(r["seed"], 9);
  EXPECT_EQ(r["shard"], "0/1");
  EXPECT_TRUE(r["counterexample"].is_null());
  ASSERT_EQ(r["families"].size(), kFamilies);
  for (const auto& [family, count] : r["families"].items()) {
    EXPECT_EQ(count, 14) << family;  // 14 rounds of the families
    EXPECT_EQ(r["family_status"][family], "passed") << family;
  }
}

// A check that a signal interrupts (conform/interrupt.hpp; here the candidate's 100th answer calls interrupt(),
// as the handler does) stops there: its cases are those checked, every family that did not fail is an error in
// JUnit, the JSON report says "interrupted", the text says how to check the same cases again, and the exit status
// is 128 + the signal. Merged, an interrupted shard makes the run interrupted, unless one could not check.
TEST(report, marks_an_interrupted_check_in_json_junit_and_the_merge_and_exits_128_plus_the_signal) {
  int answers = 0;
  const Verdict v = verdict_of([&](const Circles& w) {
    if (++answers == 100) conform::interrupt(SIGINT);
    return testing::right_step(w);
  });
  conform::clear_interruption();
  ASSERT_EQ(v.outcome, Outcome::interrupted) << v.error;
  EXPECT_EQ(v.signal, SIGINT);
  EXPECT_GT(v.cases, 0u);
  EXPECT_LT(v.cases, kCases);
  EXPECT_EQ(v.rerun, "circles conform --seed 9 --cases " + std::to_string(kCases) + " --level exact");
  const nlohmann::json r = json_of(v);
  EXPECT_EQ(r["verdict"], "interrupted");
  EXPECT_EQ(r["error"], "interrupted by SIGINT");
  EXPECT_EQ(r["cases"], v.cases);
  EXPECT_EQ(r["family_status"].size(), kFamilies);

  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(junit_report(v, "").c_str()));
  const pugi::xml_node suite = doc.child("testsuites").child("testsuite");
  std::size_t errors = 0;
  for (const pugi::xml_node testcase : suite.children("testcase"))
    if (const pugi::xml_node error = testcase.child("error")) {
      ++errors;
      EXPECT_EQ(std::string(error.attribute("type").value()), "interrupted");
      EXPECT_EQ(std::string(error.attribute("message").value()), "interrupted by SIGINT");
    }
  EXPECT_EQ(errors, kFamilies);  // none of the families was checked to its share of the cases
  EXPECT_EQ(suite.attribute("errors").as_uint(), kFamilies);

  std::ostringstream out, err;
  EXPECT_EQ(print_verdict(v, "", out, err), 128 + SIGINT);
  EXPECT_EQ(out.str(), "");
  EXPECT_EQ(err.str(), "circles conform: interrupted by SIGINT after " + std::to_string(v.checked()) +
                           " cases (seed 9)\nto check the same cases again: " + v.rerun + "\n");

  // Shards: one interrupted, one conforming, one that could not check.
  nlohmann::json interrupted = r, conforming = r, broken = r;
  interrupted["shard"] = "0/3";
  conforming["shard"] = "1/3";
  broken["shard"] = "2/3";
  conforming["verdict"] = "conforms";
  conforming["error"] = nullptr;
  broken["verdict"] = "cannot check";
  broken["error"] = "the program crashed";
  const auto merged = [](const std::vector<nlohmann::json>& reports) {
    std::vector<std::string> texts, names;
    for (const nlohmann::json& report : reports) {
      texts.push_back(report.dump());
      names.push_back(report["shard"]);
    }
    return nlohmann::json::parse(merge_reports(texts, names));
  };
  EXPECT_EQ(merged({conforming, interrupted})["verdict"], "interrupted");
  EXPECT_EQ(merged({conforming, interrupted})["error"], "interrupted by SIGINT");
  EXPECT_EQ(merged({interrupted, broken, conforming})["verdict"], "cannot check");
  EXPECT_EQ(merged({broken, interrupted})["error"], "the program crashed");
}

TEST(report, writes_a_counterexample_with_its_world_answers_and_replay_line_and_infinity_as_a_string) {
  const Verdict v = verdict_of(infinite_px);
  ASSERT_EQ(v.outcome, Outcome::does_not_conform) << v.error;
  const nlohmann::json r = json_of(v);
  EXPECT_EQ(r["verdict"], "does not conform");
  const nlohmann::json& c = r["counterexample"];
  ASSERT_TRUE(c.is_object());
  EXPECT_EQ(c["world"].size(), 2u);
  EXPECT_EQ(c["received"][0][0], "Infinity");
  EXPECT_EQ(c["expected"][0][0].get<double>(), v.counterexample->expected[0][0]);
  EXPECT_EQ(c["difference"]["field"], "px");
  EXPECT_EQ(c["difference"]["received"], "Infinity");
  EXPECT_EQ(c["replay"], v.counterexample->replay);
  EXPECT_EQ(c["family"], v.counterexample->family);
  EXPECT_EQ(c["case"], *v.counterexample->case_index);
  EXPECT_EQ(r["family_status"][v.counterexample->family.c_str()], "failed");
  EXPECT_NE(c["text"].get<std::string>().find("got Infinity"), std::string::npos);
}

// JUnit as GitHub Actions, GitLab and Jenkins read it: <testsuites>, one <testsuite>, one <testcase> per family
// with its name, a <failure message=...> in the counterexample's family, <skipped/> in those not reached, and
// counts on the suite that agree with its children.
TEST(report, writes_junit_xml_with_one_testcase_per_family_and_the_failure_in_its_family) {
  const Verdict v = verdict_of(infinite_px);
  ASSERT_EQ(v.outcome, Outcome::does_not_conform);
  const std::string text = junit_report(v, counterexample_text(v));
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_string(text.c_str());
  ASSERT_TRUE(parsed) << parsed.description() << "\n" << text;
  const pugi::xml_node suite = doc.child("testsuites").child("testsuite");
  ASSERT_TRUE(suite);
  EXPECT_EQ(std::string(suite.attribute("name").value()), "circles conform: the function <&\"'>");
  std::set<std::string> names;
  int failures = 0, skipped = 0, cases = 0;
  for (const pugi::xml_node testcase : suite.children("testcase")) {
    ++cases;
    names.insert(testcase.attribute("name").value());
    if (const pugi::xml_node failure = testcase.child("failure")) {
      ++failures;
      EXPECT_EQ(std::string(testcase.attribute("name").value()), v.counterexample->family);
      EXPECT_NE(std::string(failure.attribute("message").value()).find("circle 0, field px: expected "), std::string::npos);
      EXPECT_NE(std::string(failure.child_value()).find("got Infinity"), std::string::npos);
    }
    skipped += static_cast<bool>(testcase.child("skipped"));
  }
  EXPECT_EQ(cases, static_cast<int>(kFamilies));
  EXPECT_EQ(names.size(), kFamilies);
  EXPECT_EQ(failures, 1);
  EXPECT_EQ(suite.attribute("tests").as_int(), cases);
  EXPECT_EQ(suite.attribute("failures").as_int(), failures);
  EXPECT_EQ(suite.attribute("skipped").as_int(), skipped);
  EXPECT_EQ(doc.child("testsuites").attribute("failures").as_int(), failures);
}

// The shards of a run merged: the cases add up to the unsharded run's, each family's too, and of two
// counterexamples the one of the lower case index wins.
TEST(report, merges_the_reports_of_shards_into_the_unsharded_runs_cases_and_verdict) {
  const Verdict whole = verdict_of(testing::right_step);
  std::vector<std::string> shards, names;
  for (std::uint64_t i = 0; i < 4; ++i) {
    const Verdict v = verdict_of(testing::right_step, 3 - i, 4);  // in any order
    shards.push_back(json_report(v, ""));
    names.push_back("shard " + std::to_string(3 - i));
  }
  const nlohmann::json merged = nlohmann::json::parse(merge_reports(shards, names));
  const nlohmann::json unsharded = json_of(whole);
  EXPECT_EQ(merged["verdict"], unsharded["verdict"]);
  EXPECT_EQ(merged["cases"], unsharded["cases"]);
  EXPECT_EQ(merged["families"], unsharded["families"]);
  EXPECT_EQ(merged["shard"], "0,1,2,3/4");

  nlohmann::json early = unsharded, late = unsharded;
  early["shard"] = "0/2";
  late["shard"] = "1/2";
  early["verdict"] = late["verdict"] = "does not conform";
  early["counterexample"] = {{"case", 3}, {"family", "early"}};
  late["counterexample"] = {{"case", 40}, {"family", "late"}};
  const nlohmann::json both = nlohmann::json::parse(merge_reports({late.dump(), early.dump()}, {"late", "early"}));
  EXPECT_EQ(both["verdict"], "does not conform");
  EXPECT_EQ(both["counterexample"]["family"], "early");
  EXPECT_EQ(both["cases"], 2 * unsharded["cases"].get<int>());
  // Every family's counterexample, the one of its lowest case over the shards, in the families' order.
  early["counterexamples"] = {{{"case", 3}, {"family", "tangency"}}, {{"case", 40}, {"family", "lattice"}}};
  late["counterexamples"] = {{{"case", 20}, {"family", "lattice"}}, {{"case", 36}, {"family", "zero-radius"}}};
  const nlohmann::json all = nlohmann::json::parse(merge_reports({late.dump(), early.dump()}, {"late", "early"}));
  std::vector<std::pair<std::string, int>> merged_counterexamples;
  for (const nlohmann::json& c : all["counterexamples"]) merged_counterexamples.emplace_back(c["family"], c["case"]);
  EXPECT_EQ(merged_counterexamples,
            (std::vector<std::pair<std::string, int>>{{"lattice", 20}, {"tangency", 3}, {"zero-radius", 36}}));
}

// A report read back is the verdict it was written from: written again, the same text, the counterexample's
// infinite answer and its printed text included.
TEST(report, reads_a_report_back_into_the_verdict_it_was_written_from) {
  const Verdict v = verdict_of(infinite_px);
  ASSERT_EQ(v.outcome, Outcome::does_not_conform) << v.error;
  const std::string written = json_report(v, counterexample_text(v));
  const conform::Report read = conform::read_report(written, "r.json");
  EXPECT_EQ(read.verdict.outcome, Outcome::does_not_conform);
  ASSERT_TRUE(read.verdict.counterexample);
  EXPECT_EQ(read.verdict.counterexample->actual[0][0], INFINITY);
  EXPECT_EQ(read.text, counterexample_text(v));
  EXPECT_EQ(json_report(read.verdict, read.text), written);
  // Merged alone, a report keeps its verdict; a family the profile does not have is refused.
  EXPECT_EQ(merge_reports({written}, {"r.json"}), written);
  nlohmann::json other = nlohmann::json::parse(written);
  other["families"]["no-such-family"] = 1;
  const auto e = thrown<conform::ReportError>([&] { conform::read_report(other.dump(), "r.json"); });
  EXPECT_EQ(e ? std::string(e->what()) : "nothing thrown",
            "r.json: \"families\": no-such-family is not a family of the resolved profile");
}

TEST(report, refuses_to_merge_reports_of_different_runs_or_a_shard_twice) {
  const nlohmann::json one = json_of(verdict_of(testing::right_step, 0, 2));
  nlohmann::json other_seed = one;
  other_seed["seed"] = 10;
  other_seed["shard"] = "1/2";
  const auto refusal = [](const std::vector<std::string>& texts) {
    const auto e = thrown<conform::ReportError>([&] { merge_reports(texts, {"a.json", "b.json"}); });
    return e ? std::string(e->what()) : std::string("nothing thrown");
  };
  EXPECT_EQ(refusal({one.dump(), other_seed.dump()}),
            "b.json: \"seed\" is 10, but a.json's is 9: only the shards of one run merge");
  EXPECT_EQ(refusal({one.dump(), one.dump()}), "b.json: shard 0/2 twice");
  EXPECT_EQ(refusal({one.dump(), "{"}).substr(0, 25), "b.json: malformed JSON: [");
  EXPECT_EQ(refusal({one.dump(), "{}"}), "b.json: not a report of circles conform (\"format\": \"circles-conform-report/1\")");
  EXPECT_EQ(refusal({one.dump(), R"({"format": 1})"}),
            "b.json: not a report of circles conform (\"format\": \"circles-conform-report/1\")");
}

// A report cut short or edited by hand is refused naming its file and key, exit 2, never a crash: each key merge
// reads, of the wrong type or missing.
TEST(report, refuses_to_merge_a_report_whose_keys_have_the_wrong_type_naming_the_file_and_key) {
  const nlohmann::json one = json_of(verdict_of(testing::right_step, 0, 2));
  const auto refusal = [&](const char* key, const nlohmann::json& value) {
    nlohmann::json other = json_of(verdict_of(testing::right_step, 1, 2));
    if (value.is_discarded()) other.erase(key);
    else other[key] = value;
    const auto e = thrown<conform::ReportError>([&] { merge_reports({one.dump(), other.dump()}, {"a.json", "b.json"}); });
    return e ? std::string(e->what()) : std::string("nothing thrown");
  };
  const nlohmann::json missing = nlohmann::json::value_t::discarded;
  EXPECT_EQ(refusal("cases", "12"), "b.json: \"cases\": expected an integer >= 0, found \"12\"");
  EXPECT_EQ(refusal("verdict", missing), "b.json: \"verdict\": expected a string, found nothing");
  EXPECT_EQ(refusal("verdict", "passed"),
            "b.json: \"verdict\": expected \"conforms\", \"does not conform\", \"cannot check\" or \"interrupted\", found \"passed\"");
  EXPECT_EQ(refusal("families", {{"lattice", "x"}}),
            "b.json: \"families\": expected an object of case counts, integers >= 0, found {\"lattice\":\"x\"}");
  EXPECT_EQ(refusal("counterexample", {{"case", "zero"}}),
            "b.json: \"counterexample\": expected null or an object whose \"case\" is null or an integer >= 0, found "
            "{\"case\":\"zero\"}");
  EXPECT_EQ(refusal("elapsed_seconds", nullptr), "b.json: \"elapsed_seconds\": expected a number, found null");
}

}  // namespace
}  // namespace circles::cli

namespace circles::cli {
namespace {

// With --keep-going, --skip-families and an expectation file: each family's status in both reports, JUnit's
// <skipped> for expected failures and skipped families, a <failure> for a failure and an unexpected pass.
TEST(report, carries_each_familys_status_and_junit_skips_expected_failures_and_skipped_families) {
  // Wrong only on worlds of 3 circles or more, which some families never draw.
  FunctionCandidate candidate([](const Circles& w) { return w.size() >= 3 ? infinite_px(w) : testing::right_step(w); },
                              "the function");
  Options options{{0}, 340, 9, 1, 0, 1, {}};
  options.keep_going = true;
  options.skip = {properties::Family::zero_radius};
  Verdict v = conform::check(candidate, options);
  std::vector<std::string> failed, passed;
  for (const conform::FamilyResult& f : v.families)
    (f.status == conform::FamilyStatus::failed ? failed : passed).push_back(properties::name(f.family));
  ASSERT_GE(failed.size(), 2u);
  ASSERT_GE(passed.size(), 2u);  // zero-radius, skipped, and at least one that passed
  const std::string passing = passed.front() == "zero-radius" ? passed[1] : passed.front();
  // The file lists every failure but the first, and a family that passes.
  std::string file;
  for (std::size_t k = 1; k < failed.size(); ++k) file += failed[k] + " fail known\n";
  file += passing + " fail not any more\n";
  conform::apply(v, conform::parse_expectations(file, "f.expect", conform::Profile::resolved));
  const nlohmann::json r = json_of(v);
  EXPECT_EQ(r["verdict"], "does not conform");
  EXPECT_EQ(r["family_status"][failed.front()], "failed");
  EXPECT_EQ(r["family_status"][failed.back()], "expected failure");
  EXPECT_EQ(r["family_status"][passing], "unexpected pass");
  EXPECT_EQ(r["family_status"]["zero-radius"], "skipped");
  EXPECT_EQ(r["counterexample"]["family"], failed.front());

  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(junit_report(v, counterexample_text(v)).c_str()));
  const auto testcase = [&](const std::string& family) {
    return doc.select_node(("//testcase[@name='" + family + "']").c_str()).node();
  };
  EXPECT_EQ(std::string(testcase(failed.front()).child("failure").attribute("type").value()), "does not conform");
  EXPECT_TRUE(std::string(testcase(failed.back()).child("skipped").attribute("message").value()).starts_with("expected failure: step 1"));
  EXPECT_EQ(std::string(testcase(passing).child("failure").attribute("type").value()), "unexpected pass");
  EXPECT_EQ(std::string(testcase("zero-radius").child("skipped").attribute("message").value()),
            "skipped: left out by --families or --skip-families");
  const pugi::xml_node suite = doc.child("testsuites").child("testsuite");
  EXPECT_EQ(suite.attribute("failures").as_uint(), 2u);
  EXPECT_EQ(suite.attribute("skipped").as_uint(), failed.size());  // the expected failures and zero-radius
}

TEST(report, merges_each_familys_status_across_shards_the_failure_first) {
  nlohmann::json a = json_of(verdict_of(testing::right_step, 0, 2));
  nlohmann::json b = json_of(verdict_of(testing::right_step, 1, 2));
  a["family_status"]["lattice"] = "expected failure";  // failed in one shard as the file says, passed in the other
  b["family_status"]["tangency"] = "skipped";
  const nlohmann::json conforming = nlohmann::json::parse(merge_reports({a.dump(), b.dump()}, {"a", "b"}));
  EXPECT_EQ(conforming["verdict"], "conforms");
  EXPECT_EQ(conforming["family_status"]["lattice"], "expected failure");
  EXPECT_EQ(conforming["family_status"]["tangency"], "passed");
  b["family_status"]["tangency"] = "unexpected pass";
  a["family_status"]["ulp-nudge"] = "failed";
  b["family_status"]["ulp-nudge"] = "expected failure";
  const nlohmann::json failing = nlohmann::json::parse(merge_reports({a.dump(), b.dump()}, {"a", "b"}));
  EXPECT_EQ(failing["verdict"], "does not conform");
  EXPECT_EQ(failing["family_status"]["tangency"], "unexpected pass");
  EXPECT_EQ(failing["family_status"]["ulp-nudge"], "failed");
  b["family_status"]["lattice"] = "sideways";
  EXPECT_EQ(std::string(thrown<conform::ReportError>([&] { merge_reports({a.dump(), b.dump()}, {"a", "b"}); })->what()),
            "b: \"family_status\": lattice is \"sideways\", not a status of a family");
}


// `circles report merge --junit`: the merged verdict as JUnit XML beside the merged JSON, read back as CI servers
// read it: the counterexample's failure in its family alone; every family an error when a shard was interrupted,
// or when no shard could check; the exit status the merged verdict's.
TEST(report, merge_writes_the_merged_verdict_as_junit_with_its_failures_and_its_errors) {
  const testing::TempDir dir;
  const auto merge = [&](const std::vector<nlohmann::json>& shards, int status) {
    MergeCommandOptions options;
    for (const nlohmann::json& shard : shards)
      options.reports.push_back(dir.write("shard-" + std::to_string(options.reports.size()) + ".json", shard.dump()));
    options.out = (dir.path / "merged.json").string();
    options.formats["--junit"] = (dir.path / "merged.xml").string();
    std::ostringstream said, err;
    EXPECT_EQ(merge_command(options, said, err), status) << err.str();
    std::ifstream in(options.formats["--junit"]);
    const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto doc = std::make_unique<pugi::xml_document>();
    EXPECT_TRUE(doc->load_string(xml.c_str())) << xml;
    return doc;
  };
  const auto property = [](const pugi::xml_node suite, const char* name) {
    return std::string(suite.child("properties").find_child_by_attribute("property", "name", name).attribute("value").value());
  };

  const Verdict failing = verdict_of(infinite_px, 1, 2);
  ASSERT_EQ(failing.outcome, Outcome::does_not_conform) << failing.error;
  const nlohmann::json passing = json_of(verdict_of(testing::right_step, 0, 2));
  const auto failed = merge({passing, json_of(failing)}, 1);
  const pugi::xml_node suite = failed->child("testsuites").child("testsuite");
  EXPECT_EQ(property(suite, "verdict"), "does not conform");
  EXPECT_EQ(property(suite, "shard"), "0,1/2");
  EXPECT_EQ(property(suite, "cases"), std::to_string(passing["cases"].get<int>() + static_cast<int>(failing.cases)));
  EXPECT_EQ(suite.attribute("tests").as_uint(), kFamilies);
  EXPECT_EQ(suite.attribute("failures").as_int(), 1);
  EXPECT_EQ(suite.attribute("errors").as_int(), 0);
  const pugi::xml_node failure = suite.select_node("testcase/failure").node();
  EXPECT_EQ(std::string(failure.parent().attribute("name").value()), failing.counterexample->family);
  EXPECT_EQ(std::string(failure.child_value()), counterexample_text(failing));

  nlohmann::json interrupted = passing;
  interrupted["shard"] = "1/2";
  interrupted["verdict"] = "interrupted";
  interrupted["error"] = "interrupted by SIGTERM";
  const auto cut = merge({passing, interrupted}, 2);
  const pugi::xml_node cut_suite = cut->child("testsuites").child("testsuite");
  EXPECT_EQ(property(cut_suite, "verdict"), "interrupted");
  EXPECT_EQ(cut_suite.attribute("errors").as_uint(), kFamilies);
  EXPECT_EQ(std::string(cut_suite.select_node("testcase/error").node().attribute("message").value()), "interrupted by SIGTERM");

  nlohmann::json broken = passing;
  broken["verdict"] = "cannot check";
  broken["error"] = "the program crashed";
  broken["cases"] = 0;
  for (auto& [family, count] : broken["families"].items()) count = 0;
  nlohmann::json other = broken;
  other["shard"] = "1/2";
  const auto unchecked = merge({broken, other}, 2);
  const pugi::xml_node unchecked_suite = unchecked->child("testsuites").child("testsuite");
  EXPECT_EQ(property(unchecked_suite, "verdict"), "cannot check");
  EXPECT_EQ(unchecked_suite.attribute("errors").as_uint(), kFamilies);
  EXPECT_EQ(std::string(unchecked_suite.select_node("testcase/error").node().attribute("type").value()), "cannot check");
}

}  // namespace
}  // namespace circles::cli
