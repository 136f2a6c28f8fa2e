#include "conform/vectors.hpp"

#include "conform/conform.hpp"
#include "formats/output_file.hpp"
#include "formats/scene.hpp"
#include "properties/boundaries.hpp"
#include "properties/features.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace circles::conform {
namespace {

namespace fs = std::filesystem;

std::vector<spec::Circle> exact_circles(const Circles& w) { return spec::from_doubles(w, spec::Radii::non_negative); }

// The scene files of `dir`: every regular *.json file, in name order.
std::vector<fs::path> scene_files(const std::string& dir) {
  std::error_code error;
  fs::directory_iterator it(dir, error);
  if (error)
    throw VectorsError(dir + ": cannot read the scenes directory: " + error.message() +
                       " (the bundled scenes are scenes/ in the repository: run from its root or give --scenes DIR)");
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : it)
    if (entry.path().extension() == ".json" && entry.is_regular_file(error)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<std::string> features_of(const Circles& w) {
  const std::vector<spec::Circle> exact = exact_circles(w);
  const properties::Features f = properties::features(exact);
  bool choice = false;
  for (std::size_t k = 0; k < exact.size() && !choice; ++k) {
    int contacts = 0;
    for (std::size_t j = 0; j < exact.size(); ++j) contacts += j != k && spec::intersect(exact[k], exact[j]);
    choice = contacts >= 2;
  }
  std::vector<std::string> names;
  for (const auto& [holds, name] : {std::pair{f.contact, "contact"}, std::pair{f.tangency, "tangency"},
                                    std::pair{choice, "choice"}, std::pair{f.tie, "tie"},
                                    std::pair{f.duplicate, "duplicate"}, std::pair{f.zero_radius, "zero_radius"}})
    if (holds) names.push_back(name);
  return names;
}

std::optional<Vector> make_vector(const Circles& input) {
  Vector v;
  v.input = input;
  v.next_exact = spec::resolved_step(exact_circles(input));
  for (const spec::Circle& c : v.next_exact) {
    v.next.push_back(spec::nearest_doubles(c));
    if (!std::isfinite(v.next.back()[0]) || !std::isfinite(v.next.back()[1])) return std::nullopt;
  }
  v.features = features_of(input);
  return v;
}

VectorsSummary write_vectors(const VectorsOptions& options) {
  VectorsSummary summary;
  // The inputs and the output directory first, so that a wrong --scenes or --out is reported before any work
  // and a missing scenes directory leaves no output directory behind.
  const std::vector<fs::path> scenes = scene_files(options.scenes);
  const bool to_stdout = options.out == "-";
  std::error_code error;
  if (!to_stdout && fs::exists(options.out, error) && !fs::is_directory(options.out, error))
    throw VectorsError(options.out + ": cannot create the output directory: a file of that name is in the way");
  if (!to_stdout) fs::create_directories(options.out, error);
  if (error) throw VectorsError(options.out + ": cannot create the output directory: " + error.message());

  std::vector<Vector> vectors;
  // The scenes: w_0 from the file, then each next world the correctly rounded step of the one before.
  for (const fs::path& file : scenes) {
    ++summary.scenes;
    Circles world = formats::doubles_of(formats::load_scene(file.string()));
    for (std::uint64_t step = 0; step < options.scene_steps; ++step) {
      std::optional<Vector> v = make_vector(world);
      if (!v) {
        ++summary.skipped;
        break;  // no later world of this scene exists in doubles
      }
      v->scene = file.filename().string();
      v->step = step;
      world = v->next;
      vectors.push_back(std::move(*v));
      ++summary.scene_cases;
    }
  }
  // conform's worlds: the same case c of a seed as `circles conform --seed S --case c` checks, for the small
  // families; a big family's world (hundreds to thousands of circles, properties/boundaries.hpp) is left to
  // conform, which judges it with a fast reference, where the oracle would take minutes over each.
  const std::vector<Circles> worlds = case_worlds(options.seed, options.cases);
  const auto families = properties::families(properties::Profile::resolved);
  for (std::uint64_t c = 0; c < worlds.size(); ++c) {
    if (properties::is_big(families[c % families.size()])) {
      ++summary.big;
      continue;
    }
    std::optional<Vector> v = make_vector(worlds[c]);
    if (!v) {
      ++summary.skipped;
      continue;
    }
    v->seed = options.seed;
    v->case_index = c;
    vectors.push_back(std::move(*v));
  }

  std::string content;
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    content += formats::format_vector(i, vectors[i]) + '\n';
    for (const std::string& f : vectors[i].features) ++summary.features[f];
  }
  summary.file = to_stdout ? options.out : (fs::path(options.out) / kVectorsFile).string();
  try {  // beside its place and renamed into it: DIR never holds a half-written file
    formats::write_file(summary.file, summary.file, content);
  } catch (const formats::OutputError& e) {
    throw VectorsError(e.what());
  }
  summary.written = vectors.size();
  return summary;
}

}  // namespace circles::conform
