// `circles families`: the boundary families a profile draws from, one a line, in the order a round checks them;
// a big family (worlds of hundreds to thousands of circles) marked "(big)". `circles conform --families` with
// no list prints the same.
#pragma once

#include "properties/boundaries.hpp"

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>

namespace circles::cli {

struct FamiliesCommandOptions {
  std::string profile = "resolved";  // --profile NAME
};

// Declares the command and its options on `app`.
CLI::App* add_families_command(CLI::App& app, FamiliesCommandOptions& options);

// The families of `profile` on `out`: "lattice", ..., "sizes (big)", ...
void print_family_list(properties::Profile profile, std::ostream& out);

}  // namespace circles::cli
