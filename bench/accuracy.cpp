// accuracy_bench: run time against error (docs/accuracy.md) and numerical stability (docs/stability.md).
// scripts/accuracy builds it in Release, runs `figures` and `stability`, and writes the documents.
//
//   accuracy_bench scenes --out DIR        writes the bundled scenes (cradle, dense, random, tangency_exact,
//                                          tangency_sixtieths) as DIR/<id>.json
//   accuracy_bench figures --csv FILE      every variant on the bundled scenes read from scenes/: time per
//                                          circle-step, errors, first decision that differs; with
//                                          --contacts-csv each variant's decision at each designed contact, with
//                                          --exactness-csv the exact engine against swept_step for 10^4 steps
//   accuracy_bench stability --csv FILE    every variant on the stress scenes: errors, departures, designed
//                                          contacts kept, how each run ended
//   accuracy_bench exactness --csv FILE    only the exact engine against swept_step, --steps N (10^4) on every
//                                          scenes/*.json (default.json included) or each --scene ID; the CSV is
//                                          rewritten every 10^5 steps and on SIGTERM with the steps checked
//
// Before measuring, each scene's designed tangencies are checked in the exact run (check_designed), the
// files in scenes/ must hold exactly the generated scenes, and the stress run checks that the exact engine
// equals the oracle and that scaling a scene by 2^e scales its exact trajectory by 2^e. A failed check
// exits 1; bad usage exits 2. Output files are written beside the target and renamed.
#include "bench/accuracy.hpp"

#include "formats/scene.hpp"
#include "impl/exact_engine.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace circles::bench::accuracy {
namespace {

// A failed check of the program's own premises: exit 1.
class CheckFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad usage that the command line parser cannot see (a --scene with no file): exit 2.
class BadUsage : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes beside the target and renames, so a failure never leaves a half-written file at `path`.
void write_file(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path temporary = path.string() + ".tmp";
  std::ofstream out(temporary, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, path);
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string figure(double x, const char* format = "%.3g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

std::string error_columns(const Error& e) {
  return figure(spec::nearest_double(e.abs)) + "," + figure(e.ulps);
}

// The columns both CSVs share, after scene, circles, steps and variant.
std::string outcome_columns(const Outcome& o) {
  return std::to_string(o.steps) + "," + error_columns(o.error) + "," + error_columns(o.error_before) + "," +
         (o.departure ? std::to_string(o.departure->step) : std::string()) + "," +
         quoted(o.departure ? o.departure->describe() : "") + "," + quoted(o.input) + "," + quoted(o.end);
}

const char* const kOutcomeHeader =
    "compared_steps,max_abs_error,max_ulp_error,max_abs_error_before_departure,max_ulp_error_before_departure,"
    "departure_step,departure,input,end";

// The bundled scene as read from its committed file, which must be the generated one.
Scene committed(const Scene& generated, const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / (generated.id + ".json");
  const formats::Scene read = formats::load_scene(file.string());
  bool same = read.circles.size() == generated.circles.size() && read.steps == generated.steps &&
              read.name == generated.name;
  for (std::size_t k = 0; same && k < read.circles.size(); ++k)
    same = read.circles[k] == spec::from_doubles(generated.circles[k], k, spec::Radii::non_negative);
  if (!same)
    throw CheckFailed(file.string() + " is not the scene the program generates; run `accuracy_bench scenes --out " +
                      dir.string() + "` and review the difference");
  return generated;
}

int write_scenes(const std::filesystem::path& dir) {
  for (const Scene& s : bundled_scenes()) {
    check_designed(s);
    write_file(dir / (s.id + ".json"), scene_json(s));
    std::cerr << "wrote " << (dir / (s.id + ".json")).string() << "\n";
  }
  return 0;
}

// The oracle costs O(n²) rationals per step (docs/benchmarks.md): it follows a scene for at most
// kOracleCircleSteps / n steps and is timed on a tenth of that, always at least kOracleMinSteps.
constexpr std::uint64_t kOracleCircleSteps = 10'000;
constexpr std::uint64_t kOracleMinSteps = 10;
std::uint64_t oracle_steps_for(std::size_t n, std::uint64_t steps, std::uint64_t at_most) {
  return std::min({steps, at_most, std::max<std::uint64_t>(kOracleMinSteps, kOracleCircleSteps / std::max<std::size_t>(n, 1))});
}

// "touches", "none" or "circle k" for circle a's decision.
std::string decision_text(std::uint32_t took, const Designed& d) {
  if (took == d.b) return "touches";
  if (took == d.a) return "none";
  return "circle " + std::to_string(took);
}

// The exact engine against swept_step from w0, as rationals after every step, for `steps` steps or until
// `go_on(t)`, asked after each step t that compared equal, says to stop.
struct Comparison {
  std::uint64_t checked = 0;             // steps 1 … checked compared equal
  std::optional<std::uint64_t> differs;  // the first step that did not, if one did
};
Comparison exact_engine_against_swept_steps(const spec::Sequence& w0, std::uint64_t steps,
                                            const std::function<bool(std::uint64_t)>& go_on = {}) {
  impl::ExactEngine engine(w0, impl::EngineOptions{.threads = 1});
  spec::Sequence w = w0;
  Comparison result;
  for (std::uint64_t t = 1; t <= steps; ++t) {
    w = swept_step(w);
    engine.step();
    if (engine.exact() != w) {
      result.differs = t;
      return result;
    }
    result.checked = t;
    if (go_on && !go_on(t)) break;
  }
  return result;
}

// The scene's circles at their exact values.
spec::Sequence rationals_of(const Circles& circles) { return spec::from_doubles(circles, spec::Radii::non_negative); }

int figures(const std::filesystem::path& dir, const std::filesystem::path& csv, const std::string& contacts_csv,
            const std::string& exactness_csv, std::uint64_t exactness_steps, int repetitions,
            std::uint64_t oracle_at_most, std::uint64_t steps_override) {
  std::string exactness = "scene,circles,steps,result,seconds\n";
  std::string out = std::string("scene,circles,steps,variant,ns_per_circle_step,timed_steps,") + kOutcomeHeader + "\n";
  std::string contacts = "scene,a,b,step,gap,variant,decision,exact_decision,end\n";
  for (const Scene& generated : bundled_scenes()) {
    const Scene scene = committed(generated, dir);
    check_designed(scene);
    const std::uint64_t steps = steps_override ? steps_override : scene.steps;
    const std::uint64_t oracle_steps = oracle_steps_for(scene.circles.size(), steps, oracle_at_most);
    std::cerr << scene.id << ": " << scene.circles.size() << " circles, " << steps << " steps\n";
    const std::vector<Outcome> outcomes = follow(scene.circles, steps, kKinds, oracle_steps);
    for (const Outcome& o : outcomes) {
      const bool oracle = o.kind == Kind::oracle;
      const std::uint64_t timed = oracle ? std::max<std::uint64_t>(1, oracle_steps / 10) : steps;
      const std::optional<double> ns = ns_per_circle_step(o.kind, scene.circles, timed, oracle ? 1 : repetitions);
      std::cerr << "  " << id_of(o.kind) << ": " << (ns ? figure(*ns) + " ns" : std::string("not timed")) << ", error "
                << error_columns(o.error) << (o.departure ? ", departs: step " + std::to_string(o.departure->step) : "")
                << "\n";
      out += scene.id + "," + std::to_string(scene.circles.size()) + "," + std::to_string(steps) + "," +
             std::string(id_of(o.kind)) + "," + (ns ? figure(*ns, "%.4g") : std::string()) + "," +
             (ns ? std::to_string(timed) : std::string()) + "," + outcome_columns(o) + "\n";
    }
    const Kind engines[] = {Kind::float_naive, Kind::naive_sqrt, Kind::naive_squares, Kind::exact_decisions,
                            Kind::double_engine, Kind::exact};
    for (const Contact& c : designed_contacts(scene, engines))
      contacts += scene.id + "," + std::to_string(c.pair.a) + "," + std::to_string(c.pair.b) + "," +
                  std::to_string(c.pair.step) + "," + figure(c.pair.gap) + "," + std::string(id_of(c.kind)) + "," +
                  (c.took ? decision_text(*c.took, c.pair) : std::string()) + "," +
                  decision_text(c.exact_took, c.pair) + "," + quoted(c.end) + "\n";
  }
  write_file(csv, out);
  if (!contacts_csv.empty()) write_file(contacts_csv, contacts);
  if (!exactness_csv.empty()) {
    for (const Scene& scene : bundled_scenes()) {
      const auto start = std::chrono::steady_clock::now();
      const Comparison c = exact_engine_against_swept_steps(rationals_of(scene.circles), exactness_steps);
      const std::string differs = c.differs ? "differs at step " + std::to_string(*c.differs) : "";
      const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
      std::cerr << scene.id << ": the exact engine against swept steps, " << exactness_steps << " steps: "
                << (differs.empty() ? "equal" : differs) << "\n";
      exactness += scene.id + "," + std::to_string(scene.circles.size()) + "," + std::to_string(exactness_steps) + "," +
                   (differs.empty() ? "equal at every step" : differs) + "," + figure(took.count(), "%.1f") + "\n";
      if (!differs.empty()) throw CheckFailed(scene.id + ": the exact engine " + differs + " from the swept steps");
    }
    write_file(exactness_csv, exactness);
  }
  return 0;
}

// Set by SIGTERM or SIGINT: `exactness` stops after the step it is checking and writes how far it got.
volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int) { stop_requested = 1; }

// The exact engine against swept_step on every scene file DIR/*.json in file name order (or on those named
// in `only`, in that order), for `steps` steps each: the zero-error target (docs/benchmarks.md, Targets). The CSV
// is rewritten every kCheckpointSteps steps and when a stop is requested, so that a long run that is cut
// short still says how many steps it checked. Returns 1 if a scene differs (after the other scenes).
constexpr std::uint64_t kCheckpointSteps = 100'000;
int exactness(const std::filesystem::path& dir, const std::filesystem::path& csv, std::uint64_t steps,
              const std::vector<std::string>& only) {
  std::vector<std::filesystem::path> files;
  for (const std::string& id : only) {
    files.push_back(dir / (id + ".json"));
    if (!std::filesystem::is_regular_file(files.back()))
      throw BadUsage("--scene " + id + ": no file " + files.back().string());
  }
  if (only.empty()) {
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::ranges::sort(files);
  }
  std::signal(SIGTERM, request_stop);
  std::signal(SIGINT, request_stop);
  // end: "" when the scene ran its steps or differed, "running" on a checkpoint, "stopped" after a stop request.
  const std::string header = "scene,circles,steps,checked_steps,first_difference,seconds,ms_per_step,end\n";
  std::string done;  // the rows of the scenes finished
  bool differs = false;
  for (const std::filesystem::path& file : files) {
    const formats::Scene scene = formats::load_scene(file.string());
    const std::string id = file.stem().string();
    const auto start = std::chrono::steady_clock::now();
    const auto row = [&](const Comparison& c, const char* end) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const std::uint64_t stepped = c.differs ? *c.differs : c.checked;
      const std::string ms = stepped ? figure(1000 * seconds / static_cast<double>(stepped), "%.4g") : "";
      return id + "," + std::to_string(scene.circles.size()) + "," + std::to_string(steps) + "," +
             std::to_string(c.checked) + "," + (c.differs ? std::to_string(*c.differs) : std::string("none")) + "," +
             figure(seconds, "%.1f") + "," + ms + "," + end + "\n";
    };
    const Comparison c = exact_engine_against_swept_steps(scene.circles, steps, [&](std::uint64_t t) {
      if (t % kCheckpointSteps == 0 || stop_requested) {
        const std::string now = row(Comparison{.checked = t, .differs = std::nullopt}, "running");
        std::cerr << now;
        write_file(csv, header + done + now);
      }
      return !stop_requested;
    });
    done += row(c, c.differs || c.checked == steps ? "" : "stopped");
    std::cerr << id << ": " << scene.circles.size() << " circles, " << c.checked << " of " << steps << " steps equal"
              << (c.differs ? ", differs at step " + std::to_string(*c.differs) : std::string()) << "\n";
    differs = differs || c.differs;
    write_file(csv, header + done);
    if (stop_requested) break;
  }
  return differs ? 1 : 0;
}

// The exact run of `scaled` (every field of `base` times 2^e) is that of `base` times 2^e, step for step.
void check_scaling(const Scene& base, const Scene& scaled, int e, std::uint64_t steps) {
  impl::ExactEngine a(impl::World(base.circles), impl::EngineOptions{.threads = 1});
  impl::ExactEngine b(impl::World(scaled.circles), impl::EngineOptions{.threads = 1});
  const spec::Q factor = spec::exact(std::ldexp(1.0, e));
  for (std::uint64_t t = 0; t <= steps; ++t) {
    const spec::Sequence x = a.exact(), y = b.exact();
    for (std::size_t k = 0; k < x.size(); ++k)
      if (!(y[k].p == x[k].p * factor && y[k].v == x[k].v * factor && y[k].r == x[k].r * factor))
        throw CheckFailed(scaled.id + ": the exact run is not the base run times 2^" + std::to_string(e) + " at step " +
                          std::to_string(t) + ", circle " + std::to_string(k));
    if (t < steps) {
      a.step();
      b.step();
    }
  }
}

int stability(const std::filesystem::path& csv, std::uint64_t long_steps, std::uint64_t oracle_steps) {
  std::string out = std::string("scene,circles,steps,variant,") + kOutcomeHeader + ",non_finite,designed_as_exact\n";
  const Kind engines[] = {Kind::float_naive, Kind::naive_sqrt, Kind::naive_squares, Kind::exact_decisions,
                          Kind::double_engine, Kind::exact};
  const std::vector<Scene> scenes = stress_scenes(long_steps);
  const Scene base = bundled_scenes().back();  // tangency_sixtieths
  for (const Scene& scene : scenes) {
    std::cerr << scene.id << ": " << scene.circles.size() << " circles, " << scene.steps << " steps\n";
    check_designed(scene);
    if (scene.id.starts_with("magnitude_")) {
      const int e = std::ilogb(scene.circles[0][4] / base.circles[0][4]);
      check_scaling(base, scene, e, scene.steps);
    }
    const std::uint64_t steps = oracle_steps_for(scene.circles.size(), scene.steps, oracle_steps);
    // Per variant: how many designed pairs it decides as the exact run does, "k/m".
    std::map<Kind, std::pair<int, int>> kept;
    for (const Contact& c : designed_contacts(scene, engines)) {
      auto& [same, all] = kept[c.kind];
      same += c.took && *c.took == c.exact_took;
      ++all;
    }
    for (const Outcome& o : follow(scene.circles, scene.steps, kKinds, steps)) {
      std::cerr << "  " << id_of(o.kind) << ": error " << error_columns(o.error)
                << (o.departure ? ", departs: step " + std::to_string(o.departure->step) : "")
                << (o.end.empty() ? "" : ", " + o.end) << "\n";
      const auto k = kept.find(o.kind);
      out += scene.id + "," + std::to_string(scene.circles.size()) + "," + std::to_string(scene.steps) + "," +
             std::string(id_of(o.kind)) + "," + outcome_columns(o) + "," + (o.non_finite ? "yes" : "no") + "," +
             (k == kept.end() ? std::string()
                              : std::to_string(k->second.first) + "/" + std::to_string(k->second.second)) +
             "\n";
    }
  }
  write_file(csv, out);
  return 0;
}

}  // namespace
}  // namespace circles::bench::accuracy

int main(int argc, char** argv) {
  using namespace circles::bench::accuracy;
  CLI::App app{"accuracy_bench: run time against error of the engines' arithmetics, and their stability"};
  app.require_subcommand(1);
  std::string out_dir, csv, contacts_csv, exactness_csv, scenes_dir = CIRCLES_SOURCE_DIR "/scenes";
  int repetitions = 5;
  std::uint64_t oracle_steps = 1000, stress_oracle_steps = 2000, long_steps = 1'000'000, steps = 0,
                exactness_steps = 10'000;
  CLI::App* scenes = app.add_subcommand("scenes", "write the bundled scenes");
  scenes->add_option("--out", out_dir, "directory")->required();
  CLI::App* fig = app.add_subcommand("figures", "time, error and departure of every variant on the bundled scenes");
  fig->add_option("--csv", csv, "output file")->required();
  fig->add_option("--contacts-csv", contacts_csv, "output file: each variant's decision at each designed contact");
  fig->add_option("--exactness-csv", exactness_csv, "output file: the exact engine against swept steps");
  fig->add_option("--exactness-steps", exactness_steps, "steps of that comparison")->capture_default_str();
  fig->add_option("--scenes", scenes_dir, "directory of the bundled scenes")->capture_default_str();
  fig->add_option("--repetitions", repetitions, "timed runs per variant and scene (median)")->capture_default_str()
      ->check(CLI::PositiveNumber);
  fig->add_option("--oracle-steps", oracle_steps, "steps of the oracle at most")->capture_default_str();
  fig->add_option("--steps", steps, "steps per scene instead of the scene's own (0: the scene's)");
  std::vector<std::string> only;
  CLI::App* compare = app.add_subcommand("exactness", "the exact engine against swept steps on every scene file");
  compare->add_option("--csv", csv, "output file")->required();
  compare->add_option("--steps", exactness_steps, "steps per scene")->capture_default_str();
  compare->add_option("--scenes", scenes_dir, "directory of the scenes (every *.json)")->capture_default_str();
  compare->add_option("--scene", only, "only this scene (file name without .json); repeatable");
  CLI::App* stab = app.add_subcommand("stability", "departures of every variant on the stress scenes");
  stab->add_option("--csv", csv, "output file")->required();
  stab->add_option("--long-steps", long_steps, "steps of the long run (a multiple of 100)")
      ->capture_default_str()
      ->check([](const std::string& text) {
        std::uint64_t n = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
        const bool ok = error == std::errc() && end == text.data() + text.size() && n > 0 && n % 100 == 0;
        return ok ? std::string() : "must be a positive multiple of 100";
      });
  stab->add_option("--oracle-steps", stress_oracle_steps, "steps of the oracle at most")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (*scenes) return write_scenes(out_dir);
    if (*fig)
      return figures(scenes_dir, csv, contacts_csv, exactness_csv, exactness_steps, repetitions, oracle_steps, steps);
    if (*compare) return exactness(scenes_dir, csv, exactness_steps, only);
    return stability(csv, long_steps, stress_oracle_steps);
  } catch (const BadUsage& e) {
    std::cerr << "accuracy_bench: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "accuracy_bench: " << e.what() << "\n";
    return 1;
  }
}
