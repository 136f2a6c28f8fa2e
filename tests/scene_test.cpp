// The compact scene form read by `circles`: exact values in, clear messages for everything else.
#include "cli/scene.hpp"

#include <gtest/gtest.h>

namespace circles::cli {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_scene(text, "s.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(parse_scene, reads_the_exact_value_of_each_number) {
  const auto w = parse_scene(R"({"circles": [[0.1, -2, 9007199254740992, 1e-320, 0]]})", "s.json");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], spec::circle(spec::exact(0.1), -2, spec::exact(0x1p53), spec::exact(1e-320), 0));
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
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 9007199254740993, 1]]})"),
            "s.json: circle 0, field vy: integer 9007199254740993 is not exactly a double");
}

TEST(parse_scene, names_a_wrong_shape) {
  EXPECT_EQ(error_of(R"([1, 2])"), "s.json: expected an object with a \"circles\" array");
  EXPECT_EQ(error_of(R"({"circles": {}})"), "s.json: \"circles\" must be an array");
  EXPECT_EQ(error_of(R"({"circles": [[0, 0, 0, 1]]})"), "s.json: circle 0: expected [px, py, vx, vy, r]");
}

TEST(load_scene, names_a_missing_file) {
  EXPECT_THROW(load_scene("/nonexistent/scene.json"), SceneError);
  try {
    load_scene("/nonexistent/scene.json");
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/scene.json: cannot open the file");
  }
}

TEST(default_scene, is_the_bundled_scenes_default_json) {
  EXPECT_EQ(default_scene(), load_scene(std::string(CIRCLES_SOURCE_DIR) + "/scenes/default.json"));
}

}  // namespace
}  // namespace circles::cli
