// tests/geometry/pair_vocabulary_test.cpp: place vocabularies of metric scenes end to end, with FCL in
// the loop (geometry/kinematic_pairs.hpp -> fcl_pair_oracle.hpp -> place_vocabulary_builder.hpp):
// FCL against the exact lines-and-arcs oracle, and the hard cases (tangent
// contact, edges sliding on each other, zero play, corner against corner, normals along an axis,
// scales 1e-3 to 1e3, the scene moved, turned by 90 degrees and scaled, an all-free space, CSEGs
// spanning the space parallel to an axis), and the ratchet's and the escapement's vocabularies
// settling as the grid is refined.
#include "mechanism_text.hpp"
#include "geometry/closed_form_pairs.hpp"
#include "geometry/contact_detection.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/profile_pair_oracle.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

using namespace qm::geometry;
using qm::geometry::test::read;

namespace {


struct Built {
    PlaceResult result;
    PlaceRequest request;
};

Built build(const Mechanism& m, std::size_t pair = 0) {
    const auto sel = kinematic_pairs(m);
    REQUIRE(sel.modelled.size() > pair);
    const auto oracle = pair_oracle(m, sel.modelled[pair]);
    Built b{{}, place_request(m, sel.modelled[pair])};
    b.result = build_place_vocabulary(*oracle, b.request);
    REQUIRE(b.result.status == PlaceStatus::ok);
    return b;
}

// A relabelling-invariant summary: each place's kind, join kind, normals and concavity, and the
// adjacencies by the kinds they connect, motion and flags.
std::multiset<std::string> pair_signature(const PlaceVocabulary& v) {
    std::multiset<std::string> out;
    for (const auto& p : v.places) {
        std::ostringstream s;
        s << to_string(p.kind);
        if (p.kind == PlaceKind::join) s << ' ' << to_string(p.join_kind);
        for (auto n : p.normals) s << ' ' << to_string(n);
        if (p.concave) s << (*p.concave ? " concave" : " convex");
        out.insert(s.str());
    }
    for (const auto& a : v.adjacency) {
        std::ostringstream s;
        s << "adj " << to_string(v.at(a.from).kind) << ' ' << to_string(v.at(a.to).kind) << ' ' << to_string(a.motion)
          << (a.instantaneous ? " inst" : "") << (a.constrained ? " constrained" : "");
        out.insert(s.str());
    }
    return out;
}

void check_same(const std::multiset<std::string>& a, const std::multiset<std::string>& b) {
    std::vector<std::string> only_a, only_b;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_a));
    std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_b));
    for (const auto& x : only_a) MESSAGE("only first: ", x);
    for (const auto& x : only_b) MESSAGE("only second: ", x);
    CHECK(a == b);
}

std::string num(double x) {
    std::ostringstream os;
    os.precision(17);
    os << x;
    return os.str();
}

// The escapement of scenarios/metric/escapement.def, scaled by s, turned by k quarter turns
// about the origin and moved by (dx, dy): lengths, positions, turns and gravity all go along.
std::string escapement(double s, int k, double dx, double dy, int grid = 48) {
    const double a = k * std::numbers::pi / 2, c = std::cos(a), sn = std::sin(a);
    auto pt = [&](double x, double y) { return num(s * (c * x - sn * y) + dx) + " " + num(s * (sn * x + c * y) + dy); };
    auto dir = [&](double x, double y) { return num(c * x - sn * y) + " " + num(sn * x + c * y); };
    return "(Defmechanism escapement Settings ((chordal-tolerance 1e-5) (grid " + std::to_string(grid) + " " + std::to_string(grid) + "))"
           " Parts ((wheel (scape-wheel (teeth 15) (root-radius " + num(0.85 * s) + ") (tip-radius " + num(s) +
           ") (lean 0.8) (root-land 0.2)) (at " + pt(0, 0) + ") (turn " + num(8 + 90 * k) + ") (rotation))"
           " (pallets (anchor (span " + num(0.45 * s) + ") (reach " + num(0.5 * s) + ") (width " + num(0.1 * s) + ") (top " + num(0.1 * s) +
           ")) (at " + pt(0, 1.4) + ") (turn " + num(90 * k) + ") (rotation)))"
           " Pairs ((wheel pallets (window pallets -20 20)))"
           " Forces ((spring wheel (torque -)) (gravity pallets (direction " + dir(0, -1) + ") (at " + pt(0, 1.0) + "))))";
}

}  // namespace

TEST_CASE("geometry/pair_vocabulary: FCL and the exact lines-and-arcs oracle give the same vocabulary") {
    for (const char* scene :
         {"(Defmechanism cam Settings ((grid 40 40)) Parts ((cam (disk-cam (radius 0.5) (eccentricity 0.2)) (rotation))"
          " (follower (follower (width 4) (height 1)) (translation (0 1) (limits 0.2 1)))))",
          "(Defmechanism yoke Settings ((grid 40 40)) Parts ((crank (crank) (rotation))"
          " (yoke (yoke) (at 0.6 0) (translation (1 0) (limits -1.4 0.2)))))"}) {
        const auto m = read(scene);
        const auto sel = kinematic_pairs(m);
        const auto fcl = pair_oracle(m, sel.modelled[0]);
        const ProfilePairOracle exact(m.parts[sel.modelled[0].a], m.parts[sel.modelled[0].b]);
        const auto request = place_request(m, sel.modelled[0]);
        const auto with_fcl = build_place_vocabulary(*fcl, request);
        const auto with_exact = build_place_vocabulary(exact, request);
        INFO(m.name);
        check_same(pair_signature(with_fcl.vocabulary), pair_signature(with_exact.vocabulary));
        // Each boundary point FCL found is a configuration where the exact parts touch to within
        // the tessellation: apart by at most the chordal tolerance, or overlapping.
        const double chordal = pair_chordal_tolerance(m, sel.modelled[0]);
        REQUIRE(with_fcl.space.boundary.size() == with_exact.space.boundary.size());
        for (std::size_t i = 0; i < with_fcl.space.boundary.size(); ++i) {
            const auto& p = with_fcl.space.boundary[i];
            CHECK(p.axis == with_exact.space.boundary[i].axis);
            CHECK(p.qual == with_exact.space.boundary[i].qual);
            CHECK(exact.distance(p.q) <= 1.01 * chordal);
        }
    }
}

TEST_CASE("geometry/pair_vocabulary: a tangent contact (the disk cam) gives the closed form's vocabulary") {
    const auto m = read(
        "(Defmechanism cam Parts ((cam (disk-cam (radius 0.5) (eccentricity 0.2)) (rotation))"
        " (follower (follower (width 4) (height 1)) (translation (0 1) (limits 0.2 1)))))");
    const auto b = build(m);
    PlaceRequest closed;
    closed.cspace.axes = {CSpaceAxis{0, 2 * std::numbers::pi, true, 64}, CSpaceAxis{0.2, 1.0, false, 64}};
    const auto c = disk_cam_and_follower();
    const auto exact = build_place_vocabulary(c.exact, closed);
    for (auto k : {PlaceKind::cseg, PlaceKind::join, PlaceKind::fsd, PlaceKind::face})
        CHECK(b.result.vocabulary.count(k) == exact.vocabulary.count(k));
    std::multiset<std::string> joins_fcl, joins_exact;
    for (const auto& [v, out] : {std::pair{&b.result.vocabulary, &joins_fcl}, std::pair{&exact.vocabulary, &joins_exact}})
        for (const auto& p : v->places)
            if (p.kind == PlaceKind::join && p.join_kind == JoinKind::normal_change)
                out->insert(to_string(p.normals[0]) + to_string(p.normals[1]) + (*p.concave ? " concave" : " convex"));
    CHECK(joins_fcl == joins_exact);
    CHECK(b.result.vocabulary.count(PlaceKind::face) == 4);  // the tangent FSD at the top pinches a face off
}

TEST_CASE("geometry/pair_vocabulary: edges sliding on each other give axis-parallel CSEGs, every normal with a 0") {
    // A slides along x under B, which slides along y: B's bottom lies on A's top when q1 = -0.1.
    // (No grid sample lies exactly on a CSEG: there touching would count as blocked.)
    const auto m = read(
        "(Defmechanism slide Settings ((grid 40 40)) Parts ((a (block) (at 0 0.5) (translation (1 0) (limits -2 2)))"
        " (b (block) (at 0 1.6) (translation (0 1) (limits -1 0.5)))))");
    const auto b = build(m);
    const auto& v = b.result.vocabulary;
    CHECK(v.count(PlaceKind::cseg) == 3);
    std::set<QualDirection> normals;
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::cseg) {
            normals.insert(p.normals.front());
            CHECK((p.normals.front().s[0] == 0 || p.normals.front().s[1] == 0));
        }
    CHECK(normals == std::set<QualDirection>{{{-1, 0}}, {{1, 0}}, {{0, 1}}});
    int corners = 0;
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::join && p.join_kind == JoinKind::normal_change) {
            ++corners;
            CHECK(!*p.concave);
        }
    CHECK(corners == 2);
}

TEST_CASE("geometry/pair_vocabulary: zero play (gears meshing tightly) fails nothing; with play, one band") {
    auto gears = [](double play) {
        return "(Defmechanism gears Settings ((grid 48 48)) Parts ((g1 (spur-gear (teeth 12) (play " + num(play) +
               ")) (rotation)) (g2 (spur-gear (teeth 18) (pitch-radius 1.5) (play " + num(play) + ")) (at 2.5 0) (turn 10) (rotation))))";
    };
    const auto tight = build(read(gears(0)));
    CHECK(tight.result.vocabulary.count(PlaceKind::face) <= 1);
    for (const auto& p : tight.result.vocabulary.places) CHECK(p.points.size() >= 1);
    const auto loose = build(read(gears(0.02)));
    CHECK(loose.result.vocabulary.count(PlaceKind::face) == 1);  // the band of play, around the torus
    CHECK(loose.result.vocabulary.count(PlaceKind::cseg) == 2);
    CHECK(loose.result.vocabulary.count(PlaceKind::join) == 0);  // 8.1.6: one place describes the gears' meshing
}

TEST_CASE("geometry/pair_vocabulary: corner against corner: every corner join is a contact the geometry can name") {
    // Two squares turning about their centres, close enough for their corners to meet: the
    // space is full of corners sliding over sides and off each other's corners (3.1.1).
    const auto m = read(
        "(Defmechanism corners Settings ((grid 48 48)) Parts ((a (block) (rotation)) (b (block) (at 1.3 0.2) (rotation))))");
    const auto b = build(m);
    const auto sel = kinematic_pairs(m);
    const auto oracle = pair_oracle(m, sel.modelled[0]);
    int joins = 0, with_corner = 0;
    for (const auto& p : b.result.vocabulary.places) {
        if (p.kind != PlaceKind::join || p.join_kind != JoinKind::normal_change) continue;
        ++joins;
        const auto r = detect_contacts(*oracle, p.points.front(), {1e-3, 1e-6});
        CHECK(r.status == ContactStatus::ok);
        CHECK(!r.contacts.empty());
        for (const auto& c : r.contacts) with_corner += c.first.kind == FeatureKind::corner || c.second.kind == FeatureKind::corner;
    }
    CHECK(joins >= 8);
    CHECK(with_corner >= joins);
}

TEST_CASE("geometry/pair_vocabulary: a surface along an axis keeps normal 0 there, without flicker") {
    // The escapement's pallets resting on a root land of the wheel: an arc about the wheel's
    // pivot, so turning the wheel changes nothing and the CSEG's normal is exactly (0 +), at
    // every boundary point along it and at any grid (the meshes' chords would tilt it).
    for (int grid : {64, 128}) {
        const auto b = build(read(escapement(1, 0, 0, 0, grid)));
        double land = 1e9;
        for (const auto& p : b.result.space.boundary) land = std::min(land, p.q[1]);
        int on_land = 0;
        for (const auto& p : b.result.space.boundary)
            if (p.q[1] < land + 1e-4) {  // the meshes' chords move it by ~1e-5
                ++on_land;
                CHECK(p.qual == QualDirection{{0, 1}});
            }
        CHECK(on_land >= grid / 16);
        int land_csegs = 0;
        for (const auto& p : b.result.vocabulary.places) land_csegs += p.kind == PlaceKind::cseg && p.normals.front() == QualDirection{{0, 1}};
        CHECK(land_csegs >= 1);
        CHECK(land_csegs <= 2);  // one CSEG, perhaps split where an FSD ends on it
    }
}

TEST_CASE("geometry/pair_vocabulary: the escapement scaled 1e-3..1e3, moved, and turned by quarter turns has one vocabulary") {
    const auto base = pair_signature(build(read(escapement(1, 0, 0, 0))).result.vocabulary);
    for (const auto& [s, k, dx, dy] : std::vector<std::tuple<double, int, double, double>>{
             {1e-3, 0, 0, 0}, {1e3, 0, 0, 0}, {1, 0, 7.25, -3.5}, {1, 1, 0, 0}, {1, 2, 0, 0}, {1, 3, 2, 1}, {1e3, 1, -400, 900}}) {
        INFO("scale ", s, " quarter turns ", k, " moved ", dx, " ", dy);
        check_same(pair_signature(build(read(escapement(s, k, dx, dy))).result.vocabulary), base);
    }
}

TEST_CASE("geometry/pair_vocabulary: an all-free space is one face; CSEGs spanning the space along an axis have no joins") {
    // A crank pin inside a slot wider than its whole circle: the parts never touch, though their
    // envelopes meet, so the pair is modelled and its space is all free (9.2's degenerate case).
    const auto free_space = build(read(
        "(Defmechanism wide Settings ((grid 32 32)) Parts ((crank (crank (crank-radius 0.3) (pin-radius 0.1)) (rotation))"
        " (yoke (yoke (slot-width 1.2) (bar-width 0.3) (length 4)) (translation (1 0) (limits -0.1 0.1))))"
        " Forces ((gravity crank (direction 0 -1) (at 0.3 0))))"));
    CHECK(free_space.result.space.all_free());
    CHECK(free_space.result.vocabulary.count(PlaceKind::cseg) == 0);
    // 9.2: the crank's gravity divides it where its torque flips, at two angles, and in an
    // all-free space those divisions are kept (not taken for blocked ones): two faces.
    CHECK(free_space.result.vocabulary.count(PlaceKind::external_division) == 2);
    CHECK(free_space.result.vocabulary.count(PlaceKind::face) == 2);
    // A disk turning about its own centre over a follower: nothing depends on the turn, so the
    // contact boundary is a line along the whole periodic axis: a CSEG loop without joins.
    const auto band = build(read(
        "(Defmechanism round Settings ((grid 32 32)) Parts ((disk (disk-cam (radius 0.5) (eccentricity 0)) (rotation))"
        " (follower (follower) (translation (0 1) (limits 0.2 1)))))"));
    const auto& v = band.result.vocabulary;
    CHECK(v.count(PlaceKind::cseg) == 1);
    CHECK(v.count(PlaceKind::join) == 0);
    CHECK(v.count(PlaceKind::face) == 1);
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::cseg) CHECK(p.normals.front() == QualDirection{{0, 1}});
}

TEST_CASE("geometry/pair_vocabulary: the ratchet's place vocabulary settles as the grid is refined") {
    // scenarios/metric/ratchet.def. The pawl's slanted tip passing a tooth's tip makes a blocked
    // needle in configuration space, thinner than a cell near its apex, and the exact normals of
    // configurations found on the meshes near it can name the far side of the surface; each such
    // flicker would start a CSEG and two joins, more of them the finer the grid. The builder gives
    // such points a sound neighbour's normal and moves the apex join onto the needle's tip along
    // its own normal (docs/ACCURACY.md, "Place count against grid"), so these grids all give one
    // vocabulary, 77 places.
    auto ratchet = [](int n0, int n1) {
        return "(Defmechanism ratchet Settings ((grid 64 64))"
               " Parts ((ratchet-wheel (ratchet-wheel (teeth 12) (root-radius 0.8) (tip-radius 1.0)) (rotation))"
               " (pawl (pawl (length 0.8) (width 0.12)) (at 0.3 1.6) (turn 30) (rotation)))"
               " Pairs ((ratchet-wheel pawl (grid " + std::to_string(n0) + " " + std::to_string(n1) + ")))"
               " Forces ((spring ratchet-wheel (torque +)) (gravity pawl (direction 0 -1) (at -0.1 1.25))))";
    };
    const auto base = build(read(ratchet(64, 256))).result.vocabulary;
    CHECK(base.places.size() == 77);
    for (const auto& [n0, n1] : std::vector<std::pair<int, int>>{{64, 384}, {64, 512}, {96, 384}, {128, 512}, {128, 1024}}) {
        INFO("grid ", n0, " x ", n1);
        const auto v = build(read(ratchet(n0, n1))).result.vocabulary;
        CHECK(v.places.size() == base.places.size());
        check_same(pair_signature(v), pair_signature(base));
    }
}

TEST_CASE("geometry/pair_vocabulary: the escapement's place vocabulary settles as the grid is refined") {
    // scenarios/metric/escapement.def with its own tolerances. Near the pallet's corner on a
    // tooth, configurations found on the meshes overlap the exact arcs, and at grid 256 three
    // boundary points there got the far surface's normal, (+ -) inside a (- -) CSEG: it agreed
    // with each point's grid edge, but pointed along the boundary into blocked space. The run
    // made two joins, a CSEG and their divisions (92 places instead of 49). 192 and 256 give one
    // vocabulary (docs/ACCURACY.md: so does 384; 128 and 512 give the same 49 places, each with
    // one adjacency of its own).
    auto escapement_at = [](int n) {
        return "(Defmechanism escapement Settings ((chordal-tolerance 1e-7) (contact-tolerance 1e-3) (boundary-tolerance 1e-8))"
               " Parts ((scape-wheel (scape-wheel (teeth 15) (root-radius 0.85) (tip-radius 1.0) (lean 0.8) (root-land 0.2))"
               " (turn 8) (rotation)) (pallets (anchor (span 0.45) (reach 0.5) (width 0.1) (top 0.1)) (at 0 1.4) (rotation)))"
               " Pairs ((scape-wheel pallets (window pallets -20 20) (grid " + std::to_string(n) + " " + std::to_string(n) + ")))"
               " Forces ((spring scape-wheel (torque -)) (gravity pallets (direction 0 -1) (at 0 1.0))))";
    };
    const auto base = build(read(escapement_at(192))).result.vocabulary;
    CHECK(base.places.size() == 49);
    const auto fine = build(read(escapement_at(256))).result.vocabulary;
    CHECK(fine.places.size() == base.places.size());
    check_same(pair_signature(fine), pair_signature(base));
}
