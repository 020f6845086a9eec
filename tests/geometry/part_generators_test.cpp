// tests/geometry/part_generators_test.cpp: the parts of the thesis' mechanisms (geometry/part_generators.hpp):
// every generator gives closed, simple, counter-clockwise profiles over seeded random parameters,
// the claimed n-fold symmetry holds, dimensions match the parameters, and impossible values are
// refused with the parameter to blame.
#include "geometry/part_generators.hpp"
#include "geometry/profile_check.hpp"
#include "geometry/segment_queries.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <numbers>
#include <random>

using namespace qm::geometry;

namespace {

// Smallest distance from x to any segment of the shape.
double distance_to(const Shape& s, const Eigen::Vector2d& x) {
    double d = 1e300;
    for (const auto& p : s.profiles)
        for (const auto& seg : p.segments) d = std::min(d, closest_point(seg, x).distance);
    return d;
}

double size_of(const Shape& s) {
    Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const auto& p : s.profiles) extend_bounds(p, lo, hi);
    return (hi - lo).norm();
}

void check_valid(const Shape& s, const std::string& what) {
    INFO(what);
    const double eps = 1e-9 * size_of(s);
    for (const auto& p : s.profiles) {
        const auto problem = check_profile(p, eps);
        CHECK_MESSAGE(!problem, (problem ? problem->message : std::string()));
        CHECK(signed_area(p) > 0);
    }
    const auto apart = check_profiles_apart(s.profiles, eps);
    CHECK_MESSAGE(!apart, (apart ? apart->message : std::string()));
    // n-fold symmetry: points of the boundary turned by 2 pi / n lie on the boundary.
    const Eigen::Rotation2Dd turn(2 * std::numbers::pi / s.symmetry);
    for (const auto& p : s.profiles)
        for (const auto& seg : p.segments)
            for (double t : {0.0, 0.37, 0.5, 1.0}) CHECK(distance_to(s, turn * seg.point_at(t)) <= 1e-9 * size_of(s));
}

}  // namespace

TEST_CASE("geometry/part_generators: every generator's default shape is valid") {
    for (const auto& g : generators()) {
        const auto r = make_shape(g, {});
        INFO(g.name, ": ", r.error);
        REQUIRE(r.shape);
        check_valid(*r.shape, g.name);
    }
}

TEST_CASE("geometry/part_generators: seeded random parameters give valid shapes or a located refusal") {
    std::mt19937 rng(20240611);
    int made = 0;
    for (const auto& g : generators())
        for (int trial = 0; trial < 40; ++trial) {
            std::vector<std::pair<std::string, double>> settings;
            for (const auto& p : g.params) {
                std::uniform_real_distribution<double> f(0.5, 1.6);
                double x = p.default_value * f(rng);
                if (p.integer) x = std::round(std::max(p.min, x));
                if (p.default_value == 0) x = std::uniform_real_distribution<double>(0, 0.05)(rng);
                settings.emplace_back(p.name, x);
            }
            const auto r = make_shape(g, settings);
            if (!r.shape) {
                CHECK(!r.error.empty());
                continue;
            }
            ++made;
            check_valid(*r.shape, g.name + std::string(" trial ") + std::to_string(trial));
        }
    CHECK(made > 300);
}

TEST_CASE("geometry/part_generators: a spur gear's tips, roots and play match its parameters") {
    for (double play : {0.0, 0.05}) {
        const auto r = make_shape("spur-gear", {{"teeth", 20}, {"pitch-radius", 2}, {"play", play}});
        REQUIRE(r.shape);
        CHECK(r.shape->symmetry == 20);
        const double m = 2 * 2.0 / 20;
        double rmin = 1e300, rmax = 0;
        for (const auto& seg : r.shape->profiles[0].segments)
            for (double t : {0.0, 0.5, 1.0}) {
                rmin = std::min(rmin, seg.point_at(t).norm());
                rmax = std::max(rmax, seg.point_at(t).norm());
            }
        CHECK(rmax == doctest::Approx(2 + m).epsilon(1e-12));
        CHECK(rmin == doctest::Approx(2 - 1.25 * m).epsilon(1e-12));
        // Tooth thickness on the pitch circle: tooth 0's flanks cross it half a pitch minus the
        // play apart (an arc of length thickness).
        const Segment pitch = Segment::arc({2, 0}, {-2, 0}, {0, 0}, true), pitch2 = Segment::arc({-2, 0}, {2, 0}, {0, 0}, true);
        std::vector<double> angles;
        for (const auto& seg : r.shape->profiles[0].segments)
            for (const auto& circle : {pitch, pitch2})
                for (const auto& x : intersections(seg, circle, 1e-12).points) {
                    const double a = std::atan2(x.point.y(), x.point.x());
                    if (std::abs(a) < std::numbers::pi / 20 && (angles.empty() || std::abs(angles.back() - a) > 1e-9)) angles.push_back(a);
                }
        REQUIRE(angles.size() == 2);
        const double thickness = 2.0 * std::abs(angles[0] - angles[1]);  // pitch radius 2
        CHECK(thickness == doctest::Approx(std::numbers::pi * m / 2 - play).epsilon(1e-9));
    }
}

TEST_CASE("geometry/part_generators: impossible values name the parameter to blame") {
    const auto thin = make_shape("spur-gear", {{"teeth", 12}, {"play", 10}});
    REQUIRE(!thin.shape);
    CHECK(thin.bad_param == 2);
    const auto inverted = make_shape("ratchet-wheel", {{"root-radius", 2}, {"tip-radius", 1}});
    REQUIRE(!inverted.shape);
    CHECK(inverted.bad_param == 2);
    const auto few = make_shape("spur-gear", {{"teeth", 2.5}});
    REQUIRE(!few.shape);
    CHECK(few.bad_param == 0);
    const auto unknown = make_shape("block", {{"depth", 1}});
    REQUIRE(!unknown.shape);
    CHECK(unknown.error.find("depth") != std::string::npos);
    CHECK(find_generator("no-such-part") == nullptr);
}
