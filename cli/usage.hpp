// What `circles` says for a command line it cannot parse: CLI11's error, as the program's other errors read,
// "circles COMMAND: what is wrong", with the nearest command or option for a misspelt one.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace circles::cli {

// The name among `known` nearest to `word` by edit distance (insertions, deletions, substitutions and swaps of
// two neighbours), if it is at most 2 edits away and fewer edits than `word` has characters; else "".
std::string nearest(std::string_view word, const std::vector<std::string>& known);

// The message, one line, for `error`, thrown by `app`.parse (neither --help nor --version): "circles: unknown
// command `rn`: did you mean `run`?", "circles conform: unknown option `--step`: did you mean `--steps`?",
// "circles conform: unexpected argument `x`", or for any other error CLI11's own text after "circles COMMAND: ";
// each without a suggestion ends by naming the --help that lists what there is.
std::string usage_error(const CLI::App& app, const CLI::ParseError& error);

}  // namespace circles::cli
