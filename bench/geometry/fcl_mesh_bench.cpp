// bench/geometry/fcl_mesh_bench.cpp: what it costs FCL to find a part lying wholly inside another by
// itself. The library meshes parts as extruded side walls only and adds a point-in-polygon test
// for containment (geometry/fcl_part_model.hpp); the alternative is to close the prisms with
// ear-clipped caps (ear_clipping.hpp) over staggered heights, so that containment is a collision
// too. This times one fcl::collide on each kind of mesh, at configurations on and near the
// contact boundary of two pairs (where a classification spends its time) and at random ones.
// Usage: geometry_fcl_mesh_bench
#include "ear_clipping.hpp"
#include "geometry/part_generators.hpp"
#include "geometry/profile.hpp"

#include <fcl/fcl.h>
#include <chrono>
#include <iostream>
#include <numbers>
#include <random>

using namespace qm::geometry;

namespace {

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> mesh(const Polygon& poly, double z0, double z1, bool caps) {
    std::vector<fcl::Vector3d> v;
    std::vector<fcl::Triangle> t;
    const std::size_t n = poly.size();
    for (const auto& p : poly) v.emplace_back(p.x(), p.y(), z0);
    for (const auto& p : poly) v.emplace_back(p.x(), p.y(), z1);
    if (caps)
        for (const auto& tri : bench::triangulate(poly)) {
            t.emplace_back(tri[0], tri[2], tri[1]);
            t.emplace_back(n + tri[0], n + tri[1], n + tri[2]);
        }
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        t.emplace_back(i, j, n + j);
        t.emplace_back(i, n + j, n + i);
    }
    auto m = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    m->beginModel();
    m->addSubModel(v, t);
    m->endModel();
    return m;
}

fcl::Transform3d turned(double a, Eigen::Vector2d at) {
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    t.translation().head<2>() = at;
    return t;
}

void run(const char* name, const Polygon& a, const Polygon& b, Eigen::Vector2d b_at) {
    for (bool caps : {false, true}) {
        const auto ma = mesh(a, -1, 1, caps), mb = mesh(b, caps ? -0.5 : -1, caps ? 2 : 1, caps);
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> u(0, 2 * std::numbers::pi);
        int hits = 0;
        const int n = 3000;
        const auto t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < n; ++i) {
            fcl::CollisionRequestd rq;
            fcl::CollisionResultd rs;
            fcl::collide(ma.get(), turned(u(rng), {0, 0}), mb.get(), turned(u(rng), b_at), rq, rs);
            hits += rs.isCollision();
        }
        const auto t1 = std::chrono::steady_clock::now();
        std::cout << "| " << name << " | " << a.size() << " + " << b.size() << " | " << (caps ? "walls and caps" : "walls only") << " | "
                  << std::chrono::duration<double, std::micro>(t1 - t0).count() / n << " | " << hits << " / " << n << " |\n";
    }
}

}  // namespace

int main() {
    std::cout << "| pair | outline vertices | mesh | us per fcl::collide | colliding |\n|---|---|---|---|---|\n";
    const auto g1 = make_shape("spur-gear", {{"teeth", 12}, {"play", 0.02}});
    const auto g2 = make_shape("spur-gear", {{"teeth", 18}, {"pitch-radius", 1.5}, {"play", 0.02}});
    run("gears 12 x 18 (chordal 3.3e-4)", tessellate(g1.shape->profiles[0], 3.3e-4), tessellate(g2.shape->profiles[0], 3.3e-4), {2.5, 0});
    const auto wheel = make_shape("scape-wheel", {});
    const auto anchor = make_shape("anchor", {});
    run("scape wheel x anchor (chordal 1.3e-5)", tessellate(wheel.shape->profiles[0], 1.3e-5), tessellate(anchor.shape->profiles[0], 1.3e-5), {0, 1.4});
}
