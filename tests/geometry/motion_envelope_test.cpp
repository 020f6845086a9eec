// tests/geometry/motion_envelope_test.cpp: Def 20 envelopes are conservative (never miss a
// contact) on seeded random pairs, checked against the exact polygon oracle.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/motion_envelope.hpp"
#include "qm/assert.hpp"

#include <doctest/doctest.h>
#include <numbers>
#include <random>

using namespace qm::geometry;

TEST_CASE("geometry/motion_envelope: disjoint envelopes never touch; touching pairs have intersecting envelopes") {
    std::mt19937 rng(20);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int disjoint = 0, touching = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const Polygon box = {{-0.2, -0.1}, {0.2, -0.1}, {0.2, 0.1}, {-0.2, 0.1}};
        PolygonPart a{{tessellated_circle({u(rng) * 0.3, 0}, 0.2, 1e-2)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}};
        Polygon moved = box;
        const Eigen::Vector2d offset(1.0 + u(rng), u(rng));
        for (auto& v : moved) v += offset;
        PolygonPart b{{moved}, {PolygonDof::Kind::translation, {0, 0}, Eigen::Vector2d(u(rng), u(rng)).normalized()}};
        const double lo = -0.5, hi = 0.5;
        const bool meet = envelopes_intersect(envelope_of(a), envelope_of(b, lo, hi));
        const PolygonPairOracle oracle(a, b);
        bool blocked = false;
        for (int i = 0; i < 24 && !blocked; ++i)
            for (int j = 0; j <= 20 && !blocked; ++j)
                blocked = oracle.blocked({2 * std::numbers::pi * i / 24, lo + (hi - lo) * j / 20});
        if (blocked) CHECK(meet);
        disjoint += !meet;
        touching += blocked;
    }
    CHECK(disjoint > 10);  // the test exercises both outcomes
    CHECK(touching > 10);
}

TEST_CASE("geometry/motion_envelope: a fixed part is its bounding disk; capsules meet end to end") {
    PolygonPart fixed{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, {}};
    const auto e = envelope_of(fixed);
    CHECK(e.a.isApprox(Eigen::Vector2d(1, 1)));
    CHECK(e.radius == doctest::Approx(std::sqrt(2.0)));
    CHECK(envelopes_intersect({{0, 0}, {1, 0}, 0.1}, {{1.15, 0}, {3, 0}, 0.1}));
    CHECK(!envelopes_intersect({{0, 0}, {1, 0}, 0.1}, {{1.25, 0}, {3, 0}, 0.1}));
    CHECK(envelopes_intersect({{0, -1}, {0, 1}, 0.0}, {{-1, 0}, {1, 0}, 0.0}));  // crossing segments
    CHECK_THROWS_AS((void)envelope_of(fixed, 1.0, 0.0), qm::InternalError);
}
