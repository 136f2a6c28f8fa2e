// Rendering r (pictures/render.hpp): where circles land in the frame and in which colour, the contacts ringed, the
// view --fit chooses, and frames named and written as PNG and read back. `circles run`'s frames and video are
// cli_run_pictures_test.cpp's.
#include "pictures/render.hpp"

#include "impl/predicate.hpp"
#include "tests/temp_dir.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace circles::pictures {

std::ostream& operator<<(std::ostream& out, const Colour& c) {
  return out << "rgb(" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ")";
}

namespace {

using circles::testing::TempDir;

// Whether each channel of `c` lies strictly between those of `a` and `b` (or equals them where they agree):
// a blend, as anti-aliasing gives a pixel the edge crosses.
bool strictly_between(Colour c, Colour a, Colour b) {
  const auto between = [](int x, int p, int q) { return p == q ? x == p : x > std::min(p, q) && x < std::max(p, q); };
  return between(c.r, a.r, b.r) && between(c.g, a.g, b.g) && between(c.b, a.b, b.b) && c != a && c != b;
}

TEST(render, fills_each_circle_with_its_colour_on_the_background) {
  Frame frame;
  frame.draw({{100, 100, 0, 0, 20}, {640, 600, 5, 5, 30}, {1200, 300, 0, 0, 10}}, View::pixels());
  EXPECT_EQ(frame.pixel(100, 100), fill_colour(0));
  EXPECT_EQ(frame.pixel(640, 600), fill_colour(1));
  EXPECT_EQ(frame.pixel(1200, 300), fill_colour(2));
  EXPECT_NE(fill_colour(0), fill_colour(1));
  EXPECT_NE(fill_colour(0), kBackground);
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {1279, 719}, {640, 360}, {125, 100}, {100, 125}})
    EXPECT_EQ(frame.pixel(x, y), kBackground) << x << ", " << y;
}

// y points down: a circle at y = 100 is near the top row, not 100 rows above the bottom (row 619).
TEST(render, puts_the_origin_at_the_top_left_with_y_down_and_one_pixel_a_unit) {
  Frame frame;
  frame.draw({{300.5, 100.5, 0, 0, 3}}, View::pixels());
  EXPECT_EQ(frame.pixel(300, 100), fill_colour(0));
  EXPECT_EQ(frame.pixel(300, 619), kBackground);
  // Pixel (x, y) is the square [x, x + 1] × [y, y + 1]: pixel 304 begins 3.5 from the centre, beyond r = 3.
  EXPECT_EQ(frame.pixel(304, 100), kBackground);
  EXPECT_EQ(frame.pixel(296, 100), kBackground);
  EXPECT_EQ(frame.pixel(300, 104), kBackground);
  EXPECT_EQ(frame.pixel(302, 100), fill_colour(0));  // [302, 303] is within 2.5 of the centre
}

// The circle's right edge x = 120.5 cuts pixel (120, 100), [120, 121] × [100, 101], nearly in half.
TEST(render, anti_aliases_the_edge_of_a_circle) {
  Frame frame;
  frame.draw({{100, 100.5, 0, 0, 20.5}}, View::pixels());
  EXPECT_EQ(frame.pixel(119, 100), fill_colour(0));
  EXPECT_EQ(frame.pixel(121, 100), kBackground);
  EXPECT_TRUE(strictly_between(frame.pixel(120, 100), fill_colour(0), kBackground)) << frame.pixel(120, 100);
}

TEST(render, draws_a_point_or_a_circle_thinner_than_a_pixel_as_a_dot) {
  Frame frame;
  frame.draw({{10.5, 10.5, 0, 0, 0}, {20.5, 10.5, 0, 0, 1e-9}}, View::pixels());
  EXPECT_NE(frame.pixel(10, 10), kBackground);
  EXPECT_NE(frame.pixel(20, 10), kBackground);
  EXPECT_EQ(frame.pixel(12, 10), kBackground);
}

// Circles whose top edge is the line y = 460 through the frame: of radius 10^9 (its centre far beyond Cairo's
// 2^23: drawn as a half-plane) and 2·10^6 (just under the 2^21 where that starts: drawn as a disc, its edge
// 640²/(2 · 2·10^6) ≈ 0.1 pixel lower at the sides); then one that covers the frame, and two far away.
TEST(render, draws_circles_beyond_cairos_range_by_where_they_meet_the_frame) {
  Frame frame;
  for (const double r : {1e9, 2e6}) {
    frame.draw({{640, 460 + r, 0, 0, r}}, View::pixels());
    EXPECT_EQ(frame.pixel(640, 461), fill_colour(0)) << r;
    EXPECT_EQ(frame.pixel(640, 458), kBackground) << r;
    EXPECT_EQ(frame.pixel(2, 461), fill_colour(0)) << r;
    EXPECT_EQ(frame.pixel(1277, 458), kBackground) << r;
    EXPECT_EQ(frame.pixel(640, 719), fill_colour(0)) << r;
    EXPECT_EQ(frame.pixel(0, 0), kBackground) << r;
  }

  frame.draw({{-5e307, 1e308, 0, 0, 1.7e308}}, View::pixels());
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {1279, 0}, {0, 719}, {1279, 719}, {640, 360}})
    EXPECT_EQ(frame.pixel(x, y), fill_colour(0)) << x << ", " << y;

  frame.draw({{1e300, -1e300, 0, 0, 1e299}, {-1.7976931348623157e308, 0, 0, 0, 1}}, View::pixels());
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {1279, 0}, {0, 719}, {1279, 719}, {640, 360}})
    EXPECT_EQ(frame.pixel(x, y), kBackground) << x << ", " << y;
}

// Circles 0 and 1 touch at (350, 360); circle 2 misses circle 3 by 1.
TEST(render, rings_the_circles_in_contact) {
  Frame frame;
  frame.draw({{300, 360, 0, 0, 50}, {400, 360, 0, 0, 50}, {800, 360, 0, 0, 50}, {901, 360, 0, 0, 50}}, View::pixels());
  EXPECT_EQ(frame.pixel(349, 360), kContactOutline);
  EXPECT_EQ(frame.pixel(350, 360), kContactOutline);
  EXPECT_EQ(frame.pixel(300, 310), kContactOutline);  // the top of circle 0's ring: 49 to 51 from its centre
  EXPECT_EQ(frame.pixel(300, 360), fill_colour(0));
  EXPECT_EQ(frame.pixel(848, 360), fill_colour(2));
  EXPECT_EQ(frame.pixel(852, 360), fill_colour(3));
}

// A 3 × 3 lattice of touching circles of radius 1.5 pixels, as --fit draws scenes/dense.json's radius-5 circles
// at a scale of 0.3: each ring is a quarter of the radius wide (1.31 to 1.69 from the centre), so the pixel at
// each centre keeps the circle's fill and most of the cluster is fill, not ring; a 2-pixel ring (0.5 to 2.5)
// would whiten it whole.
TEST(render, scales_the_ring_of_a_small_circle_with_its_radius_so_that_its_fill_shows) {
  EXPECT_EQ(contact_width(1.5), 0.375);
  EXPECT_EQ(contact_width(8), kContactWidth);
  EXPECT_EQ(contact_width(50), kContactWidth);
  Circles lattice;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) lattice.push_back({100.5 + 3 * i, 100.5 + 3 * j, 0, 0, 1.5});
  Frame frame;
  frame.draw(lattice, View::pixels());
  for (std::size_t k = 0; k < lattice.size(); ++k)
    EXPECT_EQ(frame.pixel(static_cast<int>(lattice[k][0]), static_cast<int>(lattice[k][1])), fill_colour(k)) << k;
  int drawn = 0, white = 0;  // white: every channel at 0xd0 or more, which no fill colour has
  for (int x = 95; x < 112; ++x)
    for (int y = 95; y < 112; ++y) {
      const Colour c = frame.pixel(x, y);
      drawn += c != kBackground;
      white += c.r >= 0xd0 && c.g >= 0xd0 && c.b >= 0xd0;
    }
  EXPECT_GE(drawn, 49);
  EXPECT_LT(4 * white, drawn) << white << " of " << drawn << " pixels are ring";
  Frame alone;  // the rings still show: circle 0 without its neighbours is drawn otherwise
  alone.draw({lattice[0]}, View::pixels());
  EXPECT_NE(alone.pixel(101, 100), frame.pixel(101, 100));
}

TEST(contacts, marks_circles_at_a_distance_of_exactly_the_sum_of_their_radii) {
  EXPECT_EQ(contacts({{0, 0, 0, 0, 1}, {2, 0, 0, 0, 1}, {10, 10, 0, 0, 1}}), (std::vector<unsigned char>{1, 1, 0}));
  EXPECT_EQ(contacts({{0, 0, 0, 0, 1}, {std::nextafter(2.0, 3.0), 0, 0, 0, 1}}), (std::vector<unsigned char>{0, 0}));
  // 3-4-5: the pair touches exactly on a diagonal.
  EXPECT_EQ(contacts({{0, 0, 0, 0, 2}, {3, 4, 0, 0, 3}}), (std::vector<unsigned char>{1, 1}));
  EXPECT_EQ(contacts({}), std::vector<unsigned char>{});
}

// The sweep against every pair, on worlds of small integers and half-integers, where contacts and exact
// tangencies are frequent.
RC_GTEST_PROP(contacts, equal_the_exact_test_of_every_pair, ()) {
  const auto coordinate = rc::gen::map(rc::gen::inRange(-20, 21), [](int k) { return k / 2.0; });
  const auto circle = rc::gen::apply(
      [](double x, double y, double r) { return spec::CircleDoubles{x, y, 0, 0, r}; }, coordinate, coordinate,
      rc::gen::map(rc::gen::inRange(0, 8), [](int k) { return k / 2.0; }));
  const Circles w = *rc::gen::container<Circles>(circle);
  std::vector<unsigned char> want(w.size(), 0);
  for (std::size_t a = 0; a < w.size(); ++a)
    for (std::size_t b = 0; b < w.size(); ++b)
      if (a != b && impl::intersect_exact(w[a][0], w[a][1], w[a][4], w[b][0], w[b][1], w[b][4])) want[a] = 1;
  RC_ASSERT(contacts(w) == want);
}

TEST(fit, gives_world_units_as_pixels_for_no_circles_and_centres_a_single_point) {
  EXPECT_EQ(View::fit(Box{}).scale, 1);
  Box point;
  point.add({{1e6, -3e6, 0, 0, 0}});
  const View v = View::fit(point);
  EXPECT_EQ(v.scale, 1);
  EXPECT_EQ(v.cx, 1e6);
  EXPECT_EQ(v.cy, -3e6);
}

// Two circles of radius 10^4 at x = 5·10^5 and 1.5·10^6, 3·10^6 above the origin: the box is 1.02·10^6 by
// 2·10^4, so the width decides, scale = (1280 − 2·16) / 1.02·10^6, and each circle is 10^4 · scale ≈ 12.2
// pixels across, its centre 16 + 12.2 pixels from the left or right side, on the middle row.
TEST(fit, frames_a_far_away_scene_inside_the_frame) {
  const Circles w{{5e5, -3e6, 0, 0, 1e4}, {1.5e6, -3e6, 0, 0, 1e4}};
  Box box;
  box.add(w);
  const View view = View::fit(box);
  EXPECT_NEAR(static_cast<double>(view.scale), 1248 / 1.02e6, 1e-15);
  Frame frame;
  frame.draw(w, view);
  EXPECT_EQ(frame.pixel(28, 360), fill_colour(0));
  EXPECT_EQ(frame.pixel(1251, 360), fill_colour(1));
  EXPECT_EQ(frame.pixel(640, 360), kBackground);
  EXPECT_EQ(frame.pixel(28, 345), kBackground);  // 15 pixels above the centre: beyond 12.2
  EXPECT_EQ(frame.pixel(10, 360), kBackground);  // within the margin
  EXPECT_EQ(frame.pixel(1270, 360), kBackground);
  frame.draw(w, View::pixels());
  EXPECT_EQ(frame.pixel(28, 360), kBackground);  // without --fit the scene is far off the frame
}

TEST(frames, are_named_by_their_step_with_six_digits_at_least) {
  EXPECT_EQ(frame_name(0), "frame-000000.png");
  EXPECT_EQ(frame_name(42), "frame-000042.png");
  EXPECT_EQ(frame_name(1234567), "frame-1234567.png");
  EXPECT_EQ(frame_path("out/frames", 3), "out/frames/frame-000003.png");
}

TEST(frames, read_back_from_png_with_the_pixels_drawn) {
  TempDir dir;
  Frame frame;
  frame.draw({{100, 100, 0, 0, 20}, {300.5, 200, 0, 0, 7.25}}, View::pixels());
  const std::string file = (dir.path / "f.png").string();
  frame.write_png(file, "frame " + file);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"f.png"});
  const Frame back = Frame::read_png(file);
  for (int y = 0; y < kFrameHeight; ++y)
    for (int x = 0; x < kFrameWidth; ++x) ASSERT_EQ(back.pixel(x, y), frame.pixel(x, y)) << x << ", " << y;
}

}  // namespace
}  // namespace circles::pictures
