// The command that replays a counterexample, a whole line to paste into a shell: `circles conform`, the option
// that selects the candidate (Candidate::option: `--exec '…'` or `--engine NAME`) and every option that changes
// which worlds are asked or how their answers are judged. Each report of a counterexample carries it: the
// printed `replay:` line, the `--keep-going` rows, the JSON report's "replay" and the JUnit failure text.
#pragma once

#include "conform/conform.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace circles::conform {

// `word` as one word for sh: as it is when it holds only letters, digits and _ - . / : , = + @ %, else in single
// quotes, each ' written '\''. "" is ''.
std::string shell_quoted(std::string_view word);

// "circles conform CANDIDATE --seed S --case I [--circles N] --level L [--steps K] [--profile literal] [--max-circles N]
// [--families A,B,...]" for generated case `case_index` of options.seed; for a counterexample stored in the corpus (no case index),
// "circles conform CANDIDATE --save DIR --cases 0 --level L ...", which replays the corpus alone. `candidate`
// is Candidate::option(), left out when empty (a candidate no command line selects). Families left out by
// Options::skip are named as the shorter of --families and --skip-families.
// A case of a budget run's ladder (`circles`, its world's size) is replayed with --circles N; a budget run's
// other cases need no --max-circles, which only the big families' worlds read.
std::string replay_command(std::string_view candidate, const Options& options, std::optional<std::uint64_t> case_index,
                           std::optional<std::size_t> circles = std::nullopt);

// "circles conform CANDIDATE --seed S --level L [--cases N] [--shard I/N] [--save DIR] [--keep-going] ...": the
// command that checks the same cases as a run of `options` again, for a run that a signal interrupted.
std::string rerun_command(std::string_view candidate, const Options& options);

}  // namespace circles::conform
