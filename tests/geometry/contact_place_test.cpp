// tests/geometry/contact_place_test.cpp: the single place of parts that move only in contact
// (geometry/contact_place.hpp): gears meshing with zero play must give the place that 8.1.6's gap
// abstraction gives the same gears with a little play (an independent construction from the sampled
// space), a block resting on a table and sliding along it one place where it slides both ways,
// and parts drawn overlapping no place.
#include "mechanism_text.hpp"
#include "geometry/contact_place.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"

#include <doctest/doctest.h>
#include <set>
#include <sstream>

using namespace qm::geometry;
using qm::geometry::test::read;

namespace {


std::optional<PlaceVocabulary> in_contact(const Mechanism& m) {
    const auto sel = kinematic_pairs(m);
    REQUIRE(sel.modelled.size() == 1);
    const auto oracle = pair_oracle(m, sel.modelled[0]);
    return contact_place(*oracle, place_request(m, sel.modelled[0]), {m.settings.contact_tolerance, m.settings.normal_zero_tolerance});
}

std::set<std::string> motions(const PlaceVocabulary& v, bool constrained) {
    std::set<std::string> out;
    for (const auto& a : v.adjacency)
        if (a.constrained == constrained) out.insert(to_string(a.motion));
    return out;
}

std::string gears(double play, const std::string& settings) {
    std::ostringstream os;
    os << "(Defmechanism gears Settings ((grid 48 48)" << settings << ") Parts ((g1 (spur-gear (teeth 12) (play " << play
       << ")) (rotation)) (g2 (spur-gear (teeth 18) (pitch-radius 1.5) (play " << play << ")) (at 2.5 0) (turn 10) (rotation))))";
    return os.str();
}

}  // namespace

TEST_CASE("geometry/contact_place: zero-play gears give the gap place of the same gears with play") {
    const Mechanism tight = read(gears(0, ""));
    const auto sel = kinematic_pairs(tight);
    const auto oracle = pair_oracle(tight, sel.modelled[0]);
    const auto request = place_request(tight, sel.modelled[0]);
    REQUIRE(build_place_vocabulary(*oracle, request).vocabulary.count(PlaceKind::face) == 0);  // why it is needed
    const auto place = in_contact(tight);
    REQUIRE(place);
    REQUIRE(place->places.size() == 1);
    CHECK(place->places[0].gap);
    CHECK(place->adjacency.size() == 8);

    // The same pair with play 0.02 and a gap epsilon above it: 8.1.6 from the sampled space.
    const Mechanism loose = read(gears(0.02, " (gap-epsilon 0.1)"));
    const auto lsel = kinematic_pairs(loose);
    const auto lv = build_place_vocabulary(*pair_oracle(loose, lsel.modelled[0]), place_request(loose, lsel.modelled[0])).vocabulary;
    REQUIRE(lv.places.size() == 1);
    CHECK(place->places[0].normals == lv.places[0].normals);
    CHECK(motions(*place, false) == motions(lv, false));
    CHECK(motions(*place, true) == motions(lv, true));
    CHECK(motions(*place, false) == std::set<std::string>{"(+ -)", "(- +)"});  // meshing: they turn opposite ways
}

TEST_CASE("geometry/contact_place: a block resting on a table slides along it both ways") {
    // Figure 2.3: the block's bottom lies on the table's top along the whole axis of its motion.
    const auto m = read(
        "(Defmechanism rest Parts ((a (block) (translation (1 0) (limits -2 2)))"
        " (table (block (width 6) (height 0.2)) (at 0 -0.6) (fixed))))");
    const auto place = in_contact(m);
    REQUIRE(place);
    CHECK(place->places[0].normals.empty());  // the contact never opposes the block's motion
    for (const auto& a : place->adjacency)
        if (a.motion.s[0] != 0) CHECK(!a.constrained);

    // The same block on a ramp sliding along x would climb into it: a sliding direction is blocked.
    const auto ramp = read(
        "(Defmechanism ramp Parts ((a (block) (translation (0 1) (limits -2 2)))"
        " (table (block (width 6) (height 0.2)) (at 0 -0.6) (fixed))))");
    const auto up = in_contact(ramp);
    REQUIRE(up);
    REQUIRE(up->places[0].normals.size() == 1);
    CHECK(to_string(up->places[0].normals[0]) == "(+ 0)");  // moving up (q0 +) opens the gap
    for (const auto& a : up->adjacency)
        if (a.motion.s[0] < 0) CHECK(a.constrained);
}

TEST_CASE("geometry/contact_place: parts drawn overlapping, or apart, have no contact place") {
    CHECK(!in_contact(read("(Defmechanism o Parts ((a (block) (translation (1 0) (limits -2 2)))"
                           " (table (block (width 6) (height 0.2)) (at 0 -0.5) (fixed))))")));
    CHECK(!in_contact(read("(Defmechanism o Parts ((a (block) (translation (1 0) (limits -2 2)))"
                           " (table (block (width 6) (height 0.2)) (at 0 -0.7) (fixed))))")));
}
