// tests/analysis/analysis_api_test.cpp: the library API's edges (analysis/analysis.hpp): a scene with no
// situations still has its laws checked and answers with no situations; "why" cites each scene
// premise at the line where it is written (a constraint entry, a description), not at the object;
// why lists the nogoods of the argument (the queried motion's first) and the exact minimal
// responsible sets (checked by what-ifs); contacts the laws cannot use are reported; a given motion
// replaces the situation's motion of the same object.
#include "analysis/analysis.hpp"
#include "scene/scene_parser.hpp"
#include "../support/scene_reading.hpp"
#include <algorithm>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <span>
#include <sstream>

using namespace qm;

namespace {

scene::Scene scene_of(const std::string& text) { return test::read_ok(text, "api.def"); }

analysis::AnalysisOptions default_options() {
    analysis::AnalysisOptions o;
    o.rules_directory = std::string(QM_SOURCE_DIR) + "/rules";
    return o;
}

// Every leaf of a derivation tree.
void leaves(const analysis::Derivation& d, const std::function<void(const analysis::Derivation&)>& f) {
    if (d.from.empty()) f(d);
    for (const auto& x : d.from) leaves(x, f);
}

}  // namespace

TEST_CASE("analysis/api: a scene with no situations is analysed (laws checked), with no situations") {
    const scene::Scene s = scene_of("(Defscenario 2 lone\n  Individuals (a)\n  Descriptions ((rigid-ob a)))\n");
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    CHECK_FALSE(d.has_errors());
    CHECK(a->situations().empty());
    CHECK(a->scene().objects.size() == 1);

    // The laws are still checked: without Law 1 nothing concludes the motions the driver reads
    // back (rules/scene_facts.rules' `output`), which the rule checker reports before any run.
    const auto dir = std::filesystem::temp_directory_path() / "qm_api_test_rules";
    std::filesystem::remove_all(dir);
    std::filesystem::copy(std::string(QM_SOURCE_DIR) + "/rules", dir);
    std::filesystem::remove(dir / "uniqueness_of_motion.rules");
    auto o = default_options();
    o.rules_directory = dir;
    Diagnostics bad;
    CHECK_FALSE(analysis::analyse(s, o, bad));
    CHECK(test::printed(bad).find("scene_facts.rules:26:8: error: unknown predicate 'trans-motion', read back by a driver (`output`)") !=
          std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST_CASE("analysis/api: why cites constraint entries and descriptions where they are written") {
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
    const scene::Scene s = scene_of(text);
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    scene::QueryFact q;
    q.kind = scene::QueryFact::Kind::translational_motion;
    q.object = scene::ObjectId{0};
    q.direction = {scene::Sign::zero, scene::Sign::minus};
    auto w = a->why(q, 1, d);
    REQUIRE(w);
    REQUIRE(w->status == analysis::WhyAnswer::Status::ruled_out);
    REQUIRE_FALSE(w->exclusions.empty());
    int frame = 0, rigid = 0;
    for (const auto& x : w->exclusions)
        leaves(x.derivation, [&](const analysis::Derivation& leaf) {
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

namespace {

scene::Scene scene_file(const std::string& name) { return test::load_ok("scenarios/alex/" + name); }

scene::QueryFact motion_query(const scene::Scene& s, const std::string& object, bool translational,
                             std::vector<scene::Sign> direction) {
    scene::QueryFact q;
    q.kind = translational ? scene::QueryFact::Kind::translational_motion : scene::QueryFact::Kind::rotational_motion;
    q.object = s.find_object(object);
    REQUIRE(q.object);
    q.direction = std::move(direction);
    return q;
}

bool has_leaf(const analysis::Derivation& d, const std::string& fact) {
    bool found = false;
    leaves(d, [&](const analysis::Derivation& leaf) { found |= leaf.fact == fact; });
    return found;
}

// Whether `d` is the translation (or rotation) of `o` in some predicted combination.
bool predicted(const analysis::SituationResult& r, scene::ObjectId o, bool translational, const scene::Direction& d) {
    bool found = false;
    r.for_each_combination([&](const analysis::SceneMotion& m) {
        found |= (translational ? m[o].translation : m[o].rotation) == d;
        return !found;
    });
    return found;
}

using Sets = std::vector<std::vector<std::string>>;

}  // namespace

TEST_CASE("analysis/api: why a motion is ruled out by case analysis lists the argument's nogoods, the motion's first") {
    const scene::Scene s = scene_file("recoil_escapement.def");
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    // Figure 7.18: the pallet given (+) pushes the scape wheel (+), which pushes the gear (-).
    auto w = a->why(motion_query(s, "gear", false, {scene::Sign::plus}), 2, d);
    REQUIRE(w);
    REQUIRE(w->status == analysis::WhyAnswer::Status::ruled_out);
    CHECK(w->exclusions.size() <= 6);
    REQUIRE_FALSE(w->exclusions.empty());
    for (const auto& x : w->exclusions) CHECK_FALSE(x.responsible.empty());
    // The reasons with the queried motion come first; then those ruling out the alternatives.
    const std::string mine = "assumed: Rotational-Motion (gear (+))";
    CHECK(has_leaf(w->exclusions.front().derivation, mine));
    bool seen_other = false;
    for (const auto& x : w->exclusions) {
        if (!has_leaf(x.derivation, mine)) seen_other = true;
        else CHECK_FALSE(seen_other);
    }
    CHECK(w->exclusions.front().responsible == std::vector<std::string>{"Contact (s-w-b-3 gear-top-3)"});
    // The pins the argument uses are said once, not as 8 reasons.
    bool pin_note = false;
    for (const auto& n : w->notes) pin_note |= n.find("every translation of scape-wheel but (0 0)") != std::string::npos;
    CHECK(pin_note);
    CHECK(w->responsible_minimal);
    CHECK(w->responsible_sets ==
          Sets{{"Contact (s-w-1 p-1)", "Contact (s-w-b-3 gear-top-3)", "Motion (pallet (0 0) (+))"}});

    // Figure 7.14 with the driver given (-): 3 reasons, the contact's and the given motion's, not
    // the driver's pins.
    const scene::Scene g = scene_file("gears.def");
    auto o = default_options();
    auto given = scene::parse_given(g, "driver (0 0) (-)", d, "--given");
    REQUIRE(given);
    o.given.push_back(*given);
    auto b = analysis::analyse(g, o, d);
    REQUIRE(b);
    auto v = b->why(motion_query(g, "follower", false, {scene::Sign::minus}), 1, d);
    REQUIRE(v);
    REQUIRE(v->status == analysis::WhyAnswer::Status::ruled_out);
    REQUIRE(v->exclusions.size() == 3);
    CHECK(has_leaf(v->exclusions[0].derivation, "assumed: Rotational-Motion (follower (-))"));
    CHECK(v->exclusions[0].responsible == std::vector<std::string>{"Contact (l-1 d-1)"});
    CHECK(v->exclusions[1].responsible == std::vector<std::string>{"Motion (driver (0 0) (-))"});
    CHECK(v->exclusions[2].responsible == std::vector<std::string>{"Motion (driver (0 0) (-))"});
    CHECK(v->responsible_sets == Sets{{"Contact (l-1 d-1)", "Motion (driver (0 0) (-))"}});
}

TEST_CASE("analysis/api: the responsible sets of a motion ruled out by nearness are exactly the minimal ones") {
    const scene::Scene s = scene_file("wedge_ramp.def");
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    const scene::ObjectId wedge = *s.find_object("wedge");
    const scene::Direction still{scene::Sign::zero, scene::Sign::zero};
    auto w = a->why(motion_query(s, "wedge", true, still), 1, d);
    REQUIRE(w);
    REQUIRE(w->status == analysis::WhyAnswer::Status::ruled_out);
    CHECK(w->responsible_minimal);
    const Sets expected{{"Force (wedge (0 -) (0 0))"},
                        {"Contact (bl-b-l w-t-l)", "Force (block (0 -) (0 0))"},
                        {"Contact (bl-b-r w-t-r)", "Force (block (0 -) (0 0))"}};
    CHECK(w->responsible_sets == expected);

    // Checked independently with what-ifs: with only a set's items the wedge still cannot stay
    // still, and without any one of them it can.
    auto force = [&](const char* o) {
        scene::QueryFact q;
        q.kind = scene::QueryFact::Kind::force;
        q.object = s.find_object(o);
        return q;
    };
    auto contact = [&](const char* x, const char* y) {
        scene::QueryFact q;
        q.kind = scene::QueryFact::Kind::contact;
        q.first = s.find_surface(x);
        q.second = s.find_surface(y);
        return q;
    };
    const std::vector<std::pair<std::string, scene::QueryFact>> items{
        {"Force (block (0 -) (0 0))", force("block")},         {"Force (wedge (0 -) (0 0))", force("wedge")},
        {"Contact (bl-b-l w-t-l)", contact("bl-b-l", "w-t-l")}, {"Contact (bl-b-r w-t-r)", contact("bl-b-r", "w-t-r")},
        {"Contact (w-b-l r-l)", contact("w-b-l", "r-l")},       {"Contact (w-b-r r-r)", contact("w-b-r", "r-r")}};
    auto still_possible = [&](const std::vector<std::string>& only) {
        std::vector<scene::QueryFact> without;
        for (const auto& [text, q] : items)
            if (std::find(only.begin(), only.end(), text) == only.end()) without.push_back(q);
        auto r = a->what_if(1, without, d);
        REQUIRE(r);
        return predicted(*r, wedge, true, still);
    };
    for (const auto& set : expected) {
        CAPTURE(set);
        CHECK_FALSE(still_possible(set));
        for (std::size_t k = 0; k < set.size(); ++k) {
            auto fewer = set;
            fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(k));
            CHECK(still_possible(fewer));
        }
    }
    // The audit's example: {Force wedge, Contact w-b-l r-l} suffices, but is not minimal.
    CHECK_FALSE(still_possible({"Force (wedge (0 -) (0 0))", "Contact (w-b-l r-l)"}));
    CHECK_FALSE(d.has_errors());
}

TEST_CASE("analysis/api: above the re-analysis limit a responsible set is labelled as maybe not minimal") {
    // The wedge on the ramp with three more objects under a force each: 9 items, more than the 8
    // whose subsets are re-analysed.
    std::string text =
        "(Defscenario 2 wedge-ramp-more\n"
        "  Individuals (block wedge ramp f1 f2 f3)\n"
        "  Descriptions ((rigid-ob block) (rigid-ob wedge) (rigid-ob ramp) (rigid-ob f1) (rigid-ob f2) (rigid-ob f3))\n"
        "  Surfaces\n"
        "    ((block (bl-b-l (0 -) (+ +)) (bl-b-r (0 -) (- +)))\n"
        "     (wedge (w-t-l (0 +) (+ -)) (w-t-r (0 +) (- -)) (w-b-l (- -) (+ +)) (w-b-r (- -) (- +)))\n"
        "     (ramp (r-l (+ +) (0 0)) (r-r (+ +) (0 0))))\n"
        "  Translational-Constraints ((ramp (?x ?y)))\n"
        "  Rotational-Constraints ((ramp (?r)))\n"
        "  Forces ((block (0 -) (0 0)) (wedge (0 -) (0 0)) (f1 (0 -) (0 0)) (f2 (0 -) (0 0)) (f3 (0 -) (0 0))))\n"
        "(Defstates\n"
        "  ((Contact bl-b-l w-t-l) (Contact bl-b-r w-t-r) (Contact w-b-l r-l) (Contact w-b-r r-r)))\n";
    const scene::Scene s = scene_of(text);
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    auto w = a->why(motion_query(s, "wedge", true, {scene::Sign::zero, scene::Sign::zero}), 1, d);
    REQUIRE(w);
    REQUIRE(w->status == analysis::WhyAnswer::Status::ruled_out);
    CHECK_FALSE(w->responsible_minimal);
    REQUIRE(w->responsible_sets.size() == 1);
    bool said = false;
    for (const auto& n : w->notes) said |= n.find("not reduced to minimal sets") != std::string::npos;
    CHECK(said);
}

TEST_CASE("analysis/api: a contact the laws cannot use is reported, and why says so") {
    // Def 25: a tip with sides (+ -) and (- -) cannot touch a face with normal (- -).
    const std::string text =
        "(Defscenario 2 cb\n"                                                                           // 1
        "  Individuals (upper lower)\n"                                                                 // 2
        "  Descriptions ((rigid-ob upper) (rigid-ob lower))\n"                                          // 3
        "  Surfaces ((upper (c (+ -) (- +)) (d (- -) (+ +))) (lower (a (- +) (+ -)) (b (- -) (+ +))))\n"  // 4
        "  Corners ((upper (tip c d (0 +))))\n"                                                         // 5
        "  Translational-Constraints ((lower (?x ?y)))\n"                                               // 6
        "  Rotational-Constraints ((lower (?r)))\n"                                                     // 7
        "  Forces ((upper (0 -) (0 0))))\n"                                                             // 8
        "(Defstates ((Contact tip b) (Contact tip a)))\n";                                              // 9
    const scene::Scene s = scene_of(text);
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    const auto inert = a->inert_contacts(1);
    REQUIRE(inert.size() == 1);  // tip on a is usable
    CHECK(inert[0].severity == Severity::warning);
    CHECK(inert[0].where == SourceLocation{"api.def", 9, 14});
    CHECK(inert[0].message.find("Contact (tip b)") == 0);
    CHECK(inert[0].message.find("Definition 25") != std::string::npos);
    auto w = a->why(motion_query(s, "upper", true, {scene::Sign::zero, scene::Sign::minus}), 1, d);
    REQUIRE(w);
    REQUIRE_FALSE(w->notes.empty());
    CHECK(w->notes.front().find("api.def:9: Contact (tip b) in situation 1 constrains and pushes nothing") == 0);

    // The bundled corner scene's contacts are all usable.
    const scene::Scene c = scene_file("corner_contacts.def");
    auto b = analysis::analyse(c, default_options(), d);
    REQUIRE(b);
    for (std::size_t i = 1; i <= b->situations().size(); ++i) CHECK(b->inert_contacts(i).empty());
}

TEST_CASE("analysis/api: a given motion replaces the situation's motion of the same object") {
    const scene::Scene s = scene_file("recoil_escapement.def");
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    auto m = scene::parse_given(s, "pallet (0 0) (-)", d, "given");
    REQUIRE(m);
    auto r = a->with_given(2, std::span<const scene::Motion>(&*m, 1), d);
    REQUIRE(r);
    // The given (-) replaces the scene's (+): with both given, no combination would be consistent.
    CHECK(r->combination_count() > 0);
    CHECK(predicted(*r, *s.find_object("pallet"), false, {scene::Sign::minus}));
    bool said = false;
    for (const auto& n : r->notes) said |= n.find("replaces Motion (pallet (0 0) (+))") != std::string::npos;
    CHECK(said);
}

TEST_CASE("analysis/api: why an undriven object's motion is not selected names the driven motions it would need") {
    // Linked gears, situation 3: the driver's force turns the train; gear-c has no force of its
    // own, so no rank; staying still needs the driver and gears a, b still too, farther from the force.
    const scene::Scene s = scene_file("linked_gears.def");
    Diagnostics d;
    auto a = analysis::analyse(s, default_options(), d);
    REQUIRE(a);
    REQUIRE(a->situations().size() >= 3);
    auto w = a->why(motion_query(s, "gear-c", false, {scene::Sign::zero}), 3, d);
    REQUIRE(w);
    REQUIRE(w->status == analysis::WhyAnswer::Status::ruled_out);
    REQUIRE_FALSE(w->exclusions.empty());
    for (const auto& x : w->exclusions) {
        CHECK(x.derivation.fact.find("(rot-nearness ") == 0);
        CHECK(x.derivation.fact.find(" (0) ") != std::string::npos);  // the motions staying still would need
    }
    bool said = false;
    for (const auto& n : w->notes) said |= n.find("gear-c has no nearness rank of its own") != std::string::npos;
    CHECK(said);
}
