// What `circles` says for a command line it cannot parse, in the voice of its other errors: one line, "circles
// COMMAND: what is wrong", naming the option and what it takes (cli/options.hpp), with the nearest command or
// option for a misspelt one. CLI11 raises the errors; its failure-message hook (App::failure_message) calls
// usage_error, which words each kind of error from the parser's state rather than from CLI11's text.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace circles::cli {

// The name among `known` nearest to `word` by edit distance (insertions, deletions, substitutions and swaps of
// two neighbours), if it is at most 2 edits away and fewer edits than `word` has characters; else "".
std::string nearest(std::string_view word, const std::vector<std::string>& known);

// "circles", "circles conform", "circles report merge": the command `app` is.
std::string command_of(const CLI::App& app);

// The message, one line, for `error`, thrown by `app`.parse (neither --help nor --version):
//   circles: unknown command `rn`: did you mean `run`?
//   circles conform: unknown option `--step`: did you mean `--steps`?
//   circles conform: unexpected argument `x`; `circles conform --help` lists what it takes
//   circles conform: --seed: "abc" is not a whole number from 0 to 18446744073709551615
//   circles conform: --seed needs a value: N, a whole number from 0 to 18446744073709551615
//   circles check-trace: TRACE is missing: a trace file to read, or - for stdin
//   circles report: COMMAND is missing: merge
//   circles run: --coverage goes with --random, which is not given
//   circles run: SCENE and --random exclude each other: give one
//   circles run: --fit takes no value: give it alone
//   circles run: --steps is given 2 times: give it once
// An unknown command or option without a near name ends by naming the --help that lists what there is.
std::string usage_error(const CLI::App& app, const CLI::ParseError& error);

}  // namespace circles::cli
