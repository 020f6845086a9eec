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
                if (p.default_value == 0)  // play, eccentricity, hub: small; mirror: 0 or 1
                    x = p.integer ? std::uniform_int_distribution<int>(0, 1)(rng) : std::uniform_real_distribution<double>(0, 0.05)(rng);
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

TEST_CASE("geometry/part_generators: an anchor on a hub, turned upside down, clears a wheel below the hub") {
    // hub 0 is the first drawing: the bridge's top an arc through (+-span, top), whose radius
    // sqrt(span^2 + top^2) swept into the wheel when the pallets turned over (thesis 9.1).
    const auto old = make_shape("anchor", {});
    REQUIRE(old.shape);
    double top_radius = 0;
    for (const auto& seg : old.shape->profiles[0].segments)
        if (seg.is_arc()) top_radius = seg.radius();
    CHECK(top_radius == doctest::Approx(std::hypot(0.45, 0.1)).epsilon(1e-12));
    std::mt19937 rng(20261125);
    int made = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const double span = std::uniform_real_distribution<double>(0.3, 0.6)(rng);
        const double width = std::uniform_real_distribution<double>(0.05, span / 3)(rng);
        const double top = std::uniform_real_distribution<double>(0.01, 0.15)(rng);
        const double hub = std::uniform_real_distribution<double>(0.1, 0.6)(rng);
        const double reach = std::uniform_real_distribution<double>(width * 1.2, 0.7)(rng);
        const auto r = make_shape("anchor", {{"span", span}, {"reach", reach}, {"width", width}, {"top", top}, {"hub", hub}});
        const bool possible = hub > top && std::sqrt(hub * hub - top * top) > span - 2.25 * width;
        INFO("trial ", trial, " hub ", hub, " top ", top, " span ", span, " width ", width);
        REQUIRE(static_cast<bool>(r.shape) == possible);
        if (!r.shape) {
            CHECK(r.bad_param == 4);
            continue;
        }
        ++made;
        check_valid(*r.shape, "anchor with a hub");
        // Turned over about a pivot 1e-3 more than hub + R above the centre of a wheel of tip
        // radius R, the anchor keeps clear of the wheel's tip circle (the pallets inverted,
        // Figure 9.24); 1e-3 less, and the hub's arc meets it.
        const double R = 1.0;
        for (double margin : {1e-3, -1e-3}) {
            const Eigen::Isometry2d inverted = Eigen::Translation2d(0, hub + R + margin) * Eigen::Rotation2Dd(std::numbers::pi);
            double nearest = 1e300;
            for (const auto& seg : r.shape->profiles[0].segments)
                nearest = std::min(nearest, closest_point(transformed(seg, inverted), Eigen::Vector2d::Zero()).distance);
            CHECK((nearest > R) == (margin > 0));
        }
    }
    CHECK(made > 20);
}

TEST_CASE("geometry/part_generators: a mirrored ratchet wheel or pawl is the mirror image in the y axis") {
    for (const auto& [name, settings] : std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>>{
             {"ratchet-wheel", {{"teeth", 12}}}, {"ratchet-wheel", {{"teeth", 7}, {"root-radius", 0.6}}}, {"pawl", {{"length", 0.9}}}}) {
        auto with = settings;
        with.emplace_back("mirror", 1);
        const auto plain = make_shape(name, settings), mirrored = make_shape(name, with);
        REQUIRE(plain.shape);
        REQUIRE(mirrored.shape);
        check_valid(*mirrored.shape, name + " mirrored");
        CHECK(mirrored.shape->symmetry == plain.shape->symmetry);
        const auto& a = plain.shape->profiles[0];
        const auto& b = *mirrored.shape;
        // Every point of the plain outline, reflected, lies on the mirrored one; the same area.
        for (const auto& seg : a.segments)
            for (double t : {0.0, 0.3, 0.5, 1.0}) {
                const Eigen::Vector2d x = seg.point_at(t);
                CHECK(distance_to(b, Eigen::Vector2d(-x.x(), x.y())) <= 1e-12);
            }
        CHECK(signed_area(b.profiles[0]) == doctest::Approx(signed_area(a)).epsilon(1e-12));
    }
    // A ratchet wheel's radial faces face counter-clockwise; mirrored, clockwise: the outward
    // normal of the face from tooth 1's tip down to its root points along +angle or -angle.
    auto face_sense = [](const Shape& s) {
        for (const auto& seg : s.profiles[0].segments) {
            const Eigen::Vector2d m = seg.point_at(0.5), along = seg.to - seg.from;
            if (std::abs(m.normalized().dot(along.normalized())) > 1 - 1e-9) {  // radial
                const Eigen::Vector2d ccw(-m.y(), m.x());
                return seg.outward_normal_at(0.5).dot(ccw) > 0 ? 1 : -1;
            }
        }
        return 0;
    };
    CHECK(face_sense(*make_shape("ratchet-wheel").shape) == 1);
    CHECK(face_sense(*make_shape("ratchet-wheel", {{"mirror", 1}}).shape) == -1);
    const auto bad = make_shape("pawl", {{"mirror", 2}});
    REQUIRE(!bad.shape);
    CHECK(bad.bad_param == 2);
}
