// Counterexamples as data files: what `circles conform --save DIR` writes, and replays first on every run.
//
// One JSON object per file, DIR/counterexample-<16 hex digits>.json, the digits a hash of the profile and the
// world, so that the same counterexample found twice is one file:
//   {"format": "circles-counterexample/1",
//    "profile": "resolved",                       the profile the world was checked in
//    "world": [[px, py, vx, vy, r], ...],        the world asked at the failing step (shrunk)
//    "level": "exact", "seed": 3, "case": 9, "family": "tangency", "steps": 1, "step": 1,
//    "candidate": "the program `python3 step_naive.py`",
//    "expected": [[...], ...], "actual": [[...], ...],
//    "difference": {"circle": 0, "field": "py", "expected": 1.58…, "actual": 1.58…, "decision": "none: …"}}
// A program that broke on the world instead of answering has no "actual", and "fault": "crashed or exited",
// "hung" or "wrote a malformed answer", the difference's decision saying how ("none: the program … exited with
// status 134 before answering request 9"). Only "format", "profile" and "world" are needed to replay; the rest records how the counterexample was
// found and what differed, and is checked for its type when present. Numbers follow formats/json_number.hpp.
#pragma once

#include "formats/protocol.hpp"
#include "properties/conformance.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace circles::conform {

using spec::Circles;
using formats::format_line;
using formats::in_quotes;
using formats::kId;

struct StoredCounterexample {
  properties::Profile profile = properties::Profile::resolved;
  Circles world;
  // How it was found, and what differed: empty or nullopt when a file leaves them out.
  std::string level, family, candidate;
  std::optional<std::uint64_t> seed, case_index, steps, step;
  Circles expected, actual;
  std::optional<properties::Difference> difference;
  std::string fault;  // how the program broke instead of answering (ChainFailure::fault); empty for an answer
};

// A corpus file that cannot be replayed. what(): "FILE: key \"world\": circle 1, field r: radius -2 is
// negative", "FILE: malformed JSON: …", "FILE: missing key \"profile\"".
class CorpusError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string to_json(const StoredCounterexample& c);
// `source` names the text in messages. Throws CorpusError.
StoredCounterexample from_json(std::string_view text, const std::string& source);

// "counterexample-0123456789abcdef": the file name of c in a corpus, without extension.
std::string stem(const StoredCounterexample& c);

// Writes DIR/stem(c).json (to a temporary name beside it, then renamed) and returns its path. Throws
// CorpusError when it cannot.
std::filesystem::path save(const std::filesystem::path& dir, const StoredCounterexample& c);

// Every DIR/*.json, in order of name. Throws CorpusError for a file that cannot be read or replayed.
std::vector<std::pair<std::filesystem::path, StoredCounterexample>> load_corpus(const std::filesystem::path& dir);

}  // namespace circles::conform
