// The picture of a counterexample (pictures/counterexample_svg.hpp): every circle inside the page from the
// subnormals to DBL_MAX, one line per contact, the expected and answered positions dashed and, where they
// coincide, labelled, and the text wrapped inside the page.
#include "pictures/counterexample_svg.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace circles::pictures {
namespace {

using properties::Profile;

// Every number in the path data and positions of an SVG document.
std::vector<double> coordinates_in(const std::string& svg) {
  std::vector<double> xs;
  static const std::regex attribute(R"re((?:\sd|\sx|\sy)="([^"]*)")re");
  static const std::regex number(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf)");
  for (std::sregex_iterator a(svg.begin(), svg.end(), attribute), end; a != end; ++a) {
    const std::string text = (*a)[1];
    for (std::sregex_iterator n(text.begin(), text.end(), number); n != end; ++n) xs.push_back(std::stod(n->str()));
  }
  return xs;
}

TEST(counterexample_svg, draws_worlds_from_the_subnormals_to_dbl_max_inside_the_picture) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double huge = std::numeric_limits<double>::max();
  for (const Circles& w : {Circles{{0, 0, 1, 0, 5 * tiny}, {3 * tiny, 4 * tiny, 0, 0, 0}},
                           Circles{{-huge, huge, 0, 0, huge}, {huge, -huge, 0, 0, huge}, {0, 0, 0, 0, 0}},
                           Circles{{1, 1, 0, 0, 0}}}) {
    CounterexamplePicture picture{w, w, w, 0, Profile::resolved, {"a line of text"}};
    picture.actual[0][0] = std::nextafter(w[0][0], 1.0);
    const std::string svg = counterexample_svg(picture);
    EXPECT_TRUE(svg.starts_with("<?xml")) << svg.substr(0, 100);
    EXPECT_NE(svg.find(R"(width="900pt" height="760pt")"), std::string::npos);
    const std::vector<double> xs = coordinates_in(svg);
    EXPECT_GT(xs.size(), 50u);
    for (const double x : xs) {
      ASSERT_TRUE(std::isfinite(x)) << x;
      ASSERT_GE(x, -20) << x;
      ASSERT_LE(x, 920) << x;
    }
  }
}

TEST(counterexample_svg, frames_a_big_world_around_the_circles_that_decide_the_case_and_a_small_one_whole) {
  // Circle 0 touches circle 1 and answered with circle 19's velocity; 17 bystanders lie a million away.
  Circles w{{0, 0, 1, 0, 1}, {1.5, 0, 2, 0, 1}};
  for (int k = 0; k < 17; ++k) w.push_back({1e6 + k, 1e6, 0, 0, 1});
  w.push_back({-3, 0, 7, 7, 0.5});
  Circles actual = w;
  actual[0][2] = 7, actual[0][3] = 7;
  const auto [x0, x1, y0, y1] = framed_box({w, w, actual, 0, Profile::resolved, {}});
  EXPECT_EQ(x0, -3.5L);
  EXPECT_EQ(x1, 2.5L);
  EXPECT_EQ(y0, -1);
  EXPECT_EQ(y1, 1);
  // Eight circles or fewer: the whole world, bystanders too.
  const Circles small(w.begin(), w.begin() + 8);
  EXPECT_EQ(framed_box({small, small, small, 0, Profile::resolved, {}})[1], 1e6L + 5 + 1);
}

TEST(counterexample_svg, draws_one_line_for_each_contact_and_the_expected_and_answered_positions_dashed) {
  // Contacts are orange, rgb(95%, 55%, 10%): one line for each touching pair, and one in the legend.
  const auto contact_lines = [](const Circles& w) {
    const std::string svg = counterexample_svg({w, w, w, 0, Profile::resolved, {}});
    std::size_t lines = 0;
    for (std::size_t at = 0; (at = svg.find("stroke:rgb(95%,55%,10%)", at)) != std::string::npos; ++at) ++lines;
    return lines;
  };
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 1}, {10, 0, 0, 0, 1}}), 1u);
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 1}, {2, 0, 0, 0, 1}}), 2u);  // tangent: (3) holds
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 1}, {std::nextafter(2.0, 3.0), 0, 0, 0, 1}}), 1u);
  EXPECT_EQ(contact_lines({{0, 0, 0, 0, 2}, {1, 0, 0, 0, 2}, {-1, 0, 0, 0, 2}}), 4u);  // three pairs
  const std::string svg = counterexample_svg({{{0, 0, 60, 0, 1}}, {{1, 0, 60, 0, 1}}, {{2, 0, 60, 0, 1}}, 0,
                                              Profile::resolved, {}});
  std::size_t dashed = 0;
  for (std::size_t at = 0; (at = svg.find("stroke-dasharray", at)) != std::string::npos; ++at) ++dashed;
  EXPECT_EQ(dashed, 4u);  // expected and answered, in the picture and in the legend
}

// The x of each glyph of the text, and its colour ("rgb(0%,0%,0%)"): Cairo writes text as <use> elements, a
// glyph each, in groups <g style="fill:COLOUR;...">.
std::vector<std::pair<double, std::string>> glyphs_in(const std::string& svg) {
  std::vector<std::pair<double, std::string>> glyphs;
  static const std::regex group(R"re(<g style="fill:(rgb\([^)]*\));[^"]*">((?:\s*<use [^>]*/>)*))re"),
      use(R"re(<use xlink:href="#glyph[^"]*" x="([^"]*)")re");
  for (std::sregex_iterator g(svg.begin(), svg.end(), group), end; g != end; ++g) {
    const std::string uses = (*g)[2];
    for (std::sregex_iterator u(uses.begin(), uses.end(), use); u != end; ++u)
      glyphs.emplace_back(std::stod((*u)[1]), (*g)[1]);
  }
  return glyphs;
}

// The head lines of `circles conform --seed 3 --exec 'python3 examples/python/step_naive.py'`.
const std::vector<std::string> kNaiveLines = {
    "circles conform: the program `python3 examples/python/step_naive.py` does not conform (level exact, resolved "
    "profile)",
    "counterexample: case 3 of seed 3 (family ulp-nudge), shrunk from 2 to 1 circle in 2014 tries",
    "  step 1 of 1, circle 0, field px: expected 0.023966666666666667 (0x1.88ab7c61c2039p-6), got "
    "0.023966666666666664 (0x1.88ab7c61c2038p-6)",
    "  which decision: none: the velocity is right, the position is not the nearest double"};

TEST(counterexample_svg, wraps_each_line_of_text_to_end_inside_the_picture) {
  const Circles w{{0, 0, 1.438, 0, 0}};
  Circles expected = w, actual = w;
  expected[0][0] = 0.023966666666666667;
  actual[0][0] = 0.023966666666666664;
  for (const std::size_t n : {4, 12}) {
    std::vector<std::string> lines = kNaiveLines;
    while (lines.size() < n) lines.push_back(kNaiveLines[2]);
    const std::string svg = counterexample_svg({w, expected, actual, 0, Profile::resolved, lines});
    const std::vector<std::pair<double, std::string>> glyphs = glyphs_in(svg);
    ASSERT_GT(glyphs.size(), 300u);
    // DejaVu Sans Mono at 11 points advances 6.6 points a glyph; the text keeps a margin of 10.
    for (const auto& [x, colour] : glyphs) ASSERT_LE(x + 6.6, 890.01) << x;
    // Twelve lines, wrapped, need a taller text band: the picture grows rather than drawing over the world.
    if (n == 4) EXPECT_NE(svg.find(R"(width="900pt" height="760pt")"), std::string::npos);
    else EXPECT_EQ(svg.find(R"(height="760pt")"), std::string::npos);
  }
}

TEST(counterexample_svg, labels_the_expected_and_answered_positions_where_their_markers_coincide) {
  const Circles w{{0, 0, 1.438, 0, 0}};
  Circles expected = w, actual = w;
  expected[0][0] = 0.023966666666666667;
  actual[0][0] = 0.023966666666666664;  // one ulp apart: one point at any scale
  const CounterexamplePicture close{w, expected, actual, 0, Profile::resolved, {}};
  EXPECT_EQ(position_labels(close),
            (std::vector<std::string>{"expected (0.023966666666666667, 0.0)", "answered (0.023966666666666664, 0.0)"}));
  // Each label is drawn, in its marker's colour: green for the expected, red for the answered.
  std::set<std::string> colours;
  for (const auto& [x, colour] : glyphs_in(counterexample_svg(close))) colours.insert(colour);
  EXPECT_TRUE(colours.contains("rgb(10%,60%,10%)"));
  EXPECT_TRUE(colours.contains("rgb(80%,10%,10%)"));
  // Apart in the picture, the markers need no label.
  actual[0][0] = -1;
  const CounterexamplePicture apart{w, expected, actual, 0, Profile::resolved, {}};
  EXPECT_TRUE(position_labels(apart).empty());
  for (const auto& [x, colour] : glyphs_in(counterexample_svg(apart))) EXPECT_EQ(colour, "rgb(0%,0%,0%)") << x;
}

}  // namespace
}  // namespace circles::pictures
