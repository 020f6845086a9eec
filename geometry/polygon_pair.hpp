// geometry/polygon_pair.hpp
// Provides:   PolygonPairOracle, an exact 2-D PairOracle for two parts given as sets of simple
//             polygons (e.g. profiles tessellated to a chordal tolerance), each with one degree of
//             freedom (fixed, rotation about a pivot, translation along a unit axis). It is the
//             exact 2-D fallback used where FCL is not wanted: tests and the accuracy study.
// Ownership:  owns copies of its polygons.
// Invariants: polygons are closed (last vertex joins the first), counter-clockwise, >= 3 vertices.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/pair_oracle.hpp"
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace qm::geometry {

using Polygon = std::vector<Eigen::Vector2d>;

// One part's single degree of freedom, in the pair's configuration coordinate.
struct PolygonDof {
    enum class Kind { fixed, rotation, translation } kind = Kind::fixed;
    Eigen::Vector2d pivot = Eigen::Vector2d::Zero();  // rotation: centre; counter-clockwise positive
    Eigen::Vector2d axis = Eigen::Vector2d::UnitX();  // translation: unit direction
};

struct PolygonPart {
    std::vector<Polygon> polygons;
    PolygonDof dof;
};

// Pose of a part at coordinate q (angle in radians or offset along the axis).
[[nodiscard]] Eigen::Isometry2d pose_at(const PolygonDof& dof, double q);

// True if the interiors of the two placed polygon sets overlap (touching is not overlap).
[[nodiscard]] bool polygons_overlap(const std::vector<Polygon>& a, const std::vector<Polygon>& b);
// Smallest distance between the placed boundaries; 0 if they overlap.
[[nodiscard]] double polygons_distance(const std::vector<Polygon>& a, const std::vector<Polygon>& b);

class PolygonPairOracle final : public PairOracle {
public:
    // q[0] drives part a, q[1] drives part b (a fixed part ignores its coordinate).
    PolygonPairOracle(PolygonPart a, PolygonPart b);
    [[nodiscard]] bool blocked(const Eigen::Vector2d& q) const override;
    // Central differences of the boundary distance, taken on the free side of q.
    [[nodiscard]] Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override;
    [[nodiscard]] std::string fingerprint() const override;
    [[nodiscard]] double distance(const Eigen::Vector2d& q) const;
    // Pre: which is 0 or 1.
    [[nodiscard]] const PolygonPart& part(int which) const { return parts_[which]; }

private:
    [[nodiscard]] std::vector<Polygon> placed(int which, double q) const;
    PolygonPart parts_[2];
    double radius_[2] = {0, 0};  // bounding radius about the pose origin, for an early reject
};

}  // namespace qm::geometry
