// geometry/placed_part.hpp
// Provides:   PlacedPart, a part's exact profiles (lines and arcs) moved to a coordinate, with a
//             bounding box per segment; and the exact queries on two placed parts: their
//             distance (0 when they touch or overlap) and whether they overlap. These are the
//             exact side of the pair geometry: the normal into free space of the FCL oracle, the
//             exact profile oracle that checks FCL in the tests and measures boundary errors in
//             the accuracy study, and the features of contacts.
// Ownership:  a value owning its moved profiles.
// Invariants: boxes[i][j] bounds profiles[i].segments[j] exactly (arcs included).
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/part.hpp"
#include <utility>
#include <vector>

namespace qm::geometry {

struct Box {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
    [[nodiscard]] double distance(const Box& o) const noexcept;  // 0 if they overlap
};

struct PlacedPart {
    std::vector<Profile> profiles;
    std::vector<std::vector<Box>> boxes;
    Box all;
};

[[nodiscard]] PlacedPart place(const Part& part, double q);

// Exact smallest distance between the two boundaries; 0 when they touch, cross, or one part
// lies inside the other.
[[nodiscard]] double placed_distance(const PlacedPart& a, const PlacedPart& b);
// Do the parts share a point (boundaries meet, or one lies inside the other)?
[[nodiscard]] bool placed_overlap(const PlacedPart& a, const PlacedPart& b);

// The contact between two placed parts that touch or nearly touch: the unit direction `n` in
// which the first part moves away from the second there, and the contact point `x`. Apart: the
// line between the nearest points. Overlapping a little (a configuration found on tessellated
// meshes overlaps the exact arcs by up to the chordal error): the deepest penetration among the
// crossing segments: a vertex of one inside the other (n is the other's surface normal), or the
// middle of a crossing chord (n from both surfaces' normals). `found` is false when no
// direction can be told (corner exactly on corner).
struct ContactDirection {
    Eigen::Vector2d n = Eigen::Vector2d::Zero();
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    bool found = false;
};
// Pre: both parts have profiles; scale is the parts' size (for what counts as touching).
[[nodiscard]] ContactDirection contact_direction(const PlacedPart& a, const PlacedPart& b, double scale);

// The segment pairs (i, s, j, t) whose boxes lie within `radius` of each other: the only pairs
// that can be nearest after either part moves by less than (radius - distance) / 2.
struct SegmentPair {
    int i, s, j, t;
};
[[nodiscard]] std::vector<SegmentPair> near_pairs(const PlacedPart& a, const PlacedPart& b, double radius);
// Smallest distance over the given pairs only (boundaries; containment is not looked at).
[[nodiscard]] double distance_over(const PlacedPart& a, const PlacedPart& b, const std::vector<SegmentPair>& pairs);

}  // namespace qm::geometry
