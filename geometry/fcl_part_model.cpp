// geometry/fcl_part_model.cpp: parts as extruded FCL meshes.
#include "geometry/fcl_part_model.hpp"

#include "geometry/triangulation.hpp"
#include "qm/assert.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

namespace qm::geometry {

FclPartModel::FclPartModel(const Part& part, double chordal_tolerance, int layer, double height)
    : part_(part), chordal_tolerance_(chordal_tolerance) {
    QM_REQUIRE(chordal_tolerance > 0 && height > 0 && (layer == 0 || layer == 1) && !part.profiles.empty(),
               "FclPartModel needs a positive tolerance and height, layer 0 or 1, and a shape");
    const double z0 = layer == 0 ? -height : -0.5 * height, z1 = layer == 0 ? height : 2 * height;
    std::vector<fcl::Vector3d> v;
    std::vector<fcl::Triangle> t;
    for (const auto& profile : part.profiles) {
        const Polygon poly = tessellate(profile, chordal_tolerance);
        const std::size_t base = v.size(), n = poly.size();
        for (const auto& p : poly) v.emplace_back(p.x(), p.y(), z0);
        for (const auto& p : poly) v.emplace_back(p.x(), p.y(), z1);
        for (const auto& tri : triangulate(poly)) {
            const auto a = static_cast<std::size_t>(tri[0]), b = static_cast<std::size_t>(tri[1]), c = static_cast<std::size_t>(tri[2]);
            t.emplace_back(base + a, base + c, base + b);              // bottom cap, facing down
            t.emplace_back(base + n + a, base + n + b, base + n + c);  // top cap, facing up
        }
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            t.emplace_back(base + i, base + j, base + n + j);
            t.emplace_back(base + i, base + n + j, base + n + i);
        }
    }
    auto mesh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    mesh->beginModel(static_cast<int>(t.size()), static_cast<int>(v.size()));
    mesh->addSubModel(v, t);
    mesh->endModel();
    triangles_ = t.size();
    mesh_ = std::move(mesh);
}

fcl::Transform3d FclPartModel::transform(double q) const {
    const Eigen::Isometry2d p = part_.pose(q);
    fcl::Transform3d out = fcl::Transform3d::Identity();
    out.linear().topLeftCorner<2, 2>() = p.linear();
    out.translation().head<2>() = p.translation();
    return out;
}

bool fcl_collide(const FclPartModel& a, double qa, const FclPartModel& b, double qb, const Eigen::Vector2d& shift) {
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::Transform3d ta = a.transform(qa);
    ta.translation().head<2>() += shift;
    fcl::collide(a.geometry().get(), ta, b.geometry().get(), b.transform(qb), request, result);
    return result.isCollision();
}

double fcl_distance(const FclPartModel& a, double qa, const FclPartModel& b, double qb) {
    fcl::DistanceRequestd request;
    request.rel_err = 0;
    request.abs_err = 0;
    fcl::DistanceResultd result;
    const double d = fcl::distance(a.geometry().get(), a.transform(qa), b.geometry().get(), b.transform(qb), request, result);
    return d > 0 ? d : 0.0;
}

}  // namespace qm::geometry
