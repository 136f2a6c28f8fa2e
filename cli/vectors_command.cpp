#include "cli/vectors_command.hpp"

#include "formats/counted.hpp"
#include "cli/options.hpp"
#include "formats/output_file.hpp"
#include "formats/scene.hpp"

#include <limits>
#include <string>
#include <vector>

namespace circles::cli {

using conform::VectorsError;
using conform::VectorsOptions;
using conform::VectorsSummary;
using formats::counted;
using formats::output_name;
using formats::SceneError;

CLI::App* add_vectors_command(CLI::App& app, VectorsOptions& options) {
  CLI::App* vectors = app.add_subcommand(
      "vectors", "Write golden test vectors for other languages to DIR/vectors.jsonl (see vectors.md in the docs)");
  takes(vectors->add_option("--out", options.out,
                            "The directory of vectors.jsonl (created if missing), or - for the vectors on stdout")
            ->required(),
        "DIR", "a directory for vectors.jsonl, or - for stdout");
  takes_whole_number(vectors->add_option("--cases", options.cases, "Generated worlds: conform's cases 0 to N-1 of the seed")
                         ->capture_default_str(),
                     "N", 0, 1000000);
  takes_whole_number(vectors->add_option("--seed", options.seed, "Seed of the generated worlds")->capture_default_str(),
                     "N", 0, std::numeric_limits<std::uint64_t>::max());
  takes_directory(
      vectors->add_option("--scenes", options.scenes, "Directory of scenes (*.json) whose first worlds are cases")
          ->capture_default_str(),
      "a directory of scene files");
  takes_whole_number(
      vectors->add_option("--scene-steps", options.scene_steps, "Worlds w_0, w_1, ... taken from each scene")
          ->capture_default_str(),
      "N", 0, 1000000);
  return vectors;
}

int vectors_command(const VectorsOptions& options, std::ostream& out, std::ostream& err) {
  try {
    const VectorsSummary s = write_vectors(options);
    // With the vectors on stdout, the summary goes to stderr.
    std::ostream& said = s.file == "-" ? err : out;
    said << "circles vectors: " << output_name(s.file) << ": " << counted(s.written, "case") << ", "
         << s.scene_cases << " from the first " << counted(options.scene_steps, "world") << " of "
         << counted(s.scenes, "scene") << " in " << options.scenes << " and " << s.written - s.scene_cases
         << " of the " << options.cases << " cases of seed " << options.seed;
    std::vector<std::string> left_out;
    if (s.big)
      left_out.push_back(std::to_string(s.big) + " of the big families (worlds of hundreds to thousands of circles, "
                         "which conform checks with a fast reference)");
    if (s.skipped)
      left_out.push_back(std::to_string(s.skipped) + " whose next world leaves the double range");
    for (std::size_t k = 0; k < left_out.size(); ++k) said << (k == 0 ? "; left out: " : ", and ") << left_out[k];
    said << "\n  features:";
    for (const char* f : {"contact", "tangency", "choice", "tie", "duplicate", "zero_radius"}) {
      const auto it = s.features.find(f);
      said << " " << f << " " << (it == s.features.end() ? 0 : it->second);
    }
    said << "\n";
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
