// geometry/place_text.hpp
// Provides:   write_place_text(): a place vocabulary as readable lines in the thesis' notation,
//             one place per line, then (adjacent FROM TO (MOTION)) lines as in 8.1.3.
//             Coordinates are in the units a person types (the scene file's): an axis whose unit is
//             AxisUnit::degrees (cspace_svg.hpp; the coordinate is an angle in radians) is shown in
//             degrees, as `--config` and the scene's `turn` take them; any other as it is.
// Ownership:  writes to a caller's stream; keeps nothing.
#pragma once
#include "geometry/cspace_svg.hpp"
#include "geometry/place_vocabulary.hpp"
#include <array>
#include <ostream>

namespace qm::geometry {

void write_place_text(std::ostream& os, const PlaceVocabulary& vocabulary,
                      const std::array<AxisUnit, 2>& units = {AxisUnit::plain, AxisUnit::plain});

}  // namespace qm::geometry
