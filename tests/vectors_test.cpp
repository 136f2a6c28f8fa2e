// `circles vectors` (cli/vectors_command.hpp): each vector is checked against references other than the oracle that
// made it: the next world against impl::step_all_pairs, the exact next world against the input moved by its
// new velocity, the hashes against FNV-1a written out here byte by byte, the hex forms against strtod, the
// features against impl::intersect_exact. examples/python/check_vectors.py checks the same file in another
// language (tests/vectors_end_to_end.sh).
#include "conform/conform.hpp"
#include "formats/json_number.hpp"
#include "cli/run.hpp"
#include "formats/scene.hpp"
#include "cli/vectors_command.hpp"
#include "impl/engine.hpp"
#include "impl/predicate.hpp"
#include "tests/temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace circles::cli {
namespace {

using conform::case_worlds;
using conform::kVectorsFile;
using conform::make_vector;
using conform::VectorsOptions;
using conform::VectorsSummary;
using conform::write_vectors;
using formats::doubles_of;
using formats::format_vector;
using formats::load_scene;
using formats::Vector;
using spec::Circles;

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path root = CIRCLES_SOURCE_DIR;

using circles::testing::TempDir;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<json> cases_in(const fs::path& file) {
  std::vector<json> cases;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) cases.push_back(json::parse(line));
  return cases;
}

VectorsOptions options_in(const TempDir& dir, std::uint64_t cases = 200) {
  VectorsOptions o;
  o.out = dir.path.string();
  o.scenes = (root / "scenes").string();
  o.cases = cases;
  return o;
}

// The default vectors (200 cases of seed 1 and the bundled scenes), made once for the tests that only read them.
const std::vector<json>& default_cases() {
  static const std::vector<json> cases = [] {
    TempDir dir;
    write_vectors(options_in(dir));
    return cases_in(dir.path / kVectorsFile);
  }();
  return cases;
}

Circles doubles(const json& rows) {
  Circles w;
  for (const json& row : rows) w.push_back({row[0], row[1], row[2], row[3], row[4]});
  return w;
}

Circles from_hex(const json& rows) {
  Circles w;
  for (const json& row : rows) {
    spec::CircleDoubles c{};
    for (std::size_t j = 0; j < 5; ++j) c[j] = std::strtod(row[j].get<std::string>().c_str(), nullptr);
    w.push_back(c);
  }
  return w;
}

bool same_bits(const Circles& a, const Circles& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    for (std::size_t j = 0; j < 5; ++j)
      if (std::bit_cast<std::uint64_t>(a[k][j]) != std::bit_cast<std::uint64_t>(b[k][j])) return false;
  return true;
}

// "n/d" read by hand: the numerator and denominator as integers, the denominator positive and coprime to it.
spec::Q fraction_of(const std::string& text) {
  const std::size_t slash = text.find('/');
  EXPECT_NE(slash, std::string::npos) << text;
  const spec::Z n(text.substr(0, slash)), d(text.substr(slash + 1));
  EXPECT_GT(d, 0) << text;
  EXPECT_EQ(boost::multiprecision::gcd(n, d), 1) << text << " is not in lowest terms";
  return spec::Q(n, d);
}

// FNV-1a over the fields' bytes, least significant first, −0 as +0: docs/vectors.md's definition, written
// out apart from formats/state_hash.cpp.
std::string fnv1a(const Circles& w) {
  std::uint64_t h = 14695981039346656037u;  // 0xcbf29ce484222325
  for (const auto& c : w)
    for (const double x : c) {
      const std::uint64_t bits = x == 0 ? 0 : std::bit_cast<std::uint64_t>(x);
      for (int b = 0; b < 8; ++b) h = (h ^ ((bits >> (8 * b)) & 0xff)) * 1099511628211u;  // 0x100000001b3
    }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

TEST(vectors, each_next_world_is_the_all_pairs_step_of_its_input_and_each_hex_form_its_decimal) {
  ASSERT_GT(default_cases().size(), 150u);
  for (const json& c : default_cases()) {
    SCOPED_TRACE(c["source"].dump());
    const Circles input = doubles(c["input"]), next = doubles(c["next"]);
    EXPECT_TRUE(same_bits(from_hex(c["input_hex"]), input));
    EXPECT_TRUE(same_bits(from_hex(c["next_hex"]), next));
    const Circles want = impl::step_all_pairs(impl::World{input}).circles();
    ASSERT_EQ(next.size(), want.size());
    for (std::size_t k = 0; k < next.size(); ++k)
      for (std::size_t j = 0; j < 5; ++j) {
        EXPECT_EQ(next[k][j], want[k][j]) << "circle " << k << ", field " << j;  // by value: −0 == +0
        EXPECT_FALSE(next[k][j] == 0 && std::signbit(next[k][j])) << "a rounded zero is +0";
      }
  }
}

TEST(vectors, each_exact_next_world_is_the_input_moved_by_its_new_velocity_and_rounds_to_next) {
  for (const json& c : default_cases()) {
    SCOPED_TRACE(c["source"].dump());
    const Circles input = doubles(c["input"]), next = doubles(c["next"]);
    ASSERT_EQ(c["next_exact"].size(), input.size());
    for (std::size_t k = 0; k < input.size(); ++k) {
      std::array<spec::Q, 5> q;
      for (std::size_t j = 0; j < 5; ++j) {
        q[j] = fraction_of(c["next_exact"][k][j]);
        EXPECT_EQ(spec::nearest_double(q[j]), next[k][j]) << "circle " << k << ", field " << j;
      }
      // Velocities are copied from input doubles, radii kept, positions p + v/60 exactly.
      EXPECT_EQ(q[2], spec::exact(next[k][2]));
      EXPECT_EQ(q[3], spec::exact(next[k][3]));
      EXPECT_EQ(q[4], spec::exact(input[k][4]));
      EXPECT_EQ(q[0], spec::exact(input[k][0]) + q[2] / 60);
      EXPECT_EQ(q[1], spec::exact(input[k][1]) + q[3] / 60);
    }
  }
}

TEST(vectors, each_hash_is_fnv1a_of_the_little_endian_fields_with_negative_zero_as_positive_zero) {
  bool negative_zero_in_input = false;
  for (const json& c : default_cases()) {
    const Circles input = doubles(c["input"]);
    EXPECT_EQ(c["input_hash"], fnv1a(input)) << c["source"].dump();
    EXPECT_EQ(c["next_hash"], fnv1a(doubles(c["next"]))) << c["source"].dump();
    for (const auto& circle : input)
      for (const double x : circle) negative_zero_in_input = negative_zero_in_input || (x == 0 && std::signbit(x));
  }
  EXPECT_TRUE(negative_zero_in_input) << "no input holds -0, so the ±0 policy goes untested";
}

TEST(vectors, the_default_cases_cover_contacts_tangencies_choices_ties_copies_and_zero_radii) {
  std::map<std::string, int> count;
  for (const json& c : default_cases()) {
    std::set<std::string> features;
    for (const json& f : c["features"]) features.insert(f.get<std::string>());
    for (const std::string& f : features) ++count[f];
    // "contact" and "choice" against the engine's exact intersect test on the doubles.
    const Circles w = doubles(c["input"]);
    std::size_t most = 0;
    for (std::size_t a = 0; a < w.size(); ++a) {
      std::size_t contacts = 0;
      for (std::size_t b = 0; b < w.size(); ++b)
        contacts += a != b && impl::intersect_exact(w[a][0], w[a][1], w[a][4], w[b][0], w[b][1], w[b][4]);
      most = std::max(most, contacts);
    }
    EXPECT_EQ(features.contains("contact"), most >= 1) << c["source"].dump();
    EXPECT_EQ(features.contains("choice"), most >= 2) << c["source"].dump();
  }
  for (const char* f : {"contact", "tangency", "choice", "tie", "duplicate", "zero_radius"})
    EXPECT_GE(count[f], 5) << f;
}

TEST(vectors, the_scene_cases_are_the_first_three_worlds_of_each_bundled_scene) {
  std::map<std::string, std::vector<json>> by_scene;
  for (const json& c : default_cases())
    if (c["source"].contains("scene")) by_scene[c["source"]["scene"]].push_back(c);
  std::set<std::string> bundled;
  for (const auto& e : fs::directory_iterator(root / "scenes"))
    if (e.path().extension() == ".json") bundled.insert(e.path().filename().string());
  std::set<std::string> found;
  for (const auto& [scene, cases] : by_scene) found.insert(scene);
  EXPECT_EQ(found, bundled);
  for (const auto& [scene, cases] : by_scene) {
    ASSERT_EQ(cases.size(), 3u) << scene;
    EXPECT_TRUE(same_bits(doubles(cases[0]["input"]), doubles_of(load_scene((root / "scenes" / scene).string()))));
    for (std::size_t t = 0; t < cases.size(); ++t) {
      EXPECT_EQ(cases[t]["source"]["step"], t);
      if (t > 0) {
        EXPECT_EQ(cases[t]["input"], cases[t - 1]["next"]) << scene << " step " << t;
      }
    }
  }
}

TEST(vectors, the_generated_cases_are_conforms_cases_of_the_seed_in_order) {
  const std::vector<Circles> worlds = case_worlds(1, 200);
  std::size_t generated = 0, index = 0;
  for (const json& c : default_cases()) {
    EXPECT_EQ(c["case"], index++);
    if (!c["source"].contains("seed")) continue;
    ++generated;
    EXPECT_EQ(c["source"]["seed"], 1);
    const std::uint64_t k = c["source"]["case"];
    ASSERT_LT(k, worlds.size());
    EXPECT_TRUE(same_bits(doubles(c["input"]), worlds[k])) << "case " << k;
  }
  EXPECT_GT(generated, 110u);  // of 200: 136 of the small families, less those that leave the double range
}

TEST(vectors, a_vector_line_holds_fractions_hex_floats_features_and_hashes) {
  // Two circles that touch (their distance 2 is the sum of their radii) and share py = 0: each takes the
  // other's velocity. Circle 0 moves to -1 + 0 = (0 + -60/60), circle 1 to 2 + 60/60 = 3.
  const std::optional<Vector> v = make_vector({{0, 0, 60, 0, 1}, {2, 0, -60, 0, 1}});
  ASSERT_TRUE(v);
  Vector with_source = *v;
  with_source.seed = 4;
  with_source.case_index = 9;
  const Circles next{{-1, 0, -60, 0, 1}, {3, 0, 60, 0, 1}};
  EXPECT_EQ(format_vector(12, with_source),
            R"({"case":12,"source":{"seed":4,"case":9},"features":["contact","tangency","tie"],)"
            R"("input":[[0.0,0.0,60.0,0.0,1.0],[2.0,0.0,-60.0,0.0,1.0]],)"
            R"("input_hex":[["0x0p+0","0x0p+0","0x1.ep+5","0x0p+0","0x1p+0"],["0x1p+1","0x0p+0","-0x1.ep+5","0x0p+0","0x1p+0"]],)"
            R"("input_hash":")" + fnv1a({{0, 0, 60, 0, 1}, {2, 0, -60, 0, 1}}) + R"(",)"
            R"("next_exact":[["-1/1","0/1","-60/1","0/1","1/1"],["3/1","0/1","60/1","0/1","1/1"]],)"
            R"("next":[[-1.0,0.0,-60.0,0.0,1.0],[3.0,0.0,60.0,0.0,1.0]],)"
            R"("next_hex":[["-0x1p+0","0x0p+0","-0x1.ep+5","0x0p+0","0x1p+0"],["0x1.8p+1","0x0p+0","0x1.ep+5","0x0p+0","0x1p+0"]],)"
            R"("next_hash":")" + fnv1a(next) + R"("})");
  // A scene case names its file and step.
  with_source.scene = "a \"quoted\" name.json";
  with_source.step = 2;
  EXPECT_TRUE(format_vector(0, with_source).starts_with(R"({"case":0,"source":{"scene":"a \"quoted\" name.json","step":2},)"));
}

TEST(vectors, a_world_whose_next_position_leaves_the_double_range_has_no_vector) {
  EXPECT_FALSE(make_vector({{1.7976931348623157e308, 0, 1e308, 0, 1}}));
  EXPECT_FALSE(make_vector({{0, -1.7976931348623157e308, 0, -1e308, 1}}));
  EXPECT_TRUE(make_vector({{1.7976931348623157e308, 0, -1e308, 0, 1}}));
}

TEST(vectors, the_example_in_vectors_md_is_the_vector_of_its_input) {
  // The first ```json block of docs/vectors.md, pretty-printed: every field but "case" and "source" must be
  // what make_vector gives for its input, and the whole of it the line of the default vectors it says it is.
  const std::string doc = bytes_of(root / "docs" / "vectors.md");
  const std::size_t open = doc.find("```json\n"), close = doc.find("```\n", open + 8);
  ASSERT_NE(open, std::string::npos);
  ASSERT_NE(close, std::string::npos);
  const json example = json::parse(doc.substr(open + 8, close - open - 8));
  const std::optional<Vector> v = make_vector(doubles(example["input"]));
  ASSERT_TRUE(v);
  Vector with_source = *v;
  with_source.seed = example["source"]["seed"];
  with_source.case_index = example["source"]["case"];
  EXPECT_EQ(json::parse(format_vector(example["case"], with_source)), example);
  const std::size_t line = example["case"];
  ASSERT_LT(line, default_cases().size());
  EXPECT_EQ(default_cases()[line], example);
}

TEST(vectors, a_seed_gives_the_same_file_on_every_run_and_another_seed_another) {
  TempDir a, b, c;
  VectorsOptions one = options_in(a, 40);
  one.scene_steps = 0;  // the generated cases alone
  write_vectors(one);
  one.out = b.path.string();
  write_vectors(one);
  VectorsOptions other = one;
  other.out = c.path.string();
  other.seed = 2;
  write_vectors(other);
  EXPECT_EQ(bytes_of(a.path / kVectorsFile), bytes_of(b.path / kVectorsFile));
  EXPECT_NE(bytes_of(a.path / kVectorsFile), bytes_of(c.path / kVectorsFile));
}

TEST(vectors, the_file_is_replaced_whole_and_nothing_else_is_left_beside_it) {
  TempDir dir;
  std::ofstream(dir.path / kVectorsFile) << "an older file\n";
  const VectorsSummary s = write_vectors(options_in(dir, 10));
  EXPECT_EQ(dir.files(), std::vector<std::string>{kVectorsFile});
  EXPECT_EQ(cases_in(dir.path / kVectorsFile).size(), s.written);
  // No bundled scene overflows in its first worlds, so every skipped case is a generated one.
  EXPECT_EQ(s.written - s.scene_cases + s.skipped, 10u) << "every generated case is written or skipped";
}

TEST(vectors, an_output_directory_that_cannot_be_made_is_refused_and_nothing_is_written) {
  TempDir dir;
  const fs::path file = dir.path / "a file";
  std::ofstream(file) << "in the way\n";
  VectorsOptions o = options_in(dir, 5);
  o.out = file.string();
  std::ostringstream out, err;
  EXPECT_EQ(vectors_command(o, out, err), 2);
  EXPECT_EQ(err.str(), "circles vectors: " + file.string() + ": cannot create the output directory: a file of that "
                                                             "name is in the way\n");
  EXPECT_EQ(dir.files(), std::vector<std::string>{"a file"});
  EXPECT_EQ(out.str(), "");
}

TEST(vectors, a_missing_scenes_directory_is_refused_naming_it) {
  TempDir dir;
  VectorsOptions o = options_in(dir, 5);
  o.out = (dir.path / "out").string();
  o.scenes = (dir.path / "no scenes").string();
  std::ostringstream out, err;
  EXPECT_EQ(vectors_command(o, out, err), 2);
  EXPECT_EQ(err.str(), "circles vectors: " + o.scenes + ": cannot read the scenes directory: No such file or "
                                                        "directory (the bundled scenes are scenes/ in the repository: "
                                                        "run from its root or give --scenes DIR)\n");
  EXPECT_TRUE(dir.files().empty());
}

TEST(vectors, a_bad_scene_is_refused_naming_its_file) {
  TempDir dir, scenes;
  std::ofstream(scenes.path / "bad.json") << R"({"circles": [[0, 0, 0, 0, -1]]})";
  VectorsOptions o = options_in(dir, 5);
  o.scenes = scenes.path.string();
  std::ostringstream out, err;
  EXPECT_EQ(vectors_command(o, out, err), 2);
  EXPECT_TRUE(err.str().starts_with("circles vectors: " + (scenes.path / "bad.json").string() + ": ")) << err.str();
  EXPECT_TRUE(dir.files().empty());
}

}  // namespace
}  // namespace circles::cli
