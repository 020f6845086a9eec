// geometry/mechanism_transform.hpp
// Provides:   the same mechanism drawn elsewhere: every point of the drawing mapped by x -> s R x
//             + d (scaled by s > 0 about the origin, turned by an angle, moved), so that its
//             configuration spaces are the same, a translation's coordinate scaled by s (a place
//             vocabulary must not change when the scene is moved, turned or
//             scaled). Parts' outlines, pivots, translation axes and limits, forces' directions,
//             points and `when` ranges on translating parts go along; angles, symmetries, windows,
//             grids and the settings (relative to the parts' sizes) stay.
// Ownership:  a value in, a value out.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/mechanism.hpp"

namespace qm::geometry {

// Pre: scale > 0 and finite.
[[nodiscard]] Mechanism transformed(const Mechanism& m, double scale, double turn_radians, const Eigen::Vector2d& shift);

}  // namespace qm::geometry
