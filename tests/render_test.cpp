// Rendering r and the pictures of `circles run` (pictures/render.hpp, pictures/video.hpp): where circles land in the
// frame and in which colour, --fit, the frames --render writes, and --video with and without ffmpeg.
#include "pictures/render.hpp"
#include "cli/run.hpp"
#include "pictures/video.hpp"

#include "impl/predicate.hpp"
#include "tests/step_worlds.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

namespace circles::pictures {

std::ostream& operator<<(std::ostream& out, const Colour& c) {
  return out << "rgb(" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ")";
}

}  // namespace circles::pictures

namespace circles::cli {

using namespace circles::pictures;

namespace {

using engines::engine;

using circles::testing::thrown;

using circles::testing::TempDir;

// PATH set to `value` for one test, then restored.
struct PathSetTo {
  std::string saved;
  bool had;
  explicit PathSetTo(const std::string& value) {
    const char* old = std::getenv("PATH");
    had = old != nullptr;
    if (had) saved = old;
    setenv("PATH", value.c_str(), 1);
  }
  ~PathSetTo() {
    if (had) setenv("PATH", saved.c_str(), 1);
    else unsetenv("PATH");
  }
};

void write_executable(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
  chmod(file.c_str(), 0755);
}

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

RunOptions pictures(std::uint64_t steps, std::uint64_t every, std::string render, std::string video = "") {
  RunOptions o;
  o.steps = steps;
  o.engine = &engine("double");
  o.threads = 1;
  o.render = std::move(render);
  o.every = every;
  o.video = std::move(video);
  return o;
}

// One circle moving 60 pixels a step (v = 3600, v/60 exact) from x = 100.5: w_t has it at 100.5 + 60t.
const Circles kMoving{{100.5, 360.5, 3600, 0, 10}};

TEST(frames, writes_every_kth_world_from_w_0_and_not_the_last_unless_it_is_a_multiple) {
  TempDir dir;
  const RunResult result = run(kMoving, pictures(10, 3, (dir.path / "frames").string()));
  EXPECT_EQ(result.steps, 10u);
  EXPECT_EQ(result.frames, 4u);
  EXPECT_EQ(dir.files("frames"), (std::vector<std::string>{"frame-000000.png", "frame-000003.png",
                                                           "frame-000006.png", "frame-000009.png"}));
  for (const std::uint64_t t : {0, 3, 6, 9}) {
    const Frame f = Frame::read_png((dir.path / "frames" / frame_name(t)).string());
    const int x = 100 + 60 * static_cast<int>(t);
    EXPECT_EQ(f.pixel(x, 360), fill_colour(0)) << "w_" << t;
    EXPECT_EQ(f.pixel(x - 30, 360), kBackground) << "w_" << t;
    EXPECT_EQ(f.pixel(x + 30, 360), kBackground) << "w_" << t;
  }
}

TEST(frames, creates_the_directory_and_its_parents) {
  TempDir dir;
  run(kMoving, pictures(2, 1, (dir.path / "a" / "b").string()));
  EXPECT_EQ(dir.files("a/b"), (std::vector<std::string>{"frame-000000.png", "frame-000001.png", "frame-000002.png"}));
}

// From x = 0 at 100 a step for 10 steps, with frames of w_0 and w_10 only: the box of both frames is
// [−10, 1010] × [−10, 10], so scale = 1248/1020 and the circle is at 640 ∓ 500 · scale ≈ 28.2 and 1251.8. A fit
// of w_0 alone would leave w_10 off the frame.
TEST(frames, fit_holds_the_circles_of_every_frame_of_the_run) {
  TempDir dir;
  RunOptions options = pictures(10, 10, dir.path.string());
  options.fit = true;
  const RunResult result = run({{0, 0, 6000, 0, 10}}, options);
  EXPECT_EQ(result.frames, 2u);
  const Frame first = Frame::read_png((dir.path / frame_name(0)).string());
  const Frame last = Frame::read_png((dir.path / frame_name(10)).string());
  EXPECT_EQ(first.pixel(28, 360), fill_colour(0));
  EXPECT_EQ(first.pixel(1251, 360), kBackground);
  EXPECT_EQ(last.pixel(1251, 360), fill_colour(0));
  EXPECT_EQ(last.pixel(28, 360), kBackground);
  EXPECT_EQ(last.pixel(640, 360), kBackground);
}

TEST(frames, a_directory_that_cannot_be_made_is_named_and_nothing_is_written) {
  TempDir dir;
  std::ofstream(dir.path / "file") << "not a directory";
  const std::string frames = (dir.path / "file" / "frames").string();
  RunOptions options = pictures(3, 1, frames);
  options.trace = (dir.path / "t.jsonl").string();
  const auto e = thrown<OutputError>([&] { run(kMoving, options); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "render directory " + frames + ": cannot create it: Not a directory");
  EXPECT_EQ(dir.files(), std::vector<std::string>{"file"}) << "the trace or a frame was left behind";
}

// body() run by a process to which permissions apply: this one, or, when it runs as root (CI does), which writes
// in any directory, a child that drops its supplementary groups and becomes uid and gid 65534 (nobody) first.
// What body() returns comes back through a pipe; std::nullopt when the child could not become nobody.
std::optional<std::string> without_root(const std::function<std::string()>& body) {
  if (geteuid() != 0) return body();
  constexpr uid_t kNobody = 65534;
  int out[2];
  if (pipe(out) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  const pid_t child = fork();
  if (child < 0) throw std::system_error(errno, std::generic_category(), "fork");
  if (child == 0) {
    close(out[0]);
    if (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0) _exit(3);
    const std::string said = body();
    const bool whole = write(out[1], said.data(), said.size()) == static_cast<ssize_t>(said.size());
    _exit(whole ? 0 : 4);  // _exit: no atexit handlers or leak check of the parent's state in the child
  }
  close(out[1]);
  std::string said;
  char buffer[256];
  for (ssize_t n; (n = read(out[0], buffer, sizeof buffer)) > 0;) said.append(buffer, static_cast<std::size_t>(n));
  close(out[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 3) return std::nullopt;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw std::runtime_error("the unprivileged child failed");
  return said;
}

TEST(frames, a_directory_without_write_permission_is_named_and_nothing_is_written) {
  TempDir dir;
  const std::filesystem::path frames = dir.path / "frames";
  std::filesystem::create_directory(frames);
  std::filesystem::permissions(frames, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  if (geteuid() == 0) {  // nobody owns both, so the owner's bits are the ones that apply to it
    for (const auto& owned : {dir.path, frames}) ASSERT_EQ(chown(owned.c_str(), 65534, 65534), 0) << owned;
  }
  const std::optional<std::string> said = without_root([&] {
    try {
      run(kMoving, pictures(3, 1, frames.string()));
    } catch (const OutputError& e) {
      return std::string(e.what());
    }
    return std::string("nothing was thrown");
  });
  if (!said) GTEST_SKIP() << "running as root, and a child could not become nobody to test a permission";
  EXPECT_EQ(*said, "render directory " + frames.string() + ": cannot write in it: Permission denied");
  EXPECT_TRUE(dir.files("frames").empty());
}

TEST(frames, after_an_overflow_are_kept_up_to_the_last_finite_world) {
  TempDir dir;
  // Circle 1 reaches DBL_MAX in w_3 and overflows at step 4 (tests/step_worlds.hpp derives it).
  const RunResult result = run(circles::testing::kOverflowsAtStep4, pictures(10, 2, dir.path.string()));
  EXPECT_EQ(result.steps, 3u);
  ASSERT_TRUE(result.overflow);
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"frame-000000.png", "frame-000002.png"}));
}

TEST(video, finds_programs_on_path_as_execvp_does) {
  TempDir dir;
  write_executable(dir.path / "tool", "#!/bin/sh\n");
  std::ofstream(dir.path / "data") << "no x bit";
  const PathSetTo path("/nonexistent:" + dir.path.string());
  EXPECT_EQ(find_on_path("tool"), (dir.path / "tool").string());
  EXPECT_EQ(find_on_path("data"), "");
  EXPECT_EQ(find_on_path("ffmpeg"), "");
}

TEST(video, without_ffmpeg_stops_before_the_first_step_with_the_install_command_and_writes_nothing) {
  TempDir dir, empty;
  const PathSetTo path(empty.path.string());
  RunOptions options = pictures(3, 1, (dir.path / "frames").string(), (dir.path / "v.mp4").string());
  options.trace = (dir.path / "t.jsonl").string();
  const auto e = thrown<VideoError>([&] { run(kMoving, options); });
  ASSERT_TRUE(e);
  EXPECT_STREQ(e->what(), "--video needs ffmpeg, which is not installed (apt-get install ffmpeg)");
  EXPECT_TRUE(dir.files().empty());
}

TEST(video, refuses_a_name_that_does_not_end_in_mp4) {
  TempDir dir;
  const std::string file = (dir.path / "v.webm").string();
  const auto e = thrown<VideoError>([&] { run(kMoving, pictures(3, 1, "", file)); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "--video " + file + ": the video is H.264 in MP4, so its name must end in .mp4");
  EXPECT_TRUE(dir.files().empty());
}

// A stand-in for ffmpeg that exits at once: the first frame (3.7 MB, more than a pipe holds) finds the pipe
// closed.
TEST(video, reports_an_ffmpeg_that_stops_early_and_leaves_no_file) {
  TempDir dir, bin;
  write_executable(bin.path / "ffmpeg", "#!/bin/sh\nexit 1\n");
  const PathSetTo path(bin.path.string());
  const std::string file = (dir.path / "v.mp4").string();
  const auto e = thrown<VideoError>([&] { run(kMoving, pictures(3, 1, "", file)); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "video " + file + ": ffmpeg stopped reading frames (Broken pipe; ffmpeg exited with "
                                    "status 1); its messages, if any, are above");
  EXPECT_TRUE(dir.files().empty());
}

// A stand-in that reads every frame, then fails.
TEST(video, reports_an_ffmpeg_that_fails_at_the_end_and_leaves_no_file) {
  TempDir dir, bin;
  write_executable(bin.path / "ffmpeg", "#!/bin/sh\ncat >/dev/null\nexit 3\n");
  const PathSetTo path(bin.path.string() + ":/bin:/usr/bin");
  const std::string file = (dir.path / "v.mp4").string();
  const auto e = thrown<VideoError>([&] { run(kMoving, pictures(3, 1, "", file)); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "video " + file + ": ffmpeg exited with status 3; its messages, if any, are above");
  EXPECT_TRUE(dir.files().empty());
}

// The output of `command`, run by the shell.
std::string output_of(const std::string& command) {
  std::string out;
  std::FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, p)) > 0;) out.append(buffer, n);
  pclose(p);
  return out;
}

// The real ffmpeg: 30 steps, a frame every 3 steps, so 11 frames of 1280×720. The first frame decoded again
// has circle 0's colour at its centre, to within what H.264 and 4:2:0 chroma lose: a swap of red and blue (a
// wrong pixel format) would be off by 89 in each.
TEST(video, writes_an_mp4_of_every_kth_frame_with_ffmpeg) {
  if (find_on_path("ffmpeg").empty() || find_on_path("ffprobe").empty())
    GTEST_SKIP() << "ffmpeg is not installed (apt-get install ffmpeg), so the real video path is not tested here; "
                    "its absence is (video.without_ffmpeg_stops_before_the_first_step_with_the_install_command_and_"
                    "writes_nothing)";
  TempDir dir;
  const std::string file = (dir.path / "v.mp4").string();
  const Circles w{{640, 360, 0, 0, 100}, {100.5, 100, 3600, 0, 10}};
  const RunResult result = run(w, pictures(30, 3, "", file));
  EXPECT_EQ(result.frames, 11u);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"v.mp4"});
  EXPECT_EQ(output_of("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                      "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" + file + "'"),
            "h264,1280,720,11\n");
  const std::string pixels =
      output_of("ffmpeg -v error -i '" + file + "' -frames:v 1 -f rawvideo -pix_fmt rgb24 -");
  ASSERT_EQ(pixels.size(), 3u * kFrameWidth * kFrameHeight);
  const std::size_t centre = 3 * (360 * kFrameWidth + 640);
  const Colour got{static_cast<std::uint8_t>(pixels[centre]), static_cast<std::uint8_t>(pixels[centre + 1]),
                   static_cast<std::uint8_t>(pixels[centre + 2])};
  const Colour want = fill_colour(0);
  EXPECT_NEAR(got.r, want.r, 8) << got;
  EXPECT_NEAR(got.g, want.g, 8) << got;
  EXPECT_NEAR(got.b, want.b, 8) << got;
}

}  // namespace
}  // namespace circles::cli
