// tests/geometry/kinematic_pairs_test.cpp: which pairs get a configuration space and how
// (geometry/kinematic_pairs.hpp): Def 20 against brute force, axes from the degrees of freedom
// (one period of a wheel's symmetry, windows, limits, a fixed part's dummy axis), and the
// external place divisions of forces on either part's shaft.
#include "mechanism_text.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"

#include <doctest/doctest.h>
#include <numbers>

using namespace qm::geometry;

namespace {

Mechanism read_pairs(const std::string& text) { return test::read(text, "k.def"); }

std::string names(const Mechanism& m, const std::vector<PairSpec>& pairs) {
    std::string out;
    for (const auto& p : pairs) out += m.parts[p.a].name + "/" + m.parts[p.b].name + " ";
    return out;
}

}  // namespace

TEST_CASE("geometry/kinematic_pairs: undeclared pairs are the parts whose motion envelopes meet (Def 20)") {
    // Three disks turning about offset pivots, a fixed block and a slider. a and b can touch, c
    // is too far from both, the slider's stroke brings it to the block.
    const auto m = read_pairs(
        "(Defmechanism d Parts ((a (disk-cam (radius 0.5) (eccentricity 0.3)) (rotation))"
        " (b (disk-cam (radius 0.4) (eccentricity 0.3)) (at 1.4 0) (rotation))"
        " (c (disk-cam (radius 0.2)) (at 0 5) (rotation))"
        " (wall (block (width 0.2) (height 2)) (at 8 0) (fixed))"
        " (slider (block) (at 5 0) (translation (1 0) (limits -0.5 2)))))");
    const auto sel = kinematic_pairs(m);
    CHECK(names(m, sel.modelled) == "a/b wall/slider ");
    CHECK(sel.skipped.empty());  // undeclared pairs that never meet are not reported
    // Brute force: every modelled pair touches somewhere; the others never do (sampled).
    for (std::uint32_t i = 0; i < m.parts.size(); ++i)
        for (std::uint32_t j = i + 1; j < m.parts.size(); ++j) {
            const PartId a{i}, b{j};
            if (m.parts[a].fixed() && m.parts[b].fixed()) continue;
            bool modelled = false;
            for (const auto& p : sel.modelled) modelled = modelled || (p.a == a && p.b == b);
            PairSpec spec{a, b, {}, {}, {}};
            const auto oracle = pair_oracle(m, spec);
            bool touches = false;
            for (int x = 0; x < 60 && !touches; ++x)
                for (int y = 0; y < 60 && !touches; ++y) {
                    auto coord = [&](PartId p, int k) {
                        const Part& part = m.parts[p];
                        return part.translates() ? part.lo + (part.hi - part.lo) * k / 59.0 : 2 * std::numbers::pi * k / 60;
                    };
                    touches = oracle->blocked({coord(a, x), coord(b, y)});
                }
            INFO(m.parts[a].name, "/", m.parts[b].name);
            if (touches) CHECK(modelled);
        }
}

TEST_CASE("geometry/kinematic_pairs: a declared pair that can never touch is skipped with its reason") {
    const auto m = read_pairs("(Defmechanism d Parts ((a (disk-cam) (rotation)) (b (disk-cam) (at 9 0) (rotation))) Pairs ((a b)))");
    const auto sel = kinematic_pairs(m);
    CHECK(sel.modelled.empty());
    REQUIRE(sel.skipped.size() == 1);
    CHECK(sel.skipped[0].reason.find("Def 20") != std::string::npos);
    CHECK(sel.skipped[0].where.line == 1);
}

TEST_CASE("geometry/kinematic_pairs: a pair's fingerprint is its oracle's, and changes with the chordal tolerance") {
    const std::string text = "(Defmechanism d Settings ((chordal-tolerance %)) Parts ((a (disk-cam (radius 0.5) (eccentricity 0.2)) (rotation))"
                             " (b (follower (width 2) (height 0.5)) (at 0 0.5) (translation (0 1) (limits -0.3 0.5)))))";
    auto with = [&](const std::string& tolerance) { return read_pairs(std::string(text).replace(text.find('%'), 1, tolerance)); };
    const auto m = with("1e-4"), finer = with("1e-5");
    const auto pair = kinematic_pairs(m).modelled.at(0);
    CHECK(pair_fingerprint(m, pair) == pair_oracle(m, pair)->fingerprint());
    CHECK(pair_fingerprint(finer, kinematic_pairs(finer).modelled.at(0)) != pair_fingerprint(m, pair));
}

TEST_CASE("geometry/kinematic_pairs: axes follow the degrees of freedom, symmetry and windows") {
    const auto m = read_pairs(
        "(Defmechanism d Settings ((grid 40 30) (boundary-tolerance 1e-7))"
        " Parts ((wheel (scape-wheel (teeth 15)) (rotation)) (pallets (anchor) (at 0 1.4) (rotation))"
        " (stop (block (width 0.2) (height 0.2)) (at 1.05 0) (fixed)) (slide (follower) (at 0 1.05) (translation (0 1) (limits 0 0.5))))"
        " Pairs ((wheel pallets (window pallets -20 20)) (wheel stop) (wheel slide (grid 16 8))))");
    const auto sel = kinematic_pairs(m);
    REQUIRE(sel.modelled.size() == 3);
    const auto r0 = place_request(m, sel.modelled[0]);
    CHECK(r0.cspace.axes[0].periodic);
    CHECK(r0.cspace.axes[0].hi == doctest::Approx(2 * std::numbers::pi / 15));  // one tooth pitch (8.1.6)
    CHECK(r0.cspace.axes[0].samples == 40);
    CHECK(!r0.cspace.axes[1].periodic);
    CHECK(r0.cspace.axes[1].lo == doctest::Approx(-20 * std::numbers::pi / 180));
    CHECK(r0.cspace.axes[1].samples == 30);
    CHECK(!r0.cspace.axes[0].stops);  // a rotation wraps
    CHECK(r0.cspace.axes[1].stops);   // a window's ends: the vocabulary does not follow it out
    CHECK(r0.cspace.boundary_tolerance == 1e-7);
    const auto r1 = place_request(m, sel.modelled[1]);
    CHECK(r1.cspace.axes[1].periodic);  // the fixed stop's dummy coordinate
    CHECK(r1.cspace.axes[1].samples == 3);
    const auto r2 = place_request(m, sel.modelled[2]);
    CHECK(r2.cspace.axes[1].lo == 0);
    CHECK(r2.cspace.axes[1].hi == 0.5);
    CHECK(r2.cspace.axes[1].stops);  // a translation's limits are stops
    CHECK(!r1.cspace.axes[1].stops);
    CHECK(r2.cspace.axes[0].samples == 16);
    CHECK(r2.cspace.axes[1].samples == 8);
    const double slide_size = m.parts[*m.find_part("slide")].size();
    CHECK(r2.cspace.boundary_tolerance == doctest::Approx(1e-7 * std::min(1.0, slide_size)));
    CHECK(pair_chordal_tolerance(m, sel.modelled[0]) == doctest::Approx(1e-4 * m.parts[*m.find_part("pallets")].size()));
}

TEST_CASE("geometry/kinematic_pairs: forces on either shaft become external divisions; they cost the wheel its period") {
    const auto m = read_pairs(
        "(Defmechanism d Parts ((gear (spur-gear (teeth 12) (play 0.05)) (rotation))"
        " (pinion (spur-gear (teeth 10) (pitch-radius 0.8333333333333334) (play 0.05)) (rotation))"
        " (idler (spur-gear (teeth 8) (pitch-radius 0.6666666666666666) (addendum 0.8) (play 0.05)) (at 0 1.5) (rotation))"
        " (other (spur-gear (teeth 12) (play 0.05)) (at 2 0) (rotation)))"
        " Linkages ((gear pinion))"
        " Pairs ((pinion idler) (gear other))"
        " Forces ((weight gear (direction 0 -1) (at 0.5 0)) (spring idler (torque +) (when 0 90))))");
    const auto sel = kinematic_pairs(m);
    REQUIRE(sel.modelled.size() == 2);
    const auto r = place_request(m, sel.modelled[0]);  // pinion x idler
    // The weight hangs on the gear, on the pinion's shaft: the pinion's axis is a full turn with
    // the two angles where the weight's torque flips; the idler's range gives two more.
    CHECK(r.cspace.axes[0].hi == doctest::Approx(2 * std::numbers::pi));
    CHECK(r.cspace.axes[1].hi == doctest::Approx(2 * std::numbers::pi));
    std::vector<std::pair<int, double>> divisions;
    for (const auto& x : r.external) divisions.emplace_back(x.coordinate, x.value);
    REQUIRE(divisions.size() == 4);
    CHECK(divisions[0].first == 0);
    CHECK(divisions[0].second == doctest::Approx(std::numbers::pi / 2));  // arm (0.5, 0) turned 90 degrees: straight up
    CHECK(divisions[1].second == doctest::Approx(3 * std::numbers::pi / 2));
    CHECK(divisions[2] == std::make_pair(1, 0.0));
    CHECK(divisions[3].second == doctest::Approx(std::numbers::pi / 2));
    CHECK(r.external[0].label == "weight: torque changes sign on gear");
    const auto other = place_request(m, sel.modelled[1]);  // gear x other: the gear keeps no period either
    CHECK(other.cspace.axes[0].hi == doctest::Approx(2 * std::numbers::pi));
    CHECK(other.cspace.axes[1].hi == doctest::Approx(2 * std::numbers::pi / 12));
}
