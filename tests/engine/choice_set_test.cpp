// tests/engine/choice_set_test.cpp: what `[exactly one ...]` means (docs/RULES.md "## Semantics"),
// end to end from rule text: a choice set ranges over its assumptions only (a fact derived
// otherwise holds by that derivation, in every interpretation); an empty choice set is false, so
// the firing's antecedents become a nogood that explanations show; the same set declared twice is
// one set. (Overlapping sets are a located error: golden case errors/choice_set_overlap.)
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include "engine/run_report.hpp"
#include "engine/why.hpp"
#include <doctest/doctest.h>
#include <memory>

using namespace qm::engine;

namespace {
std::unique_ptr<Engine> run(const std::string& text) {
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text(text, "c.rules", spec, d);
    auto p = compile_program(spec, d);
    REQUIRE(p.has_value());
    auto e = std::make_unique<Engine>(std::move(p->program), std::move(p->values));
    e->run(d);
    REQUIRE(!d.has_errors());
    return e;
}
FactId fact(Engine& e, const std::string& predicate, std::vector<ValueId> args) {
    auto f = e.find(e.values().symbol(predicate), args);
    REQUIRE(f.has_value());
    return *f;
}
}  // namespace

TEST_CASE("engine/engine: a choice set constrains its assumptions, not facts derived otherwise") {
    // (k 1) is also concluded outright, so it holds in every interpretation, including the one that
    // picks the assumption of (k 2): the choice is between the assumptions.
    auto e = run("fact (o a)\nrule c when (o ?x) then [exactly one ?k in {1 2}: assume (k ?k)] (k 1)\n");
    const RunReport r = make_report(*e);
    CHECK(r.interpretations == std::vector<EnvText>{{"(k 1)"}, {"(k 2)"}});
    const FactId k1 = fact(*e, "k", {e->values().integer(1)});
    const FactId k2 = fact(*e, "k", {e->values().integer(2)});
    CHECK(e->atms().is_true(e->node(k1)));
    for (qm::atms::EnvId i : e->interpretations()) {
        CHECK(e->atms().holds_in(e->node(k1), i));
        CHECK(e->atms().holds_in(e->node(k2), i) == (e->print(e->atms().env(i).assumptions()[0]) == "(k 2)"));
    }
}

TEST_CASE("engine/engine: an empty choice set makes the firing's antecedents a nogood") {
    auto e = run("fact (o a)\nrule c when (o ?x) then [exactly one ?k in {1 2} where (> ?k 5): assume (k ?k)]\n");
    CHECK(e->choice_sets().empty());
    CHECK(e->interpretations().empty());
    const RunReport r = make_report(*e);
    CHECK(r.nogoods == std::vector<EnvText>{EnvText{}});  // the empty environment: (o a) is a premise
    const Why w = why(*e, fact(*e, "o", {e->values().symbol("a")}));
    REQUIRE(w.status == Why::Status::ruled_out);
    REQUIRE(w.nogoods.size() == 1);
    REQUIRE(!w.nogoods[0].steps.empty());
    CHECK(w.nogoods[0].steps.back().consequent == "false");
    CHECK(w.nogoods[0].steps.back().informant == "rule c at c.rules:2");
    CHECK(w.nogoods[0].steps.back().binding == std::vector<std::string>{"?x = a"});
}

TEST_CASE("engine/engine: an empty choice set rules out only the environments where it fired") {
    // The empty set fires only where (o a) is assumed: that assumption becomes a nogood, and the
    // other choice set keeps its two interpretations (an empty set registered as a choice set left none).
    auto e = run("assume (o a)\nfact (p b)\n"
                 "rule c when (o ?x) then [exactly one ?k in {1 2} where (> ?k 5): assume (k ?k)]\n"
                 "rule m when (p ?y) then [exactly one ?m in {on off}: assume (mode ?m)]\n");
    const RunReport r = make_report(*e);
    CHECK(r.nogoods == std::vector<EnvText>{{"(o a)"}, {"(mode off)", "(mode on)"}});
    CHECK(r.interpretations == std::vector<EnvText>{{"(mode off)"}, {"(mode on)"}});
    CHECK(e->choice_sets().size() == 1);
}

TEST_CASE("engine/engine: the same choice set declared by two firings or two rules is one set") {
    auto e = run("fact (o a)\nfact (o b)\n"
                 "rule c when (o ?x) then [exactly one ?m in {on off}: assume (mode ?m)]\n"
                 "rule d when (o a) then [exactly one ?m in {off on}: assume (mode ?m)]\n");
    CHECK(e->choice_sets().size() == 1);
    CHECK(e->interpretations().size() == 2);
}
