// tests/engine/rule_compiler_test.cpp: rule text -> compiled program -> run, through the front end
// (engine/rule_spec_reader.hpp, the X3 parser) and the compiler: the scenario programs give their known
// answers, and bad programs give located diagnostics.
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
std::string messages(const qm::Diagnostics& d) {
    std::string out;
    for (const auto& x : d.sorted())
        out += to_string(x.where) + ": " + x.message + "\n";
    return out;
}
}  // namespace

TEST_CASE("engine/rule_compiler: scenarios/rules/queensN.rules have 2, 10, 4, 40, 92 interpretations") {
    const std::size_t expected[] = {2, 10, 4, 40, 92};
    for (int n = 4; n <= 8; ++n) {
        qm::Diagnostics d;
        auto p = load_program(std::string(QM_SOURCE_DIR) + "/scenarios/rules/queens" + std::to_string(n) + ".rules", d);
        REQUIRE(p.has_value());
        Engine e(std::move(p->program), std::move(p->values));
        e.run(d);
        CHECK(!d.has_errors());
        CHECK(e.interpretations().size() == expected[n - 4]);
    }
}

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

TEST_CASE("engine/rule_compiler: bad programs give located diagnostics, several per run") {
    qm::Diagnostics d;
    auto p = compile_text("rule a when (p ?x) (frob ?x) then (q ?y)\n"
                          "rule b when (p ?x) (< ?x) then (q (abs ?x ?x))\n"
                          "fact (p ?z)\n"
                          "rule c when (p ?x) not (c ?x) then (c ?x)\n",
                          d);
    CHECK(!p.has_value());
    CHECK(messages(d) ==
          "t.rules:1:38: variable ?y is used before it is bound\n"
          "t.rules:2:20: '<' takes 2 argument(s), not 1\n"
          "t.rules:2:35: 'abs' takes 1 argument(s), not 2\n"
          "t.rules:3:9: a top-level fact or assumption must be ground, but has ?z\n"
          "t.rules:4:20: rule 'c': negation through recursion: 'c', used under `not` here, depends on this rule's "
          "own conclusion 'c' through the cycle c -> c (rule 'c', `not`)\n");
}

TEST_CASE("engine/rule_spec_reader: syntax errors are located and reading resumes at the next item") {
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text("rule a when (p ?x) then\nfact p\nrule b when (p ?x) then (q (7 ?x))\nrule c when (p ?x) then (r ?x)\n"
                   "include \"no-such-file.rules\"\n",
                   "t.rules", spec, d);
    CHECK(messages(d) ==
          "t.rules:2:1: expected a consequent (an atom, 'false', 'assume' or a bracketed quantifier) but found 'fact'\n"
          "t.rules:2:6: expected an atom like (p ?x) but found 'p'\n"
          "t.rules:3:29: expected a direction of signs or a builtin function name but found '7'\n"
          "t.rules:5:9: cannot open included file 'no-such-file.rules': no such file\n");
    CHECK(spec.rules.size() == 1);  // rule c
}
