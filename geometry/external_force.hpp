// geometry/external_force.hpp
// Provides:   the metric side of the external forces of a metric scene (thesis 8.2.1): whether a
//             force acts at a part's coordinate, where it is applied then, the sign of its torque
//             about the part's pivot, and the coordinates at which any of these changes, which
//             become external place divisions of the pair's configuration space (8.2.1: "adding
//             new metric information indicating where the force changes").
// Ownership:  free functions on values.
// Invariants: force_changes() returns each change once, in [0, 2 pi) for a rotating part and
//             within the translation limits for a sliding one, sorted.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/mechanism.hpp"
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace qm::geometry {

// Pre (all): `part` is the force's part (or one on its shaft, which moves the same way).
// Does the force act with the part at coordinate q? (when-ranges wrap at 2 pi for rotations.)
[[nodiscard]] bool force_active(const ExternalForce& f, const Part& part, double q);
// The point of application at coordinate q, if the force names one.
[[nodiscard]] std::optional<Eigen::Vector2d> application_point(const ExternalForce& f, const Part& part, double q);
// Sign of the force's torque about the pivot at q: +1 counter-clockwise, -1 clockwise, 0 when
// the line of action passes within `zero_length` of the pivot or the part does not rotate.
[[nodiscard]] int torque_sign(const ExternalForce& f, const Part& part, double q, double zero_length);

struct ForceChange {
    double q = 0.0;
    std::string what;  // "starts acting", "stops acting", "torque changes sign"
};
// Where the force's effect on the part changes: the ends of its when-range and, for a force
// applied at a point of a rotating part, the two angles where its line of action passes
// through the pivot (the pallets' gravity flips where they hang straight down).
[[nodiscard]] std::vector<ForceChange> force_changes(const ExternalForce& f, const Part& part);
// Does the force depend on the part's position at all?
[[nodiscard]] bool position_dependent(const ExternalForce& f, const Part& part);

}  // namespace qm::geometry
