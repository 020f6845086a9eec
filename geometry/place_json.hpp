// geometry/place_json.hpp
// Provides:   write_place_json(): a place vocabulary and its configuration-space axes as JSON
//             (schema "qm-place-vocabulary/1", documented in docs/PLACES.md). Coordinates are as the
//             geometry holds them (radians for a rotation); with units given, each axis states its
//             unit ("unit": "radian", "length" or "fixed"), so a program can convert.
// Ownership:  writes to a caller's stream; keeps nothing.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/place_vocabulary.hpp"
#include <array>
#include <ostream>

namespace qm::geometry {

void write_place_json(std::ostream& os, const CSpaceRequest& space, const PlaceVocabulary& vocabulary,
                      const std::array<AxisUnit, 2>& units = {AxisUnit::plain, AxisUnit::plain});

}  // namespace qm::geometry
