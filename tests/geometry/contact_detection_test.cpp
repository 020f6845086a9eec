// tests/geometry/contact_detection_test.cpp: contacts at a configuration (geometry/contact_detection.hpp)
// on the hard cases: tangent contact, edges lying and sliding on each other, a
// corner on a surface, corner against corner (Defs 25-26), a corner in a concave notch, normals
// within tolerance of an axis (sign 0, no flicker), scales 1e-3 to 1e3, and overlap beyond the
// tolerance refused.
#include "geometry/contact_detection.hpp"
#include "geometry/part_generators.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <numbers>

using namespace qm::geometry;

namespace {

using V = Eigen::Vector2d;

Part make(std::vector<Profile> profiles, PolygonDof::Kind kind, V pivot_or_axis = V::Zero(), double lo = -1, double hi = 1) {
    Part p;
    p.name = "part";
    for (auto& x : profiles) p.profiles.push_back(counter_clockwise(x));
    p.dof.kind = kind;
    if (kind == PolygonDof::Kind::rotation) p.dof.pivot = pivot_or_axis;
    if (kind == PolygonDof::Kind::translation) p.dof.axis = pivot_or_axis.normalized();
    p.lo = lo;
    p.hi = hi;
    return p;
}

Profile rect(double x0, double y0, double x1, double y1) { return polygon_profile({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}); }

Profile scaled(const Profile& p, double s) {
    Profile out = p;
    for (auto& seg : out.segments) {
        seg.from *= s;
        seg.to *= s;
        seg.centre *= s;
    }
    return out;
}

const ContactRequest request{1e-3, 1e-6};

}  // namespace

TEST_CASE("geometry/contact_detection: a disk tangent to a flat is one surface contact, within tolerance only") {
    const Part table = make({rect(-2, -1, 2, 0)}, PolygonDof::Kind::fixed);
    const Part disk = make({circle_profile({0.3, 0.5}, 0.5)}, PolygonDof::Kind::translation, V(0, 1));
    const FclPairOracle pair(disk, table, 1e-5);
    const double tol = 1e-3 * disk.size();
    for (double gap : {0.0, 0.4 * tol, -0.4 * tol * 1e-3}) {
        INFO("gap ", gap);
        const auto r = detect_contacts(pair, {gap, 0.0}, request);
        REQUIRE(r.status == ContactStatus::ok);
        REQUIRE(r.contacts.size() == 1);
        const auto& c = r.contacts[0];
        CHECK(c.first.kind == FeatureKind::surface);
        CHECK(c.second.kind == FeatureKind::surface);
        CHECK(c.first.point.x() == doctest::Approx(0.3).epsilon(1e-9));
        CHECK(qualitative(c.first.normal, 1e-6) == QualDirection{{0, -1}});
        CHECK(qualitative(c.second.normal, 1e-6) == QualDirection{{0, 1}});
        CHECK(c.distance <= tol);
    }
    CHECK(detect_contacts(pair, {2 * tol, 0.0}, request).contacts.empty());
}

TEST_CASE("geometry/contact_detection: edges lying on each other touch at both ends of their common stretch, as they slide") {
    const Part table = make({rect(-2, -1, 2, 0)}, PolygonDof::Kind::fixed);
    // A block that slides along x, resting on the table; and the same block turning about its centre.
    const Part slider = make({rect(-0.5, 0, 0.5, 1)}, PolygonDof::Kind::translation, V(1, 0), -3, 3);
    const FclPairOracle sliding(slider, table, 1e-5);
    for (double x : {-1.0, 0.0, 0.7, 1.5 + 1e-3, 2.2}) {  // the last two overhang the table's end
        INFO("x ", x);
        const auto r = detect_contacts(sliding, {x, 0.0}, request);
        REQUIRE(r.contacts.size() == 2);
        for (const auto& c : r.contacts) {
            CHECK(c.first.kind == FeatureKind::surface);
            CHECK(c.second.kind == FeatureKind::surface);
            CHECK(qualitative(c.first.normal, 1e-6) == QualDirection{{0, -1}});
            CHECK(qualitative(c.second.normal, 1e-6) == QualDirection{{0, 1}});
        }
        CHECK(r.contacts[0].first.point.x() == doctest::Approx(std::max(-0.5 + x, -2.0)));
        CHECK(r.contacts[1].first.point.x() == doctest::Approx(std::min(0.5 + x, 2.0)));
    }
    CHECK(detect_contacts(sliding, {2.6, 0.0}, request).contacts.empty());  // slid off the end
    // Turning about its centre, the two ends have origin directions (+ +) and (- +): the
    // qualitatively distinct surfaces of the block's bottom (thesis Figure 2.3).
    const Part turning = make({rect(-0.5, 0, 0.5, 1)}, PolygonDof::Kind::rotation, V(0, 0.5));
    const FclPairOracle pair(turning, table, 1e-5);
    const auto r = detect_contacts(pair, {0.0, 0.0}, request);
    REQUIRE(r.contacts.size() == 2);
    CHECK(origin_direction(turning, 0.0, r.contacts[0].first.point, r.tolerance) == QualDirection{{1, 1}});
    CHECK(origin_direction(turning, 0.0, r.contacts[1].first.point, r.tolerance) == QualDirection{{-1, 1}});
    CHECK(origin_direction(table, 0.0, r.contacts[0].second.point, r.tolerance) == QualDirection{});  // no centre of rotation
}

TEST_CASE("geometry/contact_detection: a corner on a surface, and corner against corner (Defs 18, 25)") {
    const double s = std::sqrt(0.5);
    const Profile diamond = polygon_profile({{0, -s}, {s, 0}, {0, s}, {-s, 0}});  // a unit square turned 45 degrees
    const Part table = make({rect(-2, -1, 2, 0)}, PolygonDof::Kind::fixed);
    Part upper = make({diamond}, PolygonDof::Kind::translation, V(0, 1));
    for (auto& seg : upper.profiles[0].segments) seg.from.y() += s, seg.to.y() += s;
    const FclPairOracle on_table(upper, table, 1e-5);
    auto r = detect_contacts(on_table, {0.0, 0.0}, request);
    REQUIRE(r.contacts.size() == 1);
    const auto& corner = r.contacts[0].first;
    REQUIRE(corner.kind == FeatureKind::corner);
    CHECK(corner.point.isApprox(V(0, 0), 1e-12));
    CHECK(qualitative(corner.sides[0], 1e-6) == QualDirection{{-1, -1}});
    CHECK(qualitative(corner.sides[1], 1e-6) == QualDirection{{1, -1}});
    CHECK(can_contact(corner, r.contacts[0].second.normal, 1e-9));
    CHECK(!can_contact(corner, V(-s, -s), 1e-9));  // a surface facing down-left cannot touch a corner pointing down

    // Corner against corner: the upper diamond's bottom corner on the lower diamond's top corner.
    Part lower = make({diamond}, PolygonDof::Kind::rotation, V(0, -s));
    for (auto& seg : lower.profiles[0].segments) seg.from.y() -= s, seg.to.y() -= s;
    const FclPairOracle tips(upper, lower, 1e-5);
    r = detect_contacts(tips, {0.0, 0.0}, request);
    REQUIRE(r.contacts.size() == 1);
    CHECK(r.contacts[0].first.kind == FeatureKind::corner);
    CHECK(r.contacts[0].second.kind == FeatureKind::corner);
    // Def 25: the lower corner's sides face up-left and up-right, both in the upper corner's
    // reverse half planes; and likewise the other way.
    for (int k = 0; k < 2; ++k) {
        CHECK(can_contact(r.contacts[0].first, r.contacts[0].second.sides[static_cast<std::size_t>(k)], 1e-9));
        CHECK(can_contact(r.contacts[0].second, r.contacts[0].first.sides[static_cast<std::size_t>(k)], 1e-9));
    }
    // Slid sideways by more than the tolerance, the upper corner is on the lower's sloping side.
    r = detect_contacts(tips, {-0.1, 0.0}, request);
    CHECK(r.contacts.empty());  // the slope falls away: no longer touching
}

TEST_CASE("geometry/contact_detection: a corner in a concave notch touches both of the notch's surfaces") {
    // A block with a V notch on top; a wedge pointing down into it.
    const Part notched = make({polygon_profile({{-1, -1}, {1, -1}, {1, 0}, {0.2, 0}, {0, -0.2}, {-0.2, 0}, {-1, 0}})}, PolygonDof::Kind::fixed);
    const Part wedge = make({polygon_profile({{0, -0.2}, {0.1, 0.5}, {-0.1, 0.5}})}, PolygonDof::Kind::translation, V(0, 1));
    const FclPairOracle pair(wedge, notched, 1e-5);
    const auto r = detect_contacts(pair, {0.0, 0.0}, request);
    REQUIRE(r.status == ContactStatus::ok);
    REQUIRE(r.contacts.size() == 2);
    for (const auto& c : r.contacts) {
        CHECK(c.first.kind == FeatureKind::corner);
        CHECK(c.second.kind == FeatureKind::surface);
    }
    CHECK(qualitative(r.contacts[0].second.normal, 1e-6) != qualitative(r.contacts[1].second.normal, 1e-6));
}

TEST_CASE("geometry/contact_detection: a surface within tolerance of an axis has sign 0, without flicker") {
    // A bar turning about a pivot above its bottom, on a table that rises to meet its lowest
    // point: tiny turns tilt the bottom by tiny angles.
    const Part table = make({rect(-2, -1, 2, 0)}, PolygonDof::Kind::translation, V(0, 1));
    const Part bar = make({rect(-1, 0, 1, 0.2)}, PolygonDof::Kind::rotation, V(0, 0.1));
    const FclPairOracle pair(bar, table, 1e-5);
    auto table_at = [](double a) { return 0.1 - std::abs(std::sin(a)) - 0.1 * std::cos(a); };
    for (double a : {-9e-7, -3e-7, -1e-12, 0.0, 1e-12, 3e-7, 9e-7}) {
        INFO("turn ", a);
        const auto r = detect_contacts(pair, {a, table_at(a)}, request);
        REQUIRE(r.contacts.size() == 2);  // lying on each other: both ends of the bottom
        for (const auto& c : r.contacts) {
            CHECK(qualitative(c.first.normal, 1e-6) == QualDirection{{0, -1}});
            CHECK(qualitative(c.second.normal, 1e-6) == QualDirection{{0, 1}});
        }
    }
    // Tilted beyond the tolerance, only the lowest corner touches: turned counter-clockwise the
    // right end lifts and the left corner touches; turned clockwise, the right corner.
    for (double a : {-0.05, 0.05}) {
        const auto r = detect_contacts(pair, {a, table_at(a)}, request);
        REQUIRE(r.contacts.size() == 1);
        CHECK(r.contacts[0].first.kind == FeatureKind::corner);
        CHECK((r.contacts[0].first.point.x() < 0) == (a > 0));
    }
}

TEST_CASE("geometry/contact_detection: the same contacts at scales 1e-3 to 1e3") {
    const auto ratchet = make_shape("ratchet-wheel", {{"teeth", 12}});
    const auto pawl = make_shape("pawl", {});
    REQUIRE(ratchet.shape);
    REQUIRE(pawl.shape);
    std::vector<std::string> first;
    for (double scale : {1e-3, 1.0, 1e3}) {
        const Part wheel = make({scaled(ratchet.shape->profiles[0], scale)}, PolygonDof::Kind::rotation, V::Zero());
        Part arm = make({scaled(pawl.shape->profiles[0], scale)}, PolygonDof::Kind::rotation, V(0.3, 1.6) * scale);
        const Eigen::Isometry2d place = Eigen::Translation2d(V(0.3, 1.6) * scale) * Eigen::Rotation2Dd(0.5);
        arm.profiles[0] = transformed(arm.profiles[0], place);
        const FclPairOracle pair(wheel, arm, 1e-5 * scale);
        // Turn the pawl down onto the wheel until it touches (bisection on FCL), then look.
        double lo = 0.0, hi = 0.0;
        REQUIRE(!pair.blocked({0.0, lo}));
        while (!pair.blocked({0.0, hi}) && hi > -2 * std::numbers::pi) hi -= 0.01;
        REQUIRE(pair.blocked({0.0, hi}));
        lo = hi + 0.01;
        for (int i = 0; i < 60; ++i) (pair.blocked({0.0, 0.5 * (lo + hi)}) ? hi : lo) = 0.5 * (lo + hi);
        const auto r = detect_contacts(pair, {0.0, lo}, request);
        std::vector<std::string> sig;
        for (const auto& c : r.contacts) {
            std::string s = std::to_string(static_cast<int>(c.first.kind)) + std::to_string(c.first.segment) + "/" +
                            std::to_string(static_cast<int>(c.second.kind)) + std::to_string(c.second.segment);
            if (c.first.kind == FeatureKind::surface) s += to_string(qualitative(c.first.normal, 1e-6));
            if (c.second.kind == FeatureKind::surface) s += to_string(qualitative(c.second.normal, 1e-6));
            s += to_string(origin_direction(arm, lo, c.second.point, r.tolerance));
            sig.push_back(s);
        }
        INFO("scale ", scale);
        REQUIRE(!sig.empty());
        if (first.empty()) first = sig;
        CHECK(sig == first);
    }
}

TEST_CASE("geometry/contact_detection: overlap beyond the tolerance is refused; far apart is nothing") {
    const Part table = make({rect(-2, -1, 2, 0)}, PolygonDof::Kind::fixed);
    const Part block = make({rect(-0.5, 0, 0.5, 1)}, PolygonDof::Kind::translation, V(0, 1));
    const FclPairOracle pair(block, table, 1e-5);
    const auto deep = detect_contacts(pair, {-0.1, 0.0}, request);
    CHECK(deep.status == ContactStatus::overlapping);
    CHECK(deep.message.find("overlap") != std::string::npos);
    const auto shallow = detect_contacts(pair, {-0.2 * deep.tolerance, 0.0}, request);
    CHECK(shallow.status == ContactStatus::ok);
    CHECK(shallow.contacts.size() == 2);
    const auto far = detect_contacts(pair, {0.5, 0.0}, request);
    CHECK(far.status == ContactStatus::ok);
    CHECK(far.contacts.empty());
    CHECK(far.fcl_distance == doctest::Approx(0.5));
}

TEST_CASE("geometry/contact_detection: parts apart beyond the contact tolerance are found so without FCL") {
    // A disk above a table, lowered through touching into overlap: wherever the exact profiles say
    // "apart", FCL finds no contact and no overlap; near and inside they say nothing.
    const Part table = make({rect(-2, -1, 2, 0)}, PolygonDof::Kind::fixed);
    const Part disk = make({circle_profile({0, 0.5}, 0.5)}, PolygonDof::Kind::translation, V(0, 1));
    const double chordal = 1e-3;
    const FclPairOracle pair(disk, table, chordal);
    const double reach = request.tolerance * std::min(disk.size(), table.size()) + 4 * chordal;
    int apart = 0, undecided = 0;
    for (double y = 0.2; y > -0.1; y -= 0.001) {
        const V q(y, 0.0);
        if (apart_beyond_contact(disk, table, q, request, chordal)) {
            ++apart;
            const auto r = detect_contacts(pair, q, request);
            CHECK(r.status == ContactStatus::ok);
            CHECK(r.contacts.empty());
        } else {
            ++undecided;
            CHECK(y < reach + 1e-9);  // the disk's lowest point is at y
        }
    }
    CHECK(apart > 0);
    CHECK(undecided > 0);
    CHECK_FALSE(apart_beyond_contact(disk, table, {-0.05, 0.0}, request, chordal));
}

TEST_CASE("geometry/contact_detection: the origin direction resolved against a contact's normal (7.3, Def 17)") {
    // A part turning about (0 0), touched at (-0.8 0.5): its origin direction is (+ -). Against a
    // normal (0.6 -0.8), also (+ -), the turn across the normal is qualitatively ambiguous
    // ((+)(-) - (-)(+)), exactly -0.64 + 0.30: the x term wins, so the origin is taken as (+ 0).
    const Part turning = make({rect(-1, -1, 1, 1)}, PolygonDof::Kind::rotation, V(0, 0));
    const V point(-0.8, 0.5);
    CHECK(origin_direction(turning, 0.0, point, 1e-9) == QualDirection{{1, -1}});
    CHECK(origin_direction_at_contact(turning, 0.0, point, V(0.6, -0.8), 1e-9, 1e-6) == QualDirection{{1, 0}});
    // The y term wins against (0.9 -0.43589): -0.3487 against -0.45.
    CHECK(origin_direction_at_contact(turning, 0.0, point, V(0.9, -std::sqrt(1 - 0.81)), 1e-9, 1e-6) == QualDirection{{0, -1}});
    // Not ambiguous (normal (+ +)): unchanged.
    CHECK(origin_direction_at_contact(turning, 0.0, point, V(std::sqrt(0.5), std::sqrt(0.5)), 1e-9, 1e-6) == QualDirection{{1, -1}});
    // The normal along the origin's line: the exact turn is zero, so nothing is decided: unchanged.
    const V along = V(0.8, -0.5).normalized();
    CHECK(origin_direction_at_contact(turning, 0.0, point, along, 1e-9, 1e-6) == QualDirection{{1, -1}});
    // A part that does not turn has no origin direction.
    const Part table = make({rect(-2, -1, 2, 0)}, PolygonDof::Kind::fixed);
    CHECK(origin_direction_at_contact(table, 0.0, point, V(0.6, -0.8), 1e-9, 1e-6) == QualDirection{});
}
