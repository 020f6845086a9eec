// tests/scenarios/thesis_figures_test.cpp: the thesis' Alex results (Nielsen 1988, chapter 7) reproduced
// exactly from the bundled scenes and the laws of rules/: Figures 7.3-7.6 (block and table),
// 7.9-7.10 (arch), 7.13-7.14 (gear pair), 7.17-7.18 (recoil escapement).
#include "scenario_support.hpp"

using namespace qm;
using namespace qm::test;
using S = std::set<std::string>;

namespace {
const S all_2d_translations{"(+ +)", "(+ 0)", "(+ -)", "(0 +)", "(0 0)", "(0 -)", "(- +)", "(- 0)", "(- -)"};
}

TEST_CASE("scenarios/thesis: Figures 7.3 and 7.4, the unsupported block is free and falls") {
    const scene::Scene scene = load_scene("block.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 2);
    const analysis::SituationResult& r = a.situations()[0];
    const auto block = object(scene, "block"), table = object(scene, "table");
    CHECK(texts(r.freedom[block].translation) == all_2d_translations);         // Figure 7.3
    CHECK(texts(r.freedom[block].rotation) == S{"(+)", "(0)", "(-)"});
    CHECK(texts(r.freedom[table].translation) == S{"(0 0)"});
    CHECK(texts(r.freedom[table].rotation) == S{"(0)"});
    CHECK(combinations(scene, r) == S{"block (0 -) (0); table (0 0) (0)"});    // Figure 7.4
    CHECK_FALSE(r.stable);
}

TEST_CASE("scenarios/thesis: Figures 7.5 and 7.6, the block on the table is stable") {
    const scene::Scene scene = load_scene("block.def");
    analysis::Analysis a = analyse(scene);
    const analysis::SituationResult& r = a.situations()[1];
    const auto block = object(scene, "block");
    CHECK(texts(r.freedom[block].translation) == S{"(+ 0)", "(+ +)", "(0 0)", "(0 +)", "(- 0)", "(- +)"});
    CHECK(texts(r.freedom[block].rotation) == S{"(0)"});
    CHECK(combinations(scene, r) == S{"block (0 0) (0); table (0 0) (0)"});
    CHECK(r.stable);
}

TEST_CASE("scenarios/thesis: Figures 7.9 and 7.10, the arch is stable") {
    const scene::Scene scene = load_scene("arch.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 1);
    const analysis::SituationResult& r = a.situations()[0];
    const S up_and_sideways{"(+ 0)", "(+ +)", "(0 0)", "(0 +)", "(- 0)", "(- +)"};
    for (const char* name : {"cross-bar", "left", "right"}) {
        CAPTURE(name);
        CHECK(texts(r.freedom[object(scene, name)].translation) == up_and_sideways);
        CHECK(texts(r.freedom[object(scene, name)].rotation) == S{"(0)"});
    }
    CHECK(texts(r.freedom[object(scene, "table")].translation) == S{"(0 0)"});
    CHECK(combinations(scene, r) == S{"cross-bar (0 0) (0); left (0 0) (0); right (0 0) (0); table (0 0) (0)"});
    CHECK(r.stable);
}

TEST_CASE("scenarios/thesis: Figures 7.13 and 7.14, the gear pair has six combinations") {
    const scene::Scene scene = load_scene("gears.def");
    analysis::Analysis a = analyse(scene);
    const analysis::SituationResult& r = a.situations()[0];
    for (const char* name : {"driver", "follower"}) {
        CHECK(texts(r.freedom[object(scene, name)].translation) == S{"(0 0)"});
        CHECK(texts(r.freedom[object(scene, name)].rotation) == S{"(+)", "(0)", "(-)"});
    }
    CHECK(combinations(scene, r) == S{"driver (0 0) (+); follower (0 0) (+)", "driver (0 0) (+); follower (0 0) (-)",
                                      "driver (0 0) (+); follower (0 0) (0)", "driver (0 0) (-); follower (0 0) (+)",
                                      "driver (0 0) (0); follower (0 0) (+)", "driver (0 0) (0); follower (0 0) (0)"});
    CHECK_FALSE(r.stable);
}

TEST_CASE("scenarios/thesis: Figures 7.17 and 7.18, the recoil escapement") {
    const scene::Scene scene = load_scene("recoil_escapement.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 2);
    const analysis::SituationResult& r = a.situations()[0];
    for (const char* name : {"scape-wheel", "pallet", "gear"}) {  // Figure 7.17
        CHECK(texts(r.freedom[object(scene, name)].translation) == S{"(0 0)"});
        CHECK(texts(r.freedom[object(scene, name)].rotation) == S{"(+)", "(0)", "(-)"});
    }
    CHECK(r.combination_count() == 10);                             // "ten consistent combinations"
    // Given the pallet turning counter-clockwise: one solution (Figure 7.18).
    CHECK(combinations(scene, a.situations()[1]) == S{"scape-wheel (0 0) (+); pallet (0 0) (+); gear (0 0) (-)"});
    // The same through the API's given motion, and through --given's option.
    Diagnostics d;
    auto pallet = object(scene, "pallet");
    scene::Motion turning{pallet, {scene::Sign::zero, scene::Sign::zero}, {scene::Sign::plus}, {}};
    auto given = a.with_given(1, std::span<const scene::Motion>(&turning, 1), d);
    REQUIRE(given.has_value());
    CHECK(combinations(scene, *given) == S{"scape-wheel (0 0) (+); pallet (0 0) (+); gear (0 0) (-)"});
    analysis::AnalysisOptions o;
    o.given.push_back(turning);
    analysis::Analysis b = analyse(scene, o);
    CHECK(combinations(scene, b.situations()[0]) == S{"scape-wheel (0 0) (+); pallet (0 0) (+); gear (0 0) (-)"});
}
