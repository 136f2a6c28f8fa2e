// The benchmark scenes; the draws and their order are stated in random_scene.hpp.
#include "formats/random_scene.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace circles::formats {
namespace {

// The shortest decimal that reads back as x ("0.1", "1.5", "nan"), so a message shows what the caller passed.
std::string shortest(double x) {
  char buf[32];  // to_chars' shortest form of a double needs at most 24 characters
  const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
  return std::string(buf, end);
}

// u ∈ [0, 1): the top 53 bits of one output, scaled by 2^−53; exact, so identical everywhere.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// v ∈ [−1, 1): 2u − 1 is exact (2u is a multiple of 2^−52 below 2, and so is the difference).
double uniform_signed(std::mt19937_64& rng) { return 2 * uniform01(rng) - 1; }

}  // namespace

spec::Circles random_scene(std::size_t n, double coverage, std::uint64_t seed) {
  if (n == 0) throw std::invalid_argument("random_scene: n is 0; a scene has at least one circle");
  // Written so that NaN fails too: every comparison with NaN is false.
  if (!(coverage > 0 && coverage <= 1))
    throw std::invalid_argument("random_scene: coverage " + shortest(coverage) +
                                " is not in (0, 1] (the circles' total area over the square's)");

  std::mt19937_64 rng(seed);
  spec::Circles scene(n);
  double area = 0;
  for (auto& c : scene) {
    c[4] = kSceneMinRadius + (kSceneMaxRadius - kSceneMinRadius) * uniform01(rng);
    do {
      c[2] = kSceneMaxSpeed * uniform_signed(rng);
      c[3] = kSceneMaxSpeed * uniform_signed(rng);
    } while (c[2] * c[2] + c[3] * c[3] > kSceneMaxSpeed * kSceneMaxSpeed);
    area += std::numbers::pi * c[4] * c[4];
  }
  const double side = std::sqrt(area / coverage);
  if (!std::isfinite(side))
    throw std::invalid_argument("random_scene: coverage " + shortest(coverage) +
                                " is too small: the square's side overflows to infinity");
  for (auto& c : scene) {
    c[0] = side * uniform01(rng);
    c[1] = side * uniform01(rng);
  }
  return scene;
}

}  // namespace circles::formats
