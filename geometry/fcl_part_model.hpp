// geometry/fcl_part_model.hpp
// Provides:   FclPartModel, a part (part.hpp) as an FCL collision object: its profiles with every
//             arc tessellated to a stated chordal tolerance, extruded to the side walls of a
//             prism held as an FCL BVH mesh (OBBRSS), and the FCL transform of its pose at a
//             coordinate. Two parts' walls meet exactly when their tessellated outlines do, and
//             the walls' distance is the 2-D distance of the outlines. A part lying wholly inside
//             the other has no wall touching the other's, so fcl_collide() adds one
//             point-in-polygon test per part for that case. (Caps on the prisms, ear-clipped,
//             would let FCL find it too, but made each query three times slower: a cap's long
//             thin triangles overlap everything; bench/geometry, docs/perf/geometry.md.)
//             Every step of FCL's model build is checked: FCL reports a failure (out of memory
//             for its arrays) by a status and a line on std::cerr, and a model left half built
//             crashes fcl::collide later (e.g. a gear of pitch radius 1e9 in detect_contacts), so
//             a failure is thrown as ModelBuildError instead.
// Ownership:  owns its FCL geometry through a shared_ptr (FCL's convention); copies share it.
// Invariants: chordal_tolerance() > 0; the mesh's vertices lie on the exact profiles; the model
//             is complete (every FCL build step returned BVH_OK).
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/part.hpp"
#include <fcl/geometry/collision_geometry.h>
#include <fcl/math/geometry.h>
#include <memory>
#include <stdexcept>

namespace qm::geometry {

// FCL could not build a part's model (it ran out of memory for its arrays): a resource failure,
// not a bug; drivers report it with the part and the setting that sizes the model.
class ModelBuildError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class FclPartModel {
public:
    // The walls span heights [-height, height]. Throws ModelBuildError if FCL fails.
    // Pre: chordal_tolerance > 0, height > 0, part has profiles, and its arcs need at most
    // max_chords_per_part chords (build_limits.hpp; the scene checker refuses larger parts).
    FclPartModel(const Part& part, double chordal_tolerance, double height);
    [[nodiscard]] const std::shared_ptr<fcl::CollisionGeometryd>& geometry() const noexcept { return mesh_; }
    [[nodiscard]] fcl::Transform3d transform(double q) const;
    [[nodiscard]] const Part& part() const noexcept { return part_; }
    [[nodiscard]] double chordal_tolerance() const noexcept { return chordal_tolerance_; }
    [[nodiscard]] std::size_t triangles() const noexcept { return triangles_; }
    // Is the world point x inside the tessellated part at coordinate q?
    [[nodiscard]] bool contains(const Eigen::Vector2d& x, double q) const;
    // A point on the part's outline at coordinate q.
    [[nodiscard]] Eigen::Vector2d some_point(double q) const { return part_.pose(q) * outlines_.front().front(); }

private:
    void build(double height);
    Part part_;
    double chordal_tolerance_;
    std::shared_ptr<fcl::CollisionGeometryd> mesh_;
    std::vector<Polygon> outlines_;  // the tessellation, as drawn
    std::size_t triangles_ = 0;
};

// Is the pair colliding at coordinates (qa, qb), with a moved further by `shift` (a probe of
// penetration depth)? FCL's narrow phase on the two walls, or one part inside the other.
[[nodiscard]] bool fcl_collide(const FclPartModel& a, double qa, const FclPartModel& b, double qb,
                               const Eigen::Vector2d& shift = Eigen::Vector2d::Zero());
// FCL's distance between the meshes at (qa, qb): > 0 when apart; 0 when they touch or overlap.
[[nodiscard]] double fcl_distance(const FclPartModel& a, double qa, const FclPartModel& b, double qb);

}  // namespace qm::geometry
