// gallery_candidate NAME: one entry of the gallery of wrong implementations (tests/gallery.hpp), or of the scale
// gallery of wrong optimized steps (tests/scale_gallery.hpp), behind the step
// protocol, served as `circles serve` serves an engine, so that `circles conform --exec "gallery_candidate NAME"`
// checks it as it checks any program. NAME "none" is the correct step. Exits as `circles serve` does, and with 2
// for a name that is no entry, listing the names.
#include "conform/serve.hpp"
#include "tests/gallery.hpp"
#include "tests/scale_gallery.hpp"

#include <cmath>
#include <cstddef>
#include <iostream>

namespace {

using circles::testing::Circles;

// A mistaken position beyond the double range cannot be written as a response: said as `circles serve` says
// an engine's overflow, rather than ending in an exception.
Circles finite(Circles w) {
  for (std::size_t k = 0; k < w.size(); ++k)
    for (const circles::spec::Field f : {circles::spec::Field::px, circles::spec::Field::py})
      if (!std::isfinite(w[k][static_cast<std::size_t>(f)])) throw circles::engines::StepOverflow(1, k, f);
  return w;
}

// "optimized, contact-slots, …": the scale gallery's names (tests/scale_gallery.hpp).
std::string scale_names() {
  std::string names = "optimized";
  for (const circles::testing::ScaleEntry& e : circles::testing::scale_gallery()) names += ", " + e.name;
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  const circles::testing::GalleryEntry* entry = argc == 2 ? circles::testing::find_entry(argv[1]) : nullptr;
  const circles::testing::ScaleEntry* scale = argc == 2 ? circles::testing::find_scale_entry(argv[1]) : nullptr;
  if (!entry && !scale) {
    std::cerr << "gallery_candidate: "
              << (argc == 2 ? "no gallery entry is called " + circles::formats::in_quotes(argv[1])
                            : "expected one argument, the name of a gallery entry")
              << "; the entries are: " << circles::testing::entry_names() << "; " << scale_names() << "\n";
    return 2;
  }
  std::ios::sync_with_stdio(false);  // like `circles serve`: only the C++ streams are used
  if (scale) {
    // What the optimized step keeps from one request to the next lives as long as the program.
    return circles::conform::serve(
        [bugs = scale->bugs, state = circles::testing::ScaleState{}](const Circles& w) mutable {
          return finite(circles::testing::optimized_step(w, bugs, state));
        },
        std::cin, std::cout, std::cerr);
  }
  const circles::testing::Mistakes mistakes = entry->mistakes;
  return circles::conform::serve(
      [mistakes](const Circles& w) { return finite(circles::testing::mistaken_step(w, mistakes)); }, std::cin,
      std::cout, std::cerr);
}
