// bench/geometry/fcl_pair_oracle.hpp (benchmark only)
// Provides:   FclPairOracle, a PairOracle answering blocked() with FCL collision checks on the two
//             parts extruded to prisms (convex polygons, fan-triangulated), so the accuracy study can
//             time FCL against the exact 2-D polygon oracle. The project's FCL part models are G1's
//             PartModel; this stand-in exists only to measure FCL until those are committed.
// Ownership:  owns its FCL geometry (shared_ptr, as FCL requires).
#pragma once
#include "geometry/pair_oracle.hpp"
#include "geometry/polygon_pair.hpp"

#include <fcl/fcl.h>
#include <memory>
#include <sstream>

namespace qm::geometry::bench {

class FclPairOracle final : public PairOracle {
public:
    // Pre: every polygon is convex and counter-clockwise.
    FclPairOracle(const PolygonPart& a, const PolygonPart& b) : dof_{a.dof, b.dof}, exact_(a, b) {
        model_[0] = prism(a);
        model_[1] = prism(b);
    }
    [[nodiscard]] bool blocked(const Eigen::Vector2d& q) const override {
        fcl::CollisionObjectd oa(model_[0], transform(dof_[0], q[0]));
        fcl::CollisionObjectd ob(model_[1], transform(dof_[1], q[1]));
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        fcl::collide(&oa, &ob, request, result);
        return result.isCollision();
    }
    // Normals come from the exact polygon distance (FCL's mesh distance is not needed to classify).
    [[nodiscard]] Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override { return exact_.free_normal(q); }
    [[nodiscard]] std::string fingerprint() const override { return "fcl " + exact_.fingerprint(); }

private:
    static fcl::Transform3d transform(const PolygonDof& dof, double q) {
        const Eigen::Isometry2d t = pose_at(dof, q);
        fcl::Transform3d out = fcl::Transform3d::Identity();
        out.linear().topLeftCorner<2, 2>() = t.linear();
        out.translation().head<2>() = t.translation();
        return out;
    }
    static std::shared_ptr<fcl::CollisionGeometryd> prism(const PolygonPart& part) {
        auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
        std::vector<fcl::Vector3d> v;
        std::vector<fcl::Triangle> t;
        for (const auto& poly : part.polygons) {
            const auto base = v.size(), n = poly.size();
            for (const auto& p : poly) v.emplace_back(p.x(), p.y(), -1.0);
            for (const auto& p : poly) v.emplace_back(p.x(), p.y(), 1.0);
            for (std::size_t i = 1; i + 1 < n; ++i) {
                t.emplace_back(base, base + i + 1, base + i);              // bottom cap
                t.emplace_back(base + n, base + n + i, base + n + i + 1);  // top cap
            }
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t j = (i + 1) % n;
                t.emplace_back(base + i, base + j, base + n + j);
                t.emplace_back(base + i, base + n + j, base + n + i);
            }
        }
        model->beginModel();
        model->addSubModel(v, t);
        model->endModel();
        return model;
    }
    PolygonDof dof_[2];
    std::shared_ptr<fcl::CollisionGeometryd> model_[2];
    PolygonPairOracle exact_;
};

}  // namespace qm::geometry::bench
