// tests/engine/engine_closed_world_test.cpp: `not`, aggregates and contexts (docs/RULES.md
// "## Semantics"), both the accepted and the rejected cases (the plain accepted case from rule text:
// rule_negation_test.cpp).
#include "compiled_program_builder.hpp"
#include "engine/engine.hpp"
#include <doctest/doctest.h>

using namespace qm::engine;
using namespace qm::engine::test;

namespace {

// flies(x) <- bird(x), not penguin(x); penguin(opus) a premise or an assumption.
Engine birds(bool penguin_assumed) {
    ValueTable v;
    CompiledProgram p;
    p.premises.push_back(ground(v, "bird", {v.symbol("tweety")}));
    p.premises.push_back(ground(v, "bird", {v.symbol("opus")}));
    (penguin_assumed ? p.assumptions : p.premises).push_back(ground(v, "penguin", {v.symbol("opus")}));
    p.rules.push_back(rule("flies", 1, {match(atom(v, "bird", {var(0)})), negation(atom(v, "penguin", {var(0)}))},
                           {assert_atom(atom(v, "flies", {var(0)}))}, 1));
    p.stratum_count = 2;
    return Engine(std::move(p), std::move(v));
}

std::optional<FactId> flies(Engine& e, const char* who) {
    ValueId arg = e.values().symbol(who);
    return e.find(e.values().symbol("flies"), std::span<const ValueId>(&arg, 1));
}

}  // namespace

TEST_CASE("engine/engine: generic `not` over an assumption-dependent fact is rejected with a located diagnostic") {
    Engine e = birds(true);
    qm::Diagnostics d;
    e.run(d);
    REQUIRE(d.has_errors());
    CHECK(d.items().front().message.find("cannot decide (penguin opus)") != std::string::npos);
    CHECK(d.items().front().where.file == "test.rules");
    CHECK(!flies(e, "opus").has_value());  // nothing unsound was derived
    CHECK(flies(e, "tweety").has_value()); // tweety is not a penguin in any environment
}

TEST_CASE("engine/engine: `not` in a context holds exactly when the fact does not hold in the context") {
    Engine e = birds(true);
    qm::Diagnostics d;
    FactId penguin = *e.find(e.values().symbol("penguin"), std::vector<ValueId>{e.values().symbol("opus")});
    qm::atms::AssumptionId a = *e.assumption(penguin);
    auto& atms = e.atms();

    ContextRun empty = e.run_in_context(atms.empty_environment(), d);
    REQUIRE(!d.has_errors());
    auto opus = flies(e, "opus");
    REQUIRE(opus.has_value());
    CHECK(atms.holds_in(e.node(*opus), empty.environment));
    // Sound label: the closed world of {} excludes the penguin assumption.
    CHECK(!atms.is_consistent(atms.environment({empty.closed_world, a})));

    ContextRun with_penguin = e.run_in_context(atms.environment({a}), d);
    REQUIRE(!d.has_errors());
    CHECK(!atms.holds_in(e.node(*opus), with_penguin.environment));
    CHECK(atms.holds_in(e.node(*flies(e, "tweety")), with_penguin.environment));
    // The two closed worlds exclude each other.
    CHECK(!atms.is_consistent(atms.environment({empty.closed_world, with_penguin.closed_world})));
    // Re-running a context reuses its closed-world assumption.
    CHECK(e.run_in_context(atms.environment({a}), d).closed_world == with_penguin.closed_world);
}

TEST_CASE("engine/engine: `not` over a fact that depends on a choice-set assumption is rejected in a context") {
    ValueTable v;
    CompiledProgram p;
    p.premises.push_back(ground(v, "object", {v.symbol("o")}));
    CompiledTerm choices = constant(v.set({v.symbol("left"), v.symbol("right")}));
    p.rules.push_back(rule("uniqueness", 2, {match(atom(v, "object", {var(0)}))},
                           {exactly_one(1, choices, atom(v, "moves", {var(0), var(1)}))}));
    p.rules.push_back(rule("still", 1,
                           {match(atom(v, "object", {var(0)})), negation(atom(v, "moves", {var(0), constant(v.symbol("left"))}))},
                           {assert_atom(atom(v, "not-left", {var(0)}))}, 1));
    p.stratum_count = 2;
    Engine e(std::move(p), std::move(v));
    qm::Diagnostics d;
    e.run_in_context(e.atms().empty_environment(), d);
    REQUIRE(d.has_errors());
    CHECK(d.items().front().message.find("choices of a choice set") != std::string::npos);
    CHECK(e.choice_sets().size() == 1);
    CHECK(e.interpretations().size() == 2);
}

TEST_CASE("engine/engine: an aggregate folds exactly the facts holding in the context") {
    // total(s, sum of the weights): weights a and b are premises, c an assumption.
    auto scales = [] {
        ValueTable v;
        CompiledProgram p;
        p.premises.push_back(ground(v, "weight", {v.symbol("a"), v.integer(3)}));
        p.premises.push_back(ground(v, "weight", {v.symbol("b"), v.integer(4)}));
        p.assumptions.push_back(ground(v, "weight", {v.symbol("c"), v.integer(5)}));
        p.premises.push_back(ground(v, "scale", {v.symbol("s")}));
        p.rules.push_back(rule("total", 3,
                               {match(atom(v, "scale", {var(0)})),
                                aggregate(atom(v, "weight", {var(1), var(2)}), var(2), *default_builtins().find("+"),
                                          constant(v.integer(0)), 1)},
                               {assert_atom(atom(v, "total", {var(0), var(1)}))}, 1));
        p.stratum_count = 2;
        return Engine(std::move(p), std::move(v));
    };
    Engine e = scales();
    qm::Diagnostics generic;
    e.run(generic);
    CHECK(generic.has_errors());  // weight c depends on an assumption

    Engine e2 = scales();
    qm::Diagnostics d;
    auto& vt = e2.values();
    FactId c = *e2.find(vt.symbol("weight"), std::vector<ValueId>{vt.symbol("c"), vt.integer(5)});
    auto without = e2.run_in_context(e2.atms().empty_environment(), d);
    auto with = e2.run_in_context(e2.atms().environment({*e2.assumption(c)}), d);
    REQUIRE(!d.has_errors());
    auto total = [&](int t) { return e2.find(vt.symbol("total"), std::vector<ValueId>{vt.symbol("s"), vt.integer(t)}); };
    REQUIRE(total(7).has_value());
    REQUIRE(total(12).has_value());
    CHECK(e2.atms().holds_in(e2.node(*total(7)), without.environment));
    CHECK(!e2.atms().holds_in(e2.node(*total(7)), with.environment));
    CHECK(e2.atms().holds_in(e2.node(*total(12)), with.environment));
    CHECK(!e2.atms().holds_in(e2.node(*total(12)), without.environment));
}

TEST_CASE("engine/engine: premises cannot be added once a closed world was used") {
    Engine e = birds(false);
    qm::Diagnostics d;
    e.run(d);
    ValueId arg = e.values().symbol("pingu");
    CHECK_THROWS_AS(e.add_premise(e.values().symbol("penguin"), std::span<const ValueId>(&arg, 1)), qm::InternalError);
}
