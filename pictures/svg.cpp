#include "pictures/svg.hpp"

#include "formats/xml_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace circles::pictures {

SvgDocument::SvgDocument(double width, double height, std::string_view title, std::string_view description) {
  out_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"";
  out_ += " width=\"";
  number(width);
  out_ += "pt\" height=\"";
  number(height);
  out_ += "pt\" viewBox=\"0 0 ";
  number(width);
  out_ += ' ';
  number(height);
  out_ += "\">\n<title>" + formats::xml_text(title) + "</title>\n<desc>" + formats::xml_text(description) + "</desc>\n";
  rect(0, 0, width, height, {}, {"#ffffff"});
}

// Points to 2 decimals, the trailing zeros dropped: a hundredth of a point is finer than any screen or printer.
// A coordinate is never infinite or NaN here (the callers clip to the page), but if one were it would be
// written as the page's far edge rather than as text no viewer reads.
void SvgDocument::number(double x) {
  if (!std::isfinite(x)) x = std::isnan(x) ? 0 : std::copysign(1e6, x);
  x = std::clamp(x, -1e6, 1e6);
  char text[32];
  char* end = std::to_chars(text, text + sizeof text, x, std::chars_format::fixed, 2).ptr;
  while (end[-1] == '0') --end;
  if (end[-1] == '.') --end;
  if (end - text == 2 && text[0] == '-' && text[1] == '0') {
    text[0] = '0';
    end = text + 1;
  }
  out_.append(text, end);
}

void SvgDocument::attribute(std::string_view name, double value) {
  out_ += ' ';
  out_ += name;
  out_ += "=\"";
  number(value);
  out_ += '"';
}

void SvgDocument::style(Stroke stroke, Fill fill) {
  out_ += " fill=\"";
  out_ += fill.colour;
  out_ += '"';
  if (fill.opacity != 1) attribute("fill-opacity", fill.opacity);
  out_ += " stroke=\"";
  out_ += stroke.colour;
  out_ += '"';
  if (stroke.colour != "none") attribute("stroke-width", stroke.width);
  if (!stroke.dash.empty()) {
    out_ += " stroke-dasharray=\"";
    out_ += stroke.dash;
    out_ += '"';
  }
}

void SvgDocument::circle(double cx, double cy, double r, Stroke stroke, Fill fill, std::string_view tooltip) {
  out_ += "<circle";
  attribute("cx", cx);
  attribute("cy", cy);
  attribute("r", r);
  style(stroke, fill);
  if (tooltip.empty()) {
    out_ += "/>\n";
  } else {
    out_ += "><title>" + formats::xml_text(tooltip) + "</title></circle>\n";
  }
}

void SvgDocument::line(double x1, double y1, double x2, double y2, Stroke stroke) {
  out_ += "<line";
  attribute("x1", x1);
  attribute("y1", y1);
  attribute("x2", x2);
  attribute("y2", y2);
  style(stroke, {});
  out_ += "/>\n";
}

void SvgDocument::polyline(std::span<const std::array<double, 2>> points, Stroke stroke) {
  out_ += "<polyline points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out_ += ' ';
    number(points[i][0]);
    out_ += ',';
    number(points[i][1]);
  }
  out_ += '"';
  style(stroke, {});
  out_ += "/>\n";
}

void SvgDocument::rect(double x, double y, double width, double height, Stroke stroke, Fill fill) {
  out_ += "<rect";
  attribute("x", x);
  attribute("y", y);
  attribute("width", width);
  attribute("height", height);
  style(stroke, fill);
  out_ += "/>\n";
}

void SvgDocument::text(double x, double y, std::string_view text, std::string_view colour, double size) {
  out_ += "<text xml:space=\"preserve\"";
  attribute("x", x);
  attribute("y", y);
  out_ += " font-family=\"";
  out_ += kFontFamily;
  out_ += '"';
  attribute("font-size", size);
  out_ += " fill=\"";
  out_ += colour;
  out_ += "\">" + formats::xml_text(text) + "</text>\n";
}

void SvgDocument::begin_clip(double x, double y, double width, double height) {
  const std::string id = "clip" + std::to_string(++clips_);
  out_ += "<clipPath id=\"" + id + "\">";
  rect(x, y, width, height, {}, {"#000000"});
  out_ += "</clipPath>\n<g clip-path=\"url(#" + id + ")\">\n";
}

void SvgDocument::end_clip() { out_ += "</g>\n"; }

std::string SvgDocument::finish() && {
  out_ += "</svg>\n";
  return std::move(out_);
}

}  // namespace circles::pictures
