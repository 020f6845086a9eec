// geometry/motion_envelope.hpp
// Provides:   MotionEnvelope, a region that contains a part in every configuration of its degree
//             of freedom (a disk about a rotation pivot, a capsule swept along a translation), and
//             envelopes_intersect(), the kinematic-pair test of Def 20: configuration spaces are
//             computed only for pairs whose motion envelopes intersect.
// Ownership:  value types.
// Invariants: radius >= 0; a disk has a == b.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/polygon_pair.hpp"
#include <Eigen/Core>

namespace qm::geometry {

struct MotionEnvelope {
    Eigen::Vector2d a = Eigen::Vector2d::Zero();  // capsule axis from a to b (a == b: a disk)
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    double radius = 0.0;
};

// Envelope of a polygon part over its whole motion: rotation (any angle) or translation with
// offsets in [lo, hi]; a fixed part's envelope is its bounding disk.
// Pre: lo <= hi.
[[nodiscard]] MotionEnvelope envelope_of(const PolygonPart& part, double lo = 0.0, double hi = 0.0);

// Def 20: could the two parts ever touch? Conservative: false only if they never can.
[[nodiscard]] bool envelopes_intersect(const MotionEnvelope& x, const MotionEnvelope& y) noexcept;

}  // namespace qm::geometry
