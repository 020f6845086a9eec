// tests/geometry/profile_check_test.cpp: closed simple profiles (geometry/profile_check.hpp, profile.hpp):
// the problems of a drawn profile are found and named, good profiles pass, exact areas and
// tessellation within the chordal tolerance, and the exact inside test against the polygon one.
#include "geometry/profile_check.hpp"
#include "geometry/segment_queries.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <numbers>
#include <random>

using namespace qm::geometry;

namespace {

using V = Eigen::Vector2d;

// A slot: two half circles joined by lines.
Profile stadium() {
    return Profile{{Segment::line({0, -1}, {2, -1}), Segment::arc({2, -1}, {2, 1}, {2, 0}, true), Segment::line({2, 1}, {0, 1}),
                    Segment::arc({0, 1}, {0, -1}, {0, 0}, true)}};
}

}  // namespace

TEST_CASE("geometry/profile_check: good profiles pass; areas are exact") {
    CHECK(!check_profile(stadium(), 1e-9));
    CHECK(signed_area(stadium()) == doctest::Approx(4 + std::numbers::pi));
    CHECK(signed_area(reversed(stadium())) == doctest::Approx(-4 - std::numbers::pi));
    CHECK(signed_area(counter_clockwise(reversed(stadium()))) == doctest::Approx(4 + std::numbers::pi));
    CHECK(signed_area(circle_profile({3, 4}, 2)) == doctest::Approx(4 * std::numbers::pi));
    const Eigen::Isometry2d t = Eigen::Translation2d(5, -2) * Eigen::Rotation2Dd(0.7);
    CHECK(signed_area(transformed(stadium(), t)) == doctest::Approx(4 + std::numbers::pi));
    V lo(1e9, 1e9), hi(-1e9, -1e9);
    extend_bounds(stadium(), lo, hi);
    CHECK(lo.isApprox(V(-1, -1)));
    CHECK(hi.isApprox(V(3, 1)));
    CHECK(reach(stadium(), {0, 0}) == doctest::Approx(3));
}

TEST_CASE("geometry/profile_check: tessellation stays within the chordal tolerance, vertices on the curve") {
    for (double tol : {1e-1, 1e-3, 1e-6}) {
        std::vector<int> first;
        const Polygon poly = tessellate(stadium(), tol, &first);
        CHECK(first.size() == 4);
        const Profile p = stadium();
        double worst = 0;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            double on = 1e300, mid = 1e300;
            const V m = 0.5 * (poly[i] + poly[(i + 1) % poly.size()]);
            for (const auto& s : p.segments) {
                on = std::min(on, closest_point(s, poly[i]).distance);
                mid = std::min(mid, closest_point(s, m).distance);
            }
            CHECK(on < 1e-12);
            worst = std::max(worst, mid);
        }
        CHECK(worst <= tol);
        CHECK(worst > tol / 4);  // and not needlessly fine
    }
}

TEST_CASE("geometry/profile_check: open, degenerate, self-intersecting and doubled-back profiles are named") {
    using K = ProfileProblem::Kind;
    auto kind = [](const Profile& p) { return check_profile(p, 1e-9).value().kind; };
    CHECK(kind(Profile{{Segment::line({0, 0}, {1, 0}), Segment::line({1, 0}, {1, 1}), Segment::line({1, 1}, {0, 0.5})}}) == K::open);
    CHECK(kind(polygon_profile({{0, 0}, {1, 1}, {1, 0}, {0, 1}})) == K::self_intersecting);
    CHECK(kind(polygon_profile({{0, 0}, {2, 0}, {1, 0}})) == K::self_intersecting);  // doubles back: no area
    CHECK(kind(polygon_profile({{0, 0}, {0, 0}, {1, 0}, {0, 1}})) == K::degenerate_segment);
    CHECK(kind(Profile{{Segment::arc({1, 0}, {0, 2}, {0, 0}, true), Segment::line({0, 2}, {1, 0})}}) == K::bad_arc);
    CHECK(kind(Profile{{Segment::line({0, 0}, {1, 0})}}) == K::too_few_segments);
    // A line that cuts through an arc of the same profile.
    const Profile cut{{Segment::line({0, -1}, {2, -1}), Segment::arc({2, -1}, {2, 1}, {2, 0}, true), Segment::line({2, 1}, {3.5, 0}),
                       Segment::line({3.5, 0}, {0, 1}), Segment::arc({0, 1}, {0, -1}, {0, 0}, true)}};
    const auto problem = check_profile(cut, 1e-9);
    REQUIRE(problem);
    CHECK(problem->kind == K::self_intersecting);
    CHECK(problem->message.find("segments") != std::string::npos);
}

TEST_CASE("geometry/profile_check: a part's profiles must be apart") {
    CHECK(!check_profiles_apart({circle_profile({0, 0}, 1), circle_profile({3, 0}, 1)}, 1e-9));
    CHECK(check_profiles_apart({circle_profile({0, 0}, 1), circle_profile({1.5, 0}, 1)}, 1e-9).value().other == 1);
    CHECK(check_profiles_apart({circle_profile({0, 0}, 3), circle_profile({0.5, 0}, 1)}, 1e-9));  // one inside the other
}

TEST_CASE("geometry/profile_check: the exact inside test agrees with the tessellated one away from the boundary") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.5, 3.5);
    const Profile p = stadium();
    const Polygon poly = tessellate(p, 1e-7);
    // Even-odd crossings of a ray along +x with the chords: the independent, polygonal answer.
    auto in_polygon = [&](const V& x) {
        bool in = false;
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
            if ((poly[i].y() > x.y()) != (poly[j].y() > x.y()) &&
                x.x() < poly[i].x() + (x.y() - poly[i].y()) / (poly[j].y() - poly[i].y()) * (poly[j].x() - poly[i].x()))
                in = !in;
        return in;
    };
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const V x(u(rng), u(rng));
        double d = 1e300;
        for (const auto& s : p.segments) d = std::min(d, closest_point(s, x).distance);
        if (d < 1e-6) continue;  // the chords are within 1e-7 of the arcs
        CHECK(inside(p, x) == in_polygon(x));
        ++checked;
    }
    CHECK(checked > 1900);
}

TEST_CASE("geometry/profile_check: chord counts stay exact for tolerances far below the radius") {
    // acos(1 - t/r) rounds to 0 once t/r is below a double's epsilon; the sine form does not.
    for (const double t : {1e-2, 1e-6, 1e-9}) {
        CAPTURE(t);
        const int n = chords_for(1.0, 2 * std::numbers::pi, t);
        const double sagitta = 1.0 - std::cos(std::numbers::pi / n);
        CHECK(sagitta <= t * (1 + 1e-6));
        CHECK(n >= 2);
        if (n > 2) CHECK(1.0 - std::cos(std::numbers::pi / (n - 1)) > t * (1 - 1e-6));  // the fewest that do
    }
    CHECK_THROWS(static_cast<void>(chords_for(1.0, 2 * std::numbers::pi, 1e-17)));  // beyond max_chords_per_arc: refused
}
