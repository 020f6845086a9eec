// tests/engine/rule_checker_test.cpp: check_program() against a brute-force oracle on seeded random
// programs (a predicate is inconsistent iff two of its uses differ in arity; the number of errors is
// the number of uses that disagree with the first one, plus one per repeated rule name), and the
// bundled programs pass; builtin test names are not predicates; the examples of docs/RULES.md compile.
#include "engine/rule_checker.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include "../support/golden.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <map>
#include <random>

using namespace qm::engine;

TEST_CASE("engine/rule_checker: error count matches a brute-force count on random programs") {
    std::mt19937 rng(4242);
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    for (int round = 0; round < 300; ++round) {
        ProgramSpec spec;
        std::vector<const AtomSpec*> uses;  // in the checker's visiting order
        auto atom = [&] {
            AtomSpec a;
            a.predicate = "p" + std::to_string(pick(3));
            a.args.resize(static_cast<std::size_t>(pick(3)));
            return a;
        };
        for (int i = 0, n = pick(3); i < n; ++i) spec.facts.push_back(atom());
        for (int i = 0, n = pick(4); i < n; ++i) {
            RuleSpec r;
            r.name = "r" + std::to_string(pick(3));
            ConditionSpec c;
            c.kind = pick(2) ? ConditionSpec::Kind::negation : ConditionSpec::Kind::exists;
            if (c.kind == ConditionSpec::Kind::negation)
                c.atom = atom();
            else
                c.atoms = {atom(), atom()};
            r.conditions.push_back(c);
            ConsequentSpec k;
            k.atom = atom();
            r.consequents.push_back(k);
            r.consequents.push_back(ConsequentSpec{ConsequentSpec::Kind::falsity, {}, {}, {}, {}, {}});
            spec.rules.push_back(std::move(r));
        }
        // Brute force: compare every use with the first use of its predicate; count repeated names.
        std::size_t expected = 0;
        std::vector<const AtomSpec*> all;
        for (const auto& f : spec.facts) all.push_back(&f);
        std::map<std::string, int> names;
        for (const auto& r : spec.rules) {
            expected += names[r.name]++ > 0;
            for (const auto& c : r.conditions) {
                if (c.kind == ConditionSpec::Kind::negation) all.push_back(&c.atom);
                for (const auto& a : c.atoms) all.push_back(&a);
            }
            all.push_back(&r.consequents.front().atom);
        }
        for (std::size_t i = 0; i < all.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (all[j]->predicate == all[i]->predicate) {
                    expected += all[j]->args.size() != all[i]->args.size();
                    break;
                }
        qm::Diagnostics d;
        bool ok = check_program(spec, d);
        CHECK(ok == (expected == 0));
        CHECK(d.size() == expected);
    }
}

TEST_CASE("engine/rule_checker: the bundled programs pass; messages name the first use") {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(QM_SOURCE_DIR) + "/scenarios/rules")) {
        CAPTURE(entry.path().string());
        qm::Diagnostics d;
        ProgramSpec spec;
        read_rule_file(entry.path().string(), spec, d);
        CHECK(check_program(spec, d));
        CHECK(!d.has_errors());
    }
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text("fact (p a)\nrule r\n  when (p ?x ?y)\n  then (q ?x)\n", "t.rules", spec, d);
    REQUIRE(!d.has_errors());
    CHECK(!check_program(spec, d));
    REQUIRE(d.size() == 1);
    CHECK(d.items()[0].where.line == 3);
    CHECK(d.items()[0].message == "predicate 'p' is used here with 2 argument(s) but with 1 at t.rules:1:6");
}

TEST_CASE("engine/rule_checker: every ```rules example of docs/RULES.md reads, checks and compiles") {
    const std::string text = qm::test::slurp(std::string(QM_SOURCE_DIR) + "/docs/RULES.md");
    std::size_t examples = 0;
    for (std::size_t at = text.find("```rules\n"); at != std::string::npos; at = text.find("```rules\n", at + 1)) {
        const std::size_t begin = at + 9, end = text.find("```", begin);
        REQUIRE(end != std::string::npos);
        const std::string example = text.substr(begin, end - begin);
        CAPTURE(example);
        qm::Diagnostics d;
        ProgramSpec spec;
        read_rule_text(example, "example.rules", spec, d);
        CHECK(check_program(spec, d));
        CHECK(compile_program(spec, d).has_value());
        CHECK(!d.has_errors());
        CHECK(!spec.rules.empty());
        ++examples;
    }
    CHECK(examples >= 2);
}

TEST_CASE("engine/rule_checker: a builtin test's name is not a predicate, in every atom position") {
    // Each line puts a test name in one atom position; function names (neg, +) are fine as predicates.
    const char* text = "fact (< 1 2)\nassume (zero? (0))\nfact (neg a)\nfact (+ 1)\n"
                       "rule r1 when (p ?x) not (= ?x 1) then (q ?x)\n"
                       "rule r2 when (p ?x) [exists ?y in {1}: (> ?y ?x)] then (q ?x)\n"
                       "rule r3 when (p ?x) [sum ?v over (!= ?x ?v) with + start 0 as ?t] then (q ?t)\n"
                       "rule r4 when (p ?x) then (half-plane ?x ?x)\n"
                       "rule r5 when (p ?x) then [for all ?y in {1}: (<= ?y ?x)]\n";
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text(text, "t.rules", spec, d);
    REQUIRE(!d.has_errors());
    CHECK(!check_program(spec, d));
    std::vector<std::uint32_t> lines;
    for (const auto& x : d.items()) {
        CHECK(x.message.find("is a builtin test, not a predicate") != std::string::npos);
        lines.push_back(x.where.line);
    }
    CHECK(lines == std::vector<std::uint32_t>{1, 2, 5, 6, 7, 8, 9});
}
