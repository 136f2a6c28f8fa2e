#include "pictures/render.hpp"

#include "impl/broad_phase.hpp"
#include "impl/predicate.hpp"

#include <cairo.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <numeric>
#include <system_error>

namespace circles::pictures {

Colour fill_colour(std::size_t index) {
  // Tableau 10 (Tableau's default categorical palette): ten hues told apart easily, also on a dark background.
  static constexpr std::array<Colour, 10> kPalette{{{0x4e, 0x79, 0xa7},
                                                    {0xf2, 0x8e, 0x2b},
                                                    {0xe1, 0x57, 0x59},
                                                    {0x76, 0xb7, 0xb2},
                                                    {0x59, 0xa1, 0x4f},
                                                    {0xed, 0xc9, 0x48},
                                                    {0xb0, 0x7a, 0xa1},
                                                    {0xff, 0x9d, 0xa7},
                                                    {0x9c, 0x75, 0x5f},
                                                    {0xba, 0xb0, 0xac}}};
  return kPalette[index % kPalette.size()];
}

double contact_width(double drawn_radius) {
  return std::min(kContactWidth, kContactWidthPerRadius * drawn_radius);
}

namespace {

bool finite(const spec::CircleDoubles& c) {
  return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[4]);
}

}  // namespace

void Box::add(const Circles& world) {
  for (const auto& c : world) {
    if (!finite(c)) continue;
    const long double x = c[0], y = c[1], r = c[4];
    if (empty) {
      xmin = x - r, xmax = x + r, ymin = y - r, ymax = y + r;
      empty = false;
      continue;
    }
    xmin = std::min(xmin, x - r), xmax = std::max(xmax, x + r);
    ymin = std::min(ymin, y - r), ymax = std::max(ymax, y + r);
  }
}

View View::fit(const Box& box) {
  if (box.empty) return pixels();
  const long double w = box.xmax - box.xmin, h = box.ymax - box.ymin;
  const long double room_x = kFrameWidth - 2 * kFitMargin, room_y = kFrameHeight - 2 * kFitMargin;
  long double scale = 1;
  if (w > 0 && h > 0) scale = std::min(room_x / w, room_y / h);
  else if (w > 0) scale = room_x / w;
  else if (h > 0) scale = room_y / h;
  return {(box.xmin + box.xmax) / 2, (box.ymin + box.ymax) / 2, scale};
}

std::vector<unsigned char> contacts(const Circles& world) {
  std::vector<unsigned char> touching(world.size(), 0);
  // Every exactly intersecting pair {a, b} has overlapping outward x ranges [lo, hi] (impl/broad_phase.hpp):
  // with lo_a ≤ lo_b, lo_b ≤ b_x − r_b ≤ a_x + r_a ≤ hi_a. So scanning, for each a in order of lo, the b after
  // it while lo_b ≤ hi_a meets every such pair.
  std::vector<std::size_t> order;
  std::vector<double> lo(world.size()), hi(world.size());
  for (std::size_t k = 0; k < world.size(); ++k) {
    const auto& c = world[k];
    if (!finite(c) || !(c[4] >= 0)) continue;
    lo[k] = impl::outward_lower(c[0], c[4]);
    hi[k] = impl::outward_upper(c[0], c[4]);
    order.push_back(k);
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo[a] < lo[b]; });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const auto& a = world[order[i]];
    const double ylo = impl::outward_lower(a[1], a[4]), yhi = impl::outward_upper(a[1], a[4]);
    for (std::size_t j = i + 1; j < order.size() && lo[order[j]] <= hi[order[i]]; ++j) {
      const auto& b = world[order[j]];
      if (impl::outward_lower(b[1], b[4]) > yhi || impl::outward_upper(b[1], b[4]) < ylo) continue;
      if (impl::intersect_exact(a[0], a[1], a[4], b[0], b[1], b[4])) touching[order[i]] = touching[order[j]] = 1;
    }
  }
  return touching;
}

namespace {

void set_colour(cairo_t* cr, Colour c) { cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0); }

// A circle in pixels, as Cairo can draw it (see render.hpp).
struct Placed {
  enum Kind { none, whole, half_plane, disc } kind = none;
  double x = 0, y = 0, r = 0;     // disc: centre and radius
  double qx = 0, qy = 0, ux = 0, uy = 0;  // half_plane: the edge's point nearest the frame's centre, and the
                                          // unit normal pointing into the circle
};

constexpr long double kW = kFrameWidth, kH = kFrameHeight;
constexpr long double kSlack = 2;           // pixels around the frame still drawn: anti-aliasing, the ring
// Cairo's coordinates end at 2^23 (24.8 fixed point). A disc drawn as a disc has r < 2^21 and reaches the
// frame, so its centre is within 2^21 + 1282 of the origin, and the Bézier control points of its arcs (a
// hair beyond the circle) within 2^22 + 1282 + some: well inside.
constexpr long double kHugeRadius = 0x1p21L;
constexpr long double kHalfDiagonal = 734.4;  // ⌈√(640² + 360²)⌉ to 0.1: 734.30...
constexpr double kHalfPlaneExtent = 2000;     // > kHalfDiagonal + kSlack: the half-plane's polygon covers the frame

Placed place(const spec::CircleDoubles& c, const View& view) {
  const long double x = kW / 2 + (c[0] - view.cx) * view.scale, y = kH / 2 + (c[1] - view.cy) * view.scale;
  const long double r = std::max<long double>(c[4] * view.scale, kMinRadius);
  if (x + r < -kSlack || x - r > kW + kSlack || y + r < -kSlack || y - r > kH + kSlack) return {};
  // The frame's corner farthest from the centre: within r − kSlack, the circle covers the frame, ring and all.
  const long double fx = std::max(std::fabs(x), std::fabs(x - kW)), fy = std::max(std::fabs(y), std::fabs(y - kH));
  if (r > kSlack && fx * fx + fy * fy <= (r - kSlack) * (r - kSlack)) return {Placed::whole};
  if (r < kHugeRadius) return {Placed::disc, double(x), double(y), double(r)};
  // Distance from the frame's centre to the circle's edge along the line to its centre: d − r.
  const long double dx = x - kW / 2, dy = y - kH / 2, d = std::sqrt(dx * dx + dy * dy), edge = d - r;
  if (edge > kHalfDiagonal + kSlack) return {};  // the box met the frame, the disc does not
  if (edge < -(kHalfDiagonal + kSlack)) return {Placed::whole};
  Placed p{Placed::half_plane};
  p.ux = double(dx / d), p.uy = double(dy / d);
  p.qx = double(kW / 2 + edge * dx / d), p.qy = double(kH / 2 + edge * dy / d);
  return p;
}

// The region of `p` as Cairo's current path.
void fill_path(cairo_t* cr, const Placed& p) {
  cairo_new_path(cr);
  switch (p.kind) {
    case Placed::none:
      break;
    case Placed::whole:
      cairo_rectangle(cr, 0, 0, kFrameWidth, kFrameHeight);
      break;
    case Placed::disc:
      cairo_arc(cr, p.x, p.y, p.r, 0, 2 * std::numbers::pi);
      break;
    case Placed::half_plane: {
      const double l = kHalfPlaneExtent, wx = -p.uy * l, wy = p.ux * l;
      cairo_move_to(cr, p.qx + wx, p.qy + wy);
      cairo_line_to(cr, p.qx - wx, p.qy - wy);
      cairo_line_to(cr, p.qx - wx + 2 * l * p.ux, p.qy - wy + 2 * l * p.uy);
      cairo_line_to(cr, p.qx + wx + 2 * l * p.ux, p.qy + wy + 2 * l * p.uy);
      cairo_close_path(cr);
      break;
    }
  }
}

// The edge of `p` as Cairo's current path (nothing when it is off the frame).
void edge_path(cairo_t* cr, const Placed& p) {
  cairo_new_path(cr);
  if (p.kind == Placed::disc) {
    cairo_arc(cr, p.x, p.y, p.r, 0, 2 * std::numbers::pi);
  } else if (p.kind == Placed::half_plane) {
    const double wx = -p.uy * kHalfPlaneExtent, wy = p.ux * kHalfPlaneExtent;
    cairo_move_to(cr, p.qx + wx, p.qy + wy);
    cairo_line_to(cr, p.qx - wx, p.qy - wy);
  }
}

cairo_surface_t* new_surface() {
  // RGB24: opaque pixels, so the PNG has no alpha channel (a quarter fewer bytes before compression). In
  // memory it is ARGB32's layout with the high byte unused: B, G, R, x on little-endian (ffmpeg's bgr0).
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, kFrameWidth, kFrameHeight);
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) throw std::bad_alloc();
  return s;
}

}  // namespace

Frame::Frame() : surface_(new_surface()) {
  static_assert(kStride % 4 == 0);
  if (cairo_image_surface_get_stride(surface_) != static_cast<int>(kStride)) {
    cairo_surface_destroy(surface_);
    throw std::logic_error("Frame: Cairo's stride for 1280 pixels is not 5120 bytes");
  }
  draw({}, View::pixels());
}

Frame::Frame(cairo_surface_t* surface) : surface_(surface) {}

Frame::~Frame() { cairo_surface_destroy(surface_); }

void Frame::draw(const Circles& world, const View& view) {
  cairo_t* cr = cairo_create(surface_);
  set_colour(cr, kBackground);
  cairo_paint(cr);
  std::vector<Placed> placed(world.size());
  for (std::size_t k = 0; k < world.size(); ++k) {
    if (!finite(world[k])) continue;
    placed[k] = place(world[k], view);
    if (placed[k].kind == Placed::none) continue;
    fill_path(cr, placed[k]);
    set_colour(cr, fill_colour(k));
    cairo_fill(cr);
  }
  // The rings after every fill, so that no circle hides another's contact.
  const std::vector<unsigned char> touching = contacts(world);
  set_colour(cr, kContactOutline);
  for (std::size_t k = 0; k < world.size(); ++k) {
    if (!touching[k] || placed[k].kind == Placed::none) continue;
    cairo_set_line_width(cr, placed[k].kind == Placed::disc ? contact_width(placed[k].r) : kContactWidth);
    edge_path(cr, placed[k]);
    cairo_stroke(cr);
  }
  cairo_destroy(cr);
  cairo_surface_flush(surface_);
}

const unsigned char* Frame::data() const { return cairo_image_surface_get_data(surface_); }

Colour Frame::pixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= kFrameWidth || y >= kFrameHeight)
    throw std::out_of_range("Frame::pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") is off the frame");
  std::uint32_t v;  // 0xxxRRGGBB in the machine's byte order
  std::memcpy(&v, data() + static_cast<std::size_t>(y) * kStride + 4 * static_cast<std::size_t>(x), sizeof v);
  return {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
}

void Frame::write_png(const std::string& path, const std::string& what) const {
  // libpng's simplified API with PNG_IMAGE_FLAG_FAST (zlib's fastest setting, no search over row filters):
  // about 5 times faster than cairo_surface_write_to_png (libpng's defaults: level 6, adaptive filters) on
  // these flat-coloured frames, for files about twice the size (20 KB against 11 KB, a frame of the default
  // scene). Writing PNGs is most of the cost of --render, so speed wins. The API takes packed RGB.
  rgb_.resize(3 * static_cast<std::size_t>(kFrameWidth) * kFrameHeight);
  const unsigned char* from = data();
  unsigned char* to = rgb_.data();
  for (std::size_t k = 0; k < static_cast<std::size_t>(kFrameWidth) * kFrameHeight; ++k, from += 4, to += 3)
    to[0] = from[2], to[1] = from[1], to[2] = from[0];  // B, G, R, x to R, G, B (little-endian RGB24)
  OutputFile out(path, what);
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = kFrameWidth;
  image.height = kFrameHeight;
  image.format = PNG_FORMAT_RGB;
  image.flags = PNG_IMAGE_FLAG_FAST;
  errno = 0;
  if (!png_image_write_to_stdio(&image, out.file(), 0, rgb_.data(), 0, nullptr)) {
    if (errno != 0) out.fail_write();  // a failed fwrite: the system's reason
    throw OutputError(what + ": cannot encode the PNG: " + image.message);
  }
  out.commit();
}

Frame Frame::read_png(const std::string& path) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  const cairo_status_t status = cairo_surface_status(s);
  if (status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    throw OutputError(path + ": cannot read it as a PNG: " + cairo_status_to_string(status));
  }
  const cairo_format_t format = cairo_image_surface_get_format(s);
  if (cairo_image_surface_get_width(s) != kFrameWidth || cairo_image_surface_get_height(s) != kFrameHeight ||
      (format != CAIRO_FORMAT_RGB24 && format != CAIRO_FORMAT_ARGB32) ||
      cairo_image_surface_get_stride(s) != static_cast<int>(kStride)) {
    cairo_surface_destroy(s);
    throw OutputError(path + ": not a 1280x720 RGB image");
  }
  return Frame(s);
}

std::string frame_name(std::uint64_t step) {
  char name[40];
  std::snprintf(name, sizeof name, "frame-%06llu.png", static_cast<unsigned long long>(step));
  return name;
}

FrameDirectory::FrameDirectory(std::string dir) : dir_(std::move(dir)) {
  if (dir_ == "-") return;  // no directory: the frames go to stdout
  const std::string what = "render directory " + dir_;
  std::error_code error;
  std::filesystem::create_directories(dir_, error);
  if (error) throw OutputError(what + ": cannot create it: " + error.message());
  if (!std::filesystem::is_directory(dir_, error)) throw OutputError(what + ": it is not a directory");
  // A file made and removed now: a directory we cannot write in fails here, before any step is taken.
  std::string probe = (std::filesystem::path(dir_) / ".circles-probe-XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0) throw OutputError(what + ": cannot write in it: " + std::strerror(errno));
  close(fd);
  std::remove(probe.c_str());
}

std::string frame_path(const std::string& dir, std::uint64_t step) {
  return (std::filesystem::path(dir) / frame_name(step)).string();
}

void FrameDirectory::write(const Frame& frame, std::uint64_t step) const {
  const std::string file = path(step);
  frame.write_png(file, "frame " + file);
}

}  // namespace circles::pictures
