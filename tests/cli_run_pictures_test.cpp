// `circles run`'s pictures in process (cli/run.hpp with --render and --video): the frames of every k-th world,
// their directory, --fit over the whole run, what is left when the directory cannot be written or the run
// overflows, and the video through ffmpeg, without it, and with one that fails.
#include "cli/run.hpp"
#include "engines/registry.hpp"
#include "pictures/render.hpp"
#include "pictures/video.hpp"
#include "tests/path_set_to.hpp"
#include "tests/step_worlds.hpp"
#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace circles::cli {
namespace {

using circles::testing::PathSetTo;
using circles::testing::TempDir;
using circles::testing::thrown;
using circles::testing::write_executable;
using engines::engine;
using formats::OutputError;
using pictures::Colour;
using pictures::fill_colour;
using pictures::find_on_path;
using pictures::Frame;
using pictures::frame_name;
using pictures::kBackground;
using pictures::kFrameHeight;
using pictures::kFrameWidth;
using pictures::VideoError;
using spec::Circles;

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
  const std::string shown = "rgb(" + std::to_string(got.r) + ", " + std::to_string(got.g) + ", " + std::to_string(got.b) + ")";
  EXPECT_NEAR(got.r, want.r, 8) << shown;
  EXPECT_NEAR(got.g, want.g, 8) << shown;
  EXPECT_NEAR(got.b, want.b, 8) << shown;
}

}  // namespace
}  // namespace circles::cli
