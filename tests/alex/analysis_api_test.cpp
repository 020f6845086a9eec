// tests/alex/analysis_api_test.cpp: the library API's edges (alex/analysis.hpp): a scene with no
// situations still has its laws checked and answers with no situations; "why" cites each scene
// premise at the line where it is written (a constraint entry, a description), not at the object.
#include "alex/analysis.hpp"
#include "alex/scene_parser.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

using namespace qm;

namespace {

alex::Scene scene_of(const std::string& text) {
    Diagnostics d;
    auto s = alex::read_scene("api.def", text, d);
    std::ostringstream os;
    d.print(os);
    REQUIRE_MESSAGE(s, os.str());
    return std::move(*s);
}

alex::AnalysisOptions default_options() {
    alex::AnalysisOptions o;
    o.rules_directory = std::string(QM_SOURCE_DIR) + "/rules";
    return o;
}

// Every leaf of a derivation tree.
void leaves(const alex::Derivation& d, const std::function<void(const alex::Derivation&)>& f) {
    if (d.from.empty()) f(d);
    for (const auto& x : d.from) leaves(x, f);
}

}  // namespace

TEST_CASE("alex/api: a scene with no situations is analysed (laws checked), with no situations") {
    const alex::Scene s = scene_of("(Defscenario 2 lone\n  Individuals (a)\n  Descriptions ((rigid-ob a)))\n");
    Diagnostics d;
    auto a = alex::analyse(s, default_options(), d);
    REQUIRE(a);
    CHECK_FALSE(d.has_errors());
    CHECK(a->situations().empty());
    CHECK(a->scene().objects.size() == 1);

    // The laws are still checked: without Law 1 no object has a choice of motion.
    const auto dir = std::filesystem::temp_directory_path() / "qm_api_test_rules";
    std::filesystem::remove_all(dir);
    std::filesystem::copy(std::string(QM_SOURCE_DIR) + "/rules", dir);
    std::filesystem::remove(dir / "uniqueness_of_motion.rules");
    auto o = default_options();
    o.rules_directory = dir;
    Diagnostics bad;
    CHECK_FALSE(alex::analyse(s, o, bad));
    std::ostringstream os;
    bad.print(os);
    CHECK(os.str().find("no choice of translational motion") != std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST_CASE("alex/api: why cites constraint entries and descriptions where they are written") {
    const std::string text =
        "Ramp 2\n"                                          // 1
        "Individuals : (blk, ramp)\n"                       // 2
        "Descriptions : rigid-ob(blk), rigid-ob(ramp)\n"    // 3
        "Translational-Constraints : ramp (?x ?y)\n"        // 4
        "Rotational-Constraints : ramp (?r)\n"              // 5
        "Surfaces : blk (b1 (- -) (+ +))\n"                 // 6
        "           ramp (rs (+ +) (0 0))\n"                // 7
        "Forces : blk (0 -) (0 0)\n"                        // 8
        "Situation : Contact (rs b1)\n";                    // 9
    const alex::Scene s = scene_of(text);
    Diagnostics d;
    auto a = alex::analyse(s, default_options(), d);
    REQUIRE(a);
    alex::QueryFact q;
    q.kind = alex::QueryFact::Kind::translational_motion;
    q.object = alex::ObjectId{0};
    q.direction = {alex::Sign::zero, alex::Sign::minus};
    auto w = a->why(q, 1, d);
    REQUIRE(w);
    REQUIRE(w->status == alex::WhyAnswer::Status::ruled_out);
    REQUIRE_FALSE(w->exclusions.empty());
    int frame = 0, rigid = 0;
    for (const auto& x : w->exclusions)
        leaves(x.derivation, [&](const alex::Derivation& leaf) {
            if (leaf.fact.find("frame-trans-constraint ramp") != std::string::npos) {
                ++frame;
                CHECK(leaf.source == "api.def:4");
            }
            if (leaf.fact.find("rigid-body") != std::string::npos) {
                ++rigid;
                CHECK(leaf.source == "api.def:3");
            }
        });
    CHECK(frame > 0);
    CHECK(rigid > 0);
}
