// The reports of `circles conform --report` (conform/report.hpp) of the shards of one run, each read back into a
// verdict and merged into one by conform's rule for a verdict (checked_outcome): `circles report merge`, which
// writes it in every format of conform/report_formats.hpp.
#pragma once

#include "conform/report.hpp"

#include <string>
#include <vector>

namespace circles::conform {

// The reports of shards of one run (the same candidate, seed, level, profile, steps and shard count, each
// shard once), as one verdict: cases, skipped and per-family counts add up; the verdict is cannot check if any
// is (with the first such report's error), else checked_outcome's: does not conform if it has a counterexample,
// the one found first (found_before: the lowest case index, a stored counterexample lowest of all), or if a
// family failed or passed unexpectedly; a family's status is the first of failed, expected failure, unexpected
// pass, passed, not reached, skipped that it has in any shard, and its counterexample the one found first.
// Throws ReportError. `names` name the texts in messages.
Report merged_report(const std::vector<std::string>& texts, const std::vector<std::string>& names);

}  // namespace circles::conform
