// tests/cli/run_command_test.cpp: `qm-atms run` end to end through the built executable. The JSON
// output is read back (tests/support/program_json.hpp) and compared, for N-queens N = 4..8, with
// a brute-force enumeration (facts and labels, minimal nogoods, interpretations = the solutions:
// 2, 10, 4, 40, 92); --why on a fact that holds and on a ruled-out one (exact text); exit statuses
// (0 ok, 2 bad input) and the located, caret-marked diagnostics of bad input.
#include "qm_atms_run.hpp"
#include "../support/program_json.hpp"
#include <cstdio>
#include <cstdlib>
#include <doctest/doctest.h>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace {

using OrderedJson = nlohmann::ordered_json;  // ordered: the tests check the order of the keys
using OrderedArray = OrderedJson::array_t;
using OrderedObject = OrderedJson::object_t;
using Result = qm::test::Run;

// Runs in the binary folder, so that the relative paths in messages are the same in every tree.
Result run_cli(const std::string& args) { return qm::test::run_executable("./cli/qm-atms", args, "cli_test", {std::nullopt, QM_BINARY_DIR}); }

// Written in the binary directory, named relative to it (qm_atms runs there), so messages are stable.
std::string write_relative(const std::string& name, const std::string& text) {
    std::ofstream(std::string(QM_BINARY_DIR) + "/" + name) << text;
    return name;
}

std::string scenario(const std::string& name) { return std::string(QM_SOURCE_DIR) + "/scenarios/rules/" + name; }

using Env = std::set<std::string>;

// An array of arrays of strings (a label, the nogoods, the interpretations), as sets.
std::set<Env> env_list(const OrderedJson& j) {
    std::set<Env> out;
    for (const OrderedJson& e : j.get_ref<const OrderedArray&>()) {
        Env env;
        for (const OrderedJson& a : e.get_ref<const OrderedArray&>()) env.insert(a.get<std::string>());
        out.insert(env);
    }
    return out;
}

std::string queen(int r, int c) { return "(queen " + std::to_string(r) + " " + std::to_string(c) + ")"; }

void solutions(int n, int row, std::vector<int>& cols, std::set<Env>& out) {
    if (row > n) {
        Env s;
        for (int r = 1; r <= n; ++r) s.insert(queen(r, cols[static_cast<std::size_t>(r)]));
        out.insert(s);
        return;
    }
    for (int c = 1; c <= n; ++c) {
        bool safe = true;
        for (int r = 1; r < row; ++r) {
            int d = cols[static_cast<std::size_t>(r)] - c;
            safe = safe && d != 0 && d != row - r && d != r - row;
        }
        if (!safe) continue;
        cols[static_cast<std::size_t>(row)] = c;
        solutions(n, row + 1, cols, out);
    }
}

}  // namespace

TEST_CASE("cli/run_command: --json for N-queens equals a brute-force enumeration, N = 4..8") {
    const std::map<int, std::size_t> known = {{4, 2}, {5, 10}, {6, 4}, {7, 40}, {8, 92}};  // OEIS A000170
    for (auto [n, count] : known) {
        CAPTURE(n);
        Result r = run_cli("run " + scenario("queens" + std::to_string(n) + ".rules") + " --json");
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        REQUIRE(r.out.size() > 1);
        CHECK(r.out.back() == '\n');
        const auto top = qm::test::read_json<OrderedJson>(r.out);
        REQUIRE_FALSE(top.is_discarded());
        REQUIRE(top.get_ref<const OrderedObject&>().size() == 3);  // the order of the keys: the exact output below

        // Facts: every (queen r c), labelled by its own assumption, and every premise (row r).
        std::map<std::string, std::set<Env>> labels;
        for (const OrderedJson& f : top.at("facts").get_ref<const OrderedArray&>()) {
            REQUIRE(f.get_ref<const OrderedObject&>().size() == 2);
            labels[f.at("fact").get<std::string>()] = env_list(f.at("label"));
        }
        std::map<std::string, std::set<Env>> expected_labels;
        for (int row = 1; row <= n; ++row) {
            expected_labels["(row " + std::to_string(row) + ")"] = {Env{}};
            for (int c = 1; c <= n; ++c) expected_labels[queen(row, c)] = {Env{queen(row, c)}};
        }
        CHECK(labels == expected_labels);

        // Minimal nogoods: two queens in one row (the choice set), one column or one diagonal.
        const std::set<Env> nogoods = env_list(top.at("nogoods"));
        std::set<Env> expected_nogoods;
        for (int r1 = 1; r1 <= n; ++r1)
            for (int c1 = 1; c1 <= n; ++c1)
                for (int r2 = r1; r2 <= n; ++r2)
                    for (int c2 = 1; c2 <= n; ++c2) {
                        bool attack = r1 == r2 ? c1 < c2 : (c1 == c2 || c1 - c2 == r1 - r2 || c2 - c1 == r1 - r2);
                        if (attack) expected_nogoods.insert(Env{queen(r1, c1), queen(r2, c2)});
                    }
        CHECK(nogoods == expected_nogoods);

        const std::set<Env> interpretations = env_list(top.at("interpretations"));
        std::set<Env> expected;
        CHECK(top.at("interpretations").get_ref<const OrderedArray&>().size() == count);  // no duplicates either
        std::vector<int> cols(static_cast<std::size_t>(n) + 1, 0);
        solutions(n, 1, cols, expected);
        CHECK(expected.size() == count);
        CHECK(interpretations == expected);
        // Deterministic: a second run prints the same bytes.
        CHECK(run_cli("run " + scenario("queens" + std::to_string(n) + ".rules") + " --json").out == r.out);
    }
}

TEST_CASE("cli/run_command: --json writes a fact that holds nowhere with an empty label") {
    std::string p = write_relative("cli_json_empty.rules",
                               "assume (open b)\nassume (closed b)\nrule door when (open ?d) (closed ?d) then (ajar ?d)\n"
                               "rule exclusive when (open ?d) (closed ?d) then false\n");
    Result r = run_cli("run " + p + " --json");
    CHECK(r.status == 0);
    CHECK(r.out == "{\"facts\": [{\"fact\": \"(ajar b)\", \"label\": []}, {\"fact\": \"(closed b)\", \"label\": "
                   "[[\"(closed b)\"]]}, {\"fact\": \"(open b)\", \"label\": [[\"(open b)\"]]}], \"nogoods\": "
                   "[[\"(closed b)\", \"(open b)\"]], \"interpretations\": [[]]}\n");
}

TEST_CASE("cli/run_command: --why prints the justification tree, or the nogoods ruling a fact out") {
    std::string held = write_relative("cli_why_holds.rules",
                                  "fact (edge a b)\nfact (edge b c)\nassume (open b)\n\n"
                                  "rule path-1\n  when (edge ?x ?y)\n  then (path ?x ?y)\n\n"
                                  "rule path-2\n  when (path ?x ?y) (edge ?y ?z) (open ?y)\n  then (path ?x ?z)\n");
    Result h = run_cli("run " + held + " --why '(path a c)'");
    CHECK(h.status == 0);
    CHECK(h.out == "(path a c) holds\n"
                   "  in {(open b)}:\n"
                   "    (open b) <= assumption at cli_why_holds.rules:3: assume (open b)\n"
                   "    (edge b c) <= premise at cli_why_holds.rules:2\n"
                   "    (edge a b) <= premise at cli_why_holds.rules:1\n"
                   "    (path a b) <= rule path-1 at cli_why_holds.rules:5 {?x = a, ?y = b}: (edge a b)\n"
                   "    (path a c) <= rule path-2 at cli_why_holds.rules:9 {?x = a, ?y = b, ?z = c}: (path a b), "
                   "(edge b c), (open b)\n");
    std::string out = write_relative("cli_why_out.rules",
                                 "assume (open b)\nassume (closed b)\n\nrule door\n  when (open ?d) (closed ?d)\n"
                                 "  then (ajar ?d)\n\nrule exclusive\n  when (open ?d) (closed ?d)\n  then false\n");
    Result o = run_cli("run " + out + " --why '(ajar b)'");
    CHECK(o.status == 0);
    CHECK(o.out == "(ajar b) is ruled out: every environment supporting it is nogood\n"
                   "  nogood {(closed b), (open b)}:\n"
                   "    (closed b) <= assumption at cli_why_out.rules:2: assume (closed b)\n"
                   "    (open b) <= assumption at cli_why_out.rules:1: assume (open b)\n"
                   "    false <= rule exclusive at cli_why_out.rules:8 {?d = b}: (open b), (closed b)\n");
    Result none = run_cli("run " + out + " --why '(ajar c)'");
    CHECK(none.status == 0);
    CHECK(none.out == "(ajar c) is not a fact of this program (no rule concludes it)\n");
    // The bundled polybox: (value f 12) is excluded by both of de Kleer and Williams' conflicts.
    // The `not` conditions a firing relied on are shown after it, under its binding.
    Result birds = run_cli("run " + scenario("birds.rules") + " --why '(flies tweety)'");
    CHECK(birds.status == 0);
    CHECK(birds.out.find("    (flies tweety) <= rule birds-fly-unless-penguins at " + scenario("birds.rules") +
                         ":16 {?b = tweety}: (bird tweety)\n      and not (penguin tweety)\n") != std::string::npos);
    Result poly = run_cli("run " + scenario("polybox.rules") + " --why '(value f 12)'");
    CHECK(poly.status == 0);
    CHECK(poly.out.find("(value f 12) is ruled out") == 0);
    CHECK(poly.out.find("  nogood {(mode a1 ok), (mode m1 ok), (mode m2 ok)}:\n") != std::string::npos);
    CHECK(poly.out.find("  nogood {(mode a1 ok), (mode a2 ok), (mode m1 ok), (mode m3 ok)}:\n") != std::string::npos);
}

TEST_CASE("cli/run_command: bad input exits 2 with located diagnostics and a caret") {
    std::string syntax = write_relative("cli_bad_syntax.rules", "fact (p 1)\nrule r when (p ?x) then (q ?y)\nfact q\n");
    Result r = run_cli("run " + syntax);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "cli_bad_syntax.rules:2:28: error: variable ?y is used before it is bound\n"
                   "  rule r when (p ?x) then (q ?y)\n"
                   "                             ^\n"
                   "cli_bad_syntax.rules:3:6: error: expected an atom like (p ?x) but found 'q'\n"
                   "  fact q\n"
                   "       ^\n");
    std::string negation = write_relative("cli_bad_negation.rules",
                                      "fact (bird opus)\nassume (penguin opus)\n"
                                      "rule flies when (bird ?b) not (penguin ?b) then (flies ?b)\n");
    Result n = run_cli("run " + negation);
    CHECK(n.status == 2);
    CHECK(n.err.find(negation + ":3:31: error: rule 'flies': cannot decide (penguin opus)") == 0);
    CHECK(n.err.find("\n  rule flies when (bird ?b) not (penguin ?b) then (flies ?b)\n"
                     "                                ^\n") != std::string::npos);
    Result why = run_cli("run " + scenario("queens4.rules") + " --why 'queen 1 2'");
    CHECK(why.status == 2);
    CHECK(why.err == "--why:1:1: error: expected an atom like (p ?x) but found 'queen'\n  queen 1 2\n  ^\n");
    Result ground = run_cli("run " + scenario("queens4.rules") + " --why '(queen ?r 2)'");
    CHECK(ground.status == 2);
    CHECK(ground.err.find("--why:1:8: error: expected a constant but found the variable ?r") == 0);
    Result missing = run_cli("run /no/such/file.rules");
    CHECK(missing.status == 2);
    CHECK(missing.err == "/no/such/file.rules:1:1: error: cannot open rule file '/no/such/file.rules': no such file\n");
    CHECK(run_cli("").status == 2);  // no command at all; the options' errors: limits_test.cpp
}

namespace {
// An object's keys, in the order read.
std::vector<std::string> keys_of(const OrderedJson& object) {
    std::vector<std::string> keys;
    for (const auto& [key, value] : object.get_ref<const OrderedObject&>()) keys.push_back(key);
    return keys;
}

std::string joined(const OrderedJson& list, const char* sep) {
    std::string out;
    for (std::size_t i = 0; i < list.get_ref<const OrderedArray&>().size(); ++i) out += (i > 0 ? sep : "") + list.at(i).get<std::string>();
    return out;
}
}  // namespace

// `run --why FACT --json`: the JSON must say exactly what the text form says.
TEST_CASE("cli/run_command: --why with --json gives the explanation as JSON, step for step the text form") {
    std::string held = write_relative("cli_why_json.rules",
                                  "fact (edge a b)\nfact (edge b c)\nassume (open b)\nassume (shut b)\n\n"
                                  "rule a-is-start\n  when (edge ?x ?y) not (edge ?w ?x)\n  then (start ?x)\n\n"
                                  "rule path-1\n  when (edge ?x ?y)\n  then (path ?x ?y)\n\n"
                                  "rule path-2\n  when (path ?x ?y) (edge ?y ?z) (open ?y)\n  then (path ?x ?z)\n\n"
                                  "rule path-3\n  when (path ?x ?y) (edge ?y ?z) (shut ?y)\n  then (path ?x ?z)\n\n"
                                  "rule door\n  when (open ?d) (shut ?d)\n  then (ajar ?d)\n\n"
                                  "rule exclusive\n  when (open ?d) (shut ?d)\n  then false\n");
    for (const char* fact : {"(path a c)", "(ajar b)", "(path a b)", "(start a)"}) {
        CAPTURE(fact);
        Result text = run_cli("run " + held + " --why '" + fact + "'");
        Result json = run_cli("run " + held + " --why '" + fact + "' --json");
        REQUIRE(json.status == 0);
        CHECK(json.err.empty());
        const auto doc = qm::test::read_json<OrderedJson>(json.out);
        REQUIRE_FALSE(doc.is_discarded());
        REQUIRE(keys_of(doc) == std::vector<std::string>{"fact", "status", "derivations", "nogoods"});
        CHECK(doc.at("fact").get<std::string>() == fact);
        const std::string status = doc.at("status").get<std::string>();
        // Rebuild the text form from the JSON and compare with what --why prints.
        std::string rebuilt = std::string(fact) + (status == "holds" ? " holds\n" : " is ruled out: every environment supporting it is nogood\n");
        CHECK(doc.at(status == "holds" ? "nogoods" : "derivations").get_ref<const OrderedArray&>().empty());
        for (const OrderedJson& d : doc.at(status == "holds" ? "derivations" : "nogoods").get_ref<const OrderedArray&>()) {
            REQUIRE(keys_of(d) == std::vector<std::string>{"environment", "steps"});
            rebuilt += std::string(status == "holds" ? "  in {" : "  nogood {") + joined(d.at("environment"), ", ") + "}:\n";
            for (const OrderedJson& step : d.at("steps").get_ref<const OrderedArray&>()) {
                REQUIRE(keys_of(step) == std::vector<std::string>{"fact", "informant", "binding", "antecedents", "not"});
                rebuilt += "    " + step.at("fact").get<std::string>() + " <= " + step.at("informant").get<std::string>();
                if (!step.at("binding").get_ref<const OrderedArray&>().empty()) rebuilt += " {" + joined(step.at("binding"), ", ") + "}";
                if (!step.at("antecedents").get_ref<const OrderedArray&>().empty()) rebuilt += ": " + joined(step.at("antecedents"), ", ");
                rebuilt += "\n";
                for (const OrderedJson& absent : step.at("not").get_ref<const OrderedArray&>()) rebuilt += "      and not " + absent.get<std::string>() + "\n";
            }
        }
        CHECK(rebuilt == text.out);
    }
    Result held_json = run_cli("run " + held + " --why '(path a c)' --json");
    CHECK(held_json.out.find("\"status\": \"holds\"") != std::string::npos);
    CHECK(held_json.out.find("\"environment\": [\"(open b)\"]") != std::string::npos);
    CHECK(held_json.out.find("\"environment\": [\"(shut b)\"]") != std::string::npos);
    CHECK(run_cli("run " + held + " --why '(ajar b)' --json").out.find("\"status\": \"ruled-out\"") != std::string::npos);
    // A fact nothing concludes: status unsupported, written in canonical notation.
    CHECK(run_cli("run " + held + " --why '( path  c   a)' --json").out ==
          "{\"fact\": \"(path c a)\", \"status\": \"unsupported\", \"derivations\": [], \"nogoods\": []}\n");
}
