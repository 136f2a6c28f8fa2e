// The reports of `circles conform --report` (conform/report.hpp lists their keys) of the shards of one run, merged
// into one by the rules of a verdict: `circles report merge`.
#pragma once

#include "conform/report.hpp"

#include <string>
#include <vector>

namespace circles::conform {

// The reports of shards of one run (the same candidate, seed, level, profile, steps and shard count, each
// shard once), as one: cases, skipped and per-family counts add up; the verdict is "cannot check" if any is,
// else "does not conform" if any has a counterexample, the one of the lowest case index (a stored
// counterexample, replayed before any case, lowest of all), or if a family failed or passed unexpectedly; a
// family's status is the first of failed, expected failure, unexpected pass, passed, not reached, skipped that
// it has in any shard. Throws ReportError. `names` name the texts in messages.
std::string merge_reports(const std::vector<std::string>& texts, const std::vector<std::string>& names);

}  // namespace circles::conform
