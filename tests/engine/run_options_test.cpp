// tests/engine/run_options_test.cpp: RunOptions::max_steps bounds a run. Programs that would run
// for ever (counting up) or for very long (a four-way join, a choice set of 100000 elements) stop
// with one located diagnostic naming the rule, and what they found is sound; a limit that is not
// reached changes nothing (same report, same firings) on the bundled N-queens programs (queens8
// takes 5,984 steps).
#include "engine/run_report.hpp"
#include "run_rule_text.hpp"
#include <doctest/doctest.h>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

using namespace qm::engine;

namespace {
std::unique_ptr<Engine> limited_engine(const std::string& text) { return test::engine_for(text, "limits.rules"); }
RunOptions at_most(std::size_t steps) {
    RunOptions o;
    o.max_steps = steps;
    return o;
}
std::string diagnostics_text(const qm::Diagnostics& d) {
    std::ostringstream out;
    d.print(out);
    return out.str();
}
}  // namespace

TEST_CASE("engine/run_options: a program that counts for ever stops at the limit, located at the rule") {
    auto e = limited_engine("fact (n 0)\nrule count\n  when (n ?x)\n  then (n (+ ?x 1))\n");
    qm::Diagnostics d;
    e->run(d, at_most(1000));
    REQUIRE(d.size() == 1);
    CHECK(diagnostics_text(d).rfind("limits.rules:2:1: error: rule 'count': the run stopped here after ", 0) == 0);
    CHECK(diagnostics_text(d).find("(RunOptions::max_steps)") != std::string::npos);
    // Each firing is one step (the new fact seeds its own match, which tries no other fact).
    CHECK(e->rule_firings() == 1000);
    CHECK(e->facts().size() == 1001);
    // Sound: every fact found holds, derived from (n 0) by the firings made.
    for (FactId f : e->facts_of(e->values().symbol("n"))) CHECK(e->atms().is_true(e->node(f)));
}

TEST_CASE("engine/run_options: a join over many facts and a huge choice set stop, declaring nothing partial") {
    std::string many;
    for (int i = 0; i < 200; ++i) many += "fact (k " + std::to_string(i) + ")\n";
    // 200^4 = 1.6 * 10^9 combinations, none passing the test: the matcher alone would take long.
    auto join = limited_engine(many + "rule four\n  when (k ?a) (k ?b) (k ?c) (k ?d) (< ?d 0)\n  then (never)\n");
    qm::Diagnostics d;
    join->run(d, at_most(100000));
    REQUIRE(d.size() == 1);
    CHECK(diagnostics_text(d).rfind("limits.rules:201:1: error: rule 'four': the run stopped here", 0) == 0);
    // 5 * 10^9 nogoods between the pairs of 100000 assumptions: refused before any is assumed.
    auto big = limited_engine("fact (o a)\nrule wide\n  when (o ?x)\n  then [exactly one ?k in (range 1 100000): assume (k ?k)]\n");
    qm::Diagnostics b;
    big->run(b, at_most(1000000));
    REQUIRE(b.size() == 1);
    CHECK(diagnostics_text(b).rfind("limits.rules:4:8: error: rule 'wide': the run stopped here", 0) == 0);
    CHECK(big->choice_sets().empty());
    CHECK(big->facts().size() == 1);
    CHECK(big->atms().minimal_nogoods().empty());
}

TEST_CASE("engine/run_options: a limit that is not reached changes nothing") {
    for (int n = 4; n <= 8; ++n) {
        const std::string file = std::string(QM_SOURCE_DIR) + "/scenarios/rules/queens" + std::to_string(n) + ".rules";
        qm::Diagnostics d1, d2;
        auto p1 = load_program(file, d1);
        auto p2 = load_program(file, d2);
        REQUIRE(p1.has_value());
        REQUIRE(p2.has_value());
        Engine unlimited(std::move(p1->program), std::move(p1->values));
        Engine limited(std::move(p2->program), std::move(p2->values));
        unlimited.run(d1);
        limited.run(d2, at_most(100000));  // the fuzz target's limit (tests/fuzz/engine_rules_fuzz.cpp)
        CHECK(!d1.has_errors());
        CHECK(!d2.has_errors());
        CHECK(limited.rule_firings() == unlimited.rule_firings());
        const RunReport a = make_report(unlimited), b = make_report(limited);
        CHECK(a.facts.size() == b.facts.size());
        CHECK(a.nogoods == b.nogoods);
        CHECK(a.interpretations == b.interpretations);
    }
}
