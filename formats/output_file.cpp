#include "formats/output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace circles::formats {

namespace {

std::string system_error(const std::string& what) { return what + ": " + std::strerror(errno); }

}  // namespace

OutputFile::OutputFile(std::string path, std::string what)
    : path_(std::move(path)), what_(std::move(what)), temp_(path_ + ".partial-XXXXXX") {
  const int fd = mkstemp(temp_.data());
  if (fd < 0) {
    const std::string reason = system_error(what_ + ": cannot create " + temp_);
    temp_.clear();
    throw OutputError(reason);
  }
  // mkstemp makes the file private (0600); an output is an ordinary file, so give it the mode a plain fopen
  // would: 0666 less the umask (which can only be read by setting it).
  const mode_t mask = umask(0);
  umask(mask);
  file_ = fdopen(fd, "w");
  if (!file_ || fchmod(fd, 0666 & ~mask) != 0) {
    const std::string reason = system_error(what_ + ": cannot open " + temp_);
    if (!file_) ::close(fd);
    discard();
    throw OutputError(reason);
  }
}

void OutputFile::fail_write() const { throw OutputError(system_error(what_ + ": cannot write to " + temp_)); }

void OutputFile::write(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail_write();
}

void OutputFile::close() {
  if (std::FILE* f = std::exchange(file_, nullptr); f && std::fclose(f) != 0) fail_write();
}

void OutputFile::commit() {
  close();
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    throw OutputError(system_error(what_ + ": cannot rename " + temp_ + " to it"));
  temp_.clear();
}

void write_file(const std::string& path, const std::string& what, std::string_view text) {
  OutputFile file(path, what);
  file.write(text);
  file.commit();
}

void OutputFile::discard() noexcept {
  if (file_) std::fclose(std::exchange(file_, nullptr));
  if (!temp_.empty()) std::remove(temp_.c_str());
  temp_.clear();
}

}  // namespace circles::formats
