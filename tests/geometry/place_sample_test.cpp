// tests/geometry/place_sample_test.cpp: a place's sample configuration (place_sample.hpp): a
// face's sample, a join's point, a CSEG's middle point, a straight division's middle the short
// way round a periodic axis; on a built vocabulary every CSEG's and join's sample is within the
// boundary tolerance of contact (limit joins and crossings may lie in free space), every face's sample free.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/place_sample.hpp"
#include "geometry/place_vocabulary_builder.hpp"

#include <doctest/doctest.h>
#include <numbers>

using namespace qm::geometry;

TEST_CASE("geometry/place_sample: by kind, and a division across a periodic seam") {
    CSpaceRequest r;
    r.axes = {CSpaceAxis{0, 2 * std::numbers::pi, true, 16}, CSpaceAxis{0, 1, false, 16}};
    Place division;
    division.kind = PlaceKind::fsd;
    division.axis = 0;
    division.points = {{6.0, 0.5}, {0.5, 0.5}};  // across the seam: 6.0 -> 2 pi -> 0.5
    const Eigen::Vector2d mid = sample_configuration(r, division);
    CHECK(mid.x() == doctest::Approx(std::fmod(6.0 + 0.5 * (0.5 + 2 * std::numbers::pi - 6.0), 2 * std::numbers::pi)));
    CHECK(mid.y() == doctest::Approx(0.5));
    Place cseg;
    cseg.kind = PlaceKind::cseg;
    cseg.points = {{0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}, {0.4, 0.4}};
    CHECK(sample_configuration(r, cseg) == Eigen::Vector2d(0.3, 0.3));
    Place join;
    join.kind = PlaceKind::join;
    join.points = {{1.0, 0.25}};
    CHECK(sample_configuration(r, join) == Eigen::Vector2d(1.0, 0.25));
}

TEST_CASE("geometry/place_sample: CSEGs and joins sample a contact, faces free space") {
    for (const auto& c : {disk_cam_and_follower(), pin_in_slot(), bar_and_block()}) {
        CAPTURE(c.name);
        PlaceRequest req;
        req.cspace.axes = c.axes;
        const auto res = build_place_vocabulary(c.exact, req);
        for (const auto& p : res.vocabulary.places) {
            CAPTURE(p.id.value);
            const Eigen::Vector2d q = sample_configuration(req.cspace, p);
            if (p.kind == PlaceKind::face) CHECK_FALSE(c.exact.blocked(q));
            if (p.kind == PlaceKind::cseg || (p.kind == PlaceKind::join && (p.join_kind == JoinKind::normal_change || p.join_kind == JoinKind::fsd_end)))
                CHECK(c.exact.normal_distance(q) < 1e-6);
        }
    }
}
