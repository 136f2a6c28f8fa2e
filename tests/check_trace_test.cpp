// `circles check-trace` (conform/check_trace.hpp): traces written by `circles run` agree, a trace changed in one
// field by one ulp is caught at that step, circle and field, and every trace that is not one is refused with its
// file, line and reason (exit 2), never a crash (the reader's own messages are trace_reader_test.cpp's); and the
// main job's line of an engine stepped beside the oracle (conform::compare_with_oracle, cli::print_comparison).
#include "cli/check_trace_command.hpp"
#include "conform/check_trace.hpp"
#include "engines/registry.hpp"
#include "cli/run.hpp"
#include "formats/scene.hpp"
#include "formats/trace_reader.hpp"
#include "formats/random_scene.hpp"
#include "formats/state_hash.hpp"
#include "tests/step_worlds.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace circles::cli {
namespace {

using conform::compare_with_oracle;
using conform::Comparison;
using conform::trace_reference;
using engines::engine;
using engines::EngineEntry;
using engines::Stepper;
using formats::default_scene;
using formats::doubles_of;
using formats::format_line;
using formats::kStep;
using formats::Line;
using formats::parse_line;
using formats::TraceReader;
using formats::TraceReadError;
using spec::Circles;

namespace fs = std::filesystem;
using circles::testing::kOverflowsAtStep4;
using circles::testing::kTouching;
using circles::testing::thrown;

using circles::testing::TempDir;

std::vector<std::string> lines_of(const std::string& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  return text;
}

// A trace of `steps` steps of `world` with the named engine, as `circles run --trace` writes it.
std::string record(const TempDir& dir, const std::string& name, const Circles& world, std::uint64_t steps,
                   const char* engine_name = "double") {
  const std::string path = (dir.path / name).string();
  RunOptions options;
  options.steps = steps;
  options.engine = &engine(engine_name);
  options.threads = 1;
  options.trace = path;
  run(world, options);
  return path;
}

struct Outcome {
  int code;
  std::string out, err;
};
Outcome command(const std::string& path, TraceReference reference = TraceReference::rounded) {
  std::ostringstream out, err;
  const int code = check_trace_command(path, reference, out, err);
  return {code, out.str(), err.str()};
}

// "0.1 (0x1.999999999999ap-4)", written here with printf rather than by the code under test.
std::string shown(double x, const char* decimal) {
  char hex[40];
  std::snprintf(hex, sizeof hex, "%a", x);
  return std::string(decimal) + " (" + hex + ")";
}

// One circle at rest at the origin moving by 1 per second: stepped in doubles, p = RN(p + 1/60) each step; in
// the exact sequence p = t/60, rounded. They part at step 6: RN(RN(5/60) + 1/60) = 0.09999999999999999, one
// ulp below RN(6/60) = 0.1 (computed apart with Python's fractions).
const Circles kDrifter{{0, 0, 1, 0, 1}};

TEST(check_trace, a_trace_of_the_double_engine_agrees_with_the_correctly_rounded_step_at_each_step) {
  TempDir dir;
  const std::string path = record(dir, "t.jsonl", doubles_of(default_scene()), 200);
  TraceReader reader(path);
  const TraceCheck check = check_trace(reader, TraceReference::rounded);
  EXPECT_FALSE(check.divergence);
  EXPECT_EQ(check.first_step, 0u);
  EXPECT_EQ(check.last_step, 200u);
  EXPECT_EQ(check.circles, 10u);
  // The hashes are those of the worlds in the file, read apart from the checker.
  const std::vector<std::string> lines = lines_of(path);
  ASSERT_EQ(lines.size(), 201u);
  formats::StateHash trajectory;
  Circles last;
  for (std::size_t t = 0; t < lines.size(); ++t) {
    last = parse_line(lines[t], t + 1, kStep).circles;
    trajectory.add(last);
  }
  EXPECT_EQ(check.last_hash, formats::state_hash(last));
  EXPECT_EQ(check.trajectory_hash, trajectory.value());
  const Outcome o = command(path);
  EXPECT_EQ(o.code, 0);
  char hashes[80];
  std::snprintf(hashes, sizeof hashes, "state hash of step 200: %016llx, trajectory hash: %016llx",
                static_cast<unsigned long long>(formats::state_hash(last)),
                static_cast<unsigned long long>(trajectory.value()));
  EXPECT_EQ(o.out, "circles check-trace: " + path +
                       ": agrees with the correctly rounded step at each of its 200 steps (steps 0 to 200, 10 "
                       "circles); " + hashes + "\n");
  EXPECT_EQ(o.err, "");
}

TEST(check_trace, a_trace_of_the_exact_engine_agrees_with_the_exact_sequence) {
  TempDir dir;
  const std::string path = record(dir, "t.jsonl", doubles_of(default_scene()), 100, "exact");
  const Outcome o = command(path, TraceReference::exact);
  EXPECT_EQ(o.code, 0) << o.out << o.err;
  EXPECT_TRUE(o.out.starts_with("circles check-trace: " + path +
                                ": agrees with the oracle's exact sequence, rounded, at each of its 100 steps"))
      << o.out;
}

TEST(check_trace, the_exact_reference_on_its_grid_agrees_with_the_exact_engine_on_a_big_world_and_names_a_change) {
  // 2000 circles (the grid reference's cells prune most pairs) for 5 steps; then one position of step 3 moved
  // by one ulp, which must be named by its line, step, circle and field.
  TempDir dir;
  const Circles world = formats::random_scene(2000, 0.5, 3);
  std::vector<std::string> lines = lines_of(record(dir, "t.jsonl", world, 5, "exact"));
  ASSERT_EQ(lines.size(), 6u);
  const Outcome o = command((dir.path / "t.jsonl").string(), TraceReference::exact);
  EXPECT_EQ(o.code, 0) << o.out << o.err;
  Line w3 = parse_line(lines[3], 4, kStep);
  const double was = w3.circles[1234][1], up = std::nextafter(was, INFINITY);
  w3.circles[1234][1] = up;
  lines[3] = format_line(kStep, 3, w3.circles);
  const std::string path = dir.write("tampered.jsonl", joined(lines));
  const Outcome t = command(path, TraceReference::exact);
  EXPECT_EQ(t.code, 1);
  EXPECT_TRUE(t.out.starts_with("circles check-trace: " + path + ":4: step 3 differs from the oracle's exact "
                                "sequence from line 1, rounded: circle 1234, field py: expected "))
      << t.out;
  TraceReader reader(path);
  const TraceCheck check = check_trace(reader, TraceReference::exact);
  ASSERT_TRUE(check.divergence && check.divergence->difference);
  EXPECT_EQ(check.divergence->difference->circle, 1234u);
  EXPECT_EQ(check.divergence->difference->expected, was);
  EXPECT_EQ(check.divergence->difference->actual, up);
  EXPECT_EQ(check.last_step, 2u);
}

// "0123456789abcdef": a hash as the checker prints it, written here with printf.
std::string hex(std::uint64_t h) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

// The trajectory hash of the first `count` lines of a trace, read apart from the checker.
std::uint64_t trajectory_of(const std::vector<std::string>& lines, std::size_t count) {
  formats::StateHash h;
  for (std::size_t t = 0; t < count; ++t) h.add(parse_line(lines[t], t + 1, kStep).circles);
  return h.value();
}

TEST(check_trace, a_position_changed_by_one_ulp_is_named_by_its_step_circle_and_field) {
  TempDir dir;
  std::vector<std::string> lines = lines_of(record(dir, "t.jsonl", doubles_of(default_scene()), 50));
  // Circle 3 of the default scene rests at (280, 360) for the first steps; one ulp of 280 is 2^-44.
  Line w20 = parse_line(lines[20], 21, kStep);
  ASSERT_EQ(w20.circles[3][0], 280.0);
  const double up = std::nextafter(280.0, 1000.0);
  ASSERT_EQ(up - 280.0, std::ldexp(1.0, -44));
  w20.circles[3][0] = up;
  lines[20] = format_line(kStep, 20, w20.circles);
  const std::string path = dir.write("tampered.jsonl", joined(lines));
  const Outcome o = command(path);
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.out, "circles check-trace: " + path + ":21: step 20 differs from the correctly rounded step of line 20: "
                       "circle 3, field px: expected " + shown(280.0, "280.0") + ", actual " +
                       shown(up, "280.00000000000006") +
                       "\n  which decision: none: the velocity is right, the position is not the nearest double\n"
                       "  the worlds before it agree (steps 0 to 19, 10 circles; trajectory hash " +
                       hex(trajectory_of(lines, 20)) + ")\n");
  EXPECT_EQ(o.err, "");
  TraceReader reader(path);
  const TraceCheck check = check_trace(reader, TraceReference::rounded);
  ASSERT_TRUE(check.divergence);
  EXPECT_EQ(check.divergence->line, 21u);
  EXPECT_EQ(check.divergence->step, 20u);
  ASSERT_TRUE(check.divergence->difference);
  EXPECT_EQ(check.divergence->difference->circle, 3u);
  EXPECT_EQ(check.divergence->difference->field, spec::Field::px);
  EXPECT_EQ(check.last_step, 19u);
}

TEST(check_trace, a_velocity_kept_through_a_contact_is_named_as_the_decision_of_intersect) {
  // The two circles touch; in the second world circle 0 kept its own velocity instead of taking -60.
  TempDir dir;
  const std::string path = dir.write("t.jsonl",
                                     "{\"step\": 4, \"circles\": [[0, 0, 60, 0, 1], [2, 0, -60, 0, 1]]}\n"
                                     "{\"step\": 5, \"circles\": [[1, 0, 60, 0, 1], [3, 0, 60, 0, 1]]}\n");
  const Outcome o = command(path);
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.out, "circles check-trace: " + path + ":2: step 5 differs from the correctly rounded step of line 1: "
                       "circle 0, field px: expected " + shown(-1.0, "-1.0") + ", actual " + shown(1.0, "1.0") +
                       "\n  which decision: the intersect test (3) (docs/math.md#3-intersect--specintersect): circle 0 "
                       "touches circle 1 but kept its own velocity\n"
                       "  the worlds before it agree (steps 4 to 4, 2 circles; trajectory hash " +
                       hex(formats::state_hash(Circles{{0, 0, 60, 0, 1}, {2, 0, -60, 0, 1}})) + ")\n");
}

TEST(check_trace, the_double_and_the_exact_readings_part_where_rounding_each_step_drifts) {
  TempDir dir;
  const std::string doubles = record(dir, "double.jsonl", kDrifter, 10, "double");
  const std::string exact = record(dir, "exact.jsonl", kDrifter, 10, "exact");
  EXPECT_EQ(command(doubles, TraceReference::rounded).code, 0);
  EXPECT_EQ(command(exact, TraceReference::exact).code, 0);
  const Outcome d = command(doubles, TraceReference::exact);
  EXPECT_EQ(d.code, 1);
  EXPECT_TRUE(d.out.starts_with("circles check-trace: " + doubles +
                                ":7: step 6 differs from the oracle's exact sequence from line 1, rounded: circle 0, "
                                "field px: expected " + shown(0.1, "0.1") + ", actual " +
                                shown(0.09999999999999999, "0.09999999999999999") + "\n  the worlds before it"))
      << d.out;
  const Outcome e = command(exact, TraceReference::rounded);
  EXPECT_EQ(e.code, 1);
  EXPECT_TRUE(e.out.starts_with("circles check-trace: " + exact +
                                ":7: step 6 differs from the correctly rounded step of line 6: circle 0, field px: "
                                "expected " + shown(0.09999999999999999, "0.09999999999999999") + ", actual " +
                                shown(0.1, "0.1") + "\n  which decision: none"))
      << e.out;
}

TEST(check_trace, a_world_after_a_step_that_overflows_is_a_divergence) {
  // DBL_MAX + 1e308/60 rounds to infinity: no world can follow the first.
  TempDir dir;
  const std::string path = dir.write("t.jsonl",
                                     "{\"step\":0,\"circles\":[[1.7976931348623157e+308,0.0,1e+308,0.0,1.0]]}\n"
                                     "{\"step\":1,\"circles\":[[1.7976931348623157e+308,0.0,1e+308,0.0,1.0]]}\n");
  const Outcome o = command(path);
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.out.substr(0, o.out.find('\n')),
            "circles check-trace: " + path + ":2: step 1 differs from the correctly rounded step of line 1: the step "
            "overflows (circle 0, field px: the position p + v/60 overflows to infinity), so no world can follow, "
            "yet the trace holds one");
  EXPECT_EQ(command(path, TraceReference::exact).code, 1);
}

TEST(check_trace, a_trace_of_one_world_agrees_with_no_step_to_check) {
  TempDir dir;
  const std::string path = dir.write("t.jsonl", "{\"step\":7,\"circles\":[]}");  // no final newline
  const Outcome o = command(path);
  EXPECT_EQ(o.code, 0);
  EXPECT_EQ(o.out, "circles check-trace: " + path +
                       ": agrees with the correctly rounded step at each of its 0 steps (steps 7 to 7, 0 circles); "
                       "state hash of step 7: cbf29ce484222325, trajectory hash: cbf29ce484222325\n");
}

TEST(check_trace, reads_any_json_layout_and_crlf_line_ends) {
  TempDir dir;
  const std::string path = dir.write("t.jsonl",
                                     " { \"circles\" : [ [ 0 , 0 , 60 , 0 , 1 ] ] , \"step\" : 0 } \r\n"
                                     "{\"step\":1,\"circles\":[[1.0,0.0,60.0,0.0,1.0]]}\r\n");
  EXPECT_EQ(command(path).code, 0);
}

// ── Hostile traces: exit 2, naming the file, the line and the reason ──────────────────────────────────────

TEST(check_trace, a_missing_file_exits_2_naming_it) {
  TempDir dir;
  const std::string path = (dir.path / "none.jsonl").string();
  const Outcome o = command(path);
  EXPECT_EQ(o.code, 2);
  EXPECT_EQ(o.out, "");
  EXPECT_EQ(o.err, "circles check-trace: " + path + ": cannot open the file: No such file or directory\n");
}

TEST(check_trace, a_directory_exits_2_as_not_a_file) {
  TempDir dir;
  const Outcome o = command(dir.path.string());
  EXPECT_EQ(o.code, 2);
  EXPECT_EQ(o.err, "circles check-trace: " + dir.path.string() + ": cannot read the file: it is a directory\n");
}

TEST(check_trace, an_empty_or_blank_file_exits_2_as_empty) {
  TempDir dir;
  const std::string empty = "empty file, expected one world per line {\"step\": t, \"circles\": [[px, py, vx, vy, r], ...]}";
  for (const char* bytes : {"", "\n", " \t\r\n\n"}) {
    const std::string path = dir.write("t.jsonl", bytes);
    const Outcome o = command(path);
    EXPECT_EQ(o.code, 2);
    EXPECT_EQ(o.err, "circles check-trace: " + path + ": " + empty + "\n");
  }
}

// A trace is judged as conform judges an answer: -0 and +0 are one value, and a radius that changed is no
// decision, so the message does not blame a position that is right.
TEST(check_trace, reads_minus_0_as_plus_0_and_names_a_changed_radius_as_no_decision) {
  TempDir dir;
  const std::string w_0 = "{\"step\":0,\"circles\":[[0.0,0.0,60.0,0.0,1.0]]}\n";
  EXPECT_EQ(command(dir.write("z.jsonl", w_0 + "{\"step\":1,\"circles\":[[1.0,-0.0,60.0,-0.0,1.0]]}\n")).code, 0);
  const std::string path = dir.write("r.jsonl", w_0 + "{\"step\":1,\"circles\":[[1.0,0.0,60.0,0.0,2.0]]}\n");
  const Outcome o = command(path);
  EXPECT_EQ(o.code, 1);
  EXPECT_TRUE(o.out.starts_with("circles check-trace: " + path + ":2: step 1 differs from the correctly rounded step "
                                "of line 1: circle 0, field r: expected 1.0 (0x1p+0), actual 2.0 (0x1p+1)\n  which "
                                "decision: none: the position and velocity are right, but the radius changed, which "
                                "no step does\n"))
      << o.out;
}

TEST(check_trace, the_engine_names_are_double_and_exact) {
  EXPECT_EQ(trace_reference("double"), TraceReference::rounded);
  EXPECT_EQ(trace_reference("exact"), TraceReference::exact);
  const auto e = thrown<std::invalid_argument>([] { trace_reference("oracle"); });
  ASSERT_TRUE(e);
  EXPECT_STREQ(e->what(), "--engine: \"oracle\" is not double or exact");
}

TEST(compare_with_oracle, finds_the_double_engine_in_agreement_on_the_default_scene) {
  const Comparison c = compare_with_oracle(engine("double"), doubles_of(default_scene()), 100, 0);
  EXPECT_EQ(c.steps, 100u);
  EXPECT_FALSE(c.difference);
  std::ostringstream out;
  print_comparison(engine("double"), c, out);
  EXPECT_EQ(out.str(), "double engine: agrees with the correctly rounded oracle at each of the 100 steps\n");
}

// An engine that ignores contacts: each circle keeps its velocity. Wrong at the first step with a contact.
class NoContacts final : public Stepper {
 public:
  NoContacts(const Circles& w, unsigned) : w_(w) {}
  Circles circles() const override { return w_; }

 private:
  std::optional<Overflow> advance() override {
    for (auto& c : w_) c = {c[0] + c[2] / 60, c[1] + c[3] / 60, c[2], c[3], c[4]};
    return std::nullopt;
  }
  Circles w_;
};

std::unique_ptr<Stepper> start_no_contacts(const Circles& w, unsigned threads, std::uint64_t) {
  return std::make_unique<NoContacts>(w, threads);
}
const EngineEntry kNoContacts{"no-contacts", "", false, false, 256, &start_no_contacts};

// kTouching's circles 0 and 1 touch in w_0, so in the oracle circle 0 takes velocity -1 and moves to
// RN(-1/60); the wrong engine moves it to RN(1/60). 1/60 = 2^-6 · 16/15 = 0x1.111...p-6, rounded down (the
// next hex digit is 1), and its shortest decimal needs 17 digits: 0.01666666666666667 is 3.6e-18 away, more
// than half its ulp (2^-59 ≈ 1.7e-18).
TEST(compare_with_oracle, names_the_first_step_circle_and_field_where_an_engine_differs) {
  const Comparison c = compare_with_oracle(kNoContacts, kTouching, 10, 1);
  EXPECT_EQ(c.steps, 0u);
  ASSERT_TRUE(c.difference);
  EXPECT_EQ(*c.difference,
            "step 1, circle 0, field px: oracle -0.016666666666666666 (-0x1.1111111111111p-6), engine "
            "0.016666666666666666 (0x1.1111111111111p-6)");
  std::ostringstream out;
  print_comparison(kNoContacts, c, out);
  EXPECT_EQ(out.str(), "no-contacts engine: DIFFERS from the correctly rounded oracle at " + *c.difference + "\n");
}

TEST(compare_with_oracle, agrees_when_both_stop_at_the_same_overflow) {
  const Comparison c = compare_with_oracle(engine("double"), kOverflowsAtStep4, 10, 1);
  EXPECT_EQ(c.steps, 3u);
  EXPECT_FALSE(c.difference);
  ASSERT_TRUE(c.overflow);
  std::ostringstream out;
  print_comparison(engine("double"), c, out);
  EXPECT_EQ(out.str(),
            "double engine: agrees with the correctly rounded oracle at each of the 3 steps, after which both stop: "
            "step 4, circle 1, field px: the position p + v/60 overflows to infinity\n");
}

TEST(compare_with_oracle, names_an_overflow_only_one_side_reports) {
  const Comparison c = compare_with_oracle(kNoContacts, kOverflowsAtStep4, 10, 1);
  ASSERT_TRUE(c.difference);
  EXPECT_EQ(*c.difference,
            "step 4: the oracle stops at circle 1, field px: the position p + v/60 overflows to infinity, the engine "
            "does not");
}

}  // namespace
}  // namespace circles::cli
