// geometry/cspace_region.hpp
// Provides:   blocked_region(): the blocked part of a classified configuration space (thesis Def 27,
//             8.1.1) as polygons whose sides run through the boundary points found by bisection
//             (cspace.hpp), not along grid cells: marching squares on each grid cell, its blocked
//             corners joined by the crossings on its edges. A saddle cell (four crossings) is
//             resolved by the oracle at the cell's centre, as trace_boundary() resolves it, so the
//             region's outline is the CSEGs' polylines. A run of wholly blocked cells along a row
//             is one rectangle. For pictures (cspace_svg.hpp) and area measures.
// Ownership:  values.
// Invariants: every polygon is counter-clockwise, has at least 3 vertices and lies in one grid
//             cell or one run of cells of a row; polygons do not overlap. Coordinates are not
//             wrapped: the cells after a periodic axis' last sample end at the axis' hi.
//             Their union is the blocked space to within the boundary tolerance along grid
//             edges and the chord of the boundary across each cell; features narrower than a
//             cell are missed, as in the place vocabulary.
// Knows nothing of the ATMS or the engine; never prints.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/polygon_pair.hpp"
#include <vector>

namespace qm::geometry {

// Pre: space.status == ok; space was classified with this oracle.
[[nodiscard]] std::vector<Polygon> blocked_region(const PairOracle& oracle, const CSpaceResult& space);

// The signed area of a closed polygon (counter-clockwise positive).
[[nodiscard]] double polygon_area(const Polygon& p) noexcept;

}  // namespace qm::geometry
