// tests/engine/why_test.cpp: explanations of facts that hold and of facts that are ruled out; the
// run report and its JSON form.
#include "compiled_program_builder.hpp"
#include "run_rule_text.hpp"
#include "../support/golden.hpp"
#include "engine/json_writer.hpp"
#include "engine/why.hpp"
#include "engine/why_printer.hpp"
#include <doctest/doctest.h>

using namespace qm::engine;
using namespace qm::engine::test;

namespace {
// a is assumed; b <- a; c <- b; false <- c, d (d assumed): so {a, d} is nogood.
Engine chain() {
    ValueTable v;
    CompiledProgram p;
    p.assumptions.push_back(ground(v, "a", {}));
    p.assumptions.push_back(ground(v, "d", {}));
    p.premises.push_back(ground(v, "k", {v.integer(1)}));
    p.rules.push_back(rule("a-gives-b", 1, {match(atom(v, "a", {})), match(atom(v, "k", {var(0)}))},
                           {assert_atom(atom(v, "b", {var(0)}))}));
    p.rules.push_back(rule("b-gives-c", 1, {match(atom(v, "b", {var(0)}))}, {assert_atom(atom(v, "c", {}))}));
    p.rules.push_back(rule("c-and-d-conflict", 0, {match(atom(v, "c", {})), match(atom(v, "d", {}))}, {falsity()}));
    p.rules.push_back(rule("e-needs-both", 0, {match(atom(v, "c", {})), match(atom(v, "d", {}))},
                           {assert_atom(atom(v, "e", {}))}));
    return Engine(std::move(p), std::move(v));
}
}  // namespace

TEST_CASE("engine/why: a fact that holds is explained by a chain of named rules with bindings") {
    Engine e = chain();
    qm::Diagnostics d;
    e.run(d);
    FactId c = *e.find(e.values().symbol("c"), {});
    Why w = why(e, c);
    REQUIRE(w.status == Why::Status::holds);
    REQUIRE(w.derivations.size() == 1);
    CHECK(w.derivations[0].environment == EnvText{"(a)"});
    const auto& steps = w.derivations[0].steps;
    REQUIRE(steps.size() >= 2);
    CHECK(steps.back().consequent == "(c)");
    CHECK(steps.back().informant == "rule b-gives-c at test.rules:1");
    CHECK(steps.back().binding == std::vector<std::string>{"?v0 = 1"});
    CHECK(steps.back().antecedents == std::vector<std::string>{"(b 1)"});
    std::string text = print_why(w);
    CHECK(text.find("(b 1) <= rule a-gives-b at test.rules:1 {?v0 = 1}: (a), (k 1)") != std::string::npos);
}

TEST_CASE("engine/why: a ruled-out fact is explained by the nogoods that exclude it") {
    Engine e = chain();
    qm::Diagnostics d;
    e.run(d);
    FactId f = *e.find(e.values().symbol("e"), {});
    CHECK(e.label(f).empty());
    Why w = why(e, f);
    REQUIRE(w.status == Why::Status::ruled_out);
    REQUIRE(w.nogoods.size() == 1);
    CHECK(w.nogoods[0].environment == EnvText{"(a)", "(d)"});
    CHECK(w.nogoods[0].steps.back().consequent == "false");
    CHECK(w.nogoods[0].steps.back().informant == "rule c-and-d-conflict at test.rules:1");
}

TEST_CASE("engine/json_writer: the report has exactly the agreed shape and order") {
    const std::string queens4 = qm::test::slurp(std::string(QM_SOURCE_DIR) + "/scenarios/rules/queens4.rules");
    const RunReport r = make_report(*run_rule_text(queens4, "queens4.rules"));
    REQUIRE(r.interpretations.size() == 2);
    CHECK(r.interpretations[0] == EnvText{"(queen 1 2)", "(queen 2 4)", "(queen 3 1)", "(queen 4 3)"});
    CHECK(r.interpretations[1] == EnvText{"(queen 1 3)", "(queen 2 1)", "(queen 3 4)", "(queen 4 2)"});
    std::string json = to_json(r);
    CHECK(json.rfind("{\"facts\": [{\"fact\": \"(queen 1 1)\", \"label\": [[\"(queen 1 1)\"]]}, ", 0) == 0);
    CHECK(json.find("], \"nogoods\": [[\"(queen 1 1)\", \"(queen 1 2)\"], [\"(queen 1 1)\", \"(queen 1 3)\"], ") != std::string::npos);
    CHECK(json.find("\"interpretations\": [[\"(queen 1 2)\", \"(queen 2 4)\", \"(queen 3 1)\", \"(queen 4 3)\"], ") !=
          std::string::npos);
    CHECK(json.back() == '}');
}

TEST_CASE("engine/why: a step shows the `not` conditions its firing relied on, under its binding") {
    // flies(?b) <- bird(?b), not penguin(?b), not owns(?b, ?x): ?x is local to its `not`.
    ValueTable v;
    const BuiltinRegistry& b = default_builtins();
    CompiledProgram p;
    p.premises.push_back(ground(v, "bird", {v.symbol("tweety")}));
    p.rules.push_back(rule("flies", 2,
                           {match(atom(v, "bird", {var(0)})), negation(atom(v, "penguin", {var(0)})),
                            negation(atom(v, "owns", {var(0), var(1)})),
                            negation(atom(v, "heading", {var(0), call(b, "neg", {constant(v.direction("+0"))})}))},
                           {assert_atom(atom(v, "flies", {var(0)}))}));
    Engine e(std::move(p), std::move(v));
    qm::Diagnostics d;
    e.run(d);
    REQUIRE(!d.has_errors());
    Why w = why(e, *e.find(e.values().symbol("flies"), std::vector<ValueId>{e.values().symbol("tweety")}));
    REQUIRE(w.status == Why::Status::holds);
    REQUIRE(w.derivations.size() == 1);
    const WhyStep& last = w.derivations[0].steps.back();
    CHECK(last.antecedents == std::vector<std::string>{"(bird tweety)"});
    CHECK(last.absent == std::vector<std::string>{"(penguin tweety)", "(owns tweety ?v1)", "(heading tweety (- 0))"});
    CHECK(w.derivations[0].steps.front().absent.empty());  // the premise relied on nothing
    CHECK(print_why(w) == "(flies tweety) holds\n"
                          "  in {}:\n"
                          "    (bird tweety) <= premise at test.rules:1\n"
                          "    (flies tweety) <= rule flies at test.rules:1 {?v0 = tweety}: (bird tweety)\n"
                          "      and not (penguin tweety)\n"
                          "      and not (owns tweety ?v1)\n"
                          "      and not (heading tweety (- 0))\n");
    CHECK(to_json(w).find("\"antecedents\": [\"(bird tweety)\"], \"not\": [\"(penguin tweety)\", \"(owns tweety ?v1)\", "
                          "\"(heading tweety (- 0))\"]}") != std::string::npos);
}
