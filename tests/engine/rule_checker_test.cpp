// tests/engine/rule_checker_test.cpp: check_program() against a brute-force oracle on seeded random
// programs (a predicate is inconsistent iff two of its uses differ in arity; the number of errors is
// the number of uses that disagree with the first one, plus one per repeated rule name), and the
// bundled programs pass.
#include "engine/rule_checker.hpp"
#include "engine/rule_spec_reader.hpp"
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

TEST_CASE("engine/rule_checker: the worked example of docs/RULES.md reads, checks and compiles") {
    const char* text = "fact (contact a b (0 +))\nfact (motion a (0 -))\nfact (motion a (+ 0))\n"
                       "rule contact-blocks-motion\n"
                       "  when (contact ?a ?b ?normal) (motion ?a ?d) (open-half-plane ?d (neg ?normal))\n"
                       "  then false\n";
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text(text, "example.rules", spec, d);
    CHECK(check_program(spec, d));
    CHECK(!d.has_errors());
    REQUIRE(spec.rules.size() == 1);
    CHECK(spec.rules[0].conditions.size() == 3);
    CHECK(spec.rules[0].conditions[2].kind == ConditionSpec::Kind::test);
}
