// The constructions behind gen::boundary_world (properties/boundaries.hpp), one per family.
#pragma once

#include "properties/boundaries.hpp"

#include <rapidcheck.h>

namespace circles::properties::detail {

// The circles of one world of `family`, before properties/boundaries.cpp finishes it (cuts it down to the
// literal domain, shuffles it, drops circles while shrinking): the family's own circles first, then up to two
// bystanders near them. Every number is a finite double built exactly from integers; r >= 0, and r > 0 for
// the literal profile, whose worlds are also ordered so that each circle's contacts have a least element.
rc::Gen<Circles> family_world(Family family, Profile profile);

}  // namespace circles::properties::detail
