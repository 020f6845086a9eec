// tests/geometry/segment_queries_test.cpp: exact queries on lines and arcs (geometry/segment_queries.hpp)
// against brute force: dense sampling of seeded random segments.
#include "geometry/segment_queries.hpp"

#include <doctest/doctest.h>
#include <numbers>
#include <random>

using namespace qm::geometry;

namespace {

using V = Eigen::Vector2d;

Segment random_segment(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1, 1), r(0.2, 1.5), a(-std::numbers::pi, std::numbers::pi), sweep(0.2, 5.5);
    if (std::uniform_int_distribution<int>(0, 1)(rng) == 0) return Segment::line(V(u(rng), u(rng)), V(u(rng), u(rng)));
    const V c(u(rng), u(rng));
    const double radius = r(rng), a0 = a(rng), s = sweep(rng);
    const bool ccw = std::uniform_int_distribution<int>(0, 1)(rng) == 1;
    const double a1 = ccw ? a0 + s : a0 - s;
    return Segment::arc(c + radius * V(std::cos(a0), std::sin(a0)), c + radius * V(std::cos(a1), std::sin(a1)), c, ccw);
}

std::vector<V> samples(const Segment& s, int n) {
    std::vector<V> out;
    for (int i = 0; i <= n; ++i) out.push_back(s.point_at(static_cast<double>(i) / n));
    return out;
}

}  // namespace

TEST_CASE("geometry/segment_queries: points, tangents and sweeps of an arc") {
    const Segment quarter = Segment::arc({1, 0}, {0, 1}, {0, 0}, true);
    CHECK(quarter.sweep() == doctest::Approx(std::numbers::pi / 2));
    CHECK(quarter.length() == doctest::Approx(std::numbers::pi / 2));
    CHECK(quarter.point_at(0.5).isApprox(V(std::sqrt(0.5), std::sqrt(0.5))));
    CHECK(quarter.tangent_at(0).isApprox(V(0, 1)));
    CHECK(quarter.outward_normal_at(0).isApprox(V(1, 0)));  // a counter-clockwise arc bulges out
    const Segment back = Segment::arc({0, 1}, {1, 0}, {0, 0}, false);
    CHECK(back.sweep() == doctest::Approx(-std::numbers::pi / 2));
    CHECK(back.outward_normal_at(0.5).isApprox(V(-std::sqrt(0.5), -std::sqrt(0.5))));  // clockwise: hollow
    const Segment big = Segment::arc({1, 0}, {0, -1}, {0, 0}, true);  // three quarters
    CHECK(big.sweep() == doctest::Approx(1.5 * std::numbers::pi));
    CHECK(big.covers_angle(std::numbers::pi));
    CHECK(!big.covers_angle(-0.1));
}

TEST_CASE("geometry/segment_queries: closest points and distances agree with dense sampling") {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 200; ++trial) {
        const Segment a = random_segment(rng), b = random_segment(rng);
        const V p(u(rng), u(rng));
        const auto cp = closest_point(a, p);
        double sampled = 1e300;
        for (const auto& x : samples(a, 4000)) sampled = std::min(sampled, (x - p).norm());
        CHECK(cp.distance <= sampled + 1e-12);
        CHECK(cp.distance >= sampled - a.length() / 4000);
        CHECK((a.point_at(cp.t) - cp.point).norm() < 1e-9);

        const auto d = segment_distance(a, b);
        const auto sa = samples(a, 500), sb = samples(b, 500);
        double brute = 1e300;
        for (const auto& x : sa)
            for (const auto& y : sb) brute = std::min(brute, (x - y).norm());
        INFO("trial ", trial);
        CHECK(d.distance <= brute + 1e-12);
        CHECK(d.distance >= brute - (a.length() + b.length()) / 500);
        CHECK((d.pa - d.pb).norm() == doctest::Approx(d.distance).epsilon(1e-9));
        CHECK(closest_point(a, d.pa).distance < 1e-9);
        CHECK(closest_point(b, d.pb).distance < 1e-9);
        // Meeting and distance 0 go together, and every meeting point is on both.
        const auto meet = intersections(a, b, 1e-12);
        CHECK(meet.points.empty() == (d.distance > 1e-9));
        for (const auto& m : meet.points) {
            CHECK(closest_point(a, m.point).distance < 1e-9);
            CHECK(closest_point(b, m.point).distance < 1e-9);
        }
    }
}

TEST_CASE("geometry/segment_queries: tangent touches and common pieces") {
    // A line tangent to a circle's top: one point.
    const Segment top = Segment::arc({1, 0}, {-1, 0}, {0, 0}, true);
    const auto touch = intersections(Segment::line({-2, 1}, {2, 1}), top, 1e-12);
    REQUIRE(touch.points.size() == 1);
    CHECK(touch.points[0].point.isApprox(V(0, 1)));
    CHECK(!touch.overlap);
    // Collinear lines sharing a piece, and sharing only an end.
    CHECK(intersections(Segment::line({0, 0}, {2, 0}), Segment::line({1, 0}, {3, 0}), 1e-12).overlap);
    const auto ends = intersections(Segment::line({0, 0}, {1, 0}), Segment::line({1, 0}, {3, 0}), 1e-12);
    CHECK(!ends.overlap);
    CHECK(ends.points.size() == 1);
    // Two halves of one circle share only their ends; two overlapping arcs share a piece.
    const Segment bottom = Segment::arc({-1, 0}, {1, 0}, {0, 0}, true);
    const auto halves = intersections(top, bottom, 1e-12);
    CHECK(!halves.overlap);
    CHECK(halves.points.size() == 2);
    CHECK(intersections(top, Segment::arc({0, 1}, {0, -1}, {0, 0}, true), 1e-12).overlap);
}
