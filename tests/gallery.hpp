// The gallery: deliberately wrong step functions, realistic mistakes that `circles conform` with
// its default budget (1000 cases, one step, level exact, resolved profile) must reject. One step function with a
// knob per mistake, so that each entry differs from the correct step (every knob off) in exactly one way.
// Checked two ways: in process (tests/gallery_test.cpp) and through the `circles` program over the step
// protocol, each entry served by tests/gallery_candidate.cpp (one ctest per entry, tests/CMakeLists.txt).
#pragma once

#include "formats/protocol.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace circles::testing {

using spec::Circles;

struct Mistakes {
  enum class Contact { exact, strict, hypot, small_grid } contact = Contact::exact;
  enum class Choice { least, y_key_first, first_in_index, literal_fold } choice = Choice::least;
  bool naive_update = false;       // p + v·(1/60): two roundings
  bool in_place = false;           // circles updated in index order, later ones reading the new values
  bool identity_by_value = false;  // i(c, W) leaves out every circle equal to c, not only c itself
  bool flush_subnormals = false;   // subnormal inputs read as zero
  bool swap_pairs = false;         // each touching pair swaps velocities, in index order, the last pair winning
};

// The resolved step with the mistakes `m` made; with none, the correct step (rounded to nearest).
Circles mistaken_step(const Circles& input, const Mistakes& m);

struct GalleryEntry {
  std::string name;         // "strict-intersect": gallery_candidate's argument, and its ctest's name
  std::string description;  // "< instead of <= in (3)": what the mistake is, in reports and in the corpus
  Mistakes mistakes;
};

// Every wrong implementation, in the order of docs/conform.md's table ("The gallery of wrong implementations").
const std::vector<GalleryEntry>& gallery();

// The entry called `name`, or the correct step for "none"; nullptr for any other name.
const GalleryEntry* find_entry(std::string_view name);

// "none, strict-intersect, hypot-distance, …": the names find_entry knows, for messages.
std::string entry_names();

}  // namespace circles::testing
