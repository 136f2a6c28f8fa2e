// `circles run --video FILE.mp4`: the frames piped to ffmpeg as raw video and encoded as H.264 in MP4.
//
// ffmpeg is not a dependency of the build (it is large, and only this option needs it): it is looked for on
// PATH when --video is given, and a run without it stops before its first step with exit 2 and
//   circles: --video needs ffmpeg, which is not installed (apt-get install ffmpeg)
// The command (docs/run.md): ffmpeg -hide_banner -nostats -loglevel error -f rawvideo -pixel_format bgr0
// -video_size 1280x720 -framerate 60 -i pipe:0 -an -c:v libx264 -pix_fmt yuv420p -movflags +faststart -f mp4
// -y FILE.partial-XXXXXX. ffmpeg writes the temporary file; commit() renames it to FILE once ffmpeg has
// exited with status 0, and a video dropped without commit() stops ffmpeg and removes the file. A video that
// goes to a pipe or a device ("-" for stdout, a FIFO, /dev/null: formats/output_file.hpp), which cannot seek,
// is a fragmented MP4 on ffmpeg's standard output: -movflags frag_keyframe+empty_moov -f mp4 -y pipe:1; its
// name need not end in .mp4.
#pragma once

#include "formats/output_file.hpp"
#include "pictures/render.hpp"

#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace circles::pictures {

using formats::OutputError;
using formats::OutputFile;

// A video that cannot be made: no ffmpeg, a name that is not .mp4, or ffmpeg failing.
class VideoError : public OutputError {
 public:
  using OutputError::OutputError;
};

// The path of the first executable file `name` in the directories of PATH (PATH unset: /bin:/usr/bin, as
// execvp does), or "" when there is none.
std::string find_on_path(std::string_view name);

// Frames per second: a video of every step plays at the seed's own pace, Δt = 1/60 s a step; with --every K,
// K times as fast.
inline constexpr int kVideoFrameRate = 60;

class Video {
 public:
  // Refuses a file name without the .mp4 extension and a machine without ffmpeg (VideoError, before anything
  // is created), then creates FILE.partial-XXXXXX beside FILE or opens the pipe or device (OutputError when it
  // cannot) and starts ffmpeg.
  explicit Video(std::string path);
  Video(const Video&) = delete;
  Video& operator=(const Video&) = delete;
  ~Video();

  // One frame more. Throws VideoError when ffmpeg has stopped.
  void add(const Frame& frame);
  // Ends the input, waits for ffmpeg and renames its output to FILE. Throws VideoError when ffmpeg fails.
  void commit();
  std::uint64_t frames() const noexcept { return frames_; }

 private:
  // Waits for ffmpeg: "exited with status 1", "was killed by signal 9", or "" for status 0.
  std::string wait();
  void stop() noexcept;

  std::string path_;
  std::optional<OutputFile> file_;
  pid_t pid_ = -1;
  int pipe_ = -1;  // ffmpeg's standard input
  std::uint64_t frames_ = 0;
};

}  // namespace circles::pictures
