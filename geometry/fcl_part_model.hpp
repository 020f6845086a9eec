// geometry/fcl_part_model.hpp
// Provides:   FclPartModel, a part (part.hpp) as an FCL collision object: its profiles with every
//             arc tessellated to a stated chordal tolerance, extruded to a prism (side walls and
//             ear-clipped caps) held as an FCL BVH mesh (OBBRSS), and the FCL transform of its
//             pose at a coordinate. The two parts of a pair are extruded over different heights
//             ("layers"), so that a part lying wholly inside another crosses the other's cap and
//             FCL reports it; between the layers' common heights the prisms' distance is the
//             2-D distance of the tessellated profiles.
// Ownership:  owns its FCL geometry through a shared_ptr (FCL's convention); copies share it.
// Invariants: chordal_tolerance() > 0; the mesh's vertices lie on the exact profiles.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/part.hpp"
#include <fcl/geometry/collision_geometry.h>
#include <fcl/math/geometry.h>
#include <memory>

namespace qm::geometry {

class FclPartModel {
public:
    // layer 0 spans heights [-h, h], layer 1 [-h/2, 2h], h = `height`.
    // Pre: chordal_tolerance > 0, height > 0, layer is 0 or 1, part has profiles.
    FclPartModel(const Part& part, double chordal_tolerance, int layer, double height);
    [[nodiscard]] const std::shared_ptr<fcl::CollisionGeometryd>& geometry() const noexcept { return mesh_; }
    [[nodiscard]] fcl::Transform3d transform(double q) const;
    [[nodiscard]] const Part& part() const noexcept { return part_; }
    [[nodiscard]] double chordal_tolerance() const noexcept { return chordal_tolerance_; }
    [[nodiscard]] std::size_t triangles() const noexcept { return triangles_; }

private:
    Part part_;
    double chordal_tolerance_;
    std::shared_ptr<fcl::CollisionGeometryd> mesh_;
    std::size_t triangles_ = 0;
};

// Is the pair colliding at coordinates (qa, qb), with a moved further by `shift` (a probe of
// penetration depth)? FCL's narrow phase on the two meshes.
[[nodiscard]] bool fcl_collide(const FclPartModel& a, double qa, const FclPartModel& b, double qb,
                               const Eigen::Vector2d& shift = Eigen::Vector2d::Zero());
// FCL's distance between the meshes at (qa, qb): > 0 when apart; 0 when they touch or overlap.
[[nodiscard]] double fcl_distance(const FclPartModel& a, double qa, const FclPartModel& b, double qb);

}  // namespace qm::geometry
