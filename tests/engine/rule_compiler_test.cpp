// tests/engine/rule_compiler_test.cpp: rule text -> compiled program -> run, through the front end
// (engine/rule_spec_reader.hpp, the X3 parser) and the compiler: the scenario programs give their known
// answers (N-queens: tests/cli/run_command_test.cpp), and strata are ordered. Bad programs: the
// golden cases of tests/engine/errors/.
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include "engine/run_report.hpp"
#include <doctest/doctest.h>

using namespace qm::engine;

namespace {
std::optional<LoadedProgram> compile_text(const std::string& text, qm::Diagnostics& d) {
    ProgramSpec spec;
    read_rule_text(text, "t.rules", spec, d);
    if (d.has_errors()) return std::nullopt;
    return compile_program(spec, d);
}
}  // namespace

TEST_CASE("engine/rule_compiler: the polybox finds de Kleer and Williams' two minimal conflicts") {
    qm::Diagnostics d;
    auto p = load_program(std::string(QM_SOURCE_DIR) + "/scenarios/rules/polybox.rules", d);
    REQUIRE(p.has_value());
    Engine e(std::move(p->program), std::move(p->values));
    e.run(d);
    REQUIRE(!d.has_errors());
    RunReport r = make_report(e);
    std::vector<EnvText> conflicts;
    for (const auto& n : r.nogoods)
        if (n.size() > 2) conflicts.push_back(n);
    CHECK(conflicts == std::vector<EnvText>{{"(mode a1 ok)", "(mode m1 ok)", "(mode m2 ok)"},
                                            {"(mode a1 ok)", "(mode a2 ok)", "(mode m1 ok)", "(mode m3 ok)"}});
    // 2^5 mode assignments minus those containing a conflict: 32 - 4 - 2 + 1 = 27.
    CHECK(r.interpretations.size() == 27);
}

TEST_CASE("engine/rule_compiler: birds.rules decides stratified negation generically") {
    qm::Diagnostics d;
    auto p = load_program(std::string(QM_SOURCE_DIR) + "/scenarios/rules/birds.rules", d);
    REQUIRE(p.has_value());
    Engine e(std::move(p->program), std::move(p->values));
    e.run(d);
    REQUIRE(!d.has_errors());
    auto& v = e.values();
    CHECK(e.find(v.symbol("flies"), std::vector<ValueId>{v.symbol("tweety")}).has_value());
    CHECK(!e.find(v.symbol("flies"), std::vector<ValueId>{v.symbol("opus")}).has_value());
    CHECK(e.find(v.symbol("can-travel"), std::vector<ValueId>{v.symbol("tweety")}).has_value());
}

TEST_CASE("engine/rule_compiler: strata put negated and aggregated predicates first") {
    qm::Diagnostics d;
    auto p = compile_text("rule a when (p ?x) then (q ?x)\n"
                          "rule b when (r ?x) not (q ?x) then (s ?x)\n"
                          "rule c when (p ?x) [sum ?y over (s ?y) with + start 0 as ?t] then (u ?t)\n",
                          d);
    REQUIRE(p.has_value());
    CHECK(p->program.rules[RuleId{0}].stratum == 0);
    CHECK(p->program.rules[RuleId{1}].stratum == 1);
    CHECK(p->program.rules[RuleId{2}].stratum == 2);
    CHECK(p->program.stratum_count == 3);
}
