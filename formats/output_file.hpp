// Output files of `circles run` (the trace, PNG frames, the video) written under a temporary name beside the
// target and renamed into place when complete: a reader never sees a half-written file, and a failed run
// leaves none behind.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace circles::formats {

// An output that cannot be written: what() names the file and the reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The file `path` being written. The bytes go to PATH.partial-XXXXXX (mkstemp) in the same directory, so that
// the final rename is atomic; commit() renames it to `path`. Until then `path` is untouched, and an
// OutputFile dropped without commit() removes its temporary file. `what` opens every message: with what =
// "trace t.jsonl", "trace t.jsonl: cannot create t.jsonl.partial-Xy12ab: No such file or directory".
class OutputFile {
 public:
  OutputFile(std::string path, std::string what);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile() { discard(); }

  // The temporary file's name (for a program that writes it by name, after close()).
  const std::string& temp_path() const noexcept { return temp_; }
  // The open stream, or nullptr after close().
  std::FILE* file() const noexcept { return file_; }

  void write(std::string_view bytes);
  // Closes the stream, reporting a failed flush; the temporary file stays until commit() or destruction.
  void close();
  // close() if still open, then the rename into place.
  void commit();
  // Throws OutputError("WHAT: cannot write to TEMP: <strerror(errno)>").
  [[noreturn]] void fail_write() const;

 private:
  void discard() noexcept;

  std::string path_, what_, temp_;
  std::FILE* file_ = nullptr;
};

// Writes `text` to `path` whole or not at all, through an OutputFile: the one way the suite writes a file it
// holds in memory (reports, corpus files, pictures, vectors). Throws OutputError, its message opened by `what`.
void write_file(const std::string& path, const std::string& what, std::string_view text);

}  // namespace circles::formats
