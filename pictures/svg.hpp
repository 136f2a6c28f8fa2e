// An SVG 1.1 document written element by element: circles, lines, polylines, rectangles and text, in points.
//
// The counterexample's picture (pictures/counterexample_svg.hpp) is written with it rather than with Cairo's SVG
// surface, which writes every glyph of a text as an outline (cairo-svg.h has no option to keep text as text),
// so that its words could not be searched or copied. Text here is <text>, in a monospace font whose advance the
// caller measures by characters (kAdvance).
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>

namespace circles::pictures {

// The font of every text, and its advance per character at size 1: DejaVu Sans Mono's is 1233/2048 = 0.602 em,
// and the other monospace fonts a viewer may put in its place (Liberation Mono, Menlo, Consolas) advance 0.55
// to 0.602 em. The document names the font; the reader's viewer draws it.
inline constexpr std::string_view kFontFamily = "DejaVu Sans Mono, Liberation Mono, Menlo, Consolas, monospace";
inline constexpr double kAdvance = 0.602;

// How a shape is drawn: colours as "#rrggbb" (or "none"), the stroke's width and dash pattern ("6 4"), the fill's
// opacity.
struct Stroke {
  std::string_view colour = "none";
  double width = 1;
  std::string_view dash = {};
};
struct Fill {
  std::string_view colour = "none";
  double opacity = 1;
};

class SvgDocument {
 public:
  // A document of width × height points with a <title> and a <desc>, on a white background.
  SvgDocument(double width, double height, std::string_view title, std::string_view description);

  // `tooltip`, if any, is the shape's own <title>, which viewers show when the pointer rests on it.
  void circle(double cx, double cy, double r, Stroke stroke, Fill fill = {}, std::string_view tooltip = {});
  void line(double x1, double y1, double x2, double y2, Stroke stroke);
  void polyline(std::span<const std::array<double, 2>> points, Stroke stroke);
  void rect(double x, double y, double width, double height, Stroke stroke, Fill fill = {});
  // Text whose baseline starts at (x, y), in kFontFamily at `size` points, spaces kept.
  void text(double x, double y, std::string_view text, std::string_view colour, double size);

  // What is drawn until end_clip() shows only inside the rectangle.
  void begin_clip(double x, double y, double width, double height);
  void end_clip();

  // The document, closed.
  std::string finish() &&;

 private:
  void number(double x);
  void attribute(std::string_view name, double value);
  void style(Stroke stroke, Fill fill);

  std::string out_;
  int clips_ = 0;
};

}  // namespace circles::pictures
