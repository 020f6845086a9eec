// tests/geometry/external_force_test.cpp: position-dependent forces (geometry/external_force.hpp): the
// torque of a weight hung on a turning part changes sign exactly where force_changes() says, and
// when-ranges wrap at a full turn.
#include "geometry/external_force.hpp"

#include <doctest/doctest.h>
#include <numbers>
#include <random>

using namespace qm::geometry;

namespace {

Part turning(Eigen::Vector2d pivot) {
    Part p;
    p.name = "pallets";
    p.profiles = {circle_profile(pivot + Eigen::Vector2d(0, -0.5), 0.2)};
    p.dof.kind = PolygonDof::Kind::rotation;
    p.dof.pivot = pivot;
    return p;
}

}  // namespace

TEST_CASE("geometry/external_force: gravity on a hanging part flips where it hangs straight down") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int trial = 0; trial < 50; ++trial) {
        const Eigen::Vector2d pivot(u(rng), u(rng)), at = pivot + Eigen::Vector2d(u(rng), u(rng)), g(u(rng), u(rng));
        const Part p = turning(pivot);
        ExternalForce f;
        f.kind = ExternalForce::Kind::push;
        f.direction = g;
        f.at = at;
        const auto changes = force_changes(f, p);
        REQUIRE(changes.size() == 2);
        CHECK(changes[1].q - changes[0].q == doctest::Approx(std::numbers::pi));
        for (const auto& c : changes) {
            CHECK(c.q >= 0);
            CHECK(c.q < 2 * std::numbers::pi);
            // The sign differs just before and just after, and is 0 right there.
            CHECK(torque_sign(f, p, c.q - 1e-6, 1e-12) == -torque_sign(f, p, c.q + 1e-6, 1e-12));
            CHECK(torque_sign(f, p, c.q, 1e-9) == 0);
        }
        // Between the changes the sign does not change (brute force along the turn).
        int flips = 0;
        for (int i = 0; i < 720; ++i)
            flips += torque_sign(f, p, 2 * std::numbers::pi * i / 720, 0) != torque_sign(f, p, 2 * std::numbers::pi * (i + 1) / 720, 0);
        CHECK(flips == 2);
    }
    // Hung below the pivot, gravity always turns the part back towards hanging straight down.
    const Part p = turning({0, 1.4});
    ExternalForce gravity;
    gravity.direction = {0, -1};
    gravity.at = Eigen::Vector2d(0, 1.0);
    CHECK(torque_sign(gravity, p, 0.2, 1e-9) == -1);  // swung counter-clockwise the weight moves right; gravity turns it back
    CHECK(torque_sign(gravity, p, -0.2, 1e-9) == 1);
    CHECK(position_dependent(gravity, p));
    ExternalForce spring;
    spring.kind = ExternalForce::Kind::torque;
    spring.torque_sign = 1;
    CHECK(!position_dependent(spring, p));
    CHECK(force_changes(spring, p).empty());
    CHECK(torque_sign(spring, p, 1.0, 1e-9) == 1);
}

TEST_CASE("geometry/external_force: when-ranges wrap at a full turn and bound a slide") {
    const Part p = turning({0, 0});
    ExternalForce f;
    f.kind = ExternalForce::Kind::torque;
    f.torque_sign = -1;
    f.when = std::make_pair(-0.5, 0.5);
    CHECK(force_active(f, p, 0.0));
    CHECK(force_active(f, p, 2 * std::numbers::pi + 0.4));
    CHECK(!force_active(f, p, 1.0));
    const auto changes = force_changes(f, p);
    REQUIRE(changes.size() == 2);
    CHECK(changes[0].q == doctest::Approx(0.5));
    CHECK(changes[1].q == doctest::Approx(2 * std::numbers::pi - 0.5));
    Part slide = p;
    slide.dof.kind = PolygonDof::Kind::translation;
    slide.lo = 0;
    slide.hi = 1;
    f.when = std::make_pair(0.25, 2.0);
    CHECK(force_active(f, slide, 0.5));
    CHECK(!force_active(f, slide, 0.1));
    REQUIRE(force_changes(f, slide).size() == 1);  // the end at 2 lies beyond the limits
    CHECK(force_changes(f, slide)[0].q == 0.25);
}
