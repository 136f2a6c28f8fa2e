// Programs found on PATH as execvp finds them (pictures/video.hpp, find_on_path), which is how `circles run --video`
// finds ffmpeg; the video itself is cli_run_pictures_test.cpp's.
#include "pictures/video.hpp"

#include "tests/path_set_to.hpp"
#include "tests/temp_dir.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace circles::pictures {
namespace {

using circles::testing::PathSetTo;
using circles::testing::TempDir;
using circles::testing::write_executable;

TEST(video, finds_programs_on_path_as_execvp_does) {
  TempDir dir;
  write_executable(dir.path / "tool", "#!/bin/sh\n");
  std::ofstream(dir.path / "data") << "no x bit";
  const PathSetTo path("/nonexistent:" + dir.path.string());
  EXPECT_EQ(find_on_path("tool"), (dir.path / "tool").string());
  EXPECT_EQ(find_on_path("data"), "");
  EXPECT_EQ(find_on_path("ffmpeg"), "");
}

}  // namespace
}  // namespace circles::pictures
