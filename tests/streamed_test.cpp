// The readers of big documents read in pieces (formats/streamed.hpp) against the exact readers: scenes and
// trace lines of compact circles give the same doubles bit for bit, cut at any piece size; whatever the pieces
// do not take is read whole by the exact reader, so that hostile input (huge counts, a truncated last line, a
// number of 10^6 digits, deep nesting) gets the exact reader's message, which these tests spell out.
#include "formats/scene.hpp"
#include "formats/streamed.hpp"
#include "formats/trace_reader.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace circles::formats {
namespace {

using circles::testing::thrown;

// A piece size that cuts a document of a few circles in many places, and the default.
constexpr std::size_t kPieces[] = {1, 7, 64, kStreamPiece};

bool same_bits(const Circles& a, const Circles& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    for (std::size_t f = 0; f < 5; ++f)
      if (std::bit_cast<std::uint64_t>(a[k][f]) != std::bit_cast<std::uint64_t>(b[k][f])) return false;
  return true;
}

// The compact circles of n random doubles of every exponent, with the spellings a writer may use.
// With `lines`, some of them on lines of their own (a scene's layout; a trace line has no newline).
std::string random_circles(std::size_t n, std::uint64_t seed, bool lines = true) {
  std::mt19937_64 g(seed);
  std::string out;
  for (std::size_t k = 0; k < n; ++k) {
    out += k ? (k % 3 ? "," : lines ? " ,\n " : " , ") : "";
    out += "[";
    for (std::size_t f = 0; f < 5; ++f) {
      double x = std::bit_cast<double>(g() & 0x7fefffffffffffffu);  // finite, >= 0
      if (f < 4 && g() % 2) x = -x;
      std::ostringstream s;
      s.precision(17);
      if (g() % 4 == 0) s << static_cast<std::int64_t>(g() % 2000000) - (f < 4 ? 1000000 : 0);  // an integer token
      else s << x;
      out += (f ? ", " : "") + s.str();
    }
    out += "]";
  }
  return out;
}

SceneWorld streamed_world(const std::string& text, std::size_t piece) {
  std::istringstream in(text);
  return read_scene_world(in, "s.json", piece);
}

std::string scene_message(const std::string& text, std::size_t piece) {
  std::istringstream in(text);
  const auto e = thrown<SceneError>([&] { read_scene(in, "s.json", piece); });
  return e ? e->what() : "";
}

// The fast path alone takes `text`, and read_scene_world gives what parse_scene gives.
void same_scene(const std::string& text) {
  const Scene exact = parse_scene(text, "s.json");
  for (const std::size_t piece : kPieces) {
    std::istringstream in(text);
    PlainLineReader reader;
    const std::optional<Streamed> s = stream_document(in, false, reader, piece);
    ASSERT_TRUE(s) << "piece " << piece << ": " << text.substr(0, 200);
    EXPECT_EQ(s->bytes, text.size());
    const SceneWorld world = streamed_world(text, piece);
    EXPECT_TRUE(same_bits(world.circles, doubles_of(exact))) << "piece " << piece;
    EXPECT_EQ(world.name, exact.name);
    EXPECT_EQ(world.steps, exact.steps);
    std::istringstream again(text);
    EXPECT_EQ(read_scene(again, "s.json", piece), exact) << "piece " << piece;
  }
}

TEST(streamed_scene, reads_compact_circles_in_pieces_as_parse_scene_does) {
  same_scene("{\"circles\": [" + random_circles(300, 1) + "]}");
  same_scene("{\"name\": \"a\", \"steps\": 7, \"circles\": [" + random_circles(50, 2) + "]\n}\n");
  same_scene("{\"circles\":[" + random_circles(1, 3) + "], \"$schema\": \"x\", \"name\": \"[\"}");
  same_scene("\xEF\xBB\xBF{ \"circles\" :\n[ [0, -0.0, 1e-320, -0, 0.0] , [1, 2, 3, 4, 5] ] }");
}

// -0 is +0 among doubles_of's doubles, and the exact circle 0 of the rationals.
TEST(streamed_scene, gives_a_negative_zero_as_doubles_of_does) {
  const SceneWorld w = streamed_world(R"({"circles": [[-0.0, 0, -0, 1, -0.0], [1, 2, 3, 4, 5]]})", 7);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(w.circles[0][0]), 0u);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(w.circles[0][4]), 0u);
}

// The documents the pieces leave to parse_scene, each read right: the object form, a key "circles" in a
// string before the real one, a ']' after the circles, no circles, an integer beyond 64 bits.
TEST(streamed_scene, leaves_other_scenes_to_parse_scene_with_the_same_result) {
  for (const std::string& text :
       {std::string(R"({"circles": [{"p": [1, 2], "v": [3, 4], "r": 5, "name": "a"}, [1, 2, 3, 4, 5]]})"),
        std::string(R"({"name": "\"circles\": [[1, 2, 3, 4, 5]]", "circles": [[6, 7, 8, 9, 10]]})"),
        std::string(R"({"name": "\"circles\": [", "circles": [[6, 7, 8, 9, 10]], "steps": 1})"),
        std::string(R"({"circles": [[1, 2, 3, 4, 5]], "name": "]], ["})"), std::string(R"({"circles": []})"), std::string(R"({"circles": [[1, 2, 3, 4, 100000000000000000000000]]})")})
    for (const std::size_t piece : kPieces) {
      std::istringstream in(text);
      EXPECT_EQ(read_scene(in, "s.json", piece), parse_scene(text, "s.json")) << text;
    }
}

// Hostile scenes, each with parse_scene's message whichever path starts reading it.
TEST(streamed_scene, refuses_a_huge_count_of_steps_with_the_exact_message) {
  const std::string text = "{\"steps\": 1e30, \"circles\": [" + random_circles(100, 4) + "]}";
  for (const std::size_t piece : kPieces)
    EXPECT_EQ(scene_message(text, piece), "s.json: \"steps\": expected an integer from 0 to 9223372036854775807, "
                                          "found 1e+30");
}

TEST(streamed_scene, refuses_a_truncated_scene_with_the_exact_message) {
  const std::string text = R"({"circles": [[0, 0, 60, 0, 1], [1.5, 0,)";
  for (const std::size_t piece : kPieces)
    EXPECT_EQ(scene_message(text, piece),
              "s.json: malformed JSON at byte 40: [json.exception.parse_error.101] parse error at line 1, column 40: "
              "syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal");
}

// A number of 10^6 digits: read as the nearest double when it is one; beyond the double range, refused with
// its circle and field, its token shortened in the message.
TEST(streamed_scene, reads_a_number_of_a_million_digits_or_names_its_field) {
  const std::string tiny = "0." + std::string(999998, '0') + "1";  // 10^6 digits, 10^-999999: the double 0
  const SceneWorld w = streamed_world("{\"circles\": [[1, 2, 3, 4, 5], [" + tiny + ", 0, 0, 0, 1]]}", 7);
  ASSERT_EQ(w.circles.size(), 2u);
  EXPECT_EQ(w.circles[1][0], 0.0);
  const std::string huge = "1" + std::string(999999, '0');  // 10^999999
  for (const std::size_t piece : kPieces)
    EXPECT_EQ(scene_message("{\"circles\": [[1, 2, 3, 4, 5], [0, 0, " + huge + ", 0, 1]]}", piece),
              "s.json: circle 1, field vx: 100000000000000000000...0000000000 (1000000 characters) is beyond the "
              "double range");
}

TEST(streamed_scene, refuses_deep_nesting_in_a_circle_with_the_exact_message) {
  const std::string text =
      "{\"circles\": [[1, 2, 3, 4, 5], " + std::string(100000, '[') + std::string(100000, ']') + "]}";
  for (const std::size_t piece : kPieces)
    EXPECT_EQ(scene_message(text, piece), "s.json: circle 1: expected 5 numbers [px, py, vx, vy, r], found 1");
}

// The files `circles run` loads: the doubles of load_scene, and load_scene's messages for what is not a file.
TEST(streamed_scene, loads_a_file_as_load_scene_does_and_refuses_what_is_not_a_file) {
  circles::testing::TempDir dir;
  const std::string path = dir.write("s.json", "{\"steps\": 3, \"circles\": [" + random_circles(2000, 10) + "]}");
  const SceneWorld world = load_scene_world(path);
  const Scene exact = load_scene(path);
  EXPECT_EQ(world.circles.size(), 2000u);
  EXPECT_TRUE(same_bits(world.circles, doubles_of(exact)));
  EXPECT_EQ(world.steps, std::optional<std::uint64_t>(3));
  const auto directory = thrown<SceneError>([&] { load_scene_world(dir.path.string()); });
  EXPECT_EQ(std::string(directory ? directory->what() : ""), dir.path.string() + ": cannot read the file: it is a directory");
  const auto missing = thrown<SceneError>([&] { load_scene_world(path + ".not"); });
  EXPECT_EQ(std::string(missing ? missing->what() : ""), path + ".not: cannot open the file: No such file or directory");
}

// A trace read with its lines streamed, or read whole: the worlds, or the message.
std::vector<Line> trace(const std::string& text, std::size_t piece, std::string& error) {
  std::istringstream in(text);
  TraceReader reader(in, "t.jsonl", piece);
  std::vector<Line> worlds;
  try {
    while (std::optional<Line> w = reader.next()) worlds.push_back(std::move(*w));
  } catch (const TraceReadError& e) {
    error = e.what();
  }
  return worlds;
}

std::string trace_line(std::uint64_t step, const std::string& circles) {
  return "{\"step\": " + std::to_string(step) + ", \"circles\": [" + circles + "]}";
}

TEST(streamed_trace, reads_lines_in_pieces_as_parse_line_does) {
  const std::string text = trace_line(5, random_circles(40, 5, false)) + "\n" + trace_line(6, random_circles(40, 6, false)) +
                           "\r\n{\"circles\": [" + random_circles(40, 7, false) + "], \"step\": 7}";
  std::string whole_error;
  std::istringstream in(text);
  std::vector<Line> whole;
  for (std::string line; std::getline(in, line);) whole.push_back(parse_line(line, whole.size() + 1, kStep));
  for (const std::size_t piece : kPieces) {
    // The pieces take each line, and stop at its '\n'.
    std::istringstream lines(text);
    PlainLineReader reader;
    for (std::size_t t = 0; t < 3; ++t) {
      const std::streampos start = lines.tellg();
      const std::optional<Streamed> s = stream_document(lines, true, reader, piece);
      ASSERT_TRUE(s) << "piece " << piece << ", line " << t + 1;
      EXPECT_EQ(s->circles.size(), 40u);
      lines.clear();
      lines.seekg(start + static_cast<std::streamoff>(s->bytes));
    }
    EXPECT_EQ(lines.tellg(), static_cast<std::streampos>(text.size()));
    std::string error;
    const std::vector<Line> worlds = trace(text, piece, error);
    EXPECT_EQ(error, "");
    ASSERT_EQ(worlds.size(), 3u) << "piece " << piece;
    for (std::size_t t = 0; t < 3; ++t) {
      EXPECT_EQ(worlds[t].number, whole[t].number);
      EXPECT_TRUE(same_bits(worlds[t].circles, whole[t].circles)) << "piece " << piece << ", line " << t + 1;
    }
  }
}

TEST(streamed_trace, refuses_a_truncated_last_line_naming_it) {
  const std::string circles = random_circles(30, 8, false);
  const std::string text = trace_line(0, circles) + "\n" + trace_line(1, circles).substr(0, 500);
  for (const std::size_t piece : kPieces) {
    std::string error;
    EXPECT_EQ(trace(text, piece, error).size(), 1u);
    EXPECT_EQ(error, "t.jsonl:2: malformed JSON at column 501: syntax error while parsing value - invalid number; "
                     "expected digit after exponent sign; last read: '8.3149565533166962e-'");
  }
}

TEST(streamed_trace, refuses_a_huge_step_count_naming_its_line) {
  const std::string circles = random_circles(30, 9, false);
  const std::string text = trace_line(0, circles) + "\n" +
                           "{\"step\": 100000000000000000000, \"circles\": [" + circles + "]}\n";
  for (const std::size_t piece : kPieces) {
    std::string error;
    EXPECT_EQ(trace(text, piece, error).size(), 1u);
    EXPECT_EQ(error, "t.jsonl:2: \"step\": expected an integer from 0 to 18446744073709551615, found "
                     "100000000000000000000");
  }
}

TEST(streamed_trace, refuses_a_number_of_a_million_digits_naming_its_line_and_field) {
  const std::string huge = "1" + std::string(999999, '0');  // 10^999999
  const std::string text = trace_line(0, "[1, 2, 3, 4, 5], [0, 0, " + huge + ", 0, 1]") + "\n";
  for (const std::size_t piece : kPieces) {
    std::string error;
    EXPECT_TRUE(trace(text, piece, error).empty());
    EXPECT_EQ(error, "t.jsonl:1: circle 1, field vx: 100000000000000000000...0000000000 (1000000 characters) is "
                     "beyond the double range");
  }
}

TEST(streamed_trace, refuses_deep_nesting_naming_its_line) {
  const std::string text = trace_line(0, "[1, 2, 3, 4, 5], " + std::string(100000, '[') + std::string(100000, ']'));
  for (const std::size_t piece : kPieces) {
    std::string error;
    EXPECT_TRUE(trace(text, piece, error).empty());
    EXPECT_EQ(error, "t.jsonl:1: circle 1, field px: expected a number, found an array");
  }
}

}  // namespace
}  // namespace circles::formats
