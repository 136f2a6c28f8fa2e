// libFuzzer target for the scene reader, formats::parse_scene: any bytes give a world of C (finite numbers,
// r >= 0) or a SceneError whose message names the source, never another exception or a crash. A world read
// reads again, written in the compact form, as the same exact values.
#include "formats/protocol.hpp"
#include "formats/scene.hpp"
#include "fuzz/check.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

using namespace circles;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string source = "fuzz.json";
  std::vector<spec::Circle> world;
  try {
    world = formats::parse_scene(text, source).circles;
  } catch (const formats::SceneError& e) {
    const std::string_view message = e.what();
    fuzz::require(message.starts_with(source + ": "), "the message names the source", message);
    fuzz::require(fuzz::is_one_printable_line(message), "the message is one line of printable ASCII", message);
    return 0;
  }
  // The reader keeps the exact value of each double it read, so the nearest doubles are those doubles.
  formats::Circles doubles;
  for (const spec::Circle& c : world) {
    const auto fields = spec::nearest_doubles(c);
    for (const double x : fields) fuzz::require(std::isfinite(x), "every number is finite");
    fuzz::require(fields[4] >= 0, "every radius is >= 0");
    doubles.push_back(fields);
  }
  // The protocol's compact form {"circles": [...]} is a scene: a request line without its "id".
  std::string again = formats::format_line(formats::kId, 0, doubles);
  again.replace(0, std::string_view(R"({"id":0,)").size(), "{");
  fuzz::require(formats::parse_scene(again, source).circles == world, "the world written and read again is the same",
                again);
  return 0;
}
