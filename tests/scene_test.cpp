// Scenes read by `circles` (formats/scene.hpp, docs/scenes.md): both circle forms, the optional name and steps,
// every number as its nearest double, and a message naming the place for everything else. The hostile inputs
// (depth, NUL bytes, invalid UTF-8, files that are not files) are in tests/hostile_input_test.cpp.
#include "formats/scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace circles::formats {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_scene(text, "s.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

// The one circle of {"circles": [[<number>, 0, 0, 0, 0]]}: its px, as the double the loader made of it.
double px_of(const std::string& number) {
  const Scene s = parse_scene(R"({"circles": [[)" + number + ", 0, 0, 0, 0]]}", "s.json");
  return spec::nearest_doubles(s.circles.at(0))[0];
}

TEST(parse_scene, reads_the_exact_value_of_each_number) {
  const auto w = parse_scene(R"({"circles": [[0.1, -2, 9007199254740992, 1e-320, 0]]})", "s.json").circles;
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], spec::circle(spec::exact(0.1), -2, spec::exact(0x1p53), spec::exact(1e-320), 0));
}

TEST(parse_scene, reads_the_compact_form_with_no_name_no_steps_and_unnamed_circles) {
  const Scene s = parse_scene(R"({"circles": [[1, 2, 3, 4, 5], [6, 7, 8, 9, 10]]})", "s.json");
  EXPECT_EQ(s.name, std::nullopt);
  EXPECT_EQ(s.steps, std::nullopt);
  EXPECT_EQ(s.circles, (std::vector{spec::circle(1, 2, 3, 4, 5), spec::circle(6, 7, 8, 9, 10)}));
  EXPECT_EQ(s.circle_names, (std::vector<std::optional<std::string>>(2)));
}

TEST(parse_scene, reads_a_circle_object_as_the_compact_circle_of_the_same_numbers) {
  const Scene s = parse_scene(R"({"name": "a cradle", "steps": 240, "circles": [
                                   {"r": 5, "name": "left", "v": [3, 4], "p": [1, 2]},
                                   [6, 7, 8, 9, 10],
                                   {"p": [-1, -2], "v": [-3, -4], "r": 0.5}]})",
                              "s.json");
  EXPECT_EQ(s.name, "a cradle");
  EXPECT_EQ(s.steps, 240u);
  EXPECT_EQ(s.circles, (std::vector{spec::circle(1, 2, 3, 4, 5), spec::circle(6, 7, 8, 9, 10),
                                    spec::circle(-1, -2, -3, -4, spec::exact(0.5))}));
  EXPECT_EQ(s.circle_names, (std::vector<std::optional<std::string>>{"left", std::nullopt, std::nullopt}));
}

// Every number token means the double nearest to its decimal value, ties to even (formats/json_number.hpp), the
// reading of JavaScript's JSON.parse and of strtod. The ties check the direction of rounding, which a
// truncating reader (2^53 + 3 -> 2^53 + 2) or one that rounds twice (through an 80-bit long double,
// 2^64 + 2049 -> 2^64 + 2048 -> 2^64) gets wrong.
TEST(parse_scene, reads_every_number_token_as_the_double_nearest_to_it_ties_to_even) {
  EXPECT_EQ(px_of("9007199254740993"), 0x1p53);                  // 2^53 + 1: a tie, to the even 2^53
  EXPECT_EQ(px_of("9007199254740995"), 0x1p53 + 4);              // 2^53 + 3: a tie, to the even 2^53 + 4
  EXPECT_EQ(px_of("-9223372036854775807"), -0x1p63);             // -(2^63 - 1), an int64
  EXPECT_EQ(px_of("18446744073709551615"), 0x1p64);              // 2^64 - 1, a uint64
  // Beyond 64 bits, read by strtod from the token's text.
  EXPECT_EQ(px_of("18446744073709551617"), 0x1p64);              // 2^64 + 1
  EXPECT_EQ(px_of("18446744073709553664"), 0x1p64);              // 2^64 + 2048: a tie, to the even 2^64
  EXPECT_EQ(px_of("18446744073709553665"), 0x1p64 + 4096);       // 2^64 + 2049: above the tie
  EXPECT_EQ(px_of("-9223372036854775809"), -0x1p63);             // -(2^63 + 1), below int64
  // JavaScript's JSON.stringify writes doubles of 10^21 and above in integer form.
  EXPECT_EQ(px_of("4783255246441940000"), 4.78325524644194e18);
  EXPECT_EQ(px_of("340282366920938463463374607431768211457"), 0x1p128);  // 2^128 + 1
  // Fractions and exponents as ever; below the least subnormal's half, zero.
  EXPECT_EQ(px_of("0.1"), 0.1);
  EXPECT_EQ(px_of("1.7976931348623158e308"), std::numeric_limits<double>::max());  // rounds down to DBL_MAX
  EXPECT_EQ(px_of("1e-400"), 0.0);
}

TEST(parse_scene, names_the_byte_of_malformed_json) {
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 0, 1]})"),
            "s.json: malformed JSON at byte 29: [json.exception.parse_error.101] parse error at line 1, column 29: "
            "syntax error while parsing array - unexpected '}'; expected ']'");
}

TEST(parse_scene, names_the_circle_and_field_of_a_wrong_value) {
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 0, 1], [0, "x", 0, 0, 1]]})"),
            "s.json: circle 1, field py: expected a number, found string");
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 0, -1]]})"),
            "s.json: circle 0, field r: radius -1 is negative (r >= 0, the resolved profile) (not an element of C)");
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 1e999, 0, 1]]})"),
            "s.json: circle 0, field vx: 1e999 is beyond the double range");
  // The same places in a circle object.
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 0, 1], {"p": [0, null], "v": [0, 0], "r": 1}]})"),
            "s.json: circle 1, field py: expected a number, found null");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0, 0], "v": [0, -1e400], "r": 1}]})"),
            "s.json: circle 0, field vy: -1e400 is beyond the double range");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0, 0], "v": [0, 0], "r": 2e308}]})"),
            "s.json: circle 0, field r: 2e308 is beyond the double range");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0, 0], "v": [0, 0], "r": -2}]})"),
            "s.json: circle 0, field r: radius -2 is negative (r >= 0, the resolved profile) (not an element of C)");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0, 0], "v": [0, 0], "r": "1"}]})"),
            "s.json: circle 0, field r: expected a number, found string");
}

TEST(parse_scene, names_a_wrong_shape) {
  EXPECT_EQ(error_of(R"([1, 2])"), "s.json: expected an object with a \"circles\" array");
  EXPECT_EQ(error_of(R"({"name": "x"})"), "s.json: missing key \"circles\"");
  EXPECT_EQ(error_of(R"({"circles": {}})"), "s.json: \"circles\" must be an array");
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 1]]})"),
            "s.json: circle 0: expected 5 numbers [px, py, vx, vy, r], found 4");
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 0, 1, 0]]})"),
            "s.json: circle 0: expected 5 numbers [px, py, vx, vy, r], found 6");
  EXPECT_EQ(error_of(R"({"circles": [7]})"),
            R"(s.json: circle 0: expected [px, py, vx, vy, r] or {"p": [px, py], "v": [vx, vy], "r": r}, found 7)");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0, 0], "r": 1}]})"), "s.json: circle 0: missing key \"v\"");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0], "v": [0, 0], "r": 1}]})"),
            "s.json: circle 0, field p: expected 2 numbers [px, py], found 1");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0, 0], "v": {"x": 0}, "r": 1}]})"),
            "s.json: circle 0, field v: expected [vx, vy], found object");
}

// A misspelt key would otherwise drop what it meant to say: a circle of the default radius, a run of the
// default length. The first unknown key in the file is named, with its object.
TEST(parse_scene, refuses_an_unknown_key_naming_it_and_its_place) {
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 0, 1], {"p": [0, 0], "v": [0, 0], "raduis": 1}]})"),
            R"(s.json: circle 1: unknown key "raduis" (a circle object has the keys "p", "v", "r" and "name"))");
  EXPECT_EQ(error_of(R"({"step": 10, "circles": [], "other": 1})"),
            R"(s.json: unknown key "step" in the top-level object (a scene has the keys "circles", "name", "steps" )"
            R"(and "$schema"))");
  // A protocol request is not a scene: its "id" is refused.
  EXPECT_EQ(error_of(R"({"id": 1, "circles": []})"),
            R"(s.json: unknown key "id" in the top-level object (a scene has the keys "circles", "name", "steps" )"
            R"(and "$schema"))");
  // Keys deeper than a circle are values of a wrong type, not unknown keys.
  EXPECT_EQ(error_of(R"({"name": {"first": 1}, "circles": []})"), R"(s.json: "name": expected a string, found object)");
}

TEST(parse_scene, reads_steps_as_an_integer_from_0_to_2_63_minus_1) {
  const auto steps = [](const std::string& value) {
    return parse_scene(R"({"steps": )" + value + R"(, "circles": []})", "s.json").steps;
  };
  EXPECT_EQ(steps("0"), 0u);
  EXPECT_EQ(steps("9223372036854775807"), 9223372036854775807u);
  EXPECT_EQ(steps("1e3"), 1000u);  // an integer in value, as JSON Schema's "integer" has it
  EXPECT_EQ(steps("-0.0"), 0u);
  const std::string expected = "s.json: \"steps\": expected an integer from 0 to 9223372036854775807, found ";
  EXPECT_EQ(error_of(R"({"steps": -1, "circles": []})"), expected + "-1");
  EXPECT_EQ(error_of(R"({"steps": 1.5, "circles": []})"), expected + "1.5");
  EXPECT_EQ(error_of(R"({"steps": 9223372036854775808, "circles": []})"), expected + "9223372036854775808");
  EXPECT_EQ(error_of(R"({"steps": 1e19, "circles": []})"), expected + "1e+19");
  EXPECT_EQ(error_of(R"({"steps": "10", "circles": []})"), expected + "string");
  EXPECT_EQ(error_of(R"({"steps": 1e400, "circles": []})"), "s.json: \"steps\": 1e400 is beyond the double range");
}

TEST(parse_scene, refuses_names_that_are_not_strings) {
  EXPECT_EQ(error_of(R"({"name": 5, "circles": []})"), R"(s.json: "name": expected a string, found 5)");
  EXPECT_EQ(error_of(R"({"$schema": null, "circles": []})"), R"(s.json: "$schema": expected a string, found null)");
  EXPECT_EQ(error_of(R"({"circles": [{"p": [0, 0], "v": [0, 0], "r": 1, "name": ["a"]}]})"),
            "s.json: circle 0, field name: expected a string, found array");
}

TEST(load_scene, names_a_missing_file) {
  EXPECT_THROW(load_scene("/nonexistent/scene.json"), SceneError);
  try {
    load_scene("/nonexistent/scene.json");
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/scene.json: cannot open the file: No such file or directory");
  }
}

TEST(default_scene, is_the_bundled_scenes_default_json) {
  EXPECT_EQ(default_scene(), load_scene(std::string(CIRCLES_SOURCE_DIR) + "/scenes/default.json"));
  EXPECT_TRUE(default_scene().name.has_value());
  EXPECT_EQ(default_scene().circles.size(), 10u);
}

// docs/scenes.md has a section for each bundled scene, headed by its file name, and every scene loads.
TEST(bundled_scenes, each_loads_and_has_its_section_in_docs_scenes_md) {
  const std::filesystem::path root = CIRCLES_SOURCE_DIR;
  std::ifstream in(root / "docs" / "scenes.md");
  std::stringstream doc;
  doc << in.rdbuf();
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    ++scenes;
    const std::string file = "scenes/" + entry.path().filename().string();
    EXPECT_NO_THROW(load_scene(entry.path().string())) << file;
    EXPECT_NE(doc.str().find("### `" + file + "`"), std::string::npos) << "docs/scenes.md has no section for " << file;
  }
  EXPECT_GE(scenes, 1);
}

TEST(random_world, refuses_a_world_larger_than_memory_before_allocating_it) {
  const std::size_t memory = physical_memory();
  ASSERT_GT(memory, 0u);
  const std::size_t n = memory / 40 + 1;  // 40 bytes a circle: more than the memory
  try {
    random_world(n, 0.1, 1, 40);
    ADD_FAILURE() << "no error";
  } catch (const WorldTooLarge& e) {
    EXPECT_EQ(std::string(e.what()), "world too large for memory: " + std::to_string(n) + " circles need " +
                                         std::to_string(n * 40) + " bytes, more than the " + std::to_string(memory) +
                                         " bytes of memory of this machine");
  }
  // A count whose bytes overflow size_t is refused the same way, not wrapped around to a small number.
  EXPECT_THROW(random_world(std::numeric_limits<std::size_t>::max() / 2, 0.1, 1, 40), WorldTooLarge);
}

TEST(random_world, is_the_benchmarks_scene_and_refuses_a_bad_coverage) {
  const auto w = random_world(100, 0.1, 7, 256);
  ASSERT_EQ(w.size(), 100u);
  for (const auto& c : w) {
    EXPECT_GE(c[4], 2.0);
    EXPECT_LE(c[4], 6.0);
    EXPECT_LE(c[2] * c[2] + c[3] * c[3], 100.0 * 100.0);
  }
  EXPECT_EQ(w, random_world(100, 0.1, 7, 256));
  EXPECT_NE(w, random_world(100, 0.1, 8, 256));
  EXPECT_THROW(random_world(100, 0.0, 7, 256), SceneError);
  EXPECT_THROW(random_world(0, 0.1, 7, 256), SceneError);
  const Scene s = random_scene(100, 0.1, 7, kOracleBytesPerCircle);
  EXPECT_EQ(s.name, "a random scene of 100 circles (coverage 0.1, seed 7)");
  ASSERT_EQ(s.circles.size(), 100u);
  EXPECT_EQ(spec::nearest_doubles(s.circles[99]), w[99]);
}

}  // namespace
}  // namespace circles::formats
