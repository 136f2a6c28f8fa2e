#include "pictures/counterexample_svg.hpp"

#include "formats/json_number.hpp"
#include "impl/predicate.hpp"
#include "pictures/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>
#include <string_view>
#include <tuple>

namespace circles::pictures {
namespace {

constexpr double kWidth = 900;
constexpr double kWorldHeight = 630;  // the world's area, below the text band
constexpr double kTextLeft = 10;      // the text's margin, left and right
constexpr double kFontSize = 11;
constexpr double kLineHeight = 15;
constexpr double kMargin = 40;        // between the framed box and the edges of the world's area
constexpr double kLeast = 3;          // the smallest radius drawn, in points
constexpr double kMarker = 7;         // half the size of the + and × markers
// Two labels overprint when their anchors are closer than a line's height, 12 points (a label "#12" is 3
// characters, 20 points, wide: anchors side by side closer than that share a line, one above the other
// closer than a line's height overlap).
constexpr double kLabelClash = 12;
constexpr std::size_t kListedAtMost = 24;  // the list's entries; the rest are counted in a last line
constexpr double kInset = 220;             // the zoomed inset's side, in points
constexpr double kArcAbove = 1e5;        // a circle wider than this, in points, is drawn as its visible arc

constexpr std::string_view kGrey = "#595959", kBlue = "#1a4dd9", kOrange = "#f28c1a", kGreen = "#1a991a",
                           kRed = "#cc1a1a", kBlack = "#000000", kWhite = "#ffffff";

// World coordinates to points: the bounding box of what is drawn, fitted into the area below the text, y down as
// in `circles run`'s frames. In long double, whose range holds the squares and differences of any two doubles.
class PageView {
 public:
  PageView(double band, const std::array<long double, 4>& box) : band_(band) {
    const auto [x0, x1, y0, y1] = box;
    const long double w = kWidth - 2 * kMargin, h = kWorldHeight - 2 * kMargin;
    long double dx = x1 - x0, dy = y1 - y0;
    if (!(dx > 0) && !(dy > 0)) dx = dy = 1;  // a single point: any scale
    scale_ = std::min(dx > 0 ? w / dx : INFINITY, dy > 0 ? h / dy : INFINITY);
    cx_ = (x0 + x1) / 2;
    cy_ = (y0 + y1) / 2;
  }
  long double x(long double wx) const { return kWidth / 2 + (wx - cx_) * scale_; }
  long double y(long double wy) const { return band_ + kWorldHeight / 2 + (wy - cy_) * scale_; }
  long double scale() const { return scale_; }
  double radius(double r) const { return std::max(kLeast, static_cast<double>(r * scale_)); }
  double top() const { return band_; }
  double bottom() const { return band_ + kWorldHeight; }
  // Whether a point lies inside the world's area.
  bool shows(long double px, long double py) const { return px >= 0 && px <= kWidth && py >= top() && py <= bottom(); }

 private:
  double band_;
  long double scale_ = 1, cx_ = 0, cy_ = 0;
};

// An answer may hold NaN, infinities or a negative radius (formats/protocol.hpp, Reading::answer): such a circle
// has no place in the picture, and the report's lines say what it was.
bool drawable(const spec::CircleDoubles& c) {
  return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[4]) && c[4] >= 0;
}

// The most circles of a world framed whole, and labelled whole: the small families' 8.
constexpr std::size_t kFramedWhole = 8;

PageView fit(const CounterexamplePicture& p, double band) { return PageView(band, framed_box(p)); }

// What decides the case, by (3) decided exactly on the doubles: which pairs touch, the least contact of the
// circle that differs (e (8) in the resolved profile, and in the literal one wherever (8) is defined), and the
// circle whose velocity it answered with instead, if any (one it touches first, else any other).
struct Decisions {
  std::vector<std::vector<bool>> touch;
  bool has_circle = false;  // the circle that differs is in the world and in both answers
  std::optional<std::size_t> least, taken;
};

Decisions decide(const CounterexamplePicture& p) {
  const Circles& w = p.world;
  const std::size_t n = w.size(), k = p.circle;
  Decisions d;
  d.touch.assign(n, std::vector<bool>(n, false));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      d.touch[a][b] = d.touch[b][a] = impl::intersect_exact(w[a][0], w[a][1], w[a][4], w[b][0], w[b][1], w[b][4]);
  d.has_circle = k < n && k < p.expected.size() && k < p.actual.size();
  if (!d.has_circle) return d;
  for (std::size_t j = 0; j < n; ++j)
    if (j != k && d.touch[k][j] && (!d.least || std::lexicographical_compare(w[j].begin(), w[j].end(), w[*d.least].begin(),
                                                                             w[*d.least].end())))
      d.least = j;
  const spec::CircleDoubles& answered = p.actual[k];
  const auto has_answered_velocity = [&](std::size_t j) { return w[j][2] == answered[2] && w[j][3] == answered[3]; };
  if (has_answered_velocity(k)) return d;
  for (const bool touching : {true, false})
    for (std::size_t j = 0; j < n && !d.taken; ++j)
      if (j != k && j != d.least && d.touch[k][j] == touching && has_answered_velocity(j)) d.taken = j;
  return d;
}

// zoomed_pair on the case's decisions and the picture's scale, in points per unit.
std::optional<ZoomedPair> zoomed(const CounterexamplePicture& p, const Decisions& d, long double scale) {
  if (!d.has_circle) return std::nullopt;
  const auto& a = p.world[p.circle];
  std::optional<ZoomedPair> nearest;
  for (const std::optional<std::size_t> j : {d.least, d.taken}) {
    if (!j) continue;
    const auto& b = p.world[*j];
    const long double gap = std::hypot(static_cast<long double>(b[0]) - a[0], static_cast<long double>(b[1]) - a[1]) -
                            (static_cast<long double>(a[4]) + b[4]);
    if (std::fabs(gap) * scale < 1 && (!nearest || std::fabs(gap) < std::fabs(nearest->gap)))
      nearest = ZoomedPair{p.circle, *j, gap, d.touch[p.circle][*j]};
  }
  return nearest;
}

// A number as the report writes it: the shortest decimal that reads back as the double.
std::string number_text(double x) {
  std::string text;
  formats::json_number::append_any(text, x);
  return text;
}

// The characters of a UTF-8 text (the report's lines hold −, →, ≈).
std::size_t characters(std::string_view text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}
double text_width(std::string_view text, double size = kFontSize) {
  return static_cast<double>(characters(text)) * kAdvance * size;
}

// The lines of text as drawn: each line of the report cut at spaces so that it ends inside the picture, its
// continuations indented by four spaces more than it. A word wider than the picture stays whole.
std::vector<std::string> wrapped(const std::vector<std::string>& lines) {
  const double room = kWidth - 2 * kTextLeft;
  std::vector<std::string> out;
  for (const std::string& line : lines) {
    const std::size_t first = line.find_first_not_of(' ');
    const std::string indent(first == std::string::npos ? 0 : first + 4, ' ');
    std::string rest = line;
    while (text_width(rest) > room) {
      std::size_t cut = rest.size();
      do cut = rest.rfind(' ', cut - 1);
      while (cut != std::string::npos && cut > indent.size() && text_width(std::string_view(rest).substr(0, cut)) > room);
      if (cut == std::string::npos || cut <= indent.size()) break;
      out.push_back(rest.substr(0, cut));
      rest.replace(0, cut + 1, indent);
    }
    out.push_back(rest);
  }
  return out;
}

// The text band's height for `lines` lines: the lines, then the legend's line.
double band_height(std::size_t lines) {
  return std::max(130.0, 18 + kLineHeight * static_cast<double>(std::max<std::size_t>(lines, 1) - 1) + 52);
}

void draw_text_band(SvgDocument& svg, const std::vector<std::string>& lines) {
  double y = 18;
  for (const std::string& line : lines) {
    svg.text(kTextLeft, y, line, kBlack, kFontSize);
    y += kLineHeight;
  }
}

// The legend, on one line above the world's area, and the rule below it.
void draw_legend(SvgDocument& svg, double band) {
  double x = kTextLeft;
  const double y = band - 12;
  const auto swatch = [&](std::string_view colour, bool filled, bool dashed, std::string_view label) {
    svg.circle(x + 6, y - 4, 6, {colour, 2, dashed ? "4 3" : ""}, filled ? Fill{colour, 0.3} : Fill{});
    svg.text(x + 16, y, label, kBlack, kFontSize);
    x += 16 + text_width(label) + 14;
  };
  swatch(kGrey, false, false, "circle");
  swatch(kBlue, false, false, "differs");
  swatch(kGreen, true, false, "least contact (e)");
  swatch(kRed, true, false, "velocity taken");
  swatch(kGreen, false, true, "expected");
  swatch(kRed, false, true, "answered");
  svg.line(x, y - 4, x + 14, y - 4, {kOrange, 2});
  svg.text(x + 18, y, "contact", kBlack, kFontSize);
  svg.line(0, band, kWidth, band, {kGrey, 0.5});
}

// The axes' directions, at the bottom left of the world's area: x to the right, y down.
void draw_axes(SvgDocument& svg, const PageView& v) {
  const double x = kTextLeft + 8, y = v.bottom() - 44, length = 26;
  svg.line(x, y, x + length, y, {kGrey, 1});
  svg.polyline(std::array<std::array<double, 2>, 3>{{{x + length - 5, y - 3}, {x + length, y}, {x + length - 5, y + 3}}},
               {kGrey, 1});
  svg.text(x + length + 4, y + 4, "x", kGrey, kFontSize);
  svg.line(x, y, x, y + length, {kGrey, 1});
  svg.polyline(std::array<std::array<double, 2>, 3>{{{x - 3, y + length - 5}, {x, y + length}, {x + 3, y + length - 5}}},
               {kGrey, 1});
  svg.text(x + 5, y + length + 2, "y", kGrey, kFontSize);
}

// `n` points of the circle (cx, cy, r) along its arc within `reach` of the point of the circle nearest (tx, ty),
// each mapped by `to_page`: the part of a circle far too large, or seen far too close, to be written as a circle.
template <class ToPage>
std::vector<std::array<double, 2>> arc_near(long double cx, long double cy, long double r, long double tx, long double ty,
                                            long double reach, ToPage to_page) {
  constexpr int kPoints = 97;
  const long double middle = std::atan2(ty - cy, tx - cx);
  const long double half = r > 0 ? std::min<long double>(std::numbers::pi_v<long double>, reach / r) : 0;
  std::vector<std::array<double, 2>> points;
  for (int i = 0; i < kPoints; ++i) {
    const long double angle = middle - half + 2 * half * i / (kPoints - 1);
    points.push_back(to_page(cx + r * std::cos(angle), cy + r * std::sin(angle)));
  }
  return points;
}

// The segment from (x1, y1) to (x2, y2) inside the rectangle [left, right] × [top, bottom], if any part of it is
// (Liang and Barsky's clipping), so that no coordinate written is far outside the page.
std::optional<std::array<double, 4>> clipped(long double x1, long double y1, long double x2, long double y2,
                                             double left, double right, double top, double bottom) {
  long double t0 = 0, t1 = 1;
  const long double dx = x2 - x1, dy = y2 - y1;
  for (const auto& [p, q] : {std::pair{-dx, x1 - left}, std::pair{dx, right - x1}, std::pair{-dy, y1 - top},
                            std::pair{dy, bottom - y1}}) {
    if (p == 0) {
      if (q < 0) return std::nullopt;
      continue;
    }
    const long double t = q / p;
    if (p < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return std::nullopt;
  }
  return std::array<double, 4>{static_cast<double>(x1 + t0 * dx), static_cast<double>(y1 + t0 * dy),
                               static_cast<double>(x1 + t1 * dx), static_cast<double>(y1 + t1 * dy)};
}

// The parts of a polyline inside the rectangle, each a polyline of its own.
std::vector<std::vector<std::array<double, 2>>> clipped(const std::vector<std::array<double, 2>>& points, double left,
                                                        double right, double top, double bottom) {
  std::vector<std::vector<std::array<double, 2>>> parts;
  bool open = false;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const auto s = clipped(points[i - 1][0], points[i - 1][1], points[i][0], points[i][1], left, right, top, bottom);
    if (!s) {
      open = false;
      continue;
    }
    if (!open) parts.push_back({{(*s)[0], (*s)[1]}});
    parts.back().push_back({(*s)[2], (*s)[3]});
    // The part goes on only where the segment ends inside, at the next segment's start.
    open = (*s)[2] == points[i][0] && (*s)[3] == points[i][1];
  }
  return parts;
}

// A circle of the world, if any of it lies in the world's area: as a circle, or, for one wider than kArcAbove
// points, as its arc across the area.
void draw_circle(SvgDocument& svg, const PageView& v, const spec::CircleDoubles& c, Stroke stroke, Fill fill = {},
                 std::string_view tooltip = {}) {
  const long double x = v.x(c[0]), y = v.y(c[1]);
  const long double r = std::max<long double>(kLeast, c[4] * v.scale());
  const long double nx = std::clamp<long double>(x, 0, kWidth), ny = std::clamp<long double>(y, v.top(), v.bottom());
  if (std::hypot(x - nx, y - ny) > r) return;  // wholly outside
  if (r <= kArcAbove) {
    svg.circle(static_cast<double>(x), static_cast<double>(y), static_cast<double>(r), stroke, fill, tooltip);
    return;
  }
  const auto same = [](long double px, long double py) { return std::array{static_cast<double>(px), static_cast<double>(py)}; };
  for (const auto& part : clipped(arc_near(x, y, r, kWidth / 2, (v.top() + v.bottom()) / 2, 2 * kWidth, same), 0, kWidth,
                                  v.top(), v.bottom()))
    svg.polyline(part, stroke);
}

// "#3: (px, py, vx, vy, r) = (0.5, 1, 60, 0, 1)": a circle's tooltip.
std::string tooltip(std::size_t k, const spec::CircleDoubles& c) {
  std::string text = "#" + std::to_string(k) + ": (px, py, vx, vy, r) = (";
  for (std::size_t f = 0; f < c.size(); ++f) text += (f == 0 ? "" : ", ") + number_text(c[f]);
  return text + ")";
}

// The fills of the least contact and of the circle whose velocity was taken, the contacts, and the circles, the
// one that differs last (on top).
void draw_world(SvgDocument& svg, const PageView& v, const CounterexamplePicture& p, const Decisions& d) {
  const Circles& w = p.world;
  const std::size_t n = w.size(), k = p.circle;
  for (const auto& [j, colour] : {std::pair{d.least, kGreen}, std::pair{d.taken, kRed}})
    if (j) draw_circle(svg, v, w[*j], {}, {colour, 0.25});
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      if (!d.touch[a][b]) continue;
      const bool of_k = a == k || b == k;
      if (const auto s = clipped(v.x(w[a][0]), v.y(w[a][1]), v.x(w[b][0]), v.y(w[b][1]), -10, kWidth + 10, v.top() - 10,
                                 v.bottom() + 10))
        svg.line((*s)[0], (*s)[1], (*s)[2], (*s)[3], {kOrange, of_k ? 3.0 : 1.5});
    }
  for (std::size_t pass = 0; pass < 2; ++pass)
    for (std::size_t j = 0; j < n; ++j)
      if ((j == k) == (pass == 1))
        draw_circle(svg, v, w[j], {j == k ? kBlue : kGrey, j == k ? 3.0 : 1.5}, {}, tooltip(j, w[j]));
}

// The circles labelled: every one of a small world; of a bigger one, the circles that decide the case.
std::vector<std::size_t> labelled(const CounterexamplePicture& p, const Decisions& d) {
  std::vector<std::size_t> out;
  const std::size_t n = p.world.size(), k = p.circle;
  for (std::size_t j = 0; j < n; ++j)
    if (n <= kFramedWhole || j == k || (k < n && d.touch[k][j]) || j == d.taken) out.push_back(j);
  return out;
}

// The labelled circles whose centres lie in the world's area, split into those labelled beside their centres
// and those whose labels would overprint another's (anchors closer than kLabelClash, transitively), which go to
// the list.
std::pair<std::vector<std::size_t>, std::vector<std::size_t>> place_labels(const CounterexamplePicture& p,
                                                                           const Decisions& d, const PageView& v) {
  std::vector<std::size_t> shown;
  for (const std::size_t j : labelled(p, d))
    if (v.shows(v.x(p.world[j][0]), v.y(p.world[j][1]))) shown.push_back(j);
  std::vector<std::size_t> group(shown.size());
  std::iota(group.begin(), group.end(), 0);
  const auto root = [&group](std::size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  std::vector<bool> clashes(shown.size(), false);
  for (std::size_t a = 0; a < shown.size(); ++a)
    for (std::size_t b = a + 1; b < shown.size(); ++b) {
      const auto& ca = p.world[shown[a]];
      const auto& cb = p.world[shown[b]];
      if (std::hypot(v.x(ca[0]) - v.x(cb[0]), v.y(ca[1]) - v.y(cb[1])) < kLabelClash) {
        group[root(a)] = root(b);
        clashes[a] = clashes[b] = true;
      }
    }
  std::vector<std::size_t> beside, listed;
  for (std::size_t i = 0; i < shown.size(); ++i) (clashes[i] ? listed : beside).push_back(shown[i]);
  // The list in groups, each group's circles together, in index order within it.
  std::stable_sort(listed.begin(), listed.end(), [&](std::size_t a, std::size_t b) {
    const auto position = [&](std::size_t j) {
      return static_cast<std::size_t>(std::find(shown.begin(), shown.end(), j) - shown.begin());
    };
    return root(position(a)) < root(position(b));
  });
  return {beside, listed};
}

// Each label beside its centre, and the list at the top left of the world's area: "#j" a line, on a white
// ground, joined to its circle's centre by a leader line.
void draw_labels(SvgDocument& svg, const PageView& v, const CounterexamplePicture& p,
                 const std::vector<std::size_t>& beside, const std::vector<std::size_t>& listed) {
  const Circles& w = p.world;
  for (const std::size_t j : beside)
    svg.text(static_cast<double>(v.x(w[j][0])) + 4, static_cast<double>(v.y(w[j][1])) - 4, "#" + std::to_string(j),
             kBlack, kFontSize);
  if (listed.empty()) return;
  const std::size_t entries = std::min(listed.size(), kListedAtMost);
  const double x = kTextLeft, top = v.top() + 8, width = text_width("#0000 ") + 8;
  const double height = kLineHeight * static_cast<double>(entries + (listed.size() > entries ? 1 : 0)) + 6;
  for (std::size_t i = 0; i < entries; ++i) {
    const std::size_t j = listed[i];
    const double y = top + kLineHeight * static_cast<double>(i + 1);
    svg.line(x + width - 4, y - 4, static_cast<double>(v.x(w[j][0])), static_cast<double>(v.y(w[j][1])),
             {j == p.circle ? kBlue : kGrey, 0.6});
  }
  svg.rect(x, top, width, height, {kGrey, 0.5}, {kWhite, 0.85});
  for (std::size_t i = 0; i < entries; ++i)
    svg.text(x + 4, top + kLineHeight * static_cast<double>(i + 1), "#" + std::to_string(listed[i]),
             listed[i] == p.circle ? kBlue : kBlack, kFontSize);
  if (listed.size() > entries)
    svg.text(x + 4, top + kLineHeight * static_cast<double>(entries + 1), "+" + std::to_string(listed.size() - entries),
             kBlack, kFontSize);
}

// The expected and answered positions of the circle that differs (its expected next circle dashed green with a
// +, the answered one dashed red with a ×, each joined to the present centre), and their labels where the
// markers fall on one another (position_labels): the + then twice as large, each label right of the markers or
// else left, the expected above the answered, kept inside the picture.
void draw_positions(SvgDocument& svg, const PageView& v, const CounterexamplePicture& p) {
  const std::size_t k = p.circle;
  const std::vector<std::string> labels = position_labels(p);
  const auto& now = p.world[k];
  for (const auto& [c, colour, cross] : {std::tuple{p.expected[k], kGreen, false}, std::tuple{p.actual[k], kRed, true}}) {
    if (!drawable(c)) continue;
    if (const auto s = clipped(v.x(now[0]), v.y(now[1]), v.x(c[0]), v.y(c[1]), -10, kWidth + 10, v.top() - 10,
                               v.bottom() + 10))
      svg.line((*s)[0], (*s)[1], (*s)[2], (*s)[3], {colour, 0.8});
    draw_circle(svg, v, c, {colour, 2, "6 4"});
    const long double lx = v.x(c[0]), ly = v.y(c[1]);
    if (!v.shows(lx, ly)) continue;
    const double x = static_cast<double>(lx), y = static_cast<double>(ly);
    const double size = !labels.empty() && !cross ? 2 * kMarker : kMarker;
    if (cross) {
      svg.line(x - size, y - size, x + size, y + size, {colour, 2});
      svg.line(x - size, y + size, x + size, y - size, {colour, 2});
    } else {
      svg.line(x - size, y, x + size, y, {colour, 2});
      svg.line(x, y - size, x, y + size, {colour, 2});
    }
    if (labels.empty()) continue;
    const std::string& label = labels[cross ? 1 : 0];
    const double width = text_width(label);
    const double right = x + 3 * kMarker, left = x - 3 * kMarker - width;
    const double label_x = std::clamp(right + width <= kWidth - kTextLeft ? right : left, kTextLeft,
                                      kWidth - kTextLeft - width);
    const double label_y = std::clamp(y + (cross ? 3 * kMarker : -2 * kMarker), v.top() + kLineHeight, v.bottom() - 5);
    svg.text(label_x, label_y, label, colour, kFontSize);
  }
}

// "1.2e-16": a long double to 2 significant digits, for the inset's words.
std::string short_number(long double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2Lg", x);
  return text;
}

// Where the inset looks: in coordinates relative to circle a's centre, where b's centre is the difference of two
// doubles, exact in long double (its size is the pair's own, its distance and radii, however far from the origin
// the pair lies), the point between the two edges and the half side of the window around it: twice the pair's
// distance from touching, or, where they are nearer to touching than an ulp of the largest of their distance and
// radii (exactly tangent, say), that ulp.
struct InsetWindow {
  long double dx, dy;  // b's centre
  long double px, py;  // the point between the edges
  long double half;    // the window's half side
};

InsetWindow inset_window(const spec::CircleDoubles& a, const spec::CircleDoubles& b, long double gap) {
  const long double dx = static_cast<long double>(b[0]) - a[0], dy = static_cast<long double>(b[1]) - a[1];
  const long double d = std::hypot(dx, dy);
  const long double ux = d > 0 ? dx / d : 1, uy = d > 0 ? dy / d : 0;
  const long double along = a[4] + gap / 2;
  const double largest = static_cast<double>(std::max({std::fabs(dx), std::fabs(dy), static_cast<long double>(a[4]),
                                                       static_cast<long double>(b[4])}));
  const long double ulp =
      largest > 0 ? largest - std::nextafter(largest, 0.0) : std::numeric_limits<double>::denorm_min();
  return {dx, dy, ux * along, uy * along, std::max(2 * std::fabs(gap), ulp)};
}

// The inset's corner of the world's area for a place (mx, my) of the picture: the one farthest from it, of the top
// right, the bottom right and, unless the list of labels is there, the top left (the axes' arrows are at the
// bottom left).
std::array<double, 2> inset_corner(const PageView& v, double mx, double my, bool list_shown) {
  const double right = kWidth - kTextLeft - kInset, top = v.top() + 8, bottom = v.bottom() - kInset - 4 * kLineHeight - 8;
  double x0 = right, y0 = top, farthest = -1;
  for (const auto& [x, y, free] : {std::tuple{right, top, true}, std::tuple{right, bottom, true},
                                   std::tuple{kTextLeft, top, !list_shown}}) {
    const double distance = std::hypot(x + kInset / 2 - mx, y + kInset / 2 - my);
    if (free && distance > farthest) x0 = x, y0 = y, farthest = distance;
  }
  return {x0, y0};
}

// The two edges inside the inset at (x0, y0), the other circle's first and wider, so that two edges on one another
// both show; each labelled on its own side, towards its centre. `to_inset` maps the window's coordinates to points.
template <class ToInset>
void draw_inset_edges(SvgDocument& svg, const CounterexamplePicture& p, const ZoomedPair& z, const InsetWindow& window,
                      double x0, double y0, ToInset to_inset) {
  const auto [dx, dy, px, py, half] = window;
  for (const auto& [j, cx, cy] : {std::tuple{z.b, dx, dy}, std::tuple{z.a, 0.0L, 0.0L}}) {
    const double r = p.world[j][4];
    const bool first = j == z.b;
    const std::string_view colour = j == p.circle ? kBlue : kGrey;
    const long double towards = std::atan2(cy - py, cx - px);  // from the edge to the centre
    std::array<double, 2> at = to_inset(cx, cy);
    if (r > 0) {
      for (const auto& part : clipped(arc_near(cx, cy, r, px, py, 3 * half, to_inset), x0, x0 + kInset, y0, y0 + kInset))
        svg.polyline(part, {colour, first ? 4.0 : 2.0});
      at = to_inset(cx - r * std::cos(towards), cy - r * std::sin(towards));
    } else {
      svg.circle(at[0], at[1], 3, {colour, 1}, {colour});
    }
    const double lx = std::clamp(at[0] + 16 * static_cast<double>(std::cos(towards)) - 8, x0 + 2, x0 + kInset - 30);
    const double ly = std::clamp(at[1] + 16 * static_cast<double>(std::sin(towards)) + 4, y0 + 12, y0 + kInset - 4);
    svg.text(lx, ly, "#" + std::to_string(j), colour, kFontSize);
  }
}

// Below the inset at (x0, y0): what (3) decides of the pair, their distance from touching and the inset's scale.
void draw_inset_words(SvgDocument& svg, const ZoomedPair& z, long double scale, double x0, double y0) {
  svg.rect(x0, y0 + kInset, kInset, 4 * kLineHeight + 5, {}, {kWhite, 0.85});
  const auto label = [&](double line, const std::string& text) {
    svg.text(x0 + 2, y0 + kInset + kLineHeight * line, text, kBlack, kFontSize);
  };
  label(1, "#" + std::to_string(z.a) + " and #" + std::to_string(z.b) + (z.touch ? ": touch by (3)" : ": apart by (3)"));
  label(2, "|p_b − p_a| − (r_a + r_b)");
  label(3, "  ≈ " + short_number(z.gap));
  label(4, "1 pt here = " + short_number(1 / scale) + " units");
}

// The zoomed inset of the pair that decides the case (zoomed_pair), in a corner of the world's area: the two
// circles' edges near the point between them, at a scale where the window (inset_window) spans the inset. The
// place is marked in the picture by a square, joined to the inset by a leader line; below the inset, what (3)
// decides, the distance and the scale.
void draw_inset(SvgDocument& svg, const PageView& v, const CounterexamplePicture& p, const ZoomedPair& z,
                bool list_shown) {
  const auto& a = p.world[z.a];
  const InsetWindow window = inset_window(a, p.world[z.b], z.gap);
  const double mx = static_cast<double>(v.x(a[0] + window.px)), my = static_cast<double>(v.y(a[1] + window.py));
  const auto [x0, y0] = inset_corner(v, mx, my, list_shown);
  const long double scale = kInset / 2 / window.half;
  const auto to_inset = [&, x0 = x0, y0 = y0](long double rx, long double ry) {
    return std::array{static_cast<double>(x0 + kInset / 2 + (rx - window.px) * scale),
                      static_cast<double>(y0 + kInset / 2 + (ry - window.py) * scale)};
  };
  // The marker in the picture, and the leader line to the inset's nearest corner.
  svg.rect(mx - 5, my - 5, 10, 10, {kBlack, 1});
  svg.line(mx, my, mx < x0 ? x0 : x0 + kInset, my < y0 ? y0 : y0 + kInset, {kBlack, 0.6, "3 2"});
  svg.rect(x0, y0, kInset, kInset, {kBlack, 1}, {kWhite});
  svg.begin_clip(x0, y0, kInset, kInset);
  draw_inset_edges(svg, p, z, window, x0, y0, to_inset);
  svg.end_clip();
  draw_inset_words(svg, z, scale, x0, y0);
}

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

std::vector<std::string> position_labels(const CounterexamplePicture& p) {
  const std::size_t k = p.circle;
  if (k >= p.world.size() || k >= p.expected.size() || k >= p.actual.size()) return {};
  const auto& expected = p.expected[k];
  const auto& actual = p.actual[k];
  if (!drawable(expected) || !drawable(actual)) return {};
  const PageView v = fit(p, 0);
  if (std::hypot(v.x(expected[0]) - v.x(actual[0]), v.y(expected[1]) - v.y(actual[1])) >= 2 * kMarker) return {};
  const auto label = [](const char* what, const spec::CircleDoubles& c) {
    return std::string(what) + " (" + number_text(c[0]) + ", " + number_text(c[1]) + ")";
  };
  return {label("expected", expected), label("answered", actual)};
}

std::vector<std::size_t> listed_labels(const CounterexamplePicture& p) {
  std::vector<std::size_t> listed = place_labels(p, decide(p), fit(p, 0)).second;
  std::sort(listed.begin(), listed.end());
  return listed;
}

std::optional<ZoomedPair> zoomed_pair(const CounterexamplePicture& p) { return zoomed(p, decide(p), fit(p, 0).scale()); }

std::string counterexample_svg(const CounterexamplePicture& p) {
  const std::vector<std::string> lines = wrapped(p.lines);
  const double band = band_height(lines.size());
  std::string description;
  for (const std::string& line : p.lines) description += (description.empty() ? "" : "\n") + line;
  const std::string title =
      p.lines.empty() ? "circles: a counterexample, circle " + std::to_string(p.circle) : p.lines.front();
  SvgDocument svg(kWidth, band + kWorldHeight, title, description);
  draw_text_band(svg, lines);
  draw_legend(svg, band);
  const PageView v = fit(p, band);
  const Decisions d = decide(p);
  svg.begin_clip(0, band, kWidth, kWorldHeight);
  draw_world(svg, v, p, d);
  const auto [beside, listed] = place_labels(p, d, v);
  draw_labels(svg, v, p, beside, listed);
  if (d.has_circle) draw_positions(svg, v, p);
  if (const std::optional<ZoomedPair> z = zoomed(p, d, v.scale())) draw_inset(svg, v, p, *z, !listed.empty());
  draw_axes(svg, v);
  svg.end_clip();
  return std::move(svg).finish();
}

}  // namespace circles::pictures
