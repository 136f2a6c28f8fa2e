// `circles conform` in process (cli/conform_command.hpp): options that cannot be used end with exit 2 and a
// message naming the option and the value, before any case runs and without writing anything; a run prints its
// verdict and writes its reports whole, or exits 2 and leaves no file behind.
#include "cli/conform_command.hpp"
#include "cli/conform_report.hpp"

#include "engines/registry.hpp"
#include "tests/temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace circles::cli {
namespace {

using circles::testing::TempDir;

// What the command printed, and its exit status.
struct Printed {
  int status = -1;
  std::string out, err;
};

Printed run(const ConformCommandOptions& options) {
  std::ostringstream out, err;
  Printed r;
  r.status = conform_command(options, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The command ends with exit 2, `message` on err and nothing on out.
void expect_exit_2(const ConformCommandOptions& options, const std::string& message) {
  SCOPED_TRACE(message);
  const Printed r = run(options);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, message);
  EXPECT_EQ(r.out, "");
}

// The double engine on 26 cases of seed 2: one round, a case of each of the 26 families of the resolved profile.
ConformCommandOptions double_engine() {
  ConformCommandOptions options;
  options.engine = "double";
  options.engine_given = true;
  options.threads = 1;
  options.cases = 26;
  options.cases_given = true;
  options.seed = 2;
  return options;
}

// A program that answers nothing: conform::check finds it broken at its first request.
ConformCommandOptions silent_program() {
  ConformCommandOptions options;
  options.exec = "true";
  options.cases = 26;
  options.cases_given = true;
  options.seed = 2;
  return options;
}

TEST(ConformCommand, an_engine_and_a_program_together_exit_2_before_any_case) {
  ConformCommandOptions options = silent_program();
  options.engine_given = true;
  expect_exit_2(options, "circles conform: --engine and --exec exclude each other: check one candidate at a time\n");
}

TEST(ConformCommand, threads_with_a_program_exit_2_as_the_program_runs_its_own) {
  ConformCommandOptions options = silent_program();
  options.threads = 2;
  options.threads_given = true;
  expect_exit_2(options,
                 "circles conform: --threads sets the threads of an --engine; a program given with --exec runs its "
                 "own\n");
}

TEST(ConformCommand, the_default_engine_not_given_does_not_exclude_a_program) {
  // engine holds its default "double", as the program's option does, but was not given: the program is checked,
  // and found broken at its first request (it exits without answering), which is a verdict that cannot check:
  // the message says the seed the run used, so that a run with a random one can be run again.
  expect_exit_2(silent_program(),
                 "circles conform: the program `true` exited with status 0 before answering request 1 (seed 2)\n");
}

TEST(ConformCommand, a_bad_level_profile_or_shard_names_the_option_and_the_value) {
  ConformCommandOptions options = double_engine();
  options.level = "ulps:x";
  expect_exit_2(options, "circles conform: --level: \"ulps:x\" is not exact, faithful or ulps:K (K an integer)\n");
  options = double_engine();
  options.profile = "loose";
  expect_exit_2(options, "circles conform: --profile: \"loose\" is not resolved or literal\n");
  options = double_engine();
  options.shard = "2/2";
  expect_exit_2(options, "circles conform: --shard: \"2/2\" is not i/n with 0 <= i < n\n");
}

TEST(ConformCommand, an_unknown_family_names_the_option_the_name_and_the_families) {
  const std::string families =
      "lattice, random-doubles, tangency, ulp-nudge, tie-px, tie-p, tie-p-vx, tie-p-v, duplicates, incomparable, "
      "mutual-contacts, tangent-after-step, square-overflow, subnormals, cancellation, signed-zeros, zero-radius, "
      "wire, sizes, crowds, cell-crowds, radius-spread, long-rows, index-bits, order-borders, big-chains\n";
  ConformCommandOptions options = double_engine();
  options.families = "lattice,sideways";
  options.families_given = true;
  expect_exit_2(options, "circles conform: --families: unknown family \"sideways\"; the families of the resolved "
                          "profile are " + families);
  // --skip-families given empty is a list naming no family; not given, its empty string is no list at all.
  options = double_engine();
  options.skip_families_given = true;
  expect_exit_2(options,
                 "circles conform: --skip-families: unknown family \"\"; the families of the resolved profile are " +
                     families);
  options.skip_families_given = false;
  EXPECT_EQ(run(options).status, 0);
}

TEST(ConformCommand, families_check_only_those_and_skip_the_others) {
  ConformCommandOptions options = double_engine();
  options.families = "lattice";
  options.families_given = true;
  options.keep_going = true;
  const Printed r = run(options);
  EXPECT_EQ(r.status, 0) << r.err;
  // Lattice's one case of the 26, its family's only case in one round.
  EXPECT_EQ(first_line(r.out),
            "circles conform: the double engine conforms: 1 case, 1 step each, level exact, seed 2, resolved profile");
  EXPECT_NE(r.out.find("\n  lattice             1       passed\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n  random-doubles      0       skipped\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n  families: 1 passed, 25 skipped\n"), std::string::npos) << r.out;
}

TEST(ConformCommand, an_unknown_engine_exits_2_listing_the_engines) {
  ConformCommandOptions options = double_engine();
  options.engine = "quadruple";
  expect_exit_2(options,
                "circles conform: unknown engine \"quadruple\" (the engines are: " + engines::engine_names() + ")\n");
}

TEST(ConformCommand, an_svg_file_in_a_missing_directory_exits_2_and_writes_nothing) {
  const TempDir dir;
  ConformCommandOptions options = double_engine();
  options.svg = (dir.path / "no" / "such" / "picture.svg").string();
  options.reports["--report"] = (dir.path / "r.json").string();
  expect_exit_2(options, "circles conform: --svg: cannot write " + options.svg + ": the directory " +
                             (dir.path / "no" / "such").string() + " does not exist\n");
  EXPECT_TRUE(dir.files().empty());  // not even the report: no case ran
}

TEST(ConformCommand, an_expectation_file_that_does_not_parse_exits_2_naming_its_line) {
  const TempDir dir;
  ConformCommandOptions options = double_engine();
  options.expect = dir.write("bad.expect", "# known failures\n\nfail rounding\n");
  expect_exit_2(options,
                "circles conform: --expect: " + options.expect +
                    ":3: the entry names no family: expected FAMILY fail REASON\n");
}

TEST(ConformCommand, a_missing_expectation_file_exits_2_naming_it_and_the_systems_reason) {
  const TempDir dir;
  ConformCommandOptions options = double_engine();
  options.expect = (dir.path / "missing.expect").string();
  expect_exit_2(options, "circles conform: --expect: " + options.expect + ": cannot open the file: No such file or directory\n");
  options.expect = "/nonexistent";
  expect_exit_2(options, "circles conform: --expect: /nonexistent: cannot open the file: No such file or directory\n");
}

TEST(ConformCommand, a_conforming_engine_exits_0_with_the_verdict_on_the_first_line) {
  const Printed r = run(double_engine());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(first_line(r.out),
            "circles conform: the double engine conforms: 26 cases, 1 step each (2 for tangent-after-step, whose "
            "boundary comes only at step 2; 10 for big-chains, so that what a program keeps between requests is used), "
            "level exact, seed 2, resolved profile");
}

TEST(ConformCommand, one_case_is_counted_in_the_singular) {
  ConformCommandOptions options = double_engine();
  options.only_case = 0;  // case 0: family lattice, decided in one step
  options.case_given = true;
  Printed r = run(options);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(first_line(r.out),
            "circles conform: the double engine conforms: 1 case, 1 step each, level exact, seed 2, resolved profile");
  // The same in the table of --keep-going.
  options.keep_going = true;
  r = run(options);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(first_line(r.out),
            "circles conform: the double engine conforms: 1 case, 1 step each, level exact, seed 2, resolved profile");
}

TEST(ConformCommand, one_case_skipped_and_one_chain_cut_short_are_counted_in_the_singular) {
  conform::Verdict v;
  v.candidate = "the double engine";
  v.cases = 17;
  v.options.cases = 17;
  v.options.seed = 2;
  std::ostringstream out, err;
  const auto printed = [&](std::uint64_t n) {
    v.skipped = v.cut_short = n;
    out.str("");
    EXPECT_EQ(print_verdict(v, "", out, err), 0);
    return out.str();
  };
  EXPECT_EQ(printed(1),
            "circles conform: the double engine conforms: 17 cases (1 skipped: its next world leaves the double "
            "range), 1 step each, level exact, seed 2, resolved profile\n"
            "  cases checked per family:\n"
            "  1 chain ended early: its next world leaves the double range\n");
  EXPECT_EQ(printed(2),
            "circles conform: the double engine conforms: 17 cases (2 skipped: their next world leaves the double "
            "range), 1 step each, level exact, seed 2, resolved profile\n"
            "  cases checked per family:\n"
            "  2 chains ended early: their next world leaves the double range\n");
  EXPECT_EQ(err.str(), "");
  // --keep-going's table opens with the same line: the skipped cases and the steps are there too.
  v.options.keep_going = true;
  EXPECT_EQ(first_line(printed(2)),
            "circles conform: the double engine conforms: 17 cases (2 skipped: their next world leaves the double "
            "range), 1 step each, level exact, seed 2, resolved profile");
}

TEST(ConformCommand, a_family_listed_as_failing_that_passes_fails_the_run_with_its_line) {
  const TempDir dir;
  ConformCommandOptions options = double_engine();
  options.expect = dir.write("double.expect", "lattice fail it does not\n");
  const Printed r = run(options);
  EXPECT_EQ(r.status, 1) << r.err;
  // --expect implies --keep-going: the table, then the unexpected pass after it.
  EXPECT_EQ(first_line(r.out),
            "circles conform: the double engine does not conform: 26 cases, 1 step each (2 for tangent-after-step, whose "
            "boundary comes only at step 2; 10 for big-chains, so that what a program keeps between requests is used), "
            "level exact, seed 2, resolved profile");
  EXPECT_NE(r.out.find("\nlattice: unexpected pass (1 case checked): delete its line, " + options.expect + ":1\n"),
            std::string::npos)
      << r.out;
}

TEST(ConformCommand, a_report_is_written_whole_with_the_verdict) {
  const TempDir dir;
  ConformCommandOptions options = double_engine();
  options.reports["--report"] = (dir.path / "r.json").string();
  options.reports["--junit"] = (dir.path / "r.xml").string();
  const Printed r = run(options);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"r.json", "r.xml"}));  // no temporary file left beside them
  const nlohmann::json report = nlohmann::json::parse(read(options.reports["--report"]));
  EXPECT_EQ(report["verdict"], "conforms");
  EXPECT_EQ(report["candidate"], "the double engine");
  EXPECT_EQ(report["seed"], 2);
  EXPECT_EQ(report["cases"], 26);
  EXPECT_NE(read(options.reports["--junit"]).find("<testsuite"), std::string::npos);
}

TEST(ConformCommand, a_verdict_that_cannot_check_is_reported_too) {
  const TempDir dir;
  ConformCommandOptions options = silent_program();
  options.reports["--report"] = (dir.path / "r.json").string();
  const Printed r = run(options);
  EXPECT_EQ(r.status, 2);
  const nlohmann::json report = nlohmann::json::parse(read(options.reports["--report"]));
  EXPECT_EQ(report["verdict"], "cannot check");
  EXPECT_EQ(report["error"], "the program `true` exited with status 0 before answering request 1");
}

TEST(ConformCommand, a_report_into_a_missing_directory_exits_2_and_leaves_no_file) {
  const TempDir dir;
  ConformCommandOptions options = double_engine();
  options.reports["--report"] = (dir.path / "no" / "such" / "r.json").string();
  const Printed r = run(options);
  EXPECT_EQ(r.status, 2);
  // The verdict was printed; the report could not be written.
  EXPECT_EQ(first_line(r.out).rfind("circles conform: the double engine conforms: 26 cases", 0), 0u) << r.out;
  EXPECT_EQ(r.err.rfind("circles conform: --report " + options.reports["--report"] + ": cannot create ", 0), 0u) << r.err;
  EXPECT_TRUE(dir.files().empty());
}

TEST(ConformCommand, an_expectation_file_is_written_and_named_or_exits_2_leaving_none) {
  const TempDir dir;
  ConformCommandOptions options = double_engine();
  options.write_expect = (dir.path / "double.expect").string();
  Printed r = run(options);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nexpectations: " + options.write_expect + "\n"), std::string::npos) << r.out;
  EXPECT_EQ(dir.files(), std::vector<std::string>{"double.expect"});
  options.write_expect = (dir.path / "missing" / "double.expect").string();
  r = run(options);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out.find("expectations: " + options.write_expect), std::string::npos) << r.out;
  EXPECT_EQ(r.err.rfind("circles conform: --write-expect " + options.write_expect + ": cannot create ", 0), 0u)
      << r.err;
  EXPECT_EQ(dir.files(), std::vector<std::string>{"double.expect"});
}

}  // namespace
}  // namespace circles::cli
