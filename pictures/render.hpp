// Rendering r, the seed's last function: worlds to 1280×720 images (M_{1280×720}), drawn with Cairo,
// anti-aliased, and written as PNG frames by libpng (docs/run.md says how to read them; README.md shows one).
//
// Coordinates. The seed says nothing of r beyond its type, so we read the matrix as an image: column x from the
// left, row y from the top. With the default view a world unit is a pixel, the world's origin is the frame's
// top-left corner and y points down, as on a screen, in Cairo and in SVG: the point (x, y) lies in pixel
// (⌊x⌋, ⌊y⌋), so the default scene, laid out for this frame, fills it. --fit (View::fit) scales and centres
// instead.
//
// Drawing. Circle k is filled with fill_colour(k) (ten colours by index, so one sees which circle carries
// which velocity), in index order, on kBackground; then every circle in contact with another, by (3) decided
// exactly on the doubles shown (impl::intersect_exact), gets a kContactOutline ring on its edge, 2 pixels wide
// or a quarter of the circle's drawn radius where that is less (contact_width). A circle
// thinner than a pixel is drawn with radius kMinRadius (half a pixel), so that none vanishes, points (r = 0)
// included. Circles wholly outside the frame are skipped; one that covers the frame fills it; one with a
// radius of 2^21 pixels or more is drawn as the half-plane its edge cuts the frame with (the edge is then
// straight to 1469²/(8 · 2^21) < 0.13 pixel across the frame's diagonal), since Cairo's fixed-point
// coordinates (24.8 bits) end at 2^23.
#pragma once

#include "formats/output_file.hpp"
#include "formats/protocol.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

struct _cairo_surface;  // cairo_surface_t, kept out of this header so that only render.cpp needs Cairo's

namespace circles::pictures {

using spec::Circles;
using formats::OutputError;
using formats::OutputFile;

inline constexpr int kFrameWidth = 1280, kFrameHeight = 720;

// An opaque colour, 8 bits a channel.
struct Colour {
  std::uint8_t r, g, b;
  bool operator==(const Colour&) const = default;
};

inline constexpr Colour kBackground{0x1b, 0x1e, 0x24};
inline constexpr Colour kContactOutline{0xff, 0xff, 0xff};
// Circle k's fill: the ten colours of Tableau 10, k mod 10.
Colour fill_colour(std::size_t index);

inline constexpr double kMinRadius = 0.5;      // pixels: the least radius drawn
// The contact ring's width: kContactWidth pixels, or a quarter of the circle's drawn radius where that is less,
// so that the ring of a circle of 1 or 2 pixels (a scene seen from afar, with --fit) leaves its fill in view.
inline constexpr double kContactWidth = 2;     // pixels
inline constexpr double kContactWidthPerRadius = 0.25;
double contact_width(double drawn_radius);
inline constexpr double kFitMargin = 16;       // pixels: free on each side of a box View::fit frames

// The smallest box that holds circles' discs, [px − r, px + r] × [py − r, py + r], in long double (whose
// range, to 10^4932, holds px ± r for any doubles: no overflow).
struct Box {
  long double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  bool empty = true;
  void add(const Circles& world);
};

// World to pixels: a point p lies at (kFrameWidth/2, kFrameHeight/2) + (p − centre) · scale of the frame.
struct View {
  long double cx = kFrameWidth / 2, cy = kFrameHeight / 2, scale = 1;

  // World units are pixels, the origin is the top-left corner, y points down.
  static View pixels() { return {}; }
  // The box, as large as fits within the frame less kFitMargin on each side (the scale of the tighter axis),
  // centred. An empty box gives pixels(); a box of a single point, scale 1 centred on it.
  static View fit(const Box& box);
};

// contacts(w)[k] is 1 when circle k intersects another circle of w by (3), exactly (impl::intersect_exact);
// a sweep over x, n log n plus the pairs whose x ranges overlap.
std::vector<unsigned char> contacts(const Circles& world);

// One 1280×720 image (Cairo ARGB32, opaque).
class Frame {
 public:
  Frame();
  Frame(const Frame&) = delete;
  Frame& operator=(const Frame&) = delete;
  ~Frame();

  // Draws `world` through `view` over the whole frame (what was there before is gone). Circles with a
  // non-finite coordinate (no engine makes them) are skipped.
  void draw(const Circles& world, const View& view);
  // The frame's pixels, row by row, kStride bytes a row: B, G, R and an unused byte in memory (Cairo's RGB24
  // on a little-endian machine; what ffmpeg calls bgr0). RGB24 rather than ARGB32 because every pixel is
  // opaque: the PNG then has no alpha channel, a quarter fewer bytes to compress.
  static constexpr std::size_t kStride = 4 * kFrameWidth;
  const unsigned char* data() const;
  Colour pixel(int x, int y) const;

  // Writes the frame as an 8-bit RGB PNG file (libpng, tuned for speed) through an OutputFile (a temporary
  // name, then the rename). `what` opens the messages of an OutputError: "frame frames/frame-000003.png".
  void write_png(const std::string& path, const std::string& what) const;
  // A PNG file of 1280×720 read back (for tests and tools). Throws OutputError naming the file.
  static Frame read_png(const std::string& path);

 private:
  explicit Frame(_cairo_surface* surface);
  _cairo_surface* surface_;
  mutable std::vector<unsigned char> rgb_;  // write_png's packed RGB, kept between frames
};

// "frame-000042.png": the frame of w_42 (six digits at least; more from step 10^6 on).
std::string frame_name(std::uint64_t step);
// "DIR/frame-000042.png".
std::string frame_path(const std::string& dir, std::uint64_t step);

// The directory of --render DIR. The constructor creates it (and its parents) if missing and checks that a
// file can be made in it, before any step is taken; it throws OutputError: "render directory DIR: cannot
// create it: Not a directory", "render directory DIR: cannot write in it: Permission denied". DIR "-" is no
// directory but stdout, where the frames go one after another, a stream of PNGs (what ffmpeg -f image2pipe
// reads).
class FrameDirectory {
 public:
  explicit FrameDirectory(std::string dir);
  std::string path(std::uint64_t step) const { return dir_ == "-" ? dir_ : frame_path(dir_, step); }
  void write(const Frame& frame, std::uint64_t step) const;

 private:
  std::string dir_;
};

}  // namespace circles::pictures
