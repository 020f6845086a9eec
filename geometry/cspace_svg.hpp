// geometry/cspace_svg.hpp
// Provides:   write_cspace_svg(): a picture of one configuration space in the manner of the
//             thesis' Figures 9.2-9.20: blocked samples shaded, CSEGs solid, FSDs and external
//             divisions dashed, joins as small circles, every place numbered by its id (numbers
//             that would overprint each other are moved to a free spot nearby, with a leader).
// Ownership:  writes to a caller's stream; keeps nothing.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/place_vocabulary.hpp"
#include <ostream>
#include <string>

namespace qm::geometry {

struct SvgOptions {
    int width = 640;
    int height = 480;
    std::string title;
    bool numbers = true;
};

// Pre: space.status == ok.
void write_cspace_svg(std::ostream& os, const CSpaceResult& space, const PlaceVocabulary& vocabulary,
                      const SvgOptions& options = {});

}  // namespace qm::geometry
