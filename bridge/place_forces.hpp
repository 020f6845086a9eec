// bridge/place_forces.hpp
// Provides:   the external forces of a mechanism as the envisioner's laws see them (thesis 8.2.1):
//             constant_forces(), the forces whose sign along their part's coordinate is the same
//             everywhere (a spring's torque), and pair_forces(), for one kinematic pair, the sign of
//             every position-dependent force on either part's shaft at each of the pair's places
//             (gravity on the pallets, by the side they hang to; a force acting only in a range).
//             A sign is +1 counter-clockwise (rotation) or along the axis (translation), -1 the
//             other way, 0 where the force does not act or passes through the pivot.
// Ownership:  value types; the functions read the mechanism and the vocabulary and keep nothing.
// Invariants: by_place.size() == the vocabulary's place count; each place lists the pair's
//             position-dependent forces in the mechanism's order.
// Errors:     a force whose sign is not constant within a place (the external divisions should
//             cut the space where it changes, 8.2.1) is a bug of the geometry: InternalError. A
//             place's sign is read at every point the vocabulary keeps of it (a line's polyline, a
//             join's point, a face's sample); points within the zero length of the pivot's line
//             (sign 0) may lie beside points of one sign, which is then the place's sign.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/mechanism.hpp"
#include "geometry/place_vocabulary.hpp"
#include <string>
#include <vector>

namespace qm::bridge {

struct PlaceForce {
    geometry::PartId part{0};  // the force's own part (its shaft-mates share it by linkage)
    std::string cause;
    int sign = 0;
    friend bool operator==(const PlaceForce&, const PlaceForce&) = default;
};

struct PairForces {
    std::vector<std::vector<PlaceForce>> by_place;  // indexed by PlaceId
};

// Forces that do not depend on the part's position, with a non-zero sign.
[[nodiscard]] std::vector<PlaceForce> constant_forces(const geometry::Mechanism& m);

// Pre: pair's parts belong to m; vocabulary is the pair's (q0 = pair.a's coordinate).
[[nodiscard]] PairForces pair_forces(const geometry::Mechanism& m, const geometry::PairSpec& pair,
                                     const geometry::PlaceVocabulary& vocabulary);

}  // namespace qm::bridge
