// The picture of a counterexample (pictures/counterexample_svg.hpp): every circle inside the page from the
// subnormals to DBL_MAX, y pointing down as in run's frames, one line per contact, the expected and answered
// positions dashed and, where they coincide, labelled; the report as text (searchable, with a title), wrapped
// inside the page; labels that would overprint listed with leader lines; and a zoomed inset where the deciding
// pair is closer to touching than a point.
#include "pictures/counterexample_svg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace circles::pictures {
namespace {

using properties::Profile;

// An element of the document: its name, its attributes, and its text up to the next tag.
struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  double number(const std::string& attribute) const { return std::stod(attributes.at(attribute)); }
};

std::vector<Element> elements_of(const std::string& svg) {
  std::vector<Element> out;
  static const std::regex tag(R"(<([a-zA-Z]+)((?:\s+[\w:-]+="[^"]*")*)\s*/?>([^<]*))");
  static const std::regex attribute(R"re(([\w:-]+)="([^"]*)")re");
  for (std::sregex_iterator t(svg.begin(), svg.end(), tag), end; t != end; ++t) {
    Element e{(*t)[1], {}, (*t)[3]};
    const std::string attributes = (*t)[2];
    for (std::sregex_iterator a(attributes.begin(), attributes.end(), attribute); a != end; ++a)
      e.attributes[(*a)[1]] = (*a)[2];
    out.push_back(e);
  }
  return out;
}

std::vector<Element> named(const std::string& svg, const std::string& name) {
  std::vector<Element> out;
  for (const Element& e : elements_of(svg))
    if (e.name == name) out.push_back(e);
  return out;
}

// Every coordinate the document draws with: positions, radii, sizes and polyline points.
std::vector<double> coordinates_in(const std::string& svg) {
  std::vector<double> xs;
  static const std::regex number(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf)");
  for (const Element& e : elements_of(svg))
    for (const auto& [name, value] : e.attributes)
      if (std::set<std::string>{"cx", "cy", "r", "x", "y", "x1", "y1", "x2", "y2", "points", "width", "height"}.contains(name) &&
          e.name != "svg")
        for (std::sregex_iterator n(value.begin(), value.end(), number), end; n != end; ++n)
          xs.push_back(std::stod(n->str()));
  return xs;
}

// The circle elements that carry a circle's tooltip, by circle: "#3: (px, py, vx, vy, r) = (...)".
std::map<std::size_t, Element> world_circles(const std::string& svg) {
  std::map<std::size_t, Element> out;
  static const std::regex tooltip(R"re(<circle([^>]*)><title>#(\d+): )re");
  for (std::sregex_iterator t(svg.begin(), svg.end(), tooltip), end; t != end; ++t)
    out[std::stoul((*t)[2])] = elements_of("<circle" + (*t)[1].str() + "/>").front();
  return out;
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
    EXPECT_EQ(world_circles(svg).size(), w.size());
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
  // The bystanders, far outside the frame, are not drawn; the circles that decide are.
  const std::map<std::size_t, Element> drawn = world_circles(counterexample_svg({w, w, actual, 0, Profile::resolved, {}}));
  EXPECT_EQ(drawn.size(), 3u);
  EXPECT_TRUE(drawn.contains(0) && drawn.contains(1) && drawn.contains(19));
}

TEST(counterexample_svg, points_y_down_as_run_frames_do_and_marks_the_axes) {
  // Circle 1 lies 10 units below circle 0 in y: in the picture it is lower, as in `circles run`'s frames.
  const Circles w{{0, 0, 0, 0, 1}, {3, 10, 0, 0, 1}};
  const std::string svg = counterexample_svg({w, w, w, 0, Profile::resolved, {}});
  const std::map<std::size_t, Element> circles = world_circles(svg);
  EXPECT_GT(circles.at(1).number("cy"), circles.at(0).number("cy"));
  EXPECT_GT(circles.at(1).number("cx"), circles.at(0).number("cx"));
  std::set<std::string> words;
  for (const Element& t : named(svg, "text")) words.insert(t.text);
  EXPECT_TRUE(words.contains("x") && words.contains("y"));
}

TEST(counterexample_svg, draws_one_line_for_each_contact_and_the_expected_and_answered_positions_dashed) {
  // Contacts are orange: one line for each touching pair, and one in the legend.
  const auto contact_lines = [](const Circles& w) {
    std::size_t lines = 0;
    for (const Element& e : named(counterexample_svg({w, w, w, 0, Profile::resolved, {}}), "line"))
      lines += e.attributes.at("stroke") == "#f28c1a";
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

// The head lines of `circles conform --seed 3 --exec 'python3 examples/python/step_naive.py'`.
const std::vector<std::string> kNaiveLines = {
    "circles conform: the program `python3 examples/python/step_naive.py` does not conform (level exact, resolved "
    "profile)",
    "counterexample: case 3 of seed 3 (family ulp-nudge), shrunk from 2 to 1 circle in 2014 tries",
    "  step 1 of 1, circle 0, field px: expected 0.023966666666666667 (0x1.88ab7c61c2039p-6), got "
    "0.023966666666666664 (0x1.88ab7c61c2038p-6)",
    "  which decision: none: the velocity is right, the position is not the nearest double"};

TEST(counterexample_svg, writes_the_report_as_text_with_a_title) {
  const Circles w{{0, 0, 1.438, 0, 0}};
  const std::string svg = counterexample_svg({w, w, w, 0, Profile::resolved, kNaiveLines});
  // The words are characters of <text> elements, which a viewer searches and copies, not glyph outlines.
  EXPECT_EQ(svg.find("glyph"), std::string::npos);
  EXPECT_TRUE(named(svg, "path").empty());
  std::string text;
  for (const Element& t : named(svg, "text")) text += t.text + "\n";
  EXPECT_NE(text.find("counterexample: case 3 of seed 3 (family ulp-nudge)"), std::string::npos) << text;
  EXPECT_NE(text.find("which decision: none: the velocity is right"), std::string::npos) << text;
  // The title is the report's first line, escaped for XML; the description holds every line.
  const std::vector<Element> titles = named(svg, "title");
  ASSERT_FALSE(titles.empty());
  EXPECT_EQ(titles.front().text, "circles conform: the program `python3 examples/python/step_naive.py` does not "
                                 "conform (level exact, resolved profile)");
  EXPECT_NE(named(svg, "desc").at(0).text.find("shrunk from 2 to 1 circle"), std::string::npos);
  EXPECT_NE(counterexample_svg({w, w, w, 0, Profile::resolved, {"a < b & c"}}).find("<title>a &lt; b &amp; c</title>"),
            std::string::npos);
}

TEST(counterexample_svg, wraps_each_line_of_text_to_end_inside_the_picture) {
  const Circles w{{0, 0, 1.438, 0, 0}};
  Circles expected = w, actual = w;
  expected[0][0] = 0.023966666666666667;
  actual[0][0] = 0.023966666666666664;
  for (const std::size_t n : {4, 12}) {
    std::vector<std::string> lines = kNaiveLines;
    while (lines.size() < n) lines.push_back(kNaiveLines[2]);
    const std::string svg = counterexample_svg({w, expected, actual, 0, Profile::resolved, lines});
    std::size_t texts = 0;
    // DejaVu Sans Mono at 11 points advances 0.602 × 11 = 6.62 points a character; the text keeps a margin of 10.
    for (const Element& t : named(svg, "text")) {
      ASSERT_LE(t.number("x") + 6.63 * static_cast<double>(t.text.size()), 890.01) << t.text;
      ++texts;
    }
    EXPECT_GT(texts, n + 6);
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
  std::map<std::string, std::string> by_colour;
  for (const Element& t : named(counterexample_svg(close), "text")) by_colour[t.attributes.at("fill")] += t.text;
  EXPECT_EQ(by_colour["#1a991a"], "expected (0.023966666666666667, 0.0)");
  EXPECT_EQ(by_colour["#cc1a1a"], "answered (0.023966666666666664, 0.0)");
  // Apart in the picture, the markers need no label.
  actual[0][0] = -1;
  const CounterexamplePicture apart{w, expected, actual, 0, Profile::resolved, {}};
  EXPECT_TRUE(position_labels(apart).empty());
  for (const Element& t : named(counterexample_svg(apart), "text"))
    EXPECT_TRUE(t.attributes.at("fill") != "#1a991a" && t.attributes.at("fill") != "#cc1a1a") << t.text;
}

TEST(counterexample_svg, lists_the_labels_of_coinciding_circles_with_leader_lines) {
  // Circles 0, 1 and 3 share a centre (a duplicate and a point), circle 2 lies apart: 0, 1 and 3 go to the list.
  const Circles w{{0, 0, 0, 0, 1}, {0, 0, 0, 0, 1}, {5, 0, 0, 0, 1}, {1e-9, 0, 0, 0, 0}};
  const CounterexamplePicture picture{w, w, w, 0, Profile::resolved, {}};
  EXPECT_EQ(listed_labels(picture), (std::vector<std::size_t>{0, 1, 3}));
  const std::string svg = counterexample_svg(picture);
  const std::map<std::size_t, Element> circles = world_circles(svg);
  const double cx = circles.at(0).number("cx"), cy = circles.at(0).number("cy");
  std::map<std::string, Element> labels;
  for (const Element& t : named(svg, "text")) labels[t.text] = t;
  // The listed labels stand one under another at the list's left edge, each line's leader ending at the centre.
  ASSERT_TRUE(labels.contains("#0") && labels.contains("#1") && labels.contains("#3"));
  EXPECT_EQ(labels["#0"].number("x"), labels["#1"].number("x"));
  EXPECT_GE(labels["#1"].number("y") - labels["#0"].number("y"), 12);
  std::size_t leaders = 0;
  for (const Element& l : named(svg, "line"))
    leaders += std::fabs(l.number("x2") - cx) < 0.01 && std::fabs(l.number("y2") - cy) < 0.01 &&
               l.number("x1") < labels["#0"].number("x") + 60;
  EXPECT_EQ(leaders, 3u);
  // Circle 2's label stays beside its centre.
  EXPECT_NEAR(labels["#2"].number("x"), circles.at(2).number("cx") + 4, 0.01);
  // Apart by more than a label's height, no label is listed.
  EXPECT_TRUE(listed_labels({{{0, 0, 0, 0, 1}, {3, 0, 0, 0, 1}}, w, w, 0, Profile::resolved, {}}).empty());
}

// The inset's two edges: the polylines inside the inset's clip group.
std::vector<std::vector<std::array<double, 2>>> inset_edges(const std::string& svg) {
  std::vector<std::vector<std::array<double, 2>>> edges;
  const std::size_t begin = svg.rfind("<g clip-path=");
  const std::size_t end = svg.find("</g>", begin);
  if (begin == std::string::npos || end == std::string::npos) return edges;
  for (const Element& e : named(svg.substr(begin, end - begin), "polyline")) {
    std::vector<std::array<double, 2>> points;
    const std::string text = e.attributes.at("points");
    static const std::regex point(R"(([-\d.]+),([-\d.]+))");
    for (std::sregex_iterator p(text.begin(), text.end(), point), stop; p != stop; ++p)
      points.push_back({std::stod((*p)[1]), std::stod((*p)[2])});
    edges.push_back(points);
  }
  return edges;
}

double closest(const std::vector<std::array<double, 2>>& a, const std::vector<std::array<double, 2>>& b) {
  double least = INFINITY;
  for (const auto& p : a)
    for (const auto& q : b) least = std::min(least, std::hypot(p[0] - q[0], p[1] - q[1]));
  return least;
}

TEST(counterexample_svg, zooms_into_a_deciding_pair_closer_to_touching_than_a_point) {
  // Circles 0 and 1 are 2 ulps of 2 apart, a gap of 8.9e-16 that no picture shows; circle 0 took circle 1's
  // velocity as if they touched.
  const double beyond = std::nextafter(std::nextafter(2.0, 3.0), 3.0);
  const Circles w{{0, 0, 0, 0, 1}, {beyond, 0, 60, 0, 1}};
  Circles actual = w;
  actual[0][2] = 60;
  const CounterexamplePicture apart{w, w, actual, 0, Profile::resolved, {}};
  const std::optional<ZoomedPair> z = zoomed_pair(apart);
  ASSERT_TRUE(z);
  EXPECT_EQ(z->a, 0u);
  EXPECT_EQ(z->b, 1u);
  EXPECT_FALSE(z->touch);
  EXPECT_NEAR(static_cast<double>(z->gap), beyond - 2, 1e-20);
  const std::string svg = counterexample_svg(apart);
  EXPECT_NE(svg.find("#0 and #1: apart by (3)"), std::string::npos);
  // In the inset the gap spans a quarter of its 220 points: the two edges 55 points apart.
  const auto edges = inset_edges(svg);
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_NEAR(closest(edges[0], edges[1]), 55, 3);
  // Exactly tangent: they touch, and the inset shows the edges meeting.
  const Circles tangent{{0, 0, 0, 0, 1}, {2, 0, 60, 0, 1}};
  Circles kept = tangent;  // circle 0 kept its velocity: the least contact, circle 1, decides
  const std::optional<ZoomedPair> t = zoomed_pair({tangent, tangent, kept, 0, Profile::resolved, {}});
  ASSERT_TRUE(t);
  EXPECT_TRUE(t->touch);
  EXPECT_EQ(t->gap, 0);
  const auto met = inset_edges(counterexample_svg({tangent, tangent, kept, 0, Profile::resolved, {}}));
  ASSERT_EQ(met.size(), 2u);
  EXPECT_LT(closest(met[0], met[1]), 1);
  // A gap the picture shows (half a unit, tens of points) needs no inset.
  const Circles wide{{0, 0, 0, 0, 1}, {2.5, 0, 60, 0, 1}};
  Circles took = wide;
  took[0][2] = 60;
  EXPECT_FALSE(zoomed_pair({wide, wide, took, 0, Profile::resolved, {}}));
  EXPECT_EQ(counterexample_svg({wide, wide, took, 0, Profile::resolved, {}}).find("by (3)"), std::string::npos);
}

}  // namespace
}  // namespace circles::pictures
