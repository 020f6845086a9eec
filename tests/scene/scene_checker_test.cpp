// tests/scene/scene_checker_test.cpp: scene/scene_checker.hpp - golden error cases. Each
// tests/scene/errors/<case>.def is read (parser + checker) and the printed diagnostics must equal
// <case>.err exactly (STYLE.md section 7). A case named warn_* is a scene that reads, with
// warnings (the scene still means something). QM_WRITE_GOLDEN=1 rewrites the .err files.
#include "scene/scene_checker.hpp"
#include "scene/scene_parser.hpp"

#include "../support/golden.hpp"
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;
using namespace qm::scene;

namespace {
std::string diagnostics_for(const fs::path& def) {
    qm::Diagnostics diags;
    auto s = read_scene(def.filename().string(), qm::test::slurp(def), diags);
    if (def.filename().string().starts_with("warn_")) {
        CHECK(s.has_value());
        CHECK_FALSE(diags.has_errors());
        CHECK_FALSE(diags.items().empty());
    } else {
        CHECK_FALSE(s.has_value());
        CHECK(diags.has_errors());
    }
    std::ostringstream os;
    diags.print(os);
    return os.str();
}
}  // namespace

TEST_CASE("scene/scene_checker: golden error cases") {
    const fs::path dir = fs::path(QM_SOURCE_DIR) / "tests/scene/errors";
    std::vector<fs::path> cases;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".def") cases.push_back(e.path());
    std::sort(cases.begin(), cases.end());
    CHECK(cases.size() >= 20);
    for (const auto& def : cases) {
        INFO(def.filename().string());
        qm::test::check_golden(diagnostics_for(def), fs::path(def).replace_extension(".err"));
    }
}

TEST_CASE("scene/scene_checker: several errors in one run, in source order") {
    qm::Diagnostics diags;
    auto s = read_scene("m.def",
                        "(Defscenario 2 s Individuals (a a)\n"
                        " Surfaces ((a (p (0 +) (0 -))) (z (q (0 -) (0 +))))\n"
                        " Forces ((y (0 -) (0 0))))\n"
                        "(Defstates ((Contact p r) (Motion x (0 0) (0))))",
                        diags);
    CHECK_FALSE(s.has_value());
    const auto items = diags.sorted();
    REQUIRE(items.size() == 5);
    CHECK(items[0].message == "duplicate object 'a'");
    CHECK(items[1].message == "object 'z' in Surfaces is not declared in Individuals");
    CHECK(items[2].message == "object 'y' in a force is not declared in Individuals");
    CHECK(items[3].message == "unknown surface 'r'");
    CHECK(items[4].message == "object 'x' in a motion is not declared in Individuals");
    CHECK(items[4].where.line == 4);
    for (const auto& d : items) CHECK(!d.source_line.empty());
}

TEST_CASE("scene/scene_checker: a clean AST checks without diagnostics; locations come from the PositionTable") {
    const SourceText src("ok.def", "(Defscenario 2 s Individuals (a b)\n Surfaces ((a (p (0 +) (0 -))) (b (q (0 -) (0 +)))))"
                                   "\n(Defstates ((Contact p q)))");
    qm::Diagnostics diags;
    auto parsed = parse_scene_ast(src, diags);
    REQUIRE(parsed.has_value());
    auto scene = check_scene(parsed->scenario, parsed->positions, src, diags);
    REQUIRE(scene.has_value());
    CHECK(diags.size() == 0);
    CHECK(scene->surfaces[SurfaceId{1}].where.line == 2);
    CHECK(scene->surfaces[SurfaceId{1}].where.column == 36);
    CHECK(scene->situations[0].contacts[0].where.line == 3);
    CHECK(scene->objects[ObjectId{1}].where.column == 33);
}

TEST_CASE("scene/scene_checker: corner and linkage errors are all reported in one run, in source order") {
    qm::Diagnostics diags;
    auto s = read_scene("c.def",
                        "(Defscenario 2 s Individuals (a b)\n"
                        " Linkages ((a a) (a b) (b a) (a z))\n"
                        " Corners ((a (k p q (0 +)) (j p p (0 0)) (i k p (+ 0)) (h p r (0 + 0))) (b (m r x (0 -))))\n"
                        " Surfaces ((a (p (0 +) (0 -)) (q (+ 0) (0 0))) (b (r (0 -) (0 +)) (k (0 -) (0 +)))))\n"
                        "(Defstates ((Contact k r) (Contact k p)))",
                        diags);
    CHECK_FALSE(s.has_value());
    std::vector<std::string> got;
    for (const auto& d : diags.sorted())
        got.push_back(std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + " " + d.message);
    // Corner k of a comes before face k of b in the source, so the face is the duplicate and k
    // stays a's corner: a side of i, and able to touch r but not p. Corner h's sides are checked
    // although its origin is bad.
    const std::vector<std::string> expected{
        "2:15 object 'a' is linked to itself; a linkage joins two different objects",
        "2:24 the linkage of 'b' and 'a' is listed twice",
        "2:33 object 'z' in Linkages is not declared in Individuals",
        "3:33 corner 'j' names the side 'p' twice; a corner is where two different surfaces meet",
        "3:45 side 'k' of corner 'i' is itself a corner; a corner's sides are surfaces of its object",
        "3:61 side 'r' of corner 'h' belongs to 'b', not to 'a'; a corner's sides are surfaces of its object",
        "3:63 a direction to the centre of rotation needs 2 signs in a 2-D scene but has 3",
        "3:81 unknown surface 'x' named as a side of corner 'm'",
        "4:68 surface 'k' is owned by two objects, 'a' and 'b'",
        "5:28 surfaces 'k' and 'p' both belong to 'a'; a contact joins two different objects",
    };
    CHECK(got == expected);
}
