// tests/cli/scene_command_test.cpp: `qm-atms SCENE.def` end to end through the built executable: the
// thesis notation, the JSON schema of docs/OUTPUT.md, --situation, --why (both spellings),
// --without, --given, the interactive mode, and exit statuses for bad input.
#include "qm_atms_run.hpp"
#include "../support/program_json.hpp"
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <doctest/doctest.h>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>

using Json = nlohmann::json;
using Array = Json::array_t;
using Object = Json::object_t;

namespace {

using Result = qm::test::Run;
using qm::test::slurp;

Result scene_run(const std::string& args, const std::string& input = "") { return qm::test::qm_atms(args, "scene_cli", {input, ""}); }

std::string alex_scene(const std::string& name) { return std::string(QM_SOURCE_DIR) + "/scenarios/alex/" + name; }

// A boulder resting on a table under gravity, with a force of cause wind in its one situation.
std::string windy_boulder() {
    return qm::test::write_temp("scene_cli_wind.def", "(Defscenario 2 wind\n"
                                                      "  Individuals (boulder table)\n"
                                                      "  Surfaces ((boulder (bo-b (0 -) (0 +))) (table (tb (0 +) (0 0))))\n"
                                                      "  Translational-Constraints ((table (?x ?y)))\n"
                                                      "  Rotational-Constraints ((table (?r)))\n"
                                                      "  Forces ((boulder (0 -) (0 0) gravity)))\n"
                                                      "(Defstates ((Contact bo-b tb) (Force boulder (+ 0) (0 0) wind)))\n");
}

bool is_direction(const Json& j, std::size_t arity) {
    static const std::regex shape(R"(\([+0-]( [+0-])*\))");
    return j.is_string() && std::regex_match(j.get<std::string>(), shape) && (j.get<std::string>().size() + 1) / 2 - 1 == arity;
}

// Checks the schema of docs/OUTPUT.md; returns the number of situations.
std::size_t check_schema(const Json& doc, std::size_t objects) {
    REQUIRE(doc.is_object());
    CHECK(doc.get_ref<const Object&>().size() == 3);
    REQUIRE(doc.contains("scene"));
    CHECK(doc.at("scene").is_string());
    const auto dims = static_cast<std::size_t>(doc.at("dimensions").get<double>());
    const std::size_t rot = dims == 3 ? 3 : 1;
    const auto& situations = doc.at("situations").get_ref<const Array&>();
    for (std::size_t i = 0; i < situations.size(); ++i) {
        const Json& s = situations[i];
        CHECK(s.get_ref<const Object&>().size() == 6);
        CHECK(s.at("index").get<double>() == static_cast<double>(i + 1));
        CHECK(s.at("stable").is_boolean());
        // Which set `motions` lists, and both counts (docs/OUTPUT.md "Kinematic and selected").
        CHECK(s.at("motion_set").get<std::string>() == "selected");
        const Json& counts = s.at("combinations");
        CHECK(counts.get_ref<const Object&>().size() == 4);
        CHECK(counts.at("selected").get<double>() == static_cast<double>(s.at("motions").get_ref<const Array&>().size()));
        CHECK(counts.at("selected_complete").get<bool>());
        CHECK(counts.at("kinematic").get<double>() >= counts.at("selected").get<double>());
        CHECK(counts.at("kinematic_complete").is_boolean());
        REQUIRE(s.at("freedom").get_ref<const Object&>().size() == objects);
        for (const auto& [name, f] : s.at("freedom").get_ref<const Object&>()) {
            CAPTURE(name);
            bool zero_t = false, zero_r = false;
            for (const Json& d : f.at("translation").get_ref<const Array&>()) {
                CHECK(is_direction(d, dims));
                zero_t |= d.get<std::string>().find_first_of("+-") == std::string::npos;
            }
            for (const Json& d : f.at("rotation").get_ref<const Array&>()) {
                CHECK(is_direction(d, rot));
                zero_r |= d.get<std::string>().find_first_of("+-") == std::string::npos;
            }
            CHECK(zero_t);  // the zero direction is always free
            CHECK(zero_r);
        }
        for (const Json& m : s.at("motions").get_ref<const Array&>()) {
            REQUIRE(m.get_ref<const Object&>().size() == objects);
            for (const auto& [name, motion] : m.get_ref<const Object&>()) {
                CHECK(s.at("freedom").contains(name));
                CHECK(is_direction(motion.at("translation"), dims));
                CHECK(is_direction(motion.at("rotation"), rot));
            }
        }
    }
    return situations.size();
}

}  // namespace

TEST_CASE("cli/scene_command: the thesis' notation (Figures 7.3-7.6)") {
    Result r = scene_run(alex_scene("block.def"));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    for (const char* line : {"Translational-Freedom (block (0 +))", "Rotational-Freedom (block (-))",
                             "Translational-Freedom (table (0 0))", "Translational-Motion (block (0 -))",
                             "Rotational-Motion (table (0))", "Stable: yes"})
        CHECK(r.out.find(line) != std::string::npos);
}

TEST_CASE("cli/scene_command: --json follows the documented schema") {
    for (auto [name, objects] : std::initializer_list<std::pair<const char*, std::size_t>>{
             {"block.def", 2}, {"arch.def", 4}, {"gears.def", 2}, {"recoil_escapement.def", 3}, {"block_3d.def", 2}}) {
        CAPTURE(name);
        Result r = scene_run(alex_scene(name) + " --json");
        REQUIRE(r.status == 0);
        auto doc = qm::test::read_json(r.out);
        REQUIRE_FALSE(doc.is_discarded());
        CHECK(check_schema(doc, objects) >= 1);
    }
    auto gears = qm::test::read_json(scene_run(alex_scene("gears.def") + " --json").out);
    REQUIRE_FALSE(gears.is_discarded());
    CHECK(gears.at("situations").at(0).at("motions").get_ref<const Array&>().size() == 6);
    CHECK(gears.at("dimensions").get<double>() == 2);
    auto recoil = qm::test::read_json(scene_run(alex_scene("recoil_escapement.def") + " --json --situation 2").out);
    REQUIRE_FALSE(recoil.is_discarded());
    const auto& only = recoil.at("situations").get_ref<const Array&>();
    REQUIRE(only.size() == 1);
    CHECK(only[0].at("index").get<double>() == 2);
    CHECK(only[0].at("motions").get_ref<const Array&>().size() == 1);
}

TEST_CASE("cli/scene_command: --limit stops an enumeration and says so, in text and beside JSON") {
    // The gear pair has six combinations (Figure 7.14): a limit of 4 shows four and says more exist.
    Result text = scene_run(alex_scene("gears.def") + " --limit 4");
    REQUIRE(text.status == 0);
    CHECK(text.out.find("Motions: at least 4 consistent combinations") != std::string::npos);
    CHECK(text.out.find("Combination 5") == std::string::npos);
    CHECK(text.out.find("--limit") != std::string::npos);
    Result json = scene_run(alex_scene("gears.def") + " --limit 4 --json");
    REQUIRE(json.status == 0);
    auto doc = qm::test::read_json(json.out);
    REQUIRE_FALSE(doc.is_discarded());
    CHECK(doc.at("situations").at(0).at("motions").get_ref<const Array&>().size() == 4);
    CHECK(json.err.find("enumeration stopped") != std::string::npos);
    // At or above the count nothing is cut and nothing is said.
    Result all = scene_run(alex_scene("gears.def") + " --limit 6 --json");
    CHECK(all.err.empty());
    CHECK(scene_run(alex_scene("gears.def") + " --limit 6").out.find("at least") == std::string::npos);
}

TEST_CASE("cli/scene_command: --why explains in either spelling, as text or JSON") {
    Result text = scene_run(alex_scene("block.def") + " --situation 2 --why 'Translational-Motion (block (0 -))'");
    CHECK(text.status == 0);
    CHECK(text.out.find("ruled out") != std::string::npos);
    CHECK(text.out.find("constraint-prevents-translation") != std::string::npos);
    CHECK(text.out.find("contact_constraint.rules") != std::string::npos);
    CHECK(text.out.find("{Contact (tb block-b-m)}") != std::string::npos);
    Result json = scene_run(alex_scene("block.def") + " --situation 2 --json --why '{\"block\": {\"translation\": \"(0 -)\"}}'");
    CHECK(json.status == 0);
    auto w = qm::test::read_json(json.out);
    REQUIRE_FALSE(w.is_discarded());
    CHECK(w.at("status").get<std::string>() == "ruled-out");
    CHECK(w.at("query").get<std::string>() == "Translational-Motion (block (0 -))");
    CHECK(w.at("responsible_sets").get_ref<const Array&>().size() == 3);  // any one of the three bottom contacts
    const Json& tree = w.at("exclusions").at(0).at("derivation");
    CHECK(tree.at("fact").get<std::string>() == "false");
    CHECK(tree.at("law").get<std::string>() == "constraint-prevents-translation");
    CHECK(tree.at("from").is_array());
    Result holds = scene_run(alex_scene("gears.def") + " --why 'Rotational-Motion (follower (+))'");
    CHECK(holds.out.find("holds") != std::string::npos);
    Result freedom = scene_run(alex_scene("gears.def") + " --why '{\"freedom\": {\"driver\": {\"translation\": \"(+ 0)\"}}}'");
    CHECK(freedom.out.find("Translational-Freedom (driver (+ 0)) in situation 1: ruled out") != std::string::npos);
}

TEST_CASE("cli/scene_command: --without and --given answer what-if questions") {
    Result without = scene_run(alex_scene("block.def") + " --json --situation 1 --without 'Force block'");
    auto doc = qm::test::read_json(without.out);
    REQUIRE_FALSE(doc.is_discarded());
    // Without gravity nothing drives the block: every free motion is possible.
    CHECK(doc.at("situations").at(0).at("motions").get_ref<const Array&>().size() == 27);
    Result given = scene_run(alex_scene("recoil_escapement.def") + " --json --situation 1 --given 'pallet (0 0) (+)'");
    auto g = qm::test::read_json(given.out);
    REQUIRE_FALSE(g.is_discarded());
    CHECK(g.at("situations").at(0).at("motions").get_ref<const Array&>().size() == 1);
    // A contact taken away frees the block to fall through the table.
    Result off = scene_run(alex_scene("block.def") + " --situation 2 --without 'Contact tb block-b-l' --without "
                                              "'Contact (block-b-m tb)' --without 'Contact tb block-b-r'");
    CHECK(off.out.find("Translational-Motion (block (0 -))") != std::string::npos);
}

TEST_CASE("cli/scene_command: the interactive mode answers without reloading") {
    Result r = scene_run(alex_scene("block.def") + " -i",
                       "help\nfreedom\nsituation 2\nmotions\nwhy Translational-Motion (block (0 -))\n"
                       "whatif Contact tb block-b-l; Contact tb block-b-m; Contact tb block-b-r\n"
                       "given block (0 +) (0)\njson on\nmotions\nbogus\nwhy Contact tb block-b-l\nquit\nfreedom\n");
    CHECK(r.status == 0);
    CHECK(r.out.find("  whatif Contact A B | Force OBJ [CAUSE] [; ...]") != std::string::npos);                       // help
    CHECK(r.out.find("Translational-Freedom (block (- -))") != std::string::npos);  // situation 1 freedom
    CHECK(r.out.find("Stable: yes") != std::string::npos);                       // situation 2 motions
    CHECK(r.out.find("ruled out") != std::string::npos);                         // why
    CHECK(r.out.find("the monotonic laws' labels were reused") != std::string::npos);  // whatif
    CHECK(r.out.find("Translational-Motion (block (0 +))") != std::string::npos);  // given
    CHECK(r.out.find("{\"index\": 2") != std::string::npos);                     // json on
    CHECK(r.err.find("unknown command 'bogus'") != std::string::npos);
    CHECK(r.err.find("expected a motion or a freedom") != std::string::npos);
}

TEST_CASE("cli/scene_command: a metric scene is analysed at a configuration like an Alex scene") {
    const std::string cam = std::string(QM_SOURCE_DIR) + "/scenarios/metric/cam.def";
    Result r = scene_run(cam + " --json");
    REQUIRE(r.status == 0);
    auto doc = qm::test::read_json(r.out);
    REQUIRE_FALSE(doc.is_discarded());
    CHECK(check_schema(doc, 2) == 1);
    // The same as analysing the Alex scene --emit-def writes.
    Result def = scene_run("--emit-def " + cam);
    REQUIRE(def.status == 0);
    const std::string emitted = qm::test::write_temp("scene_cli_cam_emitted.def", def.out);
    CHECK(scene_run(emitted + " --json").out == r.out);
    CHECK(scene_run(cam + " --config 'nosuch=3'").status == 2);
    CHECK(scene_run(alex_scene("block.def") + " --config 'cam=3'").status == 2);  // --config needs a metric scene
}

TEST_CASE("cli/scene_command: bad input is located and exits with 2") {
    const std::string bad = qm::test::write_temp("scene_cli_bad.def", "(Defscenario 2 broken\n  Individuals (a b\n");
    Result syntax = scene_run(bad);
    CHECK(syntax.status == 2);
    CHECK(syntax.err.find("scene_cli_bad.def:") != std::string::npos);
    CHECK(scene_run("/no/such/scene.def").status == 2);
    Result why = scene_run(alex_scene("block.def") + " --why 'Translational-Motion (block (0 x))'");
    CHECK(why.status == 2);
    CHECK(why.err.find("--why:1:") != std::string::npos);
    CHECK(scene_run(alex_scene("block.def") + " --why 'Rotational-Motion (nobody (+))'").status == 2);
    CHECK(scene_run(alex_scene("block.def") + " --without 'Translational-Motion (block (0 -))'").status == 2);
    CHECK(scene_run(alex_scene("block.def") + " --given 'block (0 -)'").status == 2);
    CHECK(scene_run(alex_scene("block.def") + " --why").status == 2);
    // Non-ASCII bytes in a query, in either spelling, are bad input, not a crash.
    Result minus = scene_run(alex_scene("block.def") + " --why 'Translational-Motion (block (0 \xe2\x88\x92))'");
    CHECK(minus.status == 2);
    CHECK(minus.err.find("--why:1:") != std::string::npos);
    CHECK(scene_run(alex_scene("block.def") + " --why '{\"block\": {\"translation\": \"(0 \xff)\"}}'").status == 2);
}

TEST_CASE("cli/scene_command: a malformed JSON query names what was expected in words") {
    for (const char* q : {R"q({"block": {}})q", "{", R"q({block: {"rotation": "(0)"}})q", R"q({"block": {"rotation": "(0)}})q"}) {
        CAPTURE(q);
        Result r = scene_run(alex_scene("block.def") + " --why '" + q + "'");
        CHECK(r.status == 2);
        CHECK(r.err.find("--why:1:") == 0);
        CHECK(r.err.find("expected ") != std::string::npos);
        CHECK(r.err.find("boost") == std::string::npos);  // no mangled parser type
        CHECK(r.err.find("N5") == std::string::npos);
    }
    Result empty = scene_run(alex_scene("block.def") + R"q( --why '{"block": {}}')q");
    CHECK(empty.err.find(R"q(error: expected "translation" or "rotation" but found '}')q") != std::string::npos);
    Result cut = scene_run(alex_scene("block.def") + R"q( --why '{"freedom": {"block": {"rotation": "(-)"}}')q");
    CHECK(cut.err.find("expected '}' but found the end of the query") != std::string::npos);
}

TEST_CASE("cli/scene_command: a scene without situations is reported, not an error") {
    const std::string none = qm::test::write_temp("scene_cli_no_situations.def", "(Defscenario 2 lone\n  Individuals (a)\n  Descriptions ((rigid-ob a)))\n");
    Result text = scene_run(none);
    CHECK(text.status == 0);
    CHECK(text.err.empty());
    CHECK(text.out.find("Scene lone (2-D, 1 object, 0 situations)") == 0);
    CHECK(text.out.find("No situations") != std::string::npos);
    Result json = scene_run(none + " --json");
    CHECK(json.status == 0);
    CHECK(json.out == "{\"scene\": \"lone\", \"dimensions\": 2, \"situations\": []}\n");
    // Queries need a situation: located errors, not an out-of-range access.
    Result i = scene_run(none + " -i", "freedom\n");
    CHECK(i.status == 2);
    CHECK(i.err.find("-i:1:1: error: expected a scene with situations") == 0);
    CHECK(scene_run(none + " --why 'Rotational-Motion (a (+))'").status == 2);
    CHECK(scene_run(none + " --situation 1").status == 2);
    // The laws are still read: a broken rule folder is reported.
    const std::string rules = std::string(QM_BINARY_DIR) + "/scene_cli_broken_rules";
    std::filesystem::create_directories(rules);
    std::ofstream(rules + "/bad.rules") << "rule r when (p ?x) then (q ?y)\n";
    Result broken = scene_run(none + " --rules " + rules);
    CHECK(broken.status == 2);
    CHECK(broken.err.find("bad.rules:1:") != std::string::npos);
}

// The messages of --without and --given: scene/what_if_test.cpp; here, that --situation scopes them.
TEST_CASE("cli/scene_command: --without something no situation has is an error, not a silent no-op") {
    // Situation 1 has no contact; situation 2 has it.
    CHECK(scene_run(alex_scene("block.def") + " --situation 1 --without 'Contact tb block-b-m'").status == 2);
    CHECK(scene_run(alex_scene("block.def") + " --situation 2 --without 'Contact tb block-b-m'").status == 0);
    CHECK(scene_run(alex_scene("block.def") + " --without 'Contact tb block-b-m'").status == 0);  // some situation has it
}

TEST_CASE("cli/scene_command: --situation N shows one situation under a header counting the scene's") {
    Result r = scene_run(alex_scene("block.def") + " --situation 2");
    CHECK(r.status == 0);
    CHECK(r.out.find("Scene block (2-D, 2 objects, 2 situations)\n\nSituation 2\n") == 0);
    CHECK(r.out.find("Situation 1") == std::string::npos);
}

TEST_CASE("cli/scene_command: interactive errors name the command, and whatif checks the situation has the item") {
    Result r = scene_run(alex_scene("gears.def") + " -i",
                       "why Contact l-1 d-1\nwhatif Force driver\nwhatif Rotational-Motion (driver (+))\n{\n"
                       "why {\"follower\": {}}\nwhatif Contact l-1 d-1\n");
    CHECK(r.status == 0);
    CHECK(r.err.find("why:1:1: error: expected a motion or a freedom to explain") == 0);
    CHECK(r.err.find("--why") == std::string::npos);
    CHECK(r.err.find("whatif:1:1: error: expected a contact or force of situation 1 to take away, but it has no "
                     "force on 'driver'") != std::string::npos);
    CHECK(r.err.find("whatif:1:1: error: expected 'Contact A B' or 'Force OBJ [CAUSE]' to take away, but found "
                     "'Rotational-Motion (driver (+))'") != std::string::npos);
    CHECK(r.err.find("boost") == std::string::npos);
    CHECK(r.out.find("9 consistent combinations") != std::string::npos);  // the last whatif still answers
}

// Which reasons and responsible sets: analysis_api_test.cpp; here, that text and JSON say the same.
TEST_CASE("cli/scene_command: --why lists the argument's reasons, the same in text and JSON") {
    const std::string args = alex_scene("recoil_escapement.def") + " --situation 2 --why 'Rotational-Motion (gear (+))'";
    Result text = scene_run(args);
    Result json = scene_run(args + " --json");
    REQUIRE(text.status == 0);
    REQUIRE(json.status == 0);
    auto w = qm::test::read_json(json.out);
    REQUIRE_FALSE(w.is_discarded());
    const auto& exclusions = w.at("exclusions").get_ref<const Array&>();
    REQUIRE_FALSE(exclusions.empty());
    REQUIRE(exclusions[0].at("responsible").get_ref<const Array&>().size() == 1);
    CHECK(exclusions[0].at("responsible").at(0).get<std::string>() == "Contact (s-w-b-3 gear-top-3)");
    std::size_t reasons = 0;
    for (std::size_t at = text.out.find("  Reason "); at != std::string::npos; at = text.out.find("  Reason ", at + 1)) ++reasons;
    CHECK(reasons == exclusions.size());
    CHECK(text.out.find("  Reason 1: resting on {Contact (s-w-b-3 gear-top-3)}") != std::string::npos);
    CHECK(text.out.find("the scene's description alone (no contact") == std::string::npos);
    CHECK(text.out.find("every translation of scape-wheel but (0 0)") != std::string::npos);
    CHECK(w.at("responsible_minimal").get<bool>());
}

TEST_CASE("cli/scene_command: --why's responsible sets are the minimal ones, and say so") {
    Result r = scene_run(alex_scene("wedge_ramp.def") + " --why 'Translational-Motion (wedge (0 0))'");
    REQUIRE(r.status == 0);
    CHECK(r.out.find("  Responsible (contacts, forces and given motions; the minimal sets, each suffices):\n"
                     "    {Force (wedge (0 -) (0 0))}\n"
                     "    {Contact (bl-b-l w-t-l), Force (block (0 -) (0 0))}\n"
                     "    {Contact (bl-b-r w-t-r), Force (block (0 -) (0 0))}\n") != std::string::npos);
}

TEST_CASE("cli/scene_command: a contact the laws cannot use is warned about, located, and --why says so") {
    const std::string bad = qm::test::write_temp("scene_cli_corner_bad.def",
                                                 "(Defscenario 2 cb\n"
                                                 "  Individuals (upper lower)\n"
                                                 "  Descriptions ((rigid-ob upper) (rigid-ob lower))\n"
                                                 "  Surfaces ((upper (c (+ -) (- +)) (d (- -) (+ +))) (lower (a (- +) (+ -)) (b (- -) (+ +))))\n"
                                                 "  Corners ((upper (tip c d (0 +))))\n"
                                                 "  Translational-Constraints ((lower (?x ?y)))\n"
                                                 "  Rotational-Constraints ((lower (?r)))\n"
                                                 "  Forces ((upper (0 -) (0 0))))\n"
                                                 "(Defstates ((Contact tip b)))\n");
    Result r = scene_run(bad);
    CHECK(r.status == 0);
    CHECK(r.err.find("scene_cli_corner_bad.def:9:14: warning: Contact (tip b) in situation 1 constrains and pushes "
                     "nothing") != std::string::npos);
    CHECK(r.err.find("Definition 25") != std::string::npos);
    Result json = scene_run(bad + " --json");
    CHECK(json.err.find("warning: Contact (tip b)") != std::string::npos);
    Result why = scene_run(bad + " --why 'Translational-Motion (upper (0 -))'");
    CHECK(why.out.find("scene_cli_corner_bad.def:9: Contact (tip b) in situation 1 constrains and pushes nothing") !=
          std::string::npos);
}

TEST_CASE("cli/scene_command: one given motion per object; --given replaces a scene's Motion") {
    CHECK(scene_run(alex_scene("gears.def") + " --given 'driver (0 0) (-)' --given 'driver (0 0) (+)'").status == 2);
    Result over = scene_run(alex_scene("recoil_escapement.def") + " --situation 2 --given 'pallet (0 0) (-)'");
    CHECK(over.status == 0);
    CHECK(over.err.find("recoil_escapement.def:16:64: note: --given 'pallet (0 0) (-)' replaces this Motion "
                        "(pallet (0 0) (+)) in situation 2") != std::string::npos);
    CHECK(over.out.find("Rotational-Motion (pallet (-))") != std::string::npos);
    CHECK(over.out.find("Motions: 0") == std::string::npos);
    // Interactive: the same replacement, said in a note.
    Result i = scene_run(alex_scene("recoil_escapement.def") + " -i", "situation 2\ngiven pallet (0 0) (-)\n");
    CHECK(i.out.find("Note: the given motion of pallet replaces Motion (pallet (0 0) (+))") != std::string::npos);
}

TEST_CASE("cli/scene_command: --without says what it took away; 'Force OBJ CAUSE' takes one cause's force") {
    Result r = scene_run(alex_scene("wedge_ramp.def") + " --without 'Force block'");
    CHECK(r.out.find("  Note: what-if: analysed without every force on 'block' (--without)\n") != std::string::npos);
    const std::string wind = windy_boulder();
    Result calm = scene_run(wind + " --json --without 'Force boulder wind'");
    REQUIRE(calm.status == 0);
    auto doc = qm::test::read_json(calm.out);
    REQUIRE_FALSE(doc.is_discarded());
    // Gravity stays: the boulder rests on the table.
    CHECK(doc.at("situations").at(0).at("stable").get<bool>());
    CHECK(calm.err.find("without the force of cause 'wind' on 'boulder'") != std::string::npos);
    Result none = scene_run(wind + " --without 'Force boulder breeze'");
    CHECK(none.status == 2);
    CHECK(none.err.find("--without:1:15: error: no force on 'boulder' has the cause 'breeze'") == 0);
}

TEST_CASE("cli/scene_command: a whole motion entry of the JSON output as a query is refused helpfully") {
    Result r = scene_run(alex_scene("block.def") + R"q( --why '{"block": {"translation": "(0 -)", "rotation": "(0)"}}')q");
    CHECK(r.status == 2);
    CHECK(r.err.find("--why:1:34: error: expected '}' but found ',': a query asks about one motion at a time, e.g. "
                     "{\"block\": {\"translation\": \"(0 -)\"}}; ask about the rotation in a query of its own") == 0);
}

TEST_CASE("cli/scene_command: --why about a consistent motion the --limit cut off is an error, not 'ruled out'") {
    // Gears: 6 consistent pairs; with --limit 1 only (driver +, follower +) is listed.
    Result r = scene_run(alex_scene("gears.def") + " --limit 1 --why 'Rotational-Motion (follower (-))'");
    CHECK(r.status == 2);
    CHECK(r.err.find("--why:1:1: error: cannot tell whether Rotational-Motion (follower (-)) is predicted") == 0);
    CHECK(scene_run(alex_scene("gears.def") + " --why 'Rotational-Motion (follower (-))'").out.find("holds") != std::string::npos);
}

// The set of combinations a JSON answer lists, each as one string (objects in name order).
std::multiset<std::string> combinations_of(const Result& r, std::size_t situation = 0) {
    auto doc = qm::test::read_json(r.out);
    REQUIRE_FALSE(doc.is_discarded());
    std::multiset<std::string> out;
    for (const Json& m : doc.at("situations").at(situation).at("motions").get_ref<const Array&>()) {
        std::string one;
        for (const auto& [name, motion] : m.get_ref<const Object&>()) one += name + motion.at("translation").get<std::string>() + motion.at("rotation").get<std::string>() + " ";
        out.insert(one);
    }
    return out;
}

// The kinematically consistent combinations are those of the same scene with every force taken away (computed here the other way: --without each force, a fresh analysis).
TEST_CASE("cli/scene_command: --kinematic lists what blocking and pushing alone allow; both counts are shown") {
    const std::string crate = alex_scene("crate_shim.def");
    Result text = scene_run(crate);
    REQUIRE(text.status == 0);
    CHECK(text.out.find("  Motions: 1 consistent combination selected by the forces, of 150 kinematically consistent "
                        "combinations (--kinematic lists them)\n") != std::string::npos);
    Result listed = scene_run(crate + " --kinematic");
    CHECK(listed.out.find("  Motions: 150 kinematically consistent combinations (blocking, pushing and given motions alone, "
                          "before the forces choose; the forces select 1 combination)\n") != std::string::npos);
    CHECK(listed.out.find("    Combination 150\n") != std::string::npos);
    Result json = scene_run(crate + " --kinematic --json");
    auto doc = qm::test::read_json(json.out);
    REQUIRE_FALSE(doc.is_discarded());
    const Json& s = doc.at("situations").at(0);
    CHECK(s.at("motion_set").get<std::string>() == "kinematic");
    CHECK(s.at("combinations").at("selected").get<double>() == 1);
    CHECK(s.at("combinations").at("kinematic").get<double>() == 150);
    CHECK(s.at("motions").get_ref<const Array&>().size() == 150);
    Result forceless = scene_run(crate + " --json --without 'Force crate' --without 'Force shim'");
    REQUIRE(forceless.status == 0);
    CHECK(combinations_of(json) == combinations_of(forceless));
    // Where the forces rule nothing out, the heading says so.
    CHECK(scene_run(alex_scene("gears.def")).out.find("Motions: 6 consistent combinations (every kinematically consistent one: "
                                                "the forces rule none out)\n") != std::string::npos);
    // A stable verdict that only the forces hold says so.
    Result block = scene_run(alex_scene("block.def") + " --situation 2");
    CHECK(block.out.find("  Stable: yes (the only possible motions are zero)\n  Note: stable only because of the forces: "
                         "blocking and pushing alone would let block translate (+ +), (+ 0), (0 +), (- +) or (- 0) (6 "
                         "kinematically consistent combinations, --kinematic lists them); the forces select not moving\n") !=
          std::string::npos);
}

// --with adds; checked against the same scene written with the item.
TEST_CASE("cli/scene_command: --with adds a contact or a force, and says so") {
    // Situation 1 of block.def with situation 2's contacts added is situation 2.
    Result added = scene_run(alex_scene("block.def") + " --json --situation 1 --with 'Contact tb block-b-l' --with 'Contact tb "
                                                "block-b-m' --with 'Contact (block-b-r tb)'");
    REQUIRE(added.status == 0);
    CHECK(added.err.find("what-if: analysed with Contact (tb block-b-l), Contact (tb block-b-m), Contact (block-b-r tb) "
                         "(--with)") != std::string::npos);
    Result two = scene_run(alex_scene("block.def") + " --json --situation 2");
    CHECK(combinations_of(added) == combinations_of(two));
    // A force taken away and added back gives the original answer.
    const std::string wind = windy_boulder();
    Result windy = scene_run(wind + " --json");
    Result back = scene_run(wind + " --json --without 'Force boulder wind' --with 'Force boulder (+ 0) (0 0) gust'");
    REQUIRE(back.status == 0);
    CHECK(combinations_of(back) == combinations_of(windy));
    CHECK(combinations_of(back) != combinations_of(scene_run(wind + " --json --without 'Force boulder wind'")));
    Result text = scene_run(wind + " --without 'Force boulder wind' --with 'Force (boulder (+ 0) (0 0) gust)'");
    CHECK(text.out.find("  Note: what-if: analysed with Force (boulder (+ 0) (0 0) gust) (--with)\n") != std::string::npos);
    // What the situation has already, a bad item, and a contact of faces that cannot touch.
    Result again = scene_run(alex_scene("block.def") + " --situation 2 --with 'Contact tb block-b-m'");
    CHECK(again.status == 2);
    CHECK(again.err == "--with:1:1: error: expected a contact to add, but situation 2 has Contact (tb block-b-m) already\n");
    Result motion = scene_run(alex_scene("block.def") + " --with 'Rotational-Motion (block (+))'");
    CHECK(motion.status == 2);
    CHECK(motion.err.find("expected 'Contact A B' or 'Force OBJ DIR ORIGIN [CAUSE]' to add, but found") != std::string::npos);
    Result facing = scene_run(alex_scene("block.def") + " --situation 1 --with 'Contact tb block-t-m'");
    CHECK(facing.status == 0);
    CHECK(facing.err.find("--with:1:1: warning: Contact (tb block-t-m): the surface normals (0 +) of 'tb' and (0 +) of "
                          "'block-t-m' are not opposite") == 0);
}

// A --why answer that reads like one. The arch query is a golden file, run from the source folder so
// that the scene's paths in it are relative (QM_WRITE_GOLDEN=1 rewrites it); --full shows
// everything, bindings included.
TEST_CASE("cli/scene_command: --why starts with the verdict and stays short; --full shows it all (golden)") {
    const std::string golden = std::string(QM_SOURCE_DIR) + "/tests/cli/why/arch_cross_bar.txt";
    const std::string out = std::string(QM_BINARY_DIR) + "/scene_cli_why_arch.out";
    const std::string run = "cd " + std::string(QM_SOURCE_DIR) + " && " + QM_BINARY_DIR + "/cli/qm-atms scenarios/alex/arch.def" +
                            " --why 'Rotational-Motion (cross-bar (+))'";
    REQUIRE(std::system((run + " >" + out).c_str()) == 0);
    const std::string text = slurp(out);
    qm::test::check_golden(text, golden);
    CHECK(std::count(text.begin(), text.end(), '\n') < 40);
    CHECK(text.find("in situation 1: ruled out by constraint-prevents-rotation (section 3.1, Table 3.1; Definition 23), resting on {") == 34);
    CHECK(text.find(" at contact_constraint.rules:") != std::string::npos);  // relative to the rules folder
    CHECK(text.find("/rules/") == std::string::npos);
    REQUIRE(std::system((run + " --full >" + out).c_str()) == 0);
    const std::string full = slurp(out);
    std::remove(out.c_str());
    CHECK(std::count(full.begin(), full.end(), '\n') > 150);
    CHECK(full.find("{?o = cross-bar, ?r = (+)}") != std::string::npos);  // bindings
    CHECK(full.find("(see [1])") != std::string::npos);
    CHECK(full.find("--full") == std::string::npos);                      // nothing left out
    // The closed world names the facts whose absence a law used (rules/freedom.rules and others).
    CHECK(full.find("the situation holds no (torque-decided-by cross-bar ?i ?c1 ?c2 ?s1 ?s2) (closed world") != std::string::npos);
    // JSON: the citation and the `not` conditions of each step.
    Result json = scene_run(alex_scene("arch.def") + " --json --why 'Rotational-Motion (cross-bar (+))'");
    CHECK(json.out.find("\"law\": \"constraint-prevents-rotation\", \"citation\": \"section 3.1, Table 3.1; Definition 23\"") !=
          std::string::npos);
    CHECK(json.out.find("\"absent\": [\"(torque-decided-by cross-bar ?i ?c1 ?c2 ?s1 ?s2)\"]") != std::string::npos);
    // In the interactive mode, `full on` does what --full does.
    Result session = scene_run(alex_scene("arch.def") + " -i", "why Rotational-Motion (cross-bar (+))\nfull on\nwhy Rotational-Motion (cross-bar (+))\n");
    CHECK(session.status == 0);
    CHECK(session.out.find("full on\n") != std::string::npos);
    CHECK(session.out.find("{?o = cross-bar, ?r = (+)}") > session.out.find("full on\n"));
    CHECK(session.out.find("cut short: --full") < session.out.find("full on\n"));
    // --full goes with --why.
    Result alone = scene_run(alex_scene("arch.def") + " --full");
    CHECK(alone.status == 2);
    CHECK(alone.err.find("--full shows a --why answer whole: give it with --why") != std::string::npos);
}
