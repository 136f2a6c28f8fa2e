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
//     markers are a fixed size, so that positions one ulp apart, which coincide at any scale, both show.
#pragma once

#include "formats/protocol.hpp"
#include "properties/boundaries.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace circles::pictures {

using formats::Circles;

struct CounterexamplePicture {
  Circles world;              // the world asked
  Circles expected, actual;   // the expected answer and the candidate's, the same length as `world`
  std::size_t circle = 0;     // the circle that differs
  properties::Profile profile = properties::Profile::resolved;
  std::vector<std::string> lines;  // the text above the picture, one line each
};

// The SVG document, 900 × 760 points. Coordinates are mapped to the picture in long double, so that worlds
// near DBL_MAX or among the subnormals are drawn too.
std::string counterexample_svg(const CounterexamplePicture& picture);

}  // namespace circles::pictures
