#include "pictures/counterexample_svg.hpp"

#include "formats/json_number.hpp"
#include "impl/predicate.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace circles::pictures {
namespace {

constexpr double kWidth = 900;
constexpr double kWorldHeight = 630;  // the world's area, below the text band
constexpr double kTextLeft = 10;      // the text's margin, left and right
constexpr double kLineHeight = 15;
constexpr double kMargin = 40;
constexpr double kLeast = 3;       // the smallest radius drawn, in points
constexpr double kMarker = 7;      // half the size of the + and × markers

struct Rgb {
  double r, g, b;
};
constexpr Rgb kGrey{0.35, 0.35, 0.35}, kBlue{0.1, 0.3, 0.85}, kOrange{0.95, 0.55, 0.1}, kGreen{0.1, 0.6, 0.1},
    kRed{0.8, 0.1, 0.1}, kBlack{0, 0, 0};

void set(cairo_t* cr, Rgb c, double alpha = 1) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

// World coordinates to points: the bounding box of what is drawn, fitted into the area below the text, y up.
// In long double, whose range holds the squares and differences of any two doubles.
class PageView {
 public:
  PageView(double band, long double x0, long double x1, long double y0, long double y1) : band_(band) {
    const long double w = kWidth - 2 * kMargin, h = kWorldHeight - 2 * kMargin;
    long double dx = x1 - x0, dy = y1 - y0;
    if (!(dx > 0) && !(dy > 0)) dx = dy = 1;  // a single point: any scale
    scale_ = std::min(dx > 0 ? w / dx : INFINITY, dy > 0 ? h / dy : INFINITY);
    // Centre the box in the area.
    cx_ = (x0 + x1) / 2;
    cy_ = (y0 + y1) / 2;
  }
  double x(double wx) const { return static_cast<double>(kWidth / 2 + (wx - cx_) * scale_); }
  double y(double wy) const {
    return static_cast<double>(band_ + kWorldHeight / 2 - (wy - cy_) * scale_);
  }
  double length(double r) const { return std::max(kLeast, static_cast<double>(r * scale_)); }

 private:
  double band_;
  long double scale_ = 1, cx_ = 0, cy_ = 0;
};

// An answer may hold NaN, infinities or a negative radius (formats/protocol.hpp, Reading::answer): such a circle
// has no place in the picture, and the report's lines say what it was.
bool drawable(const spec::CircleDoubles& c) { return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[4]) && c[4] >= 0; }

// The most circles of a world framed whole: the small families' 8.
constexpr std::size_t kFramedWhole = 8;

}  // namespace

std::array<long double, 4> framed_box(const CounterexamplePicture& p) {
  long double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  const auto include = [&](const spec::CircleDoubles& c) {
    if (!drawable(c)) return;
    const long double r = c[4];
    x0 = std::min(x0, c[0] - r);
    x1 = std::max(x1, c[0] + r);
    y0 = std::min(y0, c[1] - r);
    y1 = std::max(y1, c[1] + r);
  };
  // A world of the small families is framed whole. A bigger one (a big family's, shrunk or not) is framed around
  // the circles that decide the case: the circle that differs, the circles it touches (in long double, which is
  // enough to frame them), and any circle whose velocity it answered with; the others are drawn where they fall.
  const bool whole = p.world.size() <= kFramedWhole || p.circle >= p.world.size();
  for (std::size_t k = 0; k < p.world.size(); ++k) {
    const auto& c = p.world[k];
    if (!whole && k != p.circle) {
      const auto& d = p.world[p.circle];
      const long double dx = static_cast<long double>(c[0]) - d[0], dy = static_cast<long double>(c[1]) - d[1];
      const long double reach = static_cast<long double>(c[4]) + d[4];
      const bool touches = dx * dx + dy * dy <= reach * reach * (1 + 1e-9L);
      const bool taken = p.circle < p.actual.size() && c[2] == p.actual[p.circle][2] && c[3] == p.actual[p.circle][3];
      if (!touches && !taken) continue;
    }
    include(c);
  }
  if (p.circle < p.expected.size()) include(p.expected[p.circle]);
  if (p.circle < p.actual.size()) include(p.actual[p.circle]);
  if (p.world.empty()) return {0, 1, 0, 1};
  return {x0, x1, y0, y1};
}

namespace {

PageView fit(const CounterexamplePicture& p, double band) {
  const auto [x0, x1, y0, y1] = framed_box(p);
  return PageView(band, x0, x1, y0, y1);
}

void circle(cairo_t* cr, const PageView& v, const spec::CircleDoubles& c) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, v.x(c[0]), v.y(c[1]), v.length(c[4]), 0, 2 * std::numbers::pi);
}

void text(cairo_t* cr, double x, double y, const std::string& s) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s.c_str());
}

// The lines of text as drawn: each line of the report cut at spaces so that it ends inside the picture, its
// continuations indented by four spaces more than it. A word wider than the picture stays whole.
std::vector<std::string> wrapped(cairo_t* cr, const std::vector<std::string>& lines) {
  const auto width = [cr](const std::string& s) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    return e.x_advance;
  };
  std::vector<std::string> out;
  for (const std::string& line : lines) {
    const std::string indent(line.find_first_not_of(' ') == std::string::npos ? 0 : line.find_first_not_of(' ') + 4, ' ');
    std::string rest = line;
    while (width(rest) > kWidth - 2 * kTextLeft) {
      std::size_t cut = rest.size();
      do cut = rest.rfind(' ', cut - 1);
      while (cut != std::string::npos && cut > indent.size() && width(rest.substr(0, cut)) > kWidth - 2 * kTextLeft);
      if (cut == std::string::npos || cut <= indent.size()) break;
      out.push_back(rest.substr(0, cut));
      rest.replace(0, cut + 1, indent);
    }
    out.push_back(rest);
  }
  return out;
}

// The index of the least contact of circle k in lexicographic order on (px, py, vx, vy, r), then by index:
// e (8) in the resolved profile, and in the literal one wherever (8) is defined. Nothing if k touches none.
std::optional<std::size_t> least_contact(const Circles& w, std::size_t k, const std::vector<std::vector<bool>>& touch) {
  std::optional<std::size_t> least;
  for (std::size_t j = 0; j < w.size(); ++j)
    if (j != k && touch[k][j] && (!least || std::lexicographical_compare(w[j].begin(), w[j].end(), w[*least].begin(),
                                                                         w[*least].end())))
      least = j;
  return least;
}

}  // namespace

std::vector<std::string> position_labels(const CounterexamplePicture& p) {
  const std::size_t k = p.circle;
  if (k >= p.world.size() || k >= p.expected.size() || k >= p.actual.size()) return {};
  const auto& expected = p.expected[k];
  const auto& actual = p.actual[k];
  if (!drawable(expected) || !drawable(actual)) return {};
  const PageView v = fit(p, 0);
  if (std::hypot(v.x(expected[0]) - v.x(actual[0]), v.y(expected[1]) - v.y(actual[1])) >= 2 * kMarker) return {};
  const auto label = [](const char* what, const spec::CircleDoubles& c) {
    std::string text(what);
    text.append(" (");
    formats::json_number::append_any(text, c[0]);
    text.append(", ");
    formats::json_number::append_any(text, c[1]);
    text.push_back(')');
    return text;
  };
  return {label("expected", expected), label("answered", actual)};
}

std::string counterexample_svg(const CounterexamplePicture& p) {
  std::string svg;
  const auto write = [](void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  };
  // The lines as they fit the width, measured in the font they are drawn in, set the height of the text band.
  const auto set_font = [](cairo_t* c) {
    cairo_select_font_face(c, "DejaVu Sans Mono", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(c, 11);
  };
  cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* measure = cairo_create(scratch);
  set_font(measure);
  const std::vector<std::string> lines = wrapped(measure, p.lines);
  cairo_destroy(measure);
  cairo_surface_destroy(scratch);
  const double band = std::max(130.0, 18 + kLineHeight * static_cast<double>(std::max<std::size_t>(lines.size(), 1) - 1) + 52);

  cairo_surface_t* surface = cairo_svg_surface_create_for_stream(write, &svg, kWidth, band + kWorldHeight);
  cairo_t* cr = cairo_create(surface);

  set(cr, Rgb{1, 1, 1});
  cairo_paint(cr);

  // The text band.
  set_font(cr);
  set(cr, kBlack);
  double line_y = 18;
  for (const std::string& line : lines) {
    text(cr, kTextLeft, line_y, line);
    line_y += kLineHeight;
  }
  // The legend, on one line.
  double lx = kTextLeft;
  const double ly = band - 12;
  const auto swatch = [&](Rgb c, bool filled, bool dashed, const std::string& label) {
    set(cr, c);
    cairo_set_line_width(cr, 2);
    if (dashed) {
      const double dash[] = {4, 3};
      cairo_set_dash(cr, dash, 2, 0);
    }
    cairo_new_path(cr);
    cairo_arc(cr, lx + 6, ly - 4, 6, 0, 2 * std::numbers::pi);
    if (filled) {
      set(cr, c, 0.3);
      cairo_fill_preserve(cr);
      set(cr, c);
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    set(cr, kBlack);
    text(cr, lx + 16, ly, label);
    lx += 22 + 7 * static_cast<double>(label.size()) + 14;
  };
  swatch(kGrey, false, false, "circle");
  swatch(kBlue, false, false, "differs");
  swatch(kGreen, true, false, "least contact (e)");
  swatch(kRed, true, false, "contact taken");
  swatch(kGreen, false, true, "expected");
  swatch(kRed, false, true, "answered");
  set(cr, kOrange);
  cairo_set_line_width(cr, 2);
  cairo_move_to(cr, lx, ly - 4);
  cairo_line_to(cr, lx + 14, ly - 4);
  cairo_stroke(cr);
  set(cr, kBlack);
  text(cr, lx + 18, ly, "contact");
  set(cr, kGrey);
  cairo_set_line_width(cr, 0.5);
  cairo_move_to(cr, 0, band);
  cairo_line_to(cr, kWidth, band);
  cairo_stroke(cr);

  const Circles& w = p.world;
  const PageView v = fit(p, band);
  const std::size_t n = w.size();
  std::vector<std::vector<bool>> touch(n, std::vector<bool>(n, false));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      touch[a][b] = touch[b][a] = impl::intersect_exact(w[a][0], w[a][1], w[a][4], w[b][0], w[b][1], w[b][4]);
  const std::size_t k = p.circle;
  const bool drawn_k = k < n && k < p.expected.size() && k < p.actual.size();

  // The least contact, and the contact whose velocity was taken instead.
  if (drawn_k) {
    const std::optional<std::size_t> least = least_contact(w, k, touch);
    std::optional<std::size_t> taken;
    for (std::size_t j = 0; j < n && !taken; ++j)
      if (j != k && touch[k][j] && j != least && w[j][2] == p.actual[k][2] && w[j][3] == p.actual[k][3]) taken = j;
    for (const auto& [j, colour] : {std::pair{least, kGreen}, std::pair{taken, kRed}}) {
      if (!j) continue;
      cairo_new_path(cr);
      circle(cr, v, w[*j]);
      set(cr, colour, 0.25);
      cairo_fill(cr);
    }
  }

  // Contacts.
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      if (!touch[a][b]) continue;
      const bool of_k = a == k || b == k;
      set(cr, kOrange);
      cairo_set_line_width(cr, of_k ? 3 : 1.5);
      cairo_new_path(cr);
      cairo_move_to(cr, v.x(w[a][0]), v.y(w[a][1]));
      cairo_line_to(cr, v.x(w[b][0]), v.y(w[b][1]));
      cairo_stroke(cr);
    }

  // Circles, the one that differs last (on top).
  for (std::size_t pass = 0; pass < 2; ++pass)
    for (std::size_t j = 0; j < n; ++j) {
      if ((j == k) != (pass == 1)) continue;
      set(cr, j == k ? kBlue : kGrey);
      cairo_set_line_width(cr, j == k ? 3 : 1.5);
      cairo_new_path(cr);
      circle(cr, v, w[j]);
      cairo_stroke(cr);
      set(cr, kBlack);
      text(cr, v.x(w[j][0]) + 4, v.y(w[j][1]) - 4, std::string("#").append(std::to_string(j)));
    }

  // Expected and answered positions of the circle that differs. Where the two markers fall on one another at
  // the picture's scale, the + of the expected position is drawn larger than the × of the answered one, so that
  // both show, and each is labelled with its position (position_labels).
  const std::vector<std::string> labels = position_labels(p);
  if (drawn_k) {
    const double dash[] = {6, 4};
    for (const auto& [c, colour, cross] : {std::tuple{p.expected[k], kGreen, false}, std::tuple{p.actual[k], kRed, true}}) {
      if (!drawable(c)) continue;
      set(cr, colour);
      cairo_set_line_width(cr, 0.8);
      cairo_new_path(cr);
      cairo_move_to(cr, v.x(w[k][0]), v.y(w[k][1]));
      cairo_line_to(cr, v.x(c[0]), v.y(c[1]));
      cairo_stroke(cr);
      cairo_set_line_width(cr, 2);
      cairo_set_dash(cr, dash, 2, 0);
      cairo_new_path(cr);
      circle(cr, v, c);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      const double x = v.x(c[0]), y = v.y(c[1]);
      const double size = !labels.empty() && !cross ? 2 * kMarker : kMarker;
      cairo_new_path(cr);
      if (cross) {
        cairo_move_to(cr, x - size, y - size);
        cairo_line_to(cr, x + size, y + size);
        cairo_move_to(cr, x - size, y + size);
        cairo_line_to(cr, x + size, y - size);
      } else {
        cairo_move_to(cr, x - size, y);
        cairo_line_to(cr, x + size, y);
        cairo_move_to(cr, x, y - size);
        cairo_line_to(cr, x, y + size);
      }
      cairo_stroke(cr);
      if (labels.empty()) continue;
      // The label beside the markers, right of them or else left, the expected above the answered, kept inside
      // the picture.
      const std::string& label = labels[cross ? 1 : 0];
      cairo_text_extents_t e;
      cairo_text_extents(cr, label.c_str(), &e);
      const double right = x + 3 * kMarker, left = x - 3 * kMarker - e.x_advance;
      const double label_x = std::clamp(right + e.x_advance <= kWidth - kTextLeft ? right : left, kTextLeft,
                                        kWidth - kTextLeft - e.x_advance);
      const double label_y =
          std::clamp(y + (cross ? 3 * kMarker : -2 * kMarker), band + kLineHeight, band + kWorldHeight - 5);
      text(cr, label_x, label_y, label);
    }
  }

  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo could not draw the counterexample: ") + cairo_status_to_string(status));
  return svg;
}

}  // namespace circles::pictures
