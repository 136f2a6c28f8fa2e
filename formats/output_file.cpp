#include "formats/output_file.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <utility>

namespace circles::formats {

namespace {

std::string system_error(const std::string& what) { return what + ": " + std::strerror(errno); }

// The temporary files that remove_temporary_files() removes: a fixed table, so that a signal handler reads it
// without allocating. A slot is free (0), being filled (1) or holds a file (2); a path longer than PATH_MAX
// is not listed (mkstemp makes such a file only through a relative path, and it is then removed on exit as
// before, though not on a signal).
struct Pending {
  std::atomic<int> state{0};
  std::atomic<pid_t> writer{0};
  char path[PATH_MAX];
};
std::array<Pending, 32> pending;

int list_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int k = 0; k < static_cast<int>(pending.size()); ++k) {
    int free = 0;
    if (!pending[k].state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(pending[k].path, path.c_str(), path.size() + 1);
    pending[k].writer = 0;
    pending[k].state = 2;
    return k;
  }
  return -1;
}

void unlist_temporary(int& slot) {
  if (slot >= 0) pending[slot].state = 0;
  slot = -1;
}

// SIGINT, SIGTERM and SIGHUP held back while a temporary file is made and listed, so that an interrupt finds
// every file that exists in the list.
class InterruptsHeld {
 public:
  InterruptsHeld() {
    sigset_t held;
    sigemptyset(&held);
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held, s);
    pthread_sigmask(SIG_BLOCK, &held, &before_);
  }
  ~InterruptsHeld() { pthread_sigmask(SIG_SETMASK, &before_, nullptr); }
  InterruptsHeld(const InterruptsHeld&) = delete;
  InterruptsHeld& operator=(const InterruptsHeld&) = delete;

 private:
  sigset_t before_;
};

bool same_file(const struct stat& a, int fd) {
  struct stat b;
  return fstat(fd, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// The file a symbolic link leads to, followed link by link (a relative link from its own directory) up to the
// first name that is not a link, whether or not it exists. Throws OutputError after 40 links (the kernel's
// limit, ELOOP).
std::string link_target(std::string path, const std::string& what) {
  for (int links = 0; links < 40; ++links) {
    struct stat st;
    if (lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
    std::string to(PATH_MAX, '\0');
    const ssize_t n = readlink(path.c_str(), to.data(), to.size());
    if (n < 0) throw OutputError(system_error(what + ": cannot read the link " + path));
    to.resize(static_cast<std::size_t>(n));
    const std::size_t slash = path.rfind('/');
    path = to.starts_with('/') || slash == std::string::npos ? to : path.substr(0, slash + 1) + to;
  }
  errno = ELOOP;
  throw OutputError(system_error(what + ": cannot follow " + path));
}

}  // namespace

bool is_standard_output(const std::string& path) {
  struct stat st;
  return path == "-" || (!path.empty() && stat(path.c_str(), &st) == 0 && same_file(st, STDOUT_FILENO));
}

bool any_is_standard_output(std::initializer_list<std::string> paths) {
  for (const std::string& path : paths)
    if (is_standard_output(path)) return true;
  return false;
}

std::string output_name(const std::string& path) { return path == "-" ? "standard output" : path; }

namespace {

// Where the bytes of an output to `path` go, and how (the rules of output_file.hpp), decided without creating
// anything. Throws OutputError for a directory and a path that cannot be looked at.
struct Destination {
  OutputFile::Kind kind = OutputFile::Kind::renamed;
  std::string target{};  // renamed: the file renamed over; in place: the path opened, or "" for `stream`
  mode_t mode = 0;     // renamed: the permissions of the file
  int stream = -1;     // in place: the standard stream written through, or -1
  std::string named{};   // in place: where the bytes go, for messages
  bool truncate = false;
};

mode_t umask_now() {
  const mode_t mask = umask(0);  // it can only be read by setting it
  umask(mask);
  return mask;
}

Destination destination(const std::string& path, const std::string& what) {
  using Kind = OutputFile::Kind;
  if (path == "-") return {.kind = Kind::in_place, .stream = STDOUT_FILENO, .named = "standard output"};
  struct stat st;
  if (stat(path.c_str(), &st) != 0) {
    // Missing, or a dangling link: made where the name (or its last link) points, with the mode a plain fopen
    // would give it, 0666 less the umask. Any other reason the path cannot be looked at (a loop of links, a
    // component that is a file, no permission) is the message.
    if (errno != ENOENT) throw OutputError(system_error(what + ": cannot write " + path));
    return {.kind = Kind::renamed, .target = link_target(path, what), .mode = 0666 & ~umask_now()};
  }
  if (S_ISDIR(st.st_mode)) throw OutputError(what + ": it is a directory");
  if (same_file(st, STDOUT_FILENO)) return {.kind = Kind::in_place, .stream = STDOUT_FILENO, .named = "standard output"};
  if (same_file(st, STDERR_FILENO)) return {.kind = Kind::in_place, .stream = STDERR_FILENO, .named = "standard error"};
  if (!S_ISREG(st.st_mode)) return {.kind = Kind::in_place, .target = path, .named = path};
  // A regular file, renamed over where the links lead, keeping its permissions; unless no name leads there (a
  // link of /proc to a file deleted since), which leaves writing in place.
  const std::string target = link_target(path, what);
  if (struct stat at; stat(target.c_str(), &at) != 0 || at.st_dev != st.st_dev || at.st_ino != st.st_ino)
    return {.kind = Kind::in_place, .target = path, .named = path, .truncate = true};
  return {.kind = Kind::renamed, .target = target, .mode = static_cast<mode_t>(st.st_mode & 07777)};
}

}  // namespace

OutputFile::Kind output_kind(const std::string& path) { return destination(path, path).kind; }

OutputFile::OutputFile(std::string path, std::string what) : what_(std::move(what)) {
  const Destination to = destination(path, what_);
  if (to.kind == Kind::renamed) {
    open_renamed(to.target, to.mode);
    return;
  }
  written_ = to.named;
  open_in_place(to.stream >= 0 ? fcntl(to.stream, F_DUPFD_CLOEXEC, 0)
                               : open(to.target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY | (to.truncate ? O_TRUNC : 0)));
}

void OutputFile::open_renamed(const std::string& target, mode_t mode) {
  target_ = target;
  temp_ = target + ".partial-XXXXXX";
  int fd;
  {
    const InterruptsHeld held;
    fd = mkostemp(temp_.data(), O_CLOEXEC);
    if (fd >= 0) slot_ = list_temporary(temp_);
  }
  if (fd < 0) {
    const std::string reason = system_error(what_ + ": cannot create " + temp_);
    temp_.clear();
    throw OutputError(reason);
  }
  written_ = temp_;
  // mkostemp makes the file private (0600).
  file_ = fdopen(fd, "w");
  if (!file_ || fchmod(fd, mode) != 0) {
    const std::string reason = system_error(what_ + ": cannot open " + temp_);
    if (!file_) ::close(fd);
    discard();
    throw OutputError(reason);
  }
}

void OutputFile::open_in_place(int fd) {
  if (fd < 0 || !(file_ = fdopen(fd, "w"))) {
    const std::string reason = system_error(what_ + ": cannot open " + written_);
    if (fd >= 0) ::close(fd);
    throw OutputError(reason);
  }
}

void OutputFile::written_by(pid_t pid) noexcept {
  if (slot_ >= 0) pending[slot_].writer = pid;
}

void OutputFile::fail_write() const { throw OutputError(system_error(what_ + ": cannot write to " + written_)); }

void OutputFile::write(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail_write();
}

void OutputFile::close() {
  if (std::FILE* f = std::exchange(file_, nullptr); f && std::fclose(f) != 0) fail_write();
}

void OutputFile::commit() {
  close();
  if (kind() == Kind::in_place) return;
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw OutputError(system_error(what_ + ": cannot rename " + temp_ + " to " + target_));
  unlist_temporary(slot_);
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
  unlist_temporary(slot_);
  temp_.clear();
}

void remove_temporary_files() noexcept {
  for (Pending& p : pending) {
    if (p.state != 2) continue;
    if (const pid_t writer = p.writer; writer > 0) {
      kill(writer, SIGKILL);
      while (waitpid(writer, nullptr, 0) < 0 && errno == EINTR) {
      }
    }
    unlink(p.path);
  }
}

}  // namespace circles::formats
