// libFuzzer target for the scene reader, formats::parse_scene: any bytes give a world of C (finite numbers,
// r >= 0) or a SceneError whose message names the source, never another exception or a crash. A world read
// reads again, written in the compact form, as the same exact values. And the reader in pieces
// (formats::read_scene_world, the fast path of formats/streamed.hpp with parse_scene behind it), cut every 7
// bytes and every 1 MiB, gives what parse_scene gives: the same doubles bit for bit, name and steps, or the
// same message.
#include "formats/protocol.hpp"
#include "formats/scene.hpp"
#include "formats/streamed.hpp"
#include "fuzz/check.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

using namespace circles;

namespace {

// The scene read in pieces of `piece` bytes is `exact`, or fails with `message`.
void same_in_pieces(const std::string_view text, const std::string& source, std::size_t piece,
                    const std::optional<formats::Scene>& exact, std::string_view message) {
  std::istringstream in{std::string(text)};
  try {
    const formats::SceneWorld world = formats::read_scene_world(in, source, piece);
    fuzz::require(exact.has_value(), "the scene read in pieces is refused whole too", message);
    fuzz::require(fuzz::same_bits(world.circles, formats::doubles_of(*exact)), "in pieces, the same doubles");
    fuzz::require(world.name == exact->name && world.steps == exact->steps, "in pieces, the same name and steps");
  } catch (const formats::SceneError& e) {
    fuzz::require(!exact.has_value() && message == e.what(), "in pieces, the same message", e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string source = "fuzz.json";
  std::optional<formats::Scene> scene;
  std::string message;
  try {
    scene = formats::parse_scene(text, source);
  } catch (const formats::SceneError& e) {
    message = e.what();
    fuzz::require(message.starts_with(source + ": "), "the message names the source", message);
    fuzz::require(fuzz::is_one_printable_line(message), "the message is one line of printable ASCII", message);
  }
  for (const std::size_t piece : {std::size_t{7}, formats::kStreamPiece})
    same_in_pieces(text, source, piece, scene, message);
  if (!scene) return 0;
  const std::vector<spec::Circle> world = scene->circles;
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
