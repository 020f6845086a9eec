// tests/cli/envision_command_test.cpp: `qm-atms envision` end to end through the built executable
// (cli/envision_command.hpp, docs/ENVISION.md): the text summary, the Appendix-style table, the
// qm-envisionment/1 JSON checked against its schema, --next/--previous, --without, and bad input:
// each a located or clear error with exit status 2 and nothing on standard output.
#include "qm_atms_run.hpp"
#include "../support/program_json.hpp"
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <doctest/doctest.h>
#include <fstream>
#include <set>
#include <string>
#include <sys/wait.h>

using Json = nlohmann::json;
using Array = Json::array_t;
using Object = Json::object_t;

namespace {
using qm::test::write_temp;
using qm::test::metric_scene;

using Result = qm::test::Run;
using qm::test::slurp;

Result envision(const std::string& args) {
    return qm::test::qm_atms("envision " + args + " --cache " + QM_BINARY_DIR + "/envision-test-place-cache", "envision_test");
}


}  // namespace

TEST_CASE("cli/envision: the text summary names the chain, its pairs, states, transitions, cycles and terminal states") {
    const auto r = envision(metric_scene("cam.def"));
    REQUIRE(r.status == 0);
    CHECK(r.out.find("mechanism cam: 1 kinematic pair, 1 kinematic chain\n") == 0);
    CHECK(r.out.find("  objects: cam follower\n") != std::string::npos);
    CHECK(r.out.find("  pairs: cam/follower (") != std::string::npos);
    CHECK(r.out.find("  states: ") != std::string::npos);
    CHECK(r.out.find("summary: 1 chain, ") != std::string::npos);
}

TEST_CASE("cli/envision: --json follows qm-envisionment/1") {
    const auto r = envision(metric_scene("escapement.def") + " --json");
    REQUIRE(r.status == 0);
    const auto j = qm::test::read_json(r.out);
    REQUIRE_FALSE(j.is_discarded());
    CHECK(j.at("schema").get<std::string>() == "qm-envisionment/1");
    CHECK(j.at("mechanism").get<std::string>() == "escapement");
    CHECK(j.get_ref<const Object&>().size() == 3);
    const auto& chains = j.at("chains").get_ref<const Array&>();
    REQUIRE(chains.size() == 1);
    const auto& c = chains[0];
    CHECK(c.get_ref<const Object&>().size() == 9);
    CHECK(c.at("index").get<double>() == 1);
    CHECK(c.at("objects").get_ref<const Array&>().size() == 2);
    const auto& pairs = c.at("pairs").get_ref<const Array&>();
    REQUIRE(pairs.size() == 1);
    CHECK(pairs[0].at("parts").at(0).get<std::string>() == "scape-wheel");
    const auto places = static_cast<std::size_t>(pairs[0].at("places").get<double>());
    const auto& states = c.at("states").get_ref<const Array&>();
    REQUIRE(!states.empty());
    for (std::size_t i = 0; i < states.size(); ++i) {
        const auto& s = states[i];
        CHECK(s.get_ref<const Object&>().size() == 4);
        CHECK(s.at("id").get<double>() == static_cast<double>(i));
        CHECK(s.at("places").get_ref<const Array&>().size() == 1);
        CHECK(s.at("places").at(0).at("place").get<double>() < static_cast<double>(places));
        for (const char* key : {"motions", "net_force"}) {
            CHECK(s.at(key).get_ref<const Object&>().size() == 2);
            for (const auto& [obj, sign] : s.at(key).get_ref<const Object&>()) {
                const std::set<std::string> allowed = key == std::string("motions") ? std::set<std::string>{"(+)", "(0)", "(-)"}
                                                                                      : std::set<std::string>{"(+)", "(0)", "(-)", "(?)"};
                CHECK(allowed.count(sign.get<std::string>()) == 1);
            }
        }
    }
    for (const auto& t : c.at("transitions").get_ref<const Array&>()) {
        CHECK(t.get_ref<const Object&>().size() == 4);
        CHECK(t.at("from").get<double>() < static_cast<double>(states.size()));
        CHECK(t.at("to").get<double>() < static_cast<double>(states.size()));
        CHECK((t.at("duration").get<std::string>() == "instant" || t.at("duration").get<std::string>() == "interval"));
        CHECK(!t.at("causes").get_ref<const Array&>().empty());
        for (const auto& cause : t.at("causes").get_ref<const Array&>())
            CHECK(std::set<std::string>{"kinematic", "dynamic", "collision"}.count(cause.get<std::string>()) == 1);
    }
    for (const auto& cycle : c.at("cycles").get_ref<const Array&>()) CHECK(!cycle.get_ref<const Array&>().empty());
    CHECK(c.at("terminal").is_array());
}

TEST_CASE("cli/envision: --table has the columns of Appendices A-D") {
    const auto r = envision(metric_scene("cam.def") + " --table");
    REQUIRE(r.status == 0);
    CHECK(r.out.find("chain 1: rows: place of cam/follower; columns: motions of cam / follower\n") != std::string::npos);
    CHECK(r.out.find("place | --       | -0       | -+       | 0-       | 00       | 0+       | +-       | +0       | ++") != std::string::npos);
}

TEST_CASE("cli/envision: --next, --previous and --without") {
    const auto next = envision(metric_scene("cam.def") + " --next 'cam/follower-0 0 0'");
    REQUIRE(next.status == 0);
    CHECK(next.out.find("state #") == 0);
    // At rest in the cam's lowest join, the follower's weight rests on both flanks and comes back to
    // it with the opposite sign (Law 5: the same cause cancels), and the motor lifts it.
    CHECK(next.out.find("  forces: cam (+) motor; follower (-) gravity;") != std::string::npos);
    CHECK(next.out.find("  net force: cam (+), follower (+)") != std::string::npos);
    CHECK(next.out.find("  next (") != std::string::npos);
    const auto previous = envision(metric_scene("cam.def") + " --previous 0");
    REQUIRE(previous.status == 0);
    CHECK(previous.out.find("  previous (") != std::string::npos);
    // The cam without the follower's return force (9.4): the follower feels no force of its own.
    const auto without = envision(metric_scene("cam.def") + " --without 'Force follower' --next 'cam/follower-0 0 0'");
    REQUIRE(without.status == 0);
    CHECK(without.out.find("  forces: cam (+) motor; follower (+) motor\n") != std::string::npos);
    CHECK(without.out.find("gravity") == std::string::npos);
}

TEST_CASE("cli/envision: --why-not cites the laws' preference where it keeps another state (8.3.4)") {
    // From #28 the escapement's step reaches the places of #217 and #218; the chain settles in
    // #217, nearer to what the step allows, by the `prefer` of rules/clock/nearness.rules.
    std::ifstream rules(std::string(QM_SOURCE_DIR) + "/rules/clock/nearness.rules");
    std::string line;
    int at = 0, n = 0;
    while (std::getline(rules, line)) {
        ++n;
        if (line.rfind("prefer (motion ", 0) == 0) at = n;
    }
    REQUIRE(at > 0);
    const auto r = envision(metric_scene("escapement.def") + " --why-not '#28 -> #218'");
    REQUIRE(r.status == 0);
    CHECK(r.out.find("no transition #28 ") == 0);
    CHECK(r.out.find("state #217 has these places too and the laws prefer it: it is nearer to what the step allows for every part (the `prefer` at ") !=
          std::string::npos);
    CHECK(r.out.find("/clock/nearness.rules:" + std::to_string(at) + ")") != std::string::npos);
}

// The reasons of a --why-not answer (up to the derivations of the first state), with the source
// folder written ROOT.
std::string reasons_of(const std::string& out) {
    std::string text = out.substr(0, out.find("  the laws in the first state:\n"));
    const std::string root = QM_SOURCE_DIR;
    for (auto at = text.find(root); at != std::string::npos; at = text.find(root, at)) text.replace(at, root.size(), "ROOT");
    return text;
}

TEST_CASE("cli/envision: --why-not cites the settling law that refutes a motion (rules/clock/settling.rules)") {
    // #113: the escapement at rest at place 19 under a definite force on the scape wheel: the
    // instant step allows it only -, so it must change (Table 5.1, 8.3.3: rule must-change).
    // #188 -> #40: arriving at place 8 the collision gives the pair (+ -), not #40's motions (5.3.3:
    // rule collision-fixes-motion). Goldens: tests/cli/why_not/*.txt.
    for (const auto& [question, golden] : {std::pair{"#113 -> #114", "must_change.txt"}, std::pair{"#188 -> #40", "collision.txt"}}) {
        CAPTURE(question);
        const auto r = envision(metric_scene("escapement.def") + " --why-not '" + question + "'");
        REQUIRE(r.status == 0);
        CHECK(reasons_of(r.out) == slurp(std::string(QM_SOURCE_DIR) + "/tests/cli/why_not/" + golden));
    }
}

TEST_CASE("cli/envision: laws that prefer among motions without a step-allows for each are an error at the `prefer`") {
    // The nearness rule that assumes (step-allows O H) for every motion narrowed to (+), and made a
    // plain conclusion: each a faulty law file, refused where it is written (exit 2), not a crash.
    const std::string assumed = "  when (possible-motions ?o ?motions) (motion-value ?h)\n  then assume (step-allows ?o ?h)";
    const std::vector<std::pair<std::string, std::string>> broken{
        {"  when (possible-motions ?o ?motions) (motion-value ?h) (= ?h (+))\n  then assume (step-allows ?o ?h)",
         "nearness.rules:55:1: error: the laws prefer among the motions of scape-wheel but assume no (step-allows O H) for each of its motions"},
        {"  when (possible-motions ?o ?motions) (motion-value ?h)\n  then (step-allows ?o ?h)",
         "nearness.rules:41:1: error: the laws conclude (step-allows "},
        // A motion that is no sign of Table 5.1 (the review found it written past a table's end).
        {"  when (possible-motions ?o ?motions) (motion-value ?h)\n  then assume (step-allows ?o ?h) assume (step-allows ?o (?))",
         "(?)), but the envisioner reads (step-allows O H) only as an assumption, one for each object O and motion H of (+), (0), (-)"},
    };
    for (std::size_t i = 0; i < broken.size(); ++i) {
        CAPTURE(i);
        const std::string dir = qm::test::mutated_rules("rules/clock", "envision_" + std::to_string(i), "nearness.rules",
                                                        assumed, broken[i].first);
        const auto r = envision(metric_scene("escapement.def") + " --rules " + dir);
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK_MESSAGE(r.err.find(broken[i].second) != std::string::npos, r.err);
    }
}

TEST_CASE("cli/envision: --from, --path, --why-not, --dot and --svg") {
    const std::string ratchet = std::string(QM_SOURCE_DIR) + "/scenarios/clock/ratchet.def";
    const auto all = envision(ratchet + " --json");
    REQUIRE(all.status == 0);
    const auto j = qm::test::read_json(all.out);
    REQUIRE_FALSE(j.is_discarded());
    const auto& c = j.at("chains").at(0);
    // The one jam: terminal and not a possible rest (the ratchet's others may also move on).
    std::vector<int> jams;
    for (const auto& t : c.at("terminal").get_ref<const Array&>()) jams.push_back(static_cast<int>(t.get<double>()));
    for (const auto& r : c.at("possible_rests").get_ref<const Array&>()) std::erase(jams, static_cast<int>(r.get<double>()));
    REQUIRE(jams.size() == 1);
    const std::string jam = "#" + std::to_string(jams[0]);
    // What the jammed state leads to: itself alone.
    const auto from = envision(ratchet + " --from '" + jam + "' --json");
    REQUIRE(from.status == 0);
    const auto f = qm::test::read_json(from.out);
    REQUIRE_FALSE(f.is_discarded());
    CHECK(f.at("chains").at(0).at("states").get_ref<const Array&>().size() == 1);
    CHECK(f.at("chains").at(0).at("transitions").get_ref<const Array&>().empty());
    // From rest in free space to the jam (9.2.3, Figure 9.27).
    const auto path = envision(ratchet + " --path 'ratchet-wheel/pawl:free ratchet-wheel=0 pawl=0 ; " + jam + "'");
    REQUIRE(path.status == 0);
    CHECK(path.out.find("path (") != std::string::npos);
    CHECK(path.out.find("<- 2: " + jam) != std::string::npos);
    const auto none = envision(ratchet + " --path '" + jam + " ; ratchet-wheel=+'");
    REQUIRE(none.status == 0);
    CHECK(none.out.find("no path: descriptions 1..1 are matched") != std::string::npos);
    // Why not: a combination the jam's corner blocks, and a transition that is not there.
    const auto blocked = envision(ratchet + " --why-not '" + jam + " -> ratchet-wheel/pawl-2 + 0'");
    REQUIRE(blocked.status == 0);
    CHECK(blocked.out.find("is not a state") != std::string::npos);
    CHECK(blocked.out.find("false <= rule motion-into-blocked-space") != std::string::npos);
    const auto stuck = envision(ratchet + " --why-not '" + jam + " -> #0'");
    REQUIRE(stuck.status == 0);
    CHECK(stuck.out.find("no transition " + jam) == 0);
    CHECK(stuck.out.find("the laws in the first state:") != std::string::npos);
    // Graphviz: the graph written whole.
    const std::string dot = std::string(QM_BINARY_DIR) + "/envision_test.dot";
    std::remove(dot.c_str());
    const auto d = envision(ratchet + " --dot " + dot);
    REQUIRE(d.status == 0);
    const std::string graph = slurp(dot);
    CHECK(graph.find("digraph \"ratchet\"") == 0);
    CHECK(graph.find("peripheries=2") != std::string::npos);  // the terminal state
}

// --svg lays out and draws the graph with Graphviz's library: no program is run, so a quote or a
// blank in the file's name is only a character of it.
TEST_CASE("cli/envision: --svg draws the graph, into a file whose name holds a quote") {
    const std::string folder = std::string(QM_BINARY_DIR) + "/envision svg 'test'";
    std::filesystem::create_directories(folder);
    const std::string svg = folder + "/it's \"a\" graph.svg";
    std::filesystem::remove(svg);
    auto quoted = [](const std::string& s) {  // for the shell that runs qm-atms
        std::string out = "'";
        for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return out + "'";
    };
    // A small graph (three states): the file's name is what is tested, not Graphviz's layout.
    const auto r = envision(std::string(QM_SOURCE_DIR) + "/scenarios/clock/gear_pair.def --svg " + quoted(svg));
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const std::string drawn = slurp(svg);
    CHECK(drawn.find("<svg") != std::string::npos);
    CHECK(drawn.find("<title>gear&#45;pair</title>") != std::string::npos);  // the graph's name (Graphviz escapes its -)
    CHECK(drawn.find("</svg>") != std::string::npos);
    CHECK(!std::filesystem::exists(svg + ".part"));  // written whole, then renamed
}

TEST_CASE("cli/envision: bad input is a located error, exit status 2, and nothing on standard output") {
    struct Case {
        std::string args, message;
    };
    const std::string lonely = write_temp("envision_lonely.def", "(Defmechanism lonely\n  Parts ((wheel (circle (0 0) 1) (rotation))))\n");
    const std::string apart = write_temp("envision_apart.def",
                                         "(Defmechanism apart\n  Parts ((a (circle (0 0) 1) (rotation (0 0.5)))\n         (b (circle (5 0) 1) (rotation (5 0.5))))\n"
                                         "  Pairs ((a b)))\n");
    const std::string free = write_temp("envision_free.def",
                                        "(Defmechanism free\n  Parts ((crank (crank (crank-radius 0.6) (pin-radius 0.1)) (rotation))\n"
                                        "         (hub (block (width 0.2) (height 0.2)) (fixed)))\n  Pairs ((crank hub)))\n");
    const std::vector<Case> cases{
        {lonely, "envision_lonely.def:1:1: error: mechanism 'lonely' has no kinematic pair"},
        {apart, "envision_apart.def:4:10: error: the parts 'a' and 'b' never touch"},
        {free, "envision_free.def:4:10: error: 'crank' and 'hub' never touch: their configuration space is all free"},
        {metric_scene("cam.def") + " --max-states 10", "qm-atms: error: state limit 10 reached while finding the states of chain 1 of "},
        {metric_scene("cam.def") + " --max-states 0", "--max-states expects a positive whole number, not '0'"},
        {metric_scene("cam.def") + " --next 'cam/follower-99 0 0'", "--next:1:1: error: pair 'cam/follower' has no place 99"},
        {metric_scene("cam.def") + " --next 'wheel/follower-1 0 0'", "--next:1:1: error: unknown pair 'wheel/follower'"},
        {metric_scene("cam.def") + " --next 'cam/follower-1 0'", "--next:1:16: error: expected 2 motions"},
        {metric_scene("cam.def") + " --next 'cam/follower-1 x 0'", "--next:1:16: error: expected a motion +, 0 or -, not 'x'"},
        {metric_scene("cam.def") + " --next '#100000'", "--next:1:1: error: no state 100000"},
        {metric_scene("cam.def") + " --previous ''", "--previous:1:1: error: expected a state"},
        {metric_scene("cam.def") + " --without 'Force wheel'", "--without:1:7: error: unknown part 'wheel'"},
        {metric_scene("cam.def") + " --without 'Force cam wind'", "--without:1:11: error: no force of cause 'wind' acts on 'cam'"},
        {metric_scene("cam.def") + " --without 'Contact cam follower'", "--without:1:1: error: expected 'Force PART [CAUSE]'"},
        {metric_scene("cam.def") + " --table --json", "--table and --json are two different outputs"},
        {metric_scene("cam.def") + " --avoid 'cam=+'", "--avoid goes with --path"},
        {metric_scene("cam.def") + " --path 'cam=x'", "--path:1:5: error: expected a motion +, 0 or -, not 'x'"},
        {metric_scene("cam.def") + " --why-not '#0 #1'", "--why-not:1:1: error: expected 'STATE -> STATE'"},
        {metric_scene("cam.def") + " --why-not '#0 -> cam/follower-0 + x'", "--why-not:1:24: error: expected a motion +, 0 or -, not 'x'"},
        {metric_scene("cam.def") + " --from 'cam/follower-1'", "--from:1:1: error: expected 2 motions (one per part of the chain) after the places, found 0"},
        {metric_scene("cam.def") + " --rules /nonexistent", "/nonexistent:1:1: error: expected a folder of .rules files"},
        {std::string(QM_BINARY_DIR) + "/no_such_scene.def", "no_such_scene.def"},
    };
    for (const auto& c : cases) {
        CAPTURE(c.args);
        const auto r = envision(c.args);
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK_MESSAGE(r.err.find(c.message) != std::string::npos, r.err);
    }
}

TEST_CASE("cli/envision: --dot groups the states by behavioural cycle and doubles the terminal states") {
    // The cam without its return force has many cycles (docs/ENVISION.md); the ratchet a terminal state.
    for (const std::string def : {"clock/cam_free.def", "clock/ratchet.def"}) {
        CAPTURE(def);
        const std::string mech = std::string(QM_SOURCE_DIR) + "/scenarios/" + def;
        const std::string dot = std::string(QM_BINARY_DIR) + "/envision_test_groups.dot";
        const auto r = envision(mech + " --json --dot " + dot);
        REQUIRE(r.status == 0);
        const auto doc = qm::test::read_json(r.out);
        REQUIRE_FALSE(doc.is_discarded());
        const Json& chain = doc.at("chains").at(0);
        const std::string graph = slurp(dot);
        const auto& cycles = chain.at("cycles").get_ref<const Array&>();
        REQUIRE(!cycles.empty());
        // Each cycle is one cluster holding exactly its states.
        for (std::size_t i = 0; i < cycles.size(); ++i) {
            const std::string head = "subgraph \"cluster_1_cycle_" + std::to_string(i + 1) + "\" {";
            const auto from = graph.find(head);
            REQUIRE(from != std::string::npos);
            const std::string body = graph.substr(from, graph.find("    }\n", from) - from);
            std::set<int> inside, want;
            for (auto at = body.find("      c1s"); at != std::string::npos; at = body.find("      c1s", at + 1))
                inside.insert(std::stoi(body.substr(at + 9)));
            for (const auto& s : cycles[i].get_ref<const Array&>()) want.insert(static_cast<int>(s.get<double>()));
            CHECK(inside == want);
        }
        CHECK(graph.find("cluster_1_cycle_" + std::to_string(cycles.size() + 1)) == std::string::npos);
        for (const auto& t : chain.at("terminal").get_ref<const Array&>())
            CHECK(graph.find("c1s" + std::to_string(static_cast<int>(t.get<double>())) + " [label=") != std::string::npos);
        std::size_t doubled = 0;
        for (auto at = graph.find("peripheries=2"); at != std::string::npos; at = graph.find("peripheries=2", at + 1)) ++doubled;
        CHECK(doubled == chain.at("terminal").get_ref<const Array&>().size());
    }
}
