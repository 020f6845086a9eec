// tests/geometry/gap_abstraction_test.cpp: the gap abstraction of 8.1.6 (PlaceRequest::gap_epsilon,
// geometry/detail/gap_abstraction.cpp): play narrower than epsilon collapses a face and the CSEGs
// bounding it into one place; blocked space never collapses; the result survives the cache.
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_cache.hpp"
#include "geometry/place_vocabulary_builder.hpp"

#include <doctest/doctest.h>
#include <filesystem>
#include <set>
#include <sstream>

using namespace qm::geometry;

namespace {

// Blocked iff q1 lies outside the slot [c - w/2, c + w/2] (free band of width w along q0), or
// (wall) iff q0 lies inside a wall of width w: a thin free gap, or a thin blocked one.
class Slot final : public PairOracle {
public:
    Slot(double width, bool wall) : w_(width), wall_(wall) {}
    bool blocked(const Eigen::Vector2d& q) const override {
        return wall_ ? std::abs(q[0] - 0.5) < 0.5 * w_ : std::abs(q[1] - 0.5) > 0.5 * w_;
    }
    Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override {
        if (wall_) return {q[0] < 0.5 ? -1.0 : 1.0, 0.0};
        return {0.0, q[1] < 0.5 ? 1.0 : -1.0};
    }
    std::string fingerprint() const override { return "slot " + std::to_string(w_) + (wall_ ? " wall" : ""); }
private:
    double w_;
    bool wall_;
};

PlaceRequest square(double gap_epsilon) {
    PlaceRequest r;
    r.cspace.axes = {CSpaceAxis{0, 1, true, 32}, CSpaceAxis{0, 1, false, 32}};
    r.gap_epsilon = gap_epsilon;
    return r;
}

std::string gap_gears(double gap_epsilon) {
    std::ostringstream s;
    s << "(Defmechanism gp Settings ((grid 48 48) (gap-epsilon " << gap_epsilon << "))"
      << " Parts ((g1 (spur-gear (teeth 12) (pitch-radius 1) (play 0.03)) (rotation))"
      << " (g2 (spur-gear (teeth 24) (pitch-radius 2) (play 0.05)) (at 3 0) (rotation))))";
    return s.str();
}

PlaceVocabulary gear_places(double gap_epsilon) {
    qm::Diagnostics d;
    const auto m = read_mechanism("gp.def", gap_gears(gap_epsilon), d);
    REQUIRE(m);
    const auto sel = kinematic_pairs(*m);
    REQUIRE(sel.modelled.size() == 1);
    const auto res = build_place_vocabulary(*pair_oracle(*m, sel.modelled[0]), place_request(*m, sel.modelled[0]));
    REQUIRE(res.status == PlaceStatus::ok);
    return res.vocabulary;
}

}  // namespace

TEST_CASE("geometry/gap_abstraction: a free slot narrower than epsilon is one place bounded on two sides") {
    for (double w : {0.05, 0.2}) {
        Slot slot(w, false);
        const auto keep = build_place_vocabulary(slot, square(0)).vocabulary;
        CHECK(keep.count(PlaceKind::cseg) == 2);
        CHECK(keep.count(PlaceKind::face) == 1);
        for (double eps : {0.5 * w, 0.9 * w, 1.1 * w, 2 * w}) {
            INFO("slot ", w, " epsilon ", eps);
            const auto v = build_place_vocabulary(slot, square(eps)).vocabulary;
            if (eps < w) {  // the gap is kept: the same vocabulary as without the abstraction
                CHECK(v.places.size() == keep.places.size());
                CHECK(v.adjacency == keep.adjacency);
                continue;
            }
            REQUIRE(v.places.size() == 1);
            const Place& g = v.places[0];
            CHECK(g.kind == PlaceKind::face);
            CHECK(g.gap);
            CHECK(std::set<QualDirection>(g.normals.begin(), g.normals.end()) == std::set<QualDirection>{{{0, 1}}, {{0, -1}}});
            // Along the slot it moves over an interval; any motion across meets blocked space.
            REQUIRE(v.adjacency.size() == 8);
            for (const auto& a : v.adjacency) {
                CHECK(a.to == g.id);
                CHECK(a.constrained == (a.motion.s[1] != 0));
                CHECK(!a.instantaneous);
            }
        }
    }
}

TEST_CASE("geometry/gap_abstraction: blocked space never collapses, however thin") {
    Slot wall(0.05, true);
    const auto keep = build_place_vocabulary(wall, square(0)).vocabulary;
    const auto v = build_place_vocabulary(wall, square(0.2)).vocabulary;  // epsilon 4 x the wall
    CHECK(keep.count(PlaceKind::cseg) == 2);
    CHECK(v.places.size() == keep.places.size());
    CHECK(v.adjacency == keep.adjacency);
    for (const auto& p : v.places) CHECK(!p.gap);
}

TEST_CASE("geometry/gap_abstraction: gears' play below epsilon gives the single gear place of 8.1.6") {
    // Play 0.03 + 0.05 on the pitch circle: g2 (radius 2) turns 0.04 rad with g1 held, g1
    // (radius 1) 0.08 rad with g2 held; the gap is the narrower, 0.04 rad (flanks are circles
    // through three points of the involute, so a few per cent either way).
    const auto wide = gear_places(0.9 * 0.04);
    CHECK(wide.count(PlaceKind::cseg) == 2);
    CHECK(wide.count(PlaceKind::face) == 1);
    const auto one = gear_places(1.1 * 0.04);
    REQUIRE(one.places.size() == 1);
    CHECK(one.places[0].gap);
    // Meshing gears turn opposite ways: (+ -) and (- +) go on; every other motion jams.
    for (const auto& a : one.adjacency) {
        const bool opposite = a.motion.s[0] * a.motion.s[1] < 0;
        CHECK(a.constrained == !opposite);
    }
}

TEST_CASE("geometry/gap_abstraction: the gap epsilon is in the cache key and the gap flag round-trips") {
    Slot slot(0.05, false);
    const auto dir = std::filesystem::temp_directory_path() / "qm_gap_cache_test";
    std::filesystem::remove_all(dir);
    const PlaceCache cache(dir);
    CHECK(place_cache_material(slot, square(0)) != place_cache_material(slot, square(0.1)));
    const auto first = build_or_load(slot, square(0.1), cache);
    const auto again = build_or_load(slot, square(0.1), cache);
    CHECK(again.from_cache);
    REQUIRE(again.vocabulary.places.size() == 1);
    CHECK(again.vocabulary.places[0].gap);
    CHECK(again.vocabulary.adjacency == first.vocabulary.adjacency);
    std::filesystem::remove_all(dir);
}
