// geometry/place_json.hpp
// Provides:   write_place_json(): a place vocabulary and its configuration-space axes as JSON
//             (schema "qm-place-vocabulary/1", documented in docs/PLACES.md).
// Ownership:  writes to a caller's stream; keeps nothing.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/place_vocabulary.hpp"
#include <ostream>

namespace qm::geometry {

void write_place_json(std::ostream& os, const CSpaceRequest& space, const PlaceVocabulary& vocabulary);

}  // namespace qm::geometry
