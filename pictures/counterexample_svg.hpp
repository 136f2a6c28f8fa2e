// The picture of a counterexample: an SVG document (pictures/svg.hpp), its text as text.
//
// Its <title> is the report's first line, its <desc> all of them. Above, the text of the report: what was
// checked, the circle and field that differ (expected against actual), which decision differs. Below, the world
// asked, fitted to the picture with y pointing down, as in `circles run`'s frames (an arrow at the corner says
// so):
//   - every circle in grey, the one that differs in blue, each labelled #k beside its centre (a circle smaller
//     than 3 points is drawn at 3, so that points, r = 0, show), its exact fields as its tooltip; the labels of
//     circles whose centres fall within a label's height of one another go to a list at the top left instead,
//     each joined to its circle by a leader line;
//   - every contact (a pair that intersects by (3), decided exactly) as an orange line between the centres,
//     thick for the contacts of the circle that differs;
//   - the least of its contacts, whose velocity it must take (e (8)), filled green; the contact whose velocity
//     it took instead, if any, filled red;
//   - its expected next position as a dashed green circle with a + at the centre, the position answered as a
//     dashed red circle with a × at the centre, each joined to the present centre by a thin line. The two
//     markers are a fixed size; where they fall on one another (positions one ulp apart coincide at any
//     scale), the + is drawn twice as large, so that both show, and each is labelled with its position;
//   - where the pair that decides the case (the circle that differs and its least contact, or the circle whose
//     velocity it took) is closer to touching than a point of the picture, so that the eye cannot tell whether
//     they touch, a zoomed inset in a corner (the one farthest from the place) shows the two edges where they
//     meet, at a scale where their distance spans a quarter of the inset, with a square and a leader line marking
//     the place, and says what (3) decides.
// The report's lines are cut at spaces to fit the width, and the picture grows taller to hold them.
#pragma once

#include "formats/protocol.hpp"
#include "properties/boundaries.hpp"

#include <array>
#include <cstddef>
#include <optional>
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
// contacts, and any circle whose velocity it answered with). Coordinates are mapped to the picture in long
// double, so that worlds near DBL_MAX or among the subnormals are drawn too.
std::string counterexample_svg(const CounterexamplePicture& picture);

// The box of world coordinates the picture frames, {x0, x1, y0, y1}: every drawable circle of a world of up to 8,
// else the circles that decide the case, with the expected and answered images of the circle that differs.
std::array<long double, 4> framed_box(const CounterexamplePicture& picture);

// The labels of the expected and answered positions of the circle that differs, "expected (0.5, 0.0)" and
// "answered (0.5000000000000001, 0.0)", where their markers fall on one another in the picture; none where
// they lie apart or either position cannot be drawn.
std::vector<std::string> position_labels(const CounterexamplePicture& picture);

// The circles whose labels go to the list rather than beside their centres: those whose centres fall within a
// label's height (12 points) of another labelled circle's, in index order.
std::vector<std::size_t> listed_labels(const CounterexamplePicture& picture);

// The pair that decides the case, when the picture cannot show whether it touches: the circle that differs and
// its least contact, or the circle whose velocity it took, whichever is nearer to touching, when that distance,
// |p_b − p_a| − (r_a + r_b) in long double, is under a point of the picture. `touch` is (3) decided exactly.
struct ZoomedPair {
  std::size_t a, b;
  long double gap;  // |p_b − p_a| − (r_a + r_b): negative where they overlap
  bool touch;
};
std::optional<ZoomedPair> zoomed_pair(const CounterexamplePicture& picture);

}  // namespace circles::pictures
