// tests/engine/shared_program_test.cpp: engine/shared_program.hpp. share_program() plans every rule
// and lists the rules each predicate wakes (matched, or inside `for all` / `exists`, not under
// `not`), ascending and once each; engines over one shared program (and copies of one shared value
// table) derive what engines over their own copies do, each independently of the others.
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include "engine/shared_program.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <set>
#include <string>

using qm::Diagnostics;
using namespace qm::engine;

namespace {

const char* const shared_text = R"(
input (p ?x)
input (r ?x)
input (t ?x)
rule r1
  when (p ?x) (p ?x)
  then (q ?x)
rule r2
  when (q ?x) not (r ?x)
  then (s ?x)
rule r3
  when (t ?x) [for all ?y in {1 2}: (p ?y)]
  then (u ?x)
)";

LoadedProgram load_shared() {
    ProgramSpec spec;
    Diagnostics d;
    read_rule_text(shared_text, "shared.rules", spec, d);
    REQUIRE(!d.has_errors());
    auto p = compile_program(spec, d);
    REQUIRE(p.has_value());
    return std::move(*p);
}

std::set<std::string> derived(Engine& e) {
    Diagnostics d;
    e.run(d);
    REQUIRE(!d.has_errors());
    std::set<std::string> out;
    for (std::uint32_t i = 0; i < e.facts().size(); ++i)
        if (!e.label(FactId{i}).empty()) out.insert(e.print(FactId{i}));
    return out;
}

void add(Engine& e, const char* predicate, std::int64_t x) {
    const ValueId args[] = {e.values().integer(x)};
    e.add_premise(e.values().symbol(predicate), args);
}

}  // namespace

TEST_CASE("share_program: plans and triggers") {
    LoadedProgram p = load_shared();
    ValueTable values = p.values;
    const auto shared = share_program(p.program);
    REQUIRE(shared->plans.size() == 3);
    for (std::uint32_t r = 0; r < 3; ++r) {
        const MatchPlan expected = plan_matching(shared->program.rules[RuleId{r}]);
        CHECK(shared->plans[RuleId{r}].repeat_of == expected.repeat_of);
        CHECK(shared->plans[RuleId{r}].seed_first_safe == expected.seed_first_safe);
    }
    auto woken = [&](const char* predicate) {
        std::vector<std::uint32_t> out;
        const auto it = shared->by_trigger.find(values.symbol(predicate).value);
        if (it != shared->by_trigger.end())
            for (const RuleId r : it->second) out.push_back(r.value);
        return out;
    };
    CHECK(woken("p") == std::vector<std::uint32_t>{0, 2});  // r1 once although it matches p twice; r3 inside `for all`
    CHECK(woken("q") == std::vector<std::uint32_t>{1});
    CHECK(woken("r").empty());  // only under `not`: decided when the rule runs, not woken
    CHECK(woken("t") == std::vector<std::uint32_t>{2});
}

TEST_CASE("engines over one shared program and one shared table: as over their own copies, independent") {
    LoadedProgram p = load_shared();
    ValueTable values = p.values;
    values.share();
    const auto shared = share_program(p.program);
    Engine own(p.program, p.values);
    Engine a(shared, values), b(shared, values);
    for (Engine* e : {&own, &a}) {
        add(*e, "p", 1);
        add(*e, "p", 2);
        add(*e, "t", 7);
        add(*e, "r", 2);
    }
    add(b, "p", 5);
    const auto expected = derived(own);
    CHECK(expected.count("(u 7)") == 1);
    CHECK(expected.count("(s 1)") == 1);
    CHECK(expected.count("(s 2)") == 0);
    CHECK(derived(a) == expected);
    CHECK(derived(b) == std::set<std::string>{"(p 5)", "(q 5)", "(s 5)"});
    CHECK(&a.program() == &b.program());
    CHECK(values.size() == p.values.size());  // the engines' own values stayed their own
}
