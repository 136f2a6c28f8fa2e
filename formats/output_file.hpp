// Output files of the suite (a trace, PNG frames, a video, reports, pictures, vectors, counterexamples): each
// goes where its path points, and never destroys what the path names.
//
// What a path names decides how it is written (OutputFile::kind):
//   - "-": the program's standard output, written in place;
//   - a path that does not exist yet, or a regular file: written under a temporary name beside it and renamed
//     over it when complete, so that a reader never sees a half-written file and a failed run leaves none (an
//     existing file keeps its permissions);
//   - a symbolic link, followed to what it leads to (to any depth, dangling or not): a regular or missing target
//     is written in the target's own directory and renamed over the target, so that the link stays a link;
//   - a FIFO, a device or a socket (/dev/null, /dev/stdout on a pipe, >(gzip > t.gz) as /dev/fd/63): opened
//     and written in place, as a shell's redirection would, since renaming over it would replace the node;
//   - the program's own standard output or error, under any name (/dev/stdout with stdout a file): written in
//     place through it, so that the bytes land where that stream's own writes land;
//   - a directory: refused.
// A file written in place cannot be taken back: a failure leaves what was written so far.
//
// On SIGINT, SIGTERM or SIGHUP a command ends through remove_temporary_files(), so that an interrupted run leaves
// no temporary file behind either (cli/interrupt.hpp).
#pragma once

#include <sys/types.h>

#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

namespace circles::formats {

// An output that cannot be written: what() names the file and the reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether `path` is the program's standard output: "-", or a name of the file, pipe or terminal that stdout is
// (/dev/stdout, /dev/fd/1, the file stdout was redirected to). A command whose output goes there prints its
// summary on stderr instead, so that the output stays whole.
bool is_standard_output(const std::string& path);
// Whether any of `paths` (empty for an output not asked for) is the standard output.
bool any_is_standard_output(std::initializer_list<std::string> paths);
// How a summary names the output `path`: "standard output" for "-", else the path.
std::string output_name(const std::string& path);

// The file `path` being written. `what` opens every message: with what = "trace t.jsonl", "trace t.jsonl:
// cannot create t.jsonl.partial-Xy12ab: No such file or directory".
//
// Renamed into place (Kind::renamed): the bytes go to TARGET.partial-XXXXXX (mkostemp) in the target's directory,
// so that the final rename is atomic; commit() renames it over the target. Until then the target is untouched,
// and an OutputFile dropped without commit() removes its temporary file. In place (Kind::in_place): the bytes go
// to the path itself; commit() flushes and closes.
class OutputFile {
 public:
  enum class Kind { renamed, in_place };

  OutputFile(std::string path, std::string what);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile() { discard(); }

  Kind kind() const noexcept { return temp_.empty() ? Kind::in_place : Kind::renamed; }
  // The temporary file's name (for a program that writes it by name, after close()); "" in place.
  const std::string& temp_path() const noexcept { return temp_; }
  // The open stream, or nullptr after close().
  std::FILE* file() const noexcept { return file_; }
  // The program writing the temporary file by name (ffmpeg), if any: an interrupt stops it before removing the
  // file. 0 once it has exited.
  void written_by(pid_t pid) noexcept;

  void write(std::string_view bytes);
  // Closes the stream, reporting a failed flush; the temporary file stays until commit() or destruction.
  void close();
  // close() if still open, then the rename into place.
  void commit();
  // Throws OutputError("WHAT: cannot write to TEMP: <strerror(errno)>"), naming where the bytes go: the
  // temporary file, the path written in place, or "standard output".
  [[noreturn]] void fail_write() const;

 private:
  void open_renamed(const std::string& target, mode_t mode);
  void open_in_place(int fd);
  void discard() noexcept;

  std::string what_, target_, temp_, written_;  // written_: where the bytes go, for messages
  std::FILE* file_ = nullptr;
  int slot_ = -1;  // this file's entry among those remove_temporary_files() removes
};

// How an OutputFile would write `path`, decided without creating anything (for a writer that must know first:
// a video made in place is an MP4 that needs no seeking). Throws OutputError as OutputFile does.
OutputFile::Kind output_kind(const std::string& path);

// Writes `text` to `path` whole or not at all, through an OutputFile: the one way the suite writes a file it
// holds in memory (reports, corpus files, pictures, vectors). Throws OutputError, its message opened by `what`.
void write_file(const std::string& path, const std::string& what, std::string_view text);

// Stops the programs writing temporary files (SIGKILL, then waits for them) and removes every temporary file
// of an OutputFile not yet committed or dropped. Async-signal-safe: for a signal handler that ends the program.
void remove_temporary_files() noexcept;

}  // namespace circles::formats
