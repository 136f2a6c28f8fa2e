// The picture of a counterexample (pictures/counterexample_svg.hpp): every circle inside the page from the
// subnormals to DBL_MAX, one line per contact, the expected and answered positions dashed.
#include "pictures/counterexample_svg.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <regex>
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

}  // namespace
}  // namespace circles::pictures
