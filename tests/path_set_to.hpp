// For tests of programs found on PATH (ffmpeg, pictures/video.hpp): PATH set to a value for one test, then
// restored, and a script written with its execute bits.
#pragma once

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace circles::testing {

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
  PathSetTo(const PathSetTo&) = delete;
  PathSetTo& operator=(const PathSetTo&) = delete;
};

inline void write_executable(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
  chmod(file.c_str(), 0755);
}

}  // namespace circles::testing
