// geometry/cspace_svg.hpp
// Provides:   write_cspace_svg(): a picture of one configuration space in the manner of the
//             thesis' Figures 9.2-9.20 that a reader can check against them: the blocked region
//             filled from the bisected boundary (cspace_region.hpp), CSEGs coloured by their
//             qualitative normal, FSDs dashed, external divisions dotted, joins marked by kind,
//             every place numbered at its sample configuration (place_sample.hpp; numbers that
//             would overprint each other or the legend are moved to a free spot nearby, with a
//             leader), axes with ticks in the scene's units (degrees for a rotation) and a
//             legend. Every element drawn for a place carries data-place="ID" (the explorer page
//             selects places by it).
// Ownership:  writes to a caller's stream; keeps nothing.
// Invariants: the frame is <rect class="frame" ...>; place numbers are the <text> elements of
//             <g class="place-numbers">, each drawn once, no two overlapping (padded by 2 px),
//             none over a join's marker, the legend or the axes' text; the picture grows below
//             its height when the numbers need more room than it has.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/place_vocabulary.hpp"
#include <array>
#include <ostream>
#include <string>

namespace qm::geometry {

// How an axis' values are shown: as they are (plain), as degrees (the coordinate is an angle in
// radians), as lengths (an offset along a translation), or not at all (a fixed part's dummy axis).
enum class AxisUnit { plain, degrees, length, fixed };

struct SvgAxis {
    std::string name = "q";
    AxisUnit unit = AxisUnit::plain;
};

struct SvgOptions {
    int width = 640;
    int height = 480;
    std::string title;
    bool numbers = true;
    bool legend = true;
    std::array<SvgAxis, 2> axes{SvgAxis{"q0"}, SvgAxis{"q1"}};
};

// Pre: space.status == ok, and it was classified with `oracle` (which resolves saddle cells of
// the blocked region as the boundary tracing does).
void write_cspace_svg(std::ostream& os, const PairOracle& oracle, const CSpaceResult& space, const PlaceVocabulary& vocabulary,
                      const SvgOptions& options = {});

}  // namespace qm::geometry
