// tests/geometry/metric_scene_parser_test.cpp: the metric scene reader (geometry/metric_scene_parser.hpp):
// every bundled metric scene reads into the model it describes; bad input gives exactly the
// located diagnostics in tests/geometry/errors/<case>.err (golden files, reviewed by hand); the
// CONFIG argument reads and is checked against the scene.
#include "geometry/metric_scene_parser.hpp"

#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

using namespace qm::geometry;

namespace {

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::filesystem::path source_dir = QM_SOURCE_DIR;

Mechanism read_ok(const std::string& name) {
    qm::Diagnostics d;
    auto m = read_mechanism_file((source_dir / "scenarios/metric" / name).string(), d);
    std::ostringstream os;
    d.print(os);
    INFO(os.str());
    REQUIRE(m);
    CHECK(!d.has_errors());
    return *m;
}

}  // namespace

TEST_CASE("geometry/metric_scene_parser: the bundled metric scenes read into their models") {
    const auto esc = read_ok("escapement.def");
    CHECK(esc.name == "escapement");
    REQUIRE(esc.parts.size() == 2);
    const Part& wheel = esc.parts[*esc.find_part("scape-wheel")];
    const Part& pallets = esc.parts[*esc.find_part("pallets")];
    CHECK(wheel.rotates());
    CHECK(wheel.symmetry == 15);
    CHECK(pallets.dof.pivot.isApprox(Eigen::Vector2d(0, 1.4)));
    CHECK(esc.settings.chordal_tolerance == 1e-7);
    CHECK(esc.settings.grid == std::array<int, 2>{64, 64});
    REQUIRE(esc.pairs.size() == 1);
    REQUIRE(esc.pairs[0].window[1]);
    CHECK(esc.pairs[0].window[1]->lo == doctest::Approx(-20 * std::numbers::pi / 180));
    REQUIRE(esc.forces.size() == 2);
    CHECK(esc.forces[0].kind == ExternalForce::Kind::torque);
    CHECK(esc.forces[0].torque_sign == -1);
    CHECK(esc.forces[1].at->isApprox(Eigen::Vector2d(0, 1.0)));

    const auto gears = read_ok("gear_train.def");
    REQUIRE(gears.linkages.size() == 1);
    CHECK(gears.same_shaft(*gears.find_part("gear-2"), *gears.find_part("pinion-2")));
    CHECK(!gears.same_shaft(*gears.find_part("gear-1"), *gears.find_part("gear-2")));
    CHECK(gears.pairs.size() == 2);
    CHECK(gears.parts[*gears.find_part("gear-2")].symmetry == 18);  // turned about its own centre: still 18-fold

    const auto yoke = read_ok("scotch_yoke.def");
    const Part& y = yoke.parts[*yoke.find_part("yoke")];
    CHECK(y.translates());
    CHECK(y.profiles.size() == 2);
    CHECK(y.lo == -1.4);
    CHECK(y.hi == 0.2);
    for (const char* f : {"ratchet.def", "cam.def"}) read_ok(f);
}

TEST_CASE("geometry/metric_scene_parser: drawn profiles are placed, turned and oriented counter-clockwise") {
    qm::Diagnostics d;
    const auto m = read_mechanism("t.def",
                                  "(Defmechanism t Parts ((p (polygon (0 0) (0 1) (1 1) (1 0)) (at 10 0) (turn 90) (rotation))"
                                  " (q (profile (0 0) (line 2 0) (arc 0 0 1 0 ccw)) (at 0 5) (fixed))))",
                                  d);
    REQUIRE(m);
    const Part& p = m->parts[PartId{0}];
    CHECK(signed_area(p.profiles[0]) == doctest::Approx(1.0));  // drawn clockwise, stored counter-clockwise
    CHECK(p.dof.pivot.isApprox(Eigen::Vector2d(10, 0)));       // the pivot defaults to the placed origin
    Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
    extend_bounds(p.profiles[0], lo, hi);
    CHECK(lo.isApprox(Eigen::Vector2d(9, 0), 1e-12));  // turned 90 degrees about its origin, then moved
    CHECK(hi.isApprox(Eigen::Vector2d(10, 1), 1e-12));
    const Part& q = m->parts[PartId{1}];
    CHECK(signed_area(q.profiles[0]) == doctest::Approx(std::numbers::pi / 2));  // a half disk
}

TEST_CASE("geometry/metric_scene_parser: bad scenes give exactly the golden diagnostics") {
    int cases = 0;
    for (const auto& entry : std::filesystem::directory_iterator(source_dir / "tests/geometry/errors")) {
        if (entry.path().extension() != ".def") continue;
        ++cases;
        const std::string name = entry.path().filename().string();
        qm::Diagnostics d;
        const auto m = read_mechanism(name, slurp(entry.path()), d);
        std::ostringstream got;
        d.print(got);
        INFO(name);
        CHECK(!m);
        CHECK(d.has_errors());
        auto expected_path = entry.path();
        expected_path.replace_extension(".err");
        if (std::getenv("QM_WRITE_GOLDEN")) std::ofstream(expected_path) << got.str();
        CHECK(got.str() == slurp(expected_path));
    }
    CHECK(cases >= 15);
}

// Every keyword position names a word it does not know, with the nearest keyword of that
// position; a word that is a keyword elsewhere is misplaced; where no word stands, the expectation
// says what it found.
TEST_CASE("geometry/metric_scene_parser: a misspelt keyword is named at every keyword position, with the nearest one") {
    const std::string parts = "(Defmechanism m Parts ((a (block) (rotation)) (b (block) (at 3 0) ";
    const std::string items = "a part item (polygon, circle, profile, at, turn, fixed, rotation, translation, symmetry) or a generator "
                              "(spur-gear, ratchet-wheel, scape-wheel, anchor, pawl, crank, yoke, disk-cam, follower, block)";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"(Defmechansm m Parts ((a (block) (fixed))))", "1:2: error: unknown word 'Defmechansm': expected 'Defmechanism'; did you mean 'Defmechanism'?"},
        {"(Defmechanism m Prts ((a (block) (fixed))))",
         "1:17: error: unknown word 'Prts': expected a section keyword (Settings, Parts, Pairs, Linkages, Forces) or ')'; did you mean 'Parts'?"},
        {"(Defmechanism m Parts ((a (polygn (0 0) (1 0) (1 1)) (fixed))))", "1:28: error: unknown word 'polygn': expected " + items + "; did you mean 'polygon'?"},
        {parts + "(translate (1 0) (limits 0 1)))))", "1:68: error: unknown word 'translate': expected " + items + "; did you mean 'translation'?"},
        {parts + "(translation (1 0) (limit 0 1)))))", "1:87: error: unknown word 'limit': expected (limits lo hi); did you mean 'limits'?"},
        {"(Defmechanism m Parts ((a (profile (0 0) (lin 1 0) (line 0 0)) (fixed))))",
         "1:43: error: unknown word 'lin': expected a step (line x y) or (arc x y cx cy ccw|cw); did you mean 'line'?"},
        {"(Defmechanism m Parts ((a (profile (0 0) (line 1 0) (ark 0 0 0.5 0 ccw)) (fixed))))",
         "1:54: error: unknown word 'ark': expected a step (line x y) or (arc x y cx cy ccw|cw); did you mean 'arc'?"},
        {"(Defmechanism m Parts ((a (profile (0 0) (line 1 0) (arc 0 0 0.5 0 cww)) (fixed))))",
         "1:68: error: unknown word 'cww': expected ccw or cw; did you mean 'ccw'?"},
        {parts + "(fixed))) Pairs ((a b (grd 8 8))))",
         "1:90: error: unknown word 'grd': expected a pair setting (grid n0 n1) or (window part lo hi); did you mean 'grid'?"},
        {parts + "(fixed))) Forces ((spring a (torqe +))))",
         "1:96: error: unknown word 'torqe': expected a force item (torque +|-), (direction dx dy), (at x y) or (when lo hi); did you mean 'torque'?"},
        {parts + "(fixed) (colour red))))", "1:76: error: unknown word 'colour': expected " + items},
        {parts + "(fixed) (Torque +))))", "1:76: error: expected " + items + " but found 'Torque'"},
        {parts + "(fixed) (3 4))))", "1:75: error: expected ')' or a part item: (polygon ...), (circle ...), (profile ...), a generator "
                                     "like (spur-gear ...), (at x y), (turn deg), (fixed), (rotation [pivot]), (translation (dx dy) "
                                     "(limits lo hi)), (symmetry n) but found '('"},
    };
    for (const auto& [text, message] : cases) {
        CAPTURE(text);
        qm::Diagnostics d;
        CHECK(!read_mechanism("m.def", text, d));
        std::ostringstream got;
        d.print(got);
        const std::string first = got.str().substr(0, got.str().find('\n'));
        CHECK(first == "m.def:" + message);
        CHECK(d.items().size() == 1);  // a syntax error stops the reading
    }
}

TEST_CASE("geometry/metric_scene_parser: CONFIG reads degrees and lengths, shared by a shaft") {
    const auto m = read_ok("gear_train.def");
    qm::Diagnostics d;
    const auto c = parse_configuration(m, "gear-1=90, pinion-2 = -45.5", d);
    REQUIRE(c);
    CHECK(c->at(*m.find_part("gear-1")) == doctest::Approx(std::numbers::pi / 2));
    CHECK(c->at(*m.find_part("gear-2")) == doctest::Approx(-45.5 * std::numbers::pi / 180));  // on pinion-2's shaft
    CHECK(c->at(*m.find_part("gear-3")) == 0);
    const auto empty = parse_configuration(m, "  ", d);
    REQUIRE(empty);
    CHECK(!d.has_errors());

    const auto yoke = read_ok("scotch_yoke.def");
    const auto y = parse_configuration(yoke, "yoke=-0.5 crank=30", d);
    REQUIRE(y);
    CHECK(y->at(*yoke.find_part("yoke")) == -0.5);

    auto errors = [](const Mechanism& mech, const std::string& text) {
        qm::Diagnostics diags;
        CHECK(!parse_configuration(mech, text, diags));
        std::ostringstream os;
        diags.print(os);
        return os.str();
    };
    CHECK(errors(m, "gear-9=3") ==
          "CONFIG:1:1: error: unknown part 'gear-9'; the moving parts are gear-1, gear-2, pinion-2, gear-3\n  gear-9=3\n  ^\n");
    CHECK(errors(m, "gear-2=3, pinion-2=4") ==
          "CONFIG:1:11: error: 'pinion-2' is given a second value (its shaft was given one at column 1)\n  gear-2=3, pinion-2=4\n            ^\n");
    CHECK(errors(yoke, "yoke=2") ==
          "CONFIG:1:6: error: offset 2 of 'yoke' is outside its limits [-1.4, 0.2]\n  yoke=2\n       ^\n");
    CHECK(errors(m, "gear-1=") == "CONFIG:1:8: error: expected a number but found end of input\n  gear-1=\n         ^\n");
    CHECK(errors(m, "gear-1 3") == "CONFIG:1:8: error: expected '=' but found '3'\n  gear-1 3\n         ^\n");
    const auto ratchet = read_ok("cam.def");
    CHECK(errors(ratchet, "cam=inf") == "CONFIG:1:5: error: expected a finite number\n  cam=inf\n      ^\n");
}

TEST_CASE("geometry/metric_scene_parser: a fixed part has no coordinate") {
    qm::Diagnostics d;
    const auto m = read_mechanism("f.def", "(Defmechanism f Parts ((table (block) (fixed)) (wheel (disk-cam) (at 0 2) (rotation))))", d);
    REQUIRE(m);
    CHECK(!parse_configuration(*m, "table=1", d));
    std::ostringstream os;
    d.print(os);
    CHECK(os.str() == "CONFIG:1:1: error: part 'table' is fixed: it has no coordinate\n  table=1\n  ^\n");
}

TEST_CASE("geometry/metric_scene_parser: non-ASCII bytes are located errors, never an abort") {
    // Boost.Spirit's own character classes assert on bytes >= 0x80 in a debug build; the reader
    // classifies ASCII itself (qm/x3_ascii.hpp). Every such byte, in several places of a valid scene
    // and of a CONFIG, must give a located error (or be inside a comment), never crash.
    const std::string scene = slurp(source_dir / "scenarios/metric/cam.def");
    const Mechanism m = read_ok("cam.def");
    for (int b = 0x80; b <= 0xff; ++b) {
        const char c = static_cast<char>(b);
        for (std::size_t at : {std::size_t{0}, scene.find("Parts"), scene.find("(cam") + 1, scene.size() / 2, scene.size()}) {
            std::string text = scene;
            text.insert(std::min(at, text.size()), 1, c);
            qm::Diagnostics d;
            auto r = read_mechanism("bytes.def", text, d);
            CHECK(r.has_value() != d.has_errors());
        }
        qm::Diagnostics d;
        auto q = parse_configuration(m, std::string("cam=") + c + "3", d);
        CHECK_FALSE(q.has_value());
        CHECK(d.has_errors());
    }
}
