// Hostile input to the readers of scene files and protocol lines (the hostile cases of docs/hardening.md): each
// case is refused with the typed error (SceneError, ProtocolError: exit code 2 in `circles`) and a message
// naming the file or line, the place and the reason, never a crash. The cases tests/scene_test.cpp and
// tests/protocol_test.cpp already check are not repeated here; fuzz/ throws random bytes at the same readers
// (docs/hardening.md).
#include "formats/protocol.hpp"
#include "formats/scene.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace circles::formats {
namespace {

using circles::testing::thrown;
using namespace std::string_literals;  // "...\0..."s keeps a NUL byte

// A nesting depth that exhausts the stack of a reader recursing once per level: 100000 frames of even 100
// bytes are 10 MB, more than the 8 MB default stack of Linux.
constexpr std::size_t kDeep = 100000;

std::string scene_error(std::string_view text) {
  const auto e = thrown<SceneError>([&] { parse_scene(text, "s.json"); });
  return e ? e->what() : "";
}

std::string line_error(std::string_view text) {
  const auto e = thrown<ProtocolError>([&] { parse_line(text, 4); });
  return e ? e->what() : "";
}

// A file in a fresh directory of the test's own, removed with it.
class scene_file : public ::testing::Test {
 protected:
  std::string write(const std::string& name, std::string_view bytes) const { return dir_.write(name, std::string(bytes)); }
  std::string load_error(const std::string& path) const {
    const auto e = thrown<SceneError>([&] { load_scene(path); });
    return e ? e->what() : "";
  }

  circles::testing::TempDir dir_;
};

TEST_F(scene_file, an_empty_file_is_refused_as_empty) {
  const std::string path = write("empty.json", "");
  EXPECT_EQ(load_error(path), path + R"(: empty file, expected an object {"circles": [[px, py, vx, vy, r], ...]})");
  const std::string blank = write("blank.json", " \n\t\r\n");
  EXPECT_EQ(load_error(blank), blank + R"(: empty file, expected an object {"circles": [[px, py, vx, vy, r], ...]})");
}

// The file ends after "1.5, 0,": 39 bytes, so the end of input is byte 40.
TEST_F(scene_file, a_truncated_file_is_refused_at_its_end) {
  const std::string path = write("truncated.json", R"({"circles": [[0, 0, 60, 0, 1], [1.5, 0,)");
  EXPECT_EQ(load_error(path), path + ": malformed JSON at byte 40: [json.exception.parse_error.101] parse error at "
                                     "line 1, column 40: syntax error while parsing value - unexpected end of input; "
                                     "expected '[', '{', or a literal");
}

TEST_F(scene_file, a_directory_is_refused_as_not_a_file) {
  const std::string path = (dir_.path / "scenes").string();
  std::filesystem::create_directory(path);
  EXPECT_EQ(load_error(path), path + ": cannot read the file: it is a directory");
}

TEST(scene, refuses_nan_and_infinity_tokens_naming_their_byte) {
  EXPECT_EQ(scene_error(R"({"circles": [[0, 0, NaN, 0, 1]]})"),
            "s.json: malformed JSON at byte 21: [json.exception.parse_error.101] parse error at line 1, column 21: "
            "syntax error while parsing value - invalid literal; last read: '0, N'");
  EXPECT_EQ(scene_error(R"({"circles": [[Infinity, 0, 0, 0, 1]]})"),
            "s.json: malformed JSON at byte 15: [json.exception.parse_error.101] parse error at line 1, column 15: "
            "syntax error while parsing value - invalid literal; last read: '\"circles\": [[I'");
}

TEST(scene, refuses_a_number_beyond_the_double_range_naming_its_circle_and_field) {
  EXPECT_EQ(scene_error(R"({"circles": [[0, 0, 0, 0, 1], [0, 0, 0, -1e309, 1]]})"),
            "s.json: circle 1, field vy: -1e309 is beyond the double range");
  // Outside a circle, by its byte (the parser reports the byte after the token) and its JSON pointer.
  EXPECT_EQ(scene_error(R"({"steps": [1e400], "circles": []})"),
            "s.json: byte 16 (at /steps/0): 1e400 is beyond the double range");
}

TEST(scene, refuses_a_duplicate_key_naming_it_and_its_object) {
  EXPECT_EQ(scene_error(R"({"circles": [], "circles": [[0, 0, 0, 0, 1]]})"),
            R"(s.json: duplicate key "circles" in the top-level object)");
  EXPECT_EQ(scene_error(R"({"circles": [[0, 0, 0, 0, 1], {"p": [0, 0], "r": 1, "r": 2}]})"),
            R"(s.json: duplicate key "r" in the object at /circles/1)");
}

// -0 is a radius of C in the resolved profile (docs/protocol.md), not a negative one.
TEST(scene, reads_a_negative_zero_radius_as_zero) {
  const auto w = parse_scene(R"({"circles": [[0, 0, 0, 0, -0.0]]})", "s.json").circles;
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], spec::circle(0, 0, 0, 0, 0));
}

// The message quotes what the parser read with every byte outside printable ASCII as \xHH, so that it is one
// line of valid text whatever the file held.
TEST(scene, refuses_invalid_utf8_quoting_it_as_escaped_bytes) {
  EXPECT_EQ(scene_error("{\"name\": \"a\xff\xfe\", \"circles\": []}"),
            "s.json: malformed JSON at byte 12: [json.exception.parse_error.101] parse error at line 1, column 12: "
            "syntax error while parsing value - invalid string: ill-formed UTF-8 byte; last read: '\"a\\xFF'");
  EXPECT_EQ(scene_error("{\"circles\": [\xc3]}"),
            "s.json: malformed JSON at byte 14: [json.exception.parse_error.101] parse error at line 1, column 14: "
            "syntax error while parsing value - invalid literal; last read: '\"circles\": [\\xC3'");
}

TEST(scene, quotes_a_key_with_control_characters_as_escaped_bytes) {
  EXPECT_EQ(scene_error(R"({"circles": [], "a\u0000\n": 2})"),
            R"(s.json: unknown key "a\x00\x0A" in the top-level object (a scene has the keys "circles", "name", )"
            R"("steps" and "$schema"))");
}

// nlohmann's lexer takes a NUL byte for the end of the input, which would let anything follow a valid scene.
TEST(scene, refuses_a_nul_byte_naming_its_byte) {
  EXPECT_EQ(scene_error("{\"circles\": []}\0{\"x\""s),
            "s.json: malformed JSON at byte 16: a NUL byte, which JSON text cannot contain");
}

TEST(scene, refuses_nesting_too_deep_for_a_recursive_reader_without_exhausting_the_stack) {
  EXPECT_EQ(scene_error(std::string(kDeep, '[') + std::string(kDeep, ']')),
            R"(s.json: expected an object with a "circles" array)");
  EXPECT_EQ(scene_error(R"({"circles": )" + std::string(kDeep, '[')),
            "s.json: malformed JSON at byte 100013: [json.exception.parse_error.101] parse error at line 1, column "
            "100013: syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal");
  EXPECT_EQ(scene_error(R"({"circles": [[0, )" + std::string(kDeep, '[') + std::string(kDeep, ']') + ", 0, 0, 0]]}"),
            "s.json: circle 0, field py: expected a number, found array");
}

TEST(protocol_line, refuses_invalid_utf8_quoting_it_as_escaped_bytes) {
  EXPECT_EQ(line_error("{\"\xff\xfe\": 1, \"id\": 1, \"circles\": []}"),
            "line 4: malformed JSON at column 3: syntax error while parsing object key - invalid string: ill-formed "
            "UTF-8 byte; last read: '\"\\xFF'; expected string literal");
}

TEST(protocol_line, quotes_a_key_with_control_characters_as_escaped_bytes) {
  EXPECT_EQ(line_error(R"({"\u001b[31m": 1})"),
            R"(line 4: unexpected key "\x1B[31m" (a line has exactly the keys "id" and "circles"))");
}

TEST(protocol_line, refuses_a_nul_byte_naming_its_column) {
  EXPECT_EQ(line_error("{\"id\": 1, \"circles\": []}\0junk"s),
            "line 4: malformed JSON at column 25: a NUL byte, which JSON text cannot contain");
}

TEST(protocol_line, refuses_a_truncated_line_at_its_end) {
  EXPECT_EQ(line_error(R"({"id": 1, "circles": [[0, 0, 60)"),
            "line 4: malformed JSON at column 32: syntax error while parsing array - unexpected end of input; "
            "expected ']'");
}

TEST(protocol_line, refuses_top_level_nesting_at_its_first_bracket) {
  EXPECT_EQ(line_error(std::string(kDeep, '[')),
            R"(line 4: expected an object {"id": N, "circles": [[px, py, vx, vy, r], ...]}, found an array)");
}

}  // namespace
}  // namespace circles::formats
