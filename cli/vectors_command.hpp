// `circles vectors --out DIR`: golden test vectors for implementations in other languages (docs/vectors.md),
// made by conform/vectors.hpp, each written as formats/vectors.hpp says.
#pragma once

#include "conform/vectors.hpp"

#include <CLI/CLI.hpp>

#include <ostream>

namespace circles::cli {

// Declares the command and its options on `app`.
CLI::App* add_vectors_command(CLI::App& app, conform::VectorsOptions& options);

// The command: writes the vectors and a summary on `out`; 0 when written, 2 with the reason on `err`
// otherwise.
int vectors_command(const conform::VectorsOptions& options, std::ostream& out, std::ostream& err);

}  // namespace circles::cli
