// tests/scenarios/chapter3_test.cpp: the examples of the thesis' chapter 3 and section 6.1, written as
// scenes in scenarios/alex/, against what the text says of them (Nielsen 1988, sections 3.1-3.3,
// 5.3.2, 6.1), and the 3-D block (Table 2.1).
#include "scenario_support.hpp"

using namespace qm;
using namespace qm::test;
using S = std::set<std::string>;

namespace {
const S up_and_sideways{"(+ +)", "(+ 0)", "(0 +)", "(0 0)", "(- +)", "(- 0)"};
}

TEST_CASE("scenarios/chapter3: a stack of blocks is blocked downwards from the floor up (section 3.1)") {
    const scene::Scene scene = load_scene("block_stack.def");
    analysis::Analysis a = analyse(scene);
    const analysis::SituationResult& r = a.situations()[0];
    // "any block in the stack is prevented from moving in any downward direction"
    for (const char* name : {"a", "b"}) {
        CAPTURE(name);
        CHECK(texts(r.freedom[object(scene, name)].translation) == up_and_sideways);
        CHECK(texts(r.freedom[object(scene, name)].rotation) == S{"(0)"});
    }
    CHECK(r.stable);
}

TEST_CASE("scenarios/chapter3: block on wedge on ramp, without and with a catch (Figure 3.2)") {
    {
        const scene::Scene scene = load_scene("wedge_ramp.def");
        analysis::Analysis a = analyse(scene);
        const analysis::SituationResult& r = a.situations()[0];
        // "if the ramp is completely constrained, the block is still free to move in any direction"
        CHECK(texts(r.freedom[object(scene, "block")].translation).size() == 9);
        // "The block may move in a downward direction by pushing the wedge down and to the right."
        CHECK(combinations(scene, r) == S{"block (0 -) (0); wedge (+ -) (0); ramp (0 0) (0)"});
        CHECK_FALSE(r.stable);
    }
    {
        const scene::Scene scene = load_scene("wedge_ramp_catch.def");
        analysis::Analysis a = analyse(scene);
        const analysis::SituationResult& r = a.situations()[0];
        // "the wedge could not move in any of the directions required ... the block could not move downward"
        const S block = texts(r.freedom[object(scene, "block")].translation);
        for (const char* down : {"(0 -)", "(+ -)", "(- -)"}) CHECK(block.count(down) == 0);
        CHECK(r.stable);
    }
}

TEST_CASE("scenarios/chapter3: a block pushing a boulder moves it (Figure 3.4, Table 3.2)") {
    const scene::Scene scene = load_scene("block_boulder.def");
    analysis::Analysis a = analyse(scene);
    const analysis::SituationResult& r = a.situations()[0];
    // Pushed, the boulder must move away (Table 3.2): along the table, or up and away from it. Its
    // own weight gives it no torque, so it does not turn.
    CHECK(combinations(scene, r) == S{"block (+ 0) (0); boulder (+ 0) (0); table (0 0) (0)",
                                      "block (+ 0) (0); boulder (+ +) (0); table (0 0) (0)"});
    // Without the contact the boulder stays where gravity and the table leave it.
    Diagnostics d;
    scene::QueryFact without{scene::QueryFact::Kind::contact, std::nullopt, {}, scene.find_surface("bk-r"), scene.find_surface("bo-l"), {}};
    auto w = a.what_if(1, std::span<const scene::QueryFact>(&without, 1), d);
    REQUIRE(w.has_value());
    CHECK(combinations(scene, *w) == S{"block (+ 0) (0); boulder (0 0) (0); table (0 0) (0)"});
}

TEST_CASE("scenarios/chapter3: force fed back through B cancels on A: the mechanism jams (Figure 5.2, Law 5)") {
    const scene::Scene scene = load_scene("force_feedback.def");
    analysis::Analysis a = analyse(scene);
    const analysis::SituationResult& r = a.situations()[0];
    CHECK(combinations(scene, r) == S{"a (0 0) (0); b (0 0) (0)"});
    CHECK(r.stable);
}

TEST_CASE("scenarios/chapter3: a lever pushed down off its pivot turns clockwise (section 6.1)") {
    const scene::Scene scene = load_scene("lever.def");
    analysis::Analysis a = analyse(scene);
    CHECK(combinations(scene, a.situations()[0]) == S{"lever (0 0) (-)"});
}

TEST_CASE("scenarios/chapter3: the block in three dimensions (Table 2.1)") {
    const scene::Scene scene = load_scene("block_3d.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 3);
    const auto block = object(scene, "block");
    CHECK(texts(a.situations()[0].freedom[block].translation).size() == 27);
    CHECK(texts(a.situations()[0].freedom[block].rotation).size() == 27);
    CHECK(combinations(scene, a.situations()[0]) == S{"block (0 0 -) (0 0 0); table (0 0 0) (0 0 0)"});
    // On the table: nothing downwards, and no rotation about x or y tips a corner into it.
    const S on_table = texts(a.situations()[1].freedom[block].translation);
    CHECK(on_table.size() == 18);
    for (const auto& d : on_table) CHECK(d.substr(d.size() - 2) != "-)");
    for (const auto& r : texts(a.situations()[1].freedom[block].rotation)) {
        CAPTURE(r);
        CHECK(r.substr(0, 4) == "(0 0");  // only rotation about z remains
    }
    CHECK(a.situations()[1].stable);
    CHECK(combinations(scene, a.situations()[2]) == S{"block (0 0 0) (0 0 +); table (0 0 0) (0 0 0)"});
}

TEST_CASE("scenarios/chapter3: linked gears turn together (Def 21)") {
    const scene::Scene scene = load_scene("linked_gears.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 3);
    CHECK(a.situations()[0].combination_count() == 10);
    const S driven{"driver (0 0) (-); gear-a (0 0) (+); gear-b (0 0) (+); gear-c (0 0) (-)"};
    CHECK(combinations(scene, a.situations()[1]) == driven);  // the driver given turning clockwise
    CHECK(combinations(scene, a.situations()[2]) == driven);  // a torque on the driver instead
    for (const auto& line : combinations(scene, a.situations()[0])) {
        // gear-a and gear-b are one body: they always turn alike.
        const auto ra = line.substr(line.find("gear-a (0 0) ") + 13, 3);
        const auto rb = line.substr(line.find("gear-b (0 0) ") + 13, 3);
        CHECK(ra == rb);
    }
}

TEST_CASE("scenarios/chapter3: corner contacts (section 3.1.1, Figure 3.3)") {
    const scene::Scene scene = load_scene("corner_contacts.def");
    analysis::Analysis a = analyse(scene);
    REQUIRE(a.situations().size() == 2);
    // The lower block is free to slide on the table, so it does not sufficiently constrain the
    // tip: the triangle slides down face A and pushes the block away, whether the tip rests on A or
    // on the block's corner.
    for (const auto& r : a.situations())
        CHECK(combinations(scene, r) == S{"upper (0 -) (0); lower (+ 0) (0); table (0 0) (0)"});
    // Held by a catch on the right, the block blocks the tip: the corner takes A's reversed normal.
    scene::Scene held = scene;
    held.objects[object(held, "lower")].trans_constraints.push_back(
        {scene::PatternSlot{scene::Sign::plus, {}}, scene::PatternSlot{std::nullopt, "y"}});
    analysis::Analysis b = analyse(held);
    const S upper = texts(b.situations()[0].freedom[object(held, "upper")].translation);
    CHECK(upper.count("(+ -)") == 0);  // into A
    CHECK(upper.count("(0 -)") == 0);
    CHECK(upper.count("(- +)") == 1);  // away from A
}

TEST_CASE("scenarios/chapter3: every bundled scene loads and is analysed") {
    for (const char* name : {"arch.def", "block.def", "block_3d.def", "block_boulder.def", "block_stack.def",
                             "corner_contacts.def", "force_feedback.def", "gears.def", "lever.def",
                             "recoil_escapement.def", "wedge_ramp.def", "wedge_ramp_catch.def", "linked_gears.def",
                             "squeeze.def", "wedge_push.def"}) {
        CAPTURE(name);
        const scene::Scene scene = load_scene(name);
        analysis::Analysis a = analyse(scene);
        CHECK(a.situations().size() == scene.situations.size());
        for (const auto& r : a.situations()) CHECK(r.combination_count() >= 1);
    }
}
