#include "formats/input_file.hpp"

#include <ext/stdio_filebuf.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace circles::formats {
namespace {

// The standard input as a stream of its own: a copy of descriptor 0 read through a filebuf, fast where
// std::cin (synchronised with C's stdio) reads a character at a time, and seekable where the input is a file.
class StandardInput : public std::istream {
 public:
  explicit StandardInput(int fd) : std::istream(nullptr), buffer_(fd, std::ios::in | std::ios::binary) { rdbuf(&buffer_); }

 private:
  __gnu_cxx::stdio_filebuf<char> buffer_;
};

}  // namespace

std::string input_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

std::unique_ptr<std::istream> open_input(const std::string& path) {
  if (path == "-") {
    const int fd = dup(STDIN_FILENO);
    if (fd < 0) throw InputError(std::string("cannot read the standard input: ") + std::strerror(errno));
    return std::make_unique<StandardInput>(fd);
  }
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw InputError("cannot read the file: it is a directory");
  errno = 0;
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw InputError(std::string("cannot open the file: ") + (errno ? std::strerror(errno) : "open failed"));
  return file;
}

std::string read_input(const std::string& path) {
  const std::unique_ptr<std::istream> in = open_input(path);
  std::string text;
  char piece[1 << 16];
  errno = 0;
  while (in->read(piece, sizeof piece) || in->gcount() > 0) text.append(piece, static_cast<std::size_t>(in->gcount()));
  // The end of the input sets failbit; a read that fails sets badbit.
  if (in->bad()) throw InputError(std::string("cannot read the file: ") + (errno ? std::strerror(errno) : "read error"));
  return text;
}

}  // namespace circles::formats
