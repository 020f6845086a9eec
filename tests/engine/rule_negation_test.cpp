// tests/engine/rule_negation_test.cpp: stratified negation and aggregates written in the rule
// language, as docs/RULES.md "## Semantics" defines them, in both the accepted and the rejected
// cases:
//   - seeded random programs with `not` over predicates chosen freely: the compiler accepts exactly
//     the stratifiable ones (an independent check: no cycle of the predicate graph goes through a
//     negative edge), names the cycle of the others, and for the accepted ones the engine derives
//     exactly the facts of a brute-force evaluation SCC by SCC in dependency order;
//   - generic mode: `not` and aggregates over premises or absent facts are decided; over a fact whose
//     label depends on assumptions they are rejected with a located diagnostic and nothing is
//     derived from that binding; a fact whose label is empty counts as absent.
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include "engine/run_report.hpp"
#include "run_rule_text.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <memory>
#include <random>
#include <set>
#include <sstream>

using namespace qm::engine;

namespace {

constexpr int predicates = 5;                       // q0..q4, unary
const char* const constants[] = {"a", "b", "c"};

struct Literal {
    int predicate;
    bool negative;
    int variable;  // 0: ?x, 1: ?y, 2: ?z (only ever in a `not`, where it is local)
};
struct Rule {
    int head;
    int head_variable;
    std::vector<Literal> body;
};

std::string negation_text(const std::vector<std::pair<int, int>>& facts, const std::vector<Rule>& rules) {
    const char* vars[] = {"?x", "?y", "?z"};
    std::ostringstream out;
    for (auto [p, c] : facts) out << "fact (q" << p << " " << constants[c] << ")\n";
    for (std::size_t i = 0; i < rules.size(); ++i) {
        out << "rule r" << i << "\n  when";
        for (const Literal& l : rules[i].body) out << (l.negative ? " not" : "") << " (q" << l.predicate << " " << vars[l.variable] << ")";
        out << "\n  then (q" << rules[i].head << " " << vars[rules[i].head_variable] << ")\n";
    }
    return out.str();
}

// Independent check: reach[a][b] iff b depends on a through rules (edges body -> head).
bool stratifiable(const std::vector<Rule>& rules) {
    bool reach[predicates][predicates] = {};
    for (const Rule& r : rules)
        for (const Literal& l : r.body) reach[l.predicate][r.head] = true;
    for (int k = 0; k < predicates; ++k)
        for (int i = 0; i < predicates; ++i)
            for (int j = 0; j < predicates; ++j) reach[i][j] = reach[i][j] || (reach[i][k] && reach[k][j]);
    for (const Rule& r : rules)
        for (const Literal& l : r.body)
            if (l.negative && (l.predicate == r.head || reach[r.head][l.predicate])) return false;
    return true;
}

// Brute force: evaluate the predicates' strongly connected components in dependency order, each to a
// fixpoint over every binding of ?x and ?y. Pre: stratifiable(rules).
std::set<std::pair<int, int>> evaluate(const std::vector<std::pair<int, int>>& facts, const std::vector<Rule>& rules) {
    bool reach[predicates][predicates] = {};
    for (int i = 0; i < predicates; ++i) reach[i][i] = true;
    for (const Rule& r : rules)
        for (const Literal& l : r.body) reach[l.predicate][r.head] = true;
    for (int k = 0; k < predicates; ++k)
        for (int i = 0; i < predicates; ++i)
            for (int j = 0; j < predicates; ++j) reach[i][j] = reach[i][j] || (reach[i][k] && reach[k][j]);
    std::set<std::pair<int, int>> holds(facts.begin(), facts.end());
    std::vector<bool> done(predicates, false);
    while (std::find(done.begin(), done.end(), false) != done.end()) {
        // The next component: a predicate all of whose other ancestors are done, with its SCC.
        int p = -1;
        for (int i = 0; i < predicates && p < 0; ++i) {
            if (done[static_cast<std::size_t>(i)]) continue;
            bool ready = true;
            for (int j = 0; j < predicates; ++j)
                if (!done[static_cast<std::size_t>(j)] && reach[j][i] && !reach[i][j]) ready = false;
            if (ready) p = i;
        }
        REQUIRE(p >= 0);
        std::vector<int> scc;
        for (int j = 0; j < predicates; ++j)
            if (reach[p][j] && reach[j][p]) scc.push_back(j);
        for (bool changed = true; changed;) {
            changed = false;
            for (const Rule& r : rules) {
                if (std::find(scc.begin(), scc.end(), r.head) == scc.end()) continue;
                for (int x = 0; x < 3; ++x)
                    for (int y = 0; y < 3; ++y) {
                        const int value[] = {x, y};
                        bool ok = true;
                        for (const Literal& l : r.body) {
                            if (l.variable == 2) {  // local: no fact of the predicate at all
                                bool any = false;
                                for (int c = 0; c < 3; ++c) any = any || holds.count({l.predicate, c});
                                ok = ok && !any;
                            } else {
                                ok = ok && holds.count({l.predicate, value[l.variable]}) != (l.negative ? 1u : 0u);
                            }
                        }
                        if (ok && holds.insert({r.head, value[r.head_variable]}).second) changed = true;
                    }
            }
        }
        for (int j : scc) done[static_cast<std::size_t>(j)] = true;
    }
    return holds;
}

struct Loaded {
    std::optional<LoadedProgram> program;
    qm::Diagnostics diagnostics;
};

Loaded load_negation(const std::string& source) {
    Loaded l;
    ProgramSpec spec;
    read_rule_text(source, "n.rules", spec, l.diagnostics);
    REQUIRE(!l.diagnostics.has_errors());
    l.program = compile_program(spec, l.diagnostics);
    return l;
}

std::string fact_list(Engine& e) {
    std::string out;
    for (const auto& f : make_report(e).facts) {
        out += f.fact + " {";
        for (const auto& env : f.label) {
            out += "{";
            for (const auto& a : env) out += a + ";";
            out += "}";
        }
        out += "}\n";
    }
    return out;
}

}  // namespace

TEST_CASE("engine/rule_negation: random programs: stratifiable ones are accepted and evaluated as stratified") {
    std::mt19937 rng(1988);
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    int accepted = 0, rejected = 0;
    for (int round = 0; round < 400; ++round) {
        std::vector<std::pair<int, int>> facts;
        for (int i = 0, n = 1 + pick(5); i < n; ++i) facts.push_back({pick(predicates), pick(3)});
        std::vector<Rule> rules;
        for (int i = 0, n = 1 + pick(4); i < n; ++i) {
            Rule r{pick(predicates), pick(2), {}};
            r.body.push_back({pick(predicates), false, 0});
            r.body.push_back({pick(predicates), false, 1});
            for (int k = 0, m = pick(3); k < m; ++k) r.body.push_back({pick(predicates), true, pick(3)});
            rules.push_back(r);
        }
        const std::string source = negation_text(facts, rules);
        CAPTURE(source);
        Loaded l = load_negation(source);
        const bool expected = stratifiable(rules);
        CHECK(l.program.has_value() == expected);
        if (!expected) {
            ++rejected;
            REQUIRE(l.diagnostics.has_errors());
            CHECK(l.diagnostics.items().front().message.find("negation through recursion: 'q") != std::string::npos);
            CHECK(l.diagnostics.items().front().message.find("through the cycle q") != std::string::npos);
            continue;
        }
        if (!l.program) continue;
        ++accepted;
        Engine e(std::move(l.program->program), std::move(l.program->values));
        qm::Diagnostics d;
        e.run(d);
        REQUIRE(!d.has_errors());  // every negated fact is a premise or derived from premises only
        std::set<std::pair<int, int>> derived;
        for (int p = 0; p < predicates; ++p)
            for (int c = 0; c < 3; ++c) {
                const ValueId arg = e.values().symbol(constants[c]);
                auto f = e.find(e.values().symbol("q" + std::to_string(p)), std::span<const ValueId>(&arg, 1));
                if (f && e.atms().is_true(e.node(*f))) derived.insert({p, c});
            }
        CHECK(derived == evaluate(facts, rules));
    }
    CHECK(accepted > 100);
    CHECK(rejected > 50);
}

TEST_CASE("engine/rule_negation: generic `not` and aggregates are decided over premises and absent facts") {
    const auto e = test::run_rule_text("fact (bird tweety)\nfact (bird opus)\nfact (penguin opus)\nfact (weight tweety 3)\n"
                                       "fact (weight opus 30)\n"
                                       "rule flies\n  when (bird ?b) not (penguin ?b)\n  then (flies ?b)\n"
                                       "rule lonely\n  when (bird ?b) not (friend ?b ?other)\n  then (lonely ?b)\n"
                                       "rule total\n  when (bird tweety) [sum ?w over (weight ?b ?w) with + start 0 as ?t]\n"
                                       "  then (total ?t)\n",
                                       "n.rules");
    CHECK(fact_list(*e) == "(bird opus) {{}}\n(bird tweety) {{}}\n(flies tweety) {{}}\n(lonely opus) {{}}\n"
                          "(lonely tweety) {{}}\n(penguin opus) {{}}\n(total 33) {{}}\n"
                          "(weight opus 30) {{}}\n(weight tweety 3) {{}}\n");
}

TEST_CASE("engine/rule_negation: a fact that holds in no environment is absent for `not`") {
    // (penguin opus) is derived only from two assumptions that are nogood together: its label is empty.
    const auto e = test::run_rule_text("fact (bird opus)\nassume (cold opus)\nassume (warm opus)\n"
                                       "rule exclusive\n  when (cold ?b) (warm ?b)\n  then false\n"
                                       "rule penguin\n  when (cold ?b) (warm ?b)\n  then (penguin ?b)\n"
                                       "rule flies\n  when (bird ?b) not (penguin ?b)\n  then (flies ?b)\n",
                                       "n.rules");
    CHECK(fact_list(*e).find("(flies opus) {{}}\n") != std::string::npos);
    CHECK(fact_list(*e).find("(penguin opus) {}\n") != std::string::npos);
}

TEST_CASE("engine/rule_negation: `not` or an aggregate over an assumption-dependent fact is rejected, located") {
    const std::pair<const char*, const char*> cases[] = {
        {"not (penguin ?b)", "rule 'flies': cannot decide (penguin opus)"},
        {"[sum ?w over (ring ?b ?w) with + start 0 as ?t]", "rule 'flies': cannot decide (ring opus 2)"},
    };
    for (const auto& [condition, message] : cases) {
        CAPTURE(condition);
        const auto e = test::engine_for("fact (bird tweety)\nfact (bird opus)\nassume (penguin opus)\nassume (ring opus 2)\n"
                                        "rule flies\n  when (bird ?b) " + std::string(condition) + "\n  then (flies ?b)\n",
                                        "n.rules");
        qm::Diagnostics d;
        e->run(d);
        REQUIRE(d.has_errors());
        const auto& x = d.items().front();
        CHECK(x.where.file == "n.rules");
        CHECK(x.where.line == 6);
        CHECK(x.message.find(message) == 0);
        CHECK(fact_list(*e).find("(flies opus)") == std::string::npos);  // nothing unsound was derived
    }
}

TEST_CASE("engine/rule_negation: a rule negating its own conclusion is rejected with the cycle named") {
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text("fact (p a)\nrule r\n  when (p ?x) not (q ?x)\n  then (q ?x)\n", "n.rules", spec, d);
    CHECK(!compile_program(spec, d).has_value());
    REQUIRE(d.size() == 1);
    CHECK(d.items()[0].where.line == 3);
    CHECK(d.items()[0].where.column == 15);
    CHECK(d.items()[0].message ==
          "rule 'r': negation through recursion: 'q', used under `not` here, depends on this rule's own "
          "conclusion 'q' through the cycle q -> q (rule 'r', `not`)");
}
