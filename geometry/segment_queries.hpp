// geometry/segment_queries.hpp
// Provides:   exact queries on lines and arcs (profile.hpp): the closest point of a segment to a
//             point, the distance between two segments with its closest points, and their
//             intersection points. These are the exact side of the geometry: profile checks
//             (open, self-intersecting), contact features at a configuration, and the tests'
//             independent checks of FCL's answers on tessellated meshes.
// Ownership:  value results only.
// Invariants: distances are >= 0; closest points lie on their segments (t in [0, 1]).
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/profile.hpp"
#include <Eigen/Core>
#include <vector>

namespace qm::geometry {

struct ClosestPoint {
    double t = 0.0;                                  // parameter on the segment
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    double distance = 0.0;
};

struct SegmentDistance {
    double distance = 0.0;
    double ta = 0.0, tb = 0.0;                       // parameters of the closest points
    Eigen::Vector2d pa = Eigen::Vector2d::Zero(), pb = Eigen::Vector2d::Zero();
};

struct SegmentIntersection {
    double ta = 0.0, tb = 0.0;
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

struct Intersections {
    std::vector<SegmentIntersection> points;  // isolated crossing or touching points
    bool overlap = false;  // collinear lines or arcs of one circle sharing a piece of positive length
};

[[nodiscard]] ClosestPoint closest_point(const Segment& s, const Eigen::Vector2d& p) noexcept;

// Points where a and b meet, within `eps` (a length): tangent touches count as one point.
[[nodiscard]] Intersections intersections(const Segment& a, const Segment& b, double eps);

// Smallest distance between the two segments and where it is attained (0 where they meet).
[[nodiscard]] SegmentDistance segment_distance(const Segment& a, const Segment& b);

}  // namespace qm::geometry
