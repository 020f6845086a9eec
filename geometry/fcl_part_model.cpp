// geometry/fcl_part_model.cpp: parts as extruded FCL meshes.
#include "geometry/fcl_part_model.hpp"

#include "geometry/build_limits.hpp"
#include "qm/assert.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <new>
#include <string>

namespace qm::geometry {
namespace {

std::string bvh_status(int status) {
    switch (status) {
    case fcl::BVH_ERR_MODEL_OUT_OF_MEMORY: return "BVH_ERR_MODEL_OUT_OF_MEMORY (out of memory)";
    case fcl::BVH_ERR_BUILD_OUT_OF_SEQUENCE: return "BVH_ERR_BUILD_OUT_OF_SEQUENCE";
    case fcl::BVH_ERR_BUILD_EMPTY_MODEL: return "BVH_ERR_BUILD_EMPTY_MODEL";
    case fcl::BVH_ERR_BUILD_EMPTY_PREVIOUS_FRAME: return "BVH_ERR_BUILD_EMPTY_PREVIOUS_FRAME";
    case fcl::BVH_ERR_UNSUPPORTED_FUNCTION: return "BVH_ERR_UNSUPPORTED_FUNCTION";
    case fcl::BVH_ERR_UNUPDATED_MODEL: return "BVH_ERR_UNUPDATED_MODEL";
    case fcl::BVH_ERR_INCORRECT_DATA: return "BVH_ERR_INCORRECT_DATA";
    default: return "status " + std::to_string(status);
    }
}

}  // namespace

FclPartModel::FclPartModel(const Part& part, double chordal_tolerance, double height)
    : part_(part), chordal_tolerance_(chordal_tolerance) {
    QM_REQUIRE(chordal_tolerance > 0 && height > 0 && !part.profiles.empty(), "FclPartModel needs a positive tolerance and height, and a shape");
    QM_REQUIRE(chords_needed(part, chordal_tolerance) <= max_chords_per_part, "part '" + part.name + "' needs more chords than the build limit");
    try {
        build(height);
    } catch (const std::bad_alloc&) {  // our arrays, or FCL's that are allocated with throwing new
        throw ModelBuildError("out of memory while building the collision model of part '" + part.name + "'");
    }
}

void FclPartModel::build(double height) {
    const Part& part = part_;
    std::vector<fcl::Vector3d> v;
    std::vector<fcl::Triangle> t;
    for (const auto& profile : part.profiles) {
        outlines_.push_back(tessellate(profile, chordal_tolerance_));
        const Polygon& poly = outlines_.back();
        const std::size_t base = v.size(), n = poly.size();
        for (const auto& p : poly) v.emplace_back(p.x(), p.y(), -height);
        for (const auto& p : poly) v.emplace_back(p.x(), p.y(), height);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            t.emplace_back(base + i, base + j, base + n + j);
            t.emplace_back(base + i, base + n + j, base + n + i);
        }
    }
    auto mesh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    // FCL allocates with new(std::nothrow) and answers a failure with a status; each is checked.
    auto check = [&](int status, const char* step) {
        if (status != fcl::BVH_OK)
            throw ModelBuildError("FCL could not build the collision model of part '" + part.name + "' (" + std::to_string(t.size()) +
                                  " triangles): " + step + " returned " + bvh_status(status));
    };
    check(mesh->beginModel(static_cast<int>(t.size()), static_cast<int>(v.size())), "beginModel");
    check(mesh->addSubModel(v, t), "addSubModel");
    check(mesh->endModel(), "endModel");
    triangles_ = t.size();
    mesh_ = std::move(mesh);
}

bool FclPartModel::contains(const Eigen::Vector2d& x, double q) const {
    const Eigen::Vector2d local = part_.pose(q).inverse() * x;
    for (const auto& poly : outlines_) {
        bool in = false;  // even-odd crossings of a ray along +x
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
            const auto& a = poly[i];
            const auto& b = poly[j];
            if ((a.y() > local.y()) != (b.y() > local.y()) && local.x() < a.x() + (local.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x())) in = !in;
        }
        if (in) return true;
    }
    return false;
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
    if (result.isCollision()) return true;
    // Walls apart: the parts overlap only if one lies wholly inside the other.
    Eigen::Isometry2d shift_a = Eigen::Isometry2d::Identity();
    shift_a.translate(shift);
    return b.contains(shift_a * a.some_point(qa), qb) || a.contains(shift_a.inverse() * b.some_point(qb), qa);
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
