// geometry/place_sample.hpp
// Provides:   sample_configuration(), one configuration of a place (thesis 4.2, 8.1.2) at which
//             pictures draw the parts "at" the place and print its number, as the thesis draws
//             the parts at a place in Figures 9.11-9.13: a face's sample inside it, a join's
//             point, the middle point of a CSEG's polyline (a boundary point, parts touching),
//             and the middle of a division (the midpoint of a straight piece, the short way
//             round a periodic axis; else the polyline's middle point).
// Ownership:  a free function on values.
// Invariants: the result lies in the axes' domain (wrapped on periodic axes) and on the place
//             (a CSEG's and a join's within the boundary tolerance of contact).
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/place_vocabulary.hpp"
#include <Eigen/Core>

namespace qm::geometry {

// Pre: place.points is not empty (every built place has a point).
[[nodiscard]] Eigen::Vector2d sample_configuration(const CSpaceRequest& space, const Place& place);

}  // namespace qm::geometry
