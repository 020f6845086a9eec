// geometry/triangulation.hpp
// Provides:   triangulate(), the triangles of a simple polygon by ear clipping, for the caps of
//             the extruded prisms that stand for parts in FCL (fcl_part_model.hpp): with caps,
//             one part lying wholly inside another is a collision, not a miss.
// Ownership:  value results only.
// Invariants: for a simple counter-clockwise polygon of n >= 3 vertices: n - 2 triangles, each
//             counter-clockwise, whose areas sum to the polygon's area (tested).
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/polygon_pair.hpp"
#include <array>
#include <vector>

namespace qm::geometry {

// Pre: poly is simple and counter-clockwise with >= 3 vertices. Degenerate (collinear) vertices
// are allowed; they yield zero-area triangles.
[[nodiscard]] std::vector<std::array<int, 3>> triangulate(const Polygon& poly);

}  // namespace qm::geometry
