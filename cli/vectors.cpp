#include "cli/vectors.hpp"

#include "formats/scene.hpp"

namespace circles::cli {

CLI::App* add_vectors_command(CLI::App& app, VectorsOptions& options) {
  CLI::App* vectors = app.add_subcommand(
      "vectors", "Write golden test vectors for other languages to DIR/vectors.jsonl (docs/vectors.md)");
  vectors->add_option("--out", options.out, "The directory of vectors.jsonl (created if missing)")->required();
  // Ranges as for --steps: CLI11 reads "-5" as 2^64 - 5, which they refuse.
  vectors->add_option("--cases", options.cases, "Generated worlds: conform's cases 0 to N-1 of the seed")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{1000000}));
  vectors->add_option("--seed", options.seed, "Seed of the generated worlds")->capture_default_str();
  vectors->add_option("--scenes", options.scenes, "Directory of scenes (*.json) whose first worlds are cases")
      ->capture_default_str();
  vectors->add_option("--scene-steps", options.scene_steps, "Worlds w_0, w_1, ... taken from each scene")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{1000000}));
  return vectors;
}

int vectors_command(const VectorsOptions& options, std::ostream& out, std::ostream& err) {
  try {
    const VectorsSummary s = write_vectors(options);
    out << "circles vectors: " << s.file << ": " << s.written << " cases, " << s.scene_cases << " from the first "
        << options.scene_steps << " worlds of " << s.scenes << " scene" << (s.scenes == 1 ? "" : "s") << " in "
        << options.scenes << " and " << s.written - s.scene_cases << " of seed " << options.seed;
    if (s.skipped) out << " (" << s.skipped << " skipped: their next world leaves the double range)";
    out << "\n  features:";
    for (const char* f : {"contact", "tangency", "choice", "tie", "duplicate", "zero_radius"}) {
      const auto it = s.features.find(f);
      out << " " << f << " " << (it == s.features.end() ? 0 : it->second);
    }
    out << "\n";
    return 0;
  } catch (const VectorsError& e) {
    err << "circles vectors: " << e.what() << "\n";
    return 2;
  } catch (const SceneError& e) {
    err << "circles vectors: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace circles::cli
