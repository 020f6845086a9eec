// geometry/place_text.hpp
// Provides:   write_place_text(): a place vocabulary as readable lines in the thesis' notation,
//             one place per line, then (adjacent FROM TO (MOTION)) lines as in 8.1.3.
// Ownership:  writes to a caller's stream; keeps nothing.
#pragma once
#include "geometry/place_vocabulary.hpp"
#include <ostream>

namespace qm::geometry {

void write_place_text(std::ostream& os, const PlaceVocabulary& vocabulary);

}  // namespace qm::geometry
