// The picture of a counterexample: an SVG document drawn with Cairo's SVG surface.
//
// Above, the text of the report: what was checked, the circle and field that differ (expected against
// actual), which decision differs. Below, the world asked, fitted to the picture (y up):
//   - every circle in grey, the one that differs in blue, each labelled #k at its centre (a circle smaller than
//     3 px is drawn at 3 px, so that points, r = 0, show);
//   - every contact (a pair that intersects by (3), decided exactly) as an orange line between the centres,
//     thick for the contacts of the circle that differs;
//   - the least of its contacts, whose velocity it must take (e (8)), filled green; the contact whose velocity
//     it took instead, if any, filled red;
//   - its expected next position as a dashed green circle with a + at the centre, the position answered as a
//     dashed red circle with a × at the centre, each joined to the present centre by a thin line. The two
//     markers are a fixed size; where they fall on one another (positions one ulp apart coincide at any
//     scale), the + is drawn twice as large, so that both show, and each is labelled with its position.
// The report's lines are cut at spaces to fit the width, and the picture grows taller to hold them.
#pragma once

#include "formats/protocol.hpp"
#include "properties/boundaries.hpp"

#include <cstddef>
#include <array>
#include <string>
#include <vector>

namespace circles::pictures {

using spec::Circles;

struct CounterexamplePicture {
  Circles world;              // the world asked
  Circles expected, actual;   // the expected answer and the candidate's, the same length as `world`
  std::size_t circle = 0;     // the circle that differs
  properties::Profile profile = properties::Profile::resolved;
  std::vector<std::string> lines;  // the text above the picture, one line each
};

// The SVG document, 900 × 760 points, taller when the report's lines wrap to more than four. A world of up to 8
// circles is framed whole; a bigger one around the circles that decide the case (the circle that differs, its
// contacts, and any circle whose velocity it answered with). Coordinates are
// mapped to the picture in long double, so that worlds near DBL_MAX or among the subnormals are drawn too.
std::string counterexample_svg(const CounterexamplePicture& picture);

// The box of world coordinates the picture frames, {x0, x1, y0, y1}: every drawable circle of a world of up to 8,
// else the circles that decide the case, with the expected and answered images of the circle that differs.
std::array<long double, 4> framed_box(const CounterexamplePicture& picture);

// The labels of the expected and answered positions of the circle that differs, "expected (0.5, 0.0)" and
// "answered (0.5000000000000001, 0.0)", where their markers fall on one another in the picture; none where
// they lie apart or either position cannot be drawn.
std::vector<std::string> position_labels(const CounterexamplePicture& picture);

}  // namespace circles::pictures
