// The readers of big files alone, for docs/benchmarks.md ("Loading scenes and reading traces"): the time and,
// under /usr/bin/time, the peak memory of reading a file, without the engine that `circles run` and
// `circles check-trace` then build on it.
//   load_bench scene FILE         formats::load_scene_world, the doubles `circles run` steps
//   load_bench exact-scene FILE   formats::load_scene, the exact circles of the other commands
//   load_bench trace FILE         formats::TraceReader, every line, as `circles check-trace` reads them
// Prints the circles read, the bytes of the file, the seconds and the megabytes per second.
#include "formats/scene.hpp"
#include "formats/trace_reader.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>

int main(int argc, char** argv) {
  using namespace circles::formats;
  if (argc != 3) {
    std::fprintf(stderr, "usage: load_bench scene|exact-scene|trace FILE\n");
    return 2;
  }
  const std::string_view what = argv[1];
  const std::string path = argv[2];
  const auto start = std::chrono::steady_clock::now();
  std::size_t circles = 0, worlds = 1;
  try {
    if (what == "scene") {
      circles = load_scene_world(path).circles.size();
    } else if (what == "exact-scene") {
      circles = load_scene(path).circles.size();
    } else if (what == "trace") {
      TraceReader reader(path);
      worlds = 0;
      while (std::optional<Line> world = reader.next()) {
        circles = world->circles.size();
        ++worlds;
      }
    } else {
      std::fprintf(stderr, "load_bench: unknown reader '%s' (scene, exact-scene or trace)\n", argv[1]);
      return 2;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "load_bench: %s\n", e.what());
    return 2;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double bytes = static_cast<double>(std::filesystem::file_size(path));
  std::printf("%s: %zu worlds of %zu circles, %.0f bytes in %.3f s, %.0f MB/s\n", path.c_str(), worlds, circles, bytes,
              seconds, bytes / seconds / 1e6);
  return 0;
}
