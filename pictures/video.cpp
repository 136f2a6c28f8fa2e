#include "pictures/video.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

extern char** environ;

namespace circles::pictures {

using formats::output_kind;

std::string find_on_path(std::string_view name) {
  const char* path = std::getenv("PATH");
  const std::string_view dirs = path ? path : "/bin:/usr/bin";
  for (std::size_t begin = 0;;) {
    const std::size_t end = std::min(dirs.find(':', begin), dirs.size());
    const std::string_view dir = dirs.substr(begin, end - begin);
    // An empty entry is the current directory, as for execvp.
    const std::string file = (dir.empty() ? std::string(".") : std::string(dir)) + "/" + std::string(name);
    struct stat st;
    if (stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(file.c_str(), X_OK) == 0) return file;
    if (end == dirs.size()) return "";
    begin = end + 1;
  }
}

Video::Video(std::string path) : path_(std::move(path)) {
  const bool in_place = output_kind(path_) == OutputFile::Kind::in_place;
  if (!in_place && !path_.ends_with(".mp4"))
    throw VideoError("--video " + path_ + ": the video is H.264 in MP4, so its name must end in .mp4");
  const std::string ffmpeg = find_on_path("ffmpeg");
  if (ffmpeg.empty()) throw VideoError("--video needs ffmpeg, which is not installed (apt-get install ffmpeg)");
  file_.emplace(path_, "video " + path_);
  // A file renamed into place is written by ffmpeg by name, and seekable: the index goes first (+faststart).
  // A pipe or a device is ffmpeg's standard output, which cannot seek: a fragmented MP4, its index in pieces.
  if (!in_place) file_->close();

  std::signal(SIGPIPE, SIG_IGN);  // a write to a stopped ffmpeg fails with EPIPE, which add() reports
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw VideoError("video " + path_ + ": cannot create a pipe: " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  if (in_place) posix_spawn_file_actions_adddup2(&actions, fileno(file_->file()), STDOUT_FILENO);
  else posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;  // SIGPIPE back to its default in ffmpeg
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  const std::string size = std::to_string(kFrameWidth) + "x" + std::to_string(kFrameHeight);
  const std::string rate = std::to_string(kVideoFrameRate);
  std::vector<std::string> args{ffmpeg, "-hide_banner", "-nostats", "-loglevel", "error",
                                "-f", "rawvideo", "-pixel_format", "bgr0", "-video_size", size, "-framerate", rate,
                                "-i", "pipe:0", "-an", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                                "-movflags", in_place ? "frag_keyframe+empty_moov" : "+faststart", "-f", "mp4", "-y",
                                in_place ? "pipe:1" : file_->temp_path()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int spawned = posix_spawn(&pid_, ffmpeg.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(fds[0]);
  pipe_ = fds[1];
  if (spawned != 0) {
    pid_ = -1;
    close(std::exchange(pipe_, -1));
    throw VideoError("video " + path_ + ": cannot start " + ffmpeg + ": " + std::strerror(spawned));
  }
  file_->written_by(pid_);
}

Video::~Video() { stop(); }

void Video::stop() noexcept {
  if (pipe_ >= 0) close(std::exchange(pipe_, -1));
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    int status;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    if (file_) file_->written_by(0);
  }
}

std::string Video::wait() {
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0)
    if (errno != EINTR) return std::string("cannot be waited for: ") + std::strerror(errno);
  pid_ = -1;
  file_->written_by(0);
  if (WIFEXITED(status))
    return WEXITSTATUS(status) == 0 ? "" : "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "was killed by signal " + std::to_string(WTERMSIG(status));
  return "stopped";
}

void Video::add(const Frame& frame) {
  const unsigned char* bytes = frame.data();
  std::size_t left = Frame::kStride * kFrameHeight;
  while (left > 0) {
    const ssize_t n = ::write(pipe_, bytes, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::string reason = std::strerror(errno);
      close(std::exchange(pipe_, -1));
      const std::string status = wait();
      throw VideoError("video " + path_ + ": ffmpeg stopped reading frames (" + reason + "; ffmpeg " +
                       (status.empty() ? "exited with status 0" : status) + "); its messages, if any, are above");
    }
    bytes += n;
    left -= static_cast<std::size_t>(n);
  }
  ++frames_;
}

void Video::commit() {
  close(std::exchange(pipe_, -1));
  if (const std::string status = wait(); !status.empty())
    throw VideoError("video " + path_ + ": ffmpeg " + status + "; its messages, if any, are above");
  file_->commit();
}

}  // namespace circles::pictures
