// tests/geometry/fcl_pair_oracle_test.cpp: FCL as the metric diagram of a pair (geometry/fcl_pair_oracle.hpp),
// checked against the independent exact 2-D polygon oracle on the same tessellation: the same
// blocked/free answer at seeded random configurations away from the boundary, a distance equal
// to the polygon distance, containment reported as a collision, and a normal pointing into
// free space.
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/part_generators.hpp"
#include "geometry/polygon_pair.hpp"

#include <doctest/doctest.h>
#include <numbers>
#include <random>

using namespace qm::geometry;

namespace {

Part make_part(const std::string& gen, std::vector<std::pair<std::string, double>> params, Eigen::Vector2d at, PolygonDof::Kind kind,
               Eigen::Vector2d axis = Eigen::Vector2d::UnitX()) {
    const auto shape = make_shape(gen, params);
    REQUIRE(shape.shape);
    Part p;
    p.name = gen;
    Eigen::Isometry2d t = Eigen::Isometry2d::Identity();
    t.translate(at);
    for (const auto& profile : shape.shape->profiles) p.profiles.push_back(transformed(profile, t));
    p.dof.kind = kind;
    p.dof.pivot = at;
    p.dof.axis = axis;
    p.lo = -1;
    p.hi = 1;
    p.symmetry = shape.shape->symmetry;
    return p;
}

}  // namespace

TEST_CASE("geometry/fcl_pair_oracle: FCL agrees with the exact polygon oracle away from the boundary") {
    const double tol = 1e-3;
    const std::vector<std::pair<Part, Part>> pairs = {
        {make_part("spur-gear", {{"teeth", 12}, {"play", 0.05}}, {0, 0}, PolygonDof::Kind::rotation),
         make_part("spur-gear", {{"teeth", 12}, {"play", 0.05}}, {2, 0}, PolygonDof::Kind::rotation)},
        {make_part("scape-wheel", {}, {0, 0}, PolygonDof::Kind::rotation), make_part("anchor", {}, {0, 1.4}, PolygonDof::Kind::rotation)},
        {make_part("disk-cam", {}, {0, 0}, PolygonDof::Kind::rotation),
         make_part("follower", {}, {0, 0.5}, PolygonDof::Kind::translation, Eigen::Vector2d::UnitY())},
        {make_part("crank", {}, {0, 0}, PolygonDof::Kind::rotation), make_part("yoke", {}, {0.6, 0}, PolygonDof::Kind::translation)},
    };
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi), offset(-1, 1);
    for (const auto& [a, b] : pairs) {
        const FclPairOracle fcl(a, b, tol);
        const PolygonPairOracle exact(tessellated(a, tol), tessellated(b, tol));
        int blocked = 0, free = 0;
        for (int i = 0; i < 250; ++i) {
            const Eigen::Vector2d q(a.translates() ? offset(rng) : angle(rng), b.translates() ? offset(rng) : angle(rng));
            const double d = exact.distance(q);
            const bool fb = fcl.blocked(q);
            INFO(a.name, " / ", b.name, " q = ", q.transpose());
            CHECK(fb == exact.blocked(q));
            if (!fb) {
                CHECK(fcl.signed_distance(q) == doctest::Approx(d).epsilon(1e-9));
                ++free;
            } else {
                CHECK(fcl.signed_distance(q) < 0);
                ++blocked;
            }
        }
        CHECK(blocked > 10);
        CHECK(free > 10);
    }
}

TEST_CASE("geometry/fcl_pair_oracle: a part wholly inside another is blocked (the caps catch it)") {
    const Part big = make_part("block", {{"width", 4}, {"height", 4}}, {0, 0}, PolygonDof::Kind::fixed);
    const Part small = make_part("disk-cam", {{"radius", 0.3}, {"eccentricity", 0}}, {0, 0}, PolygonDof::Kind::translation);
    for (int order = 0; order < 2; ++order) {
        const FclPairOracle fcl(order ? small : big, order ? big : small, 1e-3);
        CHECK(fcl.blocked({0.0, 0.0}));
        CHECK(fcl.blocked({0.5, 0.5}));
    }
}

TEST_CASE("geometry/fcl_pair_oracle: the free normal points into free space") {
    // Disk cam against a flat follower: raising the follower (q1 up) always frees it.
    const Part cam = make_part("disk-cam", {}, {0, 0}, PolygonDof::Kind::rotation);
    const Part follower = make_part("follower", {}, {0, 0}, PolygonDof::Kind::translation, Eigen::Vector2d::UnitY());
    const FclPairOracle fcl(cam, follower, 1e-4);
    for (double q0 : {-2.0, -0.5, 0.3, 1.9}) {
        // Boundary: the follower's face at the cam's top, 0.2 sin q0 + 0.5.
        const Eigen::Vector2d q(q0, 0.2 * std::sin(q0) + 0.5 + 1e-7);
        const Eigen::Vector2d n = fcl.free_normal(q);
        CHECK(n.y() > 0);
        CHECK(n.x() * std::cos(q0) < 0);  // the cam rising (d/dq0 of its top has the sign of cos q0) closes the gap
    }
    CHECK(fcl.fingerprint().find("fcl-pair/1") == 0);
    CHECK(fcl.fcl_calls() == 0);  // the normal comes from the exact lines and arcs, not FCL
    CHECK(fcl.blocked({0.0, 0.45}));
    CHECK(fcl.fcl_calls() == 1);
}
