// Input files of the suite (a scene, a trace, an expectation file, the reports to merge): "-" is the standard
// input, any other path a file.
#pragma once

#include <istream>
#include <memory>
#include <stdexcept>
#include <string>

namespace circles::formats {

// An input that cannot be opened: what() is the reason alone ("cannot open the file: No such file or
// directory", "cannot read the file: it is a directory"), for the reader's own error to put after the name.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How messages name the input `path`: "<stdin>" for "-", else the path.
std::string input_name(const std::string& path);

// The input `path` opened for reading in binary: the standard input (descriptor 0, through a buffer of its own)
// for "-", else the file. A directory, which opens on Linux and reads as empty, is refused. Throws InputError.
std::unique_ptr<std::istream> open_input(const std::string& path);

// The whole text of the input `path`, as open_input opens it. Throws InputError, also for a read that fails
// ("cannot read the file: Input/output error").
std::string read_input(const std::string& path);

}  // namespace circles::formats
