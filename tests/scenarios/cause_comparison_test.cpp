// tests/scenarios/cause_comparison_test.cpp: opposing forces of different causes (Nielsen 1988,
// section 2.3: "we resolve this ambiguity by branching"; section 2.1.3: the cause "allows a method of
// comparison") in the bundled scenes squeeze.def and wedge_push.def, and the zero threshold of
// section 8.3.4 for a pushed object (block_boulder.def with a wind).
#include "scenario_support.hpp"

using namespace qm;
using namespace qm::test;
using S = std::set<std::string>;

namespace {
scene::Scene scene_from(const std::string& text) {
    Diagnostics d;
    auto s = scene::read_scene("inline.def", text, d);
    if (!s) {
        std::ostringstream os;
        d.print(os);
        FAIL("scene does not load: " << os.str());
    }
    return *s;
}
}  // namespace

TEST_CASE("scenarios/cause_comparison: squeezed blocks move together, or stay (squeeze.def)") {
    const scene::Scene scene = load_scene("squeeze.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 1);
    const analysis::SituationResult& r = a.situations()[0];
    // One answer to "hand or wind?" for both blocks: never apart, never one into the other.
    CHECK(combinations(scene, r) == S{"a (+ 0) (0); b (+ 0) (0); table (0 0) (0)",   // the hand prevails
                                      "a (0 0) (0); b (0 0) (0); table (0 0) (0)",   // they balance
                                      "a (- 0) (0); b (- 0) (0); table (0 0) (0)"}); // the wind prevails
    CHECK_FALSE(r.stable);
    // Without the wind the hand pushes both; without the hand the wind does.
    Diagnostics d;
    scene::QueryFact no_wind{scene::QueryFact::Kind::force, object(scene, "b"), {}, std::nullopt, std::nullopt, std::nullopt};
    auto w = a.what_if(1, std::span<const scene::QueryFact>(&no_wind, 1), d);
    REQUIRE(w.has_value());
    CHECK(combinations(scene, *w) == S{"a (+ 0) (0); b (+ 0) (0); table (0 0) (0)"});
}

TEST_CASE("scenarios/cause_comparison: a wedge pushed under a guided block (wedge_push.def)") {
    const scene::Scene scene = load_scene("wedge_push.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 2);
    // Hand against gravity, one answer for the wedge and the block.
    CHECK(combinations(scene, a.situations()[0]) == S{"block (0 +) (0); wedge (+ 0) (0); table (0 0) (0)",
                                                      "block (0 0) (0); wedge (0 0) (0); table (0 0) (0)",
                                                      "block (0 -) (0); wedge (- 0) (0); table (0 0) (0)"});
    // No hand: the block sinks and drives the wedge out to the left.
    CHECK(combinations(scene, a.situations()[1]) == S{"block (0 -) (0); wedge (- 0) (0); table (0 0) (0)"});
}

TEST_CASE("scenarios/cause_comparison: why a squeezed block does not move apart") {
    const scene::Scene scene = load_scene("squeeze.def");
    analysis::Analysis a = analyse(scene);
    Diagnostics d;
    // b moving right is predicted (where the hand prevails); its explanation names a combination.
    scene::QueryFact right{scene::QueryFact::Kind::translational_motion, object(scene, "b"), {scene::Sign::plus, scene::Sign::zero},
                          std::nullopt, std::nullopt, std::nullopt};
    auto w = a.why(right, 1, d);
    REQUIRE(w.has_value());
    CHECK(w->status == analysis::WhyAnswer::Status::holds);
    // b moving up and right is consistent but never nearest: ruled out in every branch.
    scene::QueryFact up{scene::QueryFact::Kind::translational_motion, object(scene, "b"), {scene::Sign::plus, scene::Sign::plus},
                       std::nullopt, std::nullopt, std::nullopt};
    auto u = a.why(up, 1, d);
    REQUIRE(u.has_value());
    CHECK(u->status == analysis::WhyAnswer::Status::ruled_out);
    // a lifting off the table is past the zero threshold of its net force in every branch: excluded
    // by cases over the branches (with the nogoods that the other objects meet on the way).
    scene::QueryFact lift{scene::QueryFact::Kind::translational_motion, object(scene, "a"), {scene::Sign::zero, scene::Sign::plus},
                         std::nullopt, std::nullopt, std::nullopt};
    auto l = a.why(lift, 1, d);
    REQUIRE(l.has_value());
    CHECK(l->status == analysis::WhyAnswer::Status::ruled_out);
    CHECK(l->exclusions.size() >= 3);
    REQUIRE_FALSE(l->notes.empty());
    CHECK(l->notes.front().find("in every branch") != std::string::npos);
    CHECK_FALSE(d.has_errors());
}

TEST_CASE("scenarios/cause_comparison: a pushed object's force prefers none of the motions past zero (8.3.4)") {
    // Figure 3.4's boulder, pushed right by the block's given motion, with a wind blowing it left
    // (net force (- 0)). Moving away from the block, right or up and right, is past the zero
    // threshold of that force either way: the force does not choose between them, the push moves it.
    const scene::Scene base = load_scene("block_boulder.def");
    analysis::Analysis plain = analyse(base);
    const S pushed{"block (+ 0) (0); boulder (+ +) (0); table (0 0) (0)", "block (+ 0) (0); boulder (+ 0) (0); table (0 0) (0)"};
    CHECK(combinations(base, plain.situations()[0]) == pushed);
    const scene::Scene windy = scene_from(R"((Defscenario 2 block-boulder-wind
  Individuals (block boulder table)
  Surfaces
    ((block (bk-r (+ 0) (- 0)) (bk-b-l (0 -) (+ +)) (bk-b-r (0 -) (- +)))
     (boulder (bo-l (- 0) (+ 0)) (bo-b (0 -) (0 +)))
     (table (tb (0 +) (0 0))))
  Translational-Constraints ((table (?x ?y)))
  Rotational-Constraints ((table (?r)))
  Forces ((block (0 -) (0 0)) (boulder (0 -) (0 0))))
(Defstates
  ((Contact bk-r bo-l) (Contact bk-b-l tb) (Contact bk-b-r tb) (Contact bo-b tb)
   (Motion block (+ 0) (0)) (Force boulder (- 0) (0 0) wind))))");
    analysis::Analysis a = analyse(windy);
    CHECK(combinations(windy, a.situations()[0]) == pushed);
}
