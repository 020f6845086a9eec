// tests/engine/quantifier_test.cpp: `[for all ...]` and `[exists ...]` conditions and `[for all ...]`
// consequents, end to end from rule text: which firings happen, with exactly which antecedents,
// including when the facts a `for all` needs arrive late (the rule must wake).
#include "engine/run_report.hpp"
#include "run_rule_text.hpp"
#include <doctest/doctest.h>
#include <memory>

using namespace qm::engine;

namespace {
std::unique_ptr<Engine> run_quantified(const std::string& text) { return test::run_rule_text(text, "q.rules"); }

std::vector<EnvText> label_of(Engine& e, const std::string& fact) {
    for (const auto& f : make_report(e).facts)
        if (f.fact == fact) return f.label;
    return {{"<absent>"}};
}
}  // namespace

TEST_CASE("engine/matcher: a `for all` condition needs every element's fact, each an antecedent") {
    // (covered ?x) needs (mark ?x k) for every k in 1..3 with k != 2; (mark a 2) is irrelevant.
    // The marks of b arrive through a rule chain, after the covering rule was first matched.
    auto r = run_quantified("assume (mark a 1)\nassume (mark a 3)\nfact (thing a)\nfact (thing b)\nfact (seed b)\n"
                 "assume (mark c 1)\nfact (thing c)\n"
                 "rule covered when (thing ?x) [for all ?k in (range 1 3) where (!= ?k 2): (mark ?x ?k)]\n"
                 "  then (covered ?x)\n"
                 "rule late-1 when (seed ?x) then (mark ?x 1)\n"
                 "rule late-3 when (mark ?x 1) (seed ?x) then (mark ?x 3)\n");
    Engine& e = *r;
    CHECK(label_of(e, "(covered a)") == std::vector<EnvText>{{"(mark a 1)", "(mark a 3)"}});
    CHECK(label_of(e, "(covered b)") == std::vector<EnvText>{{}});
    CHECK(label_of(e, "(covered c)") == std::vector<EnvText>{{"<absent>"}});
}

TEST_CASE("engine/matcher: `exists` fires once per witness, with the witness's facts as antecedents") {
    auto r = run_quantified("assume (edge a b)\nassume (edge a c)\nfact (node a)\nfact (red c)\nfact (red b)\n"
                 "rule has-red-neighbour when (node ?x) [exists ?y in {b c d} where (!= ?y d): (edge ?x ?y) and (red ?y)]\n"
                 "  then (touches-red ?x ?y)\n");
    Engine& e = *r;
    CHECK(label_of(e, "(touches-red a b)") == std::vector<EnvText>{{"(edge a b)"}});
    CHECK(label_of(e, "(touches-red a c)") == std::vector<EnvText>{{"(edge a c)"}});
    CHECK(e.rule_firings() == 2);
}

TEST_CASE("engine/engine: a `for all` consequent asserts one fact per element passing its test") {
    auto r = run_quantified("assume (size 4)\n"
                 "rule pick-two when (size ?n) then [for all ?k in (range 1 ?n) where (= (abs (- ?k 2)) 0): (chosen ?k)]\n"
                 "  (done ?n)\n");
    Engine& e = *r;
    CHECK(label_of(e, "(chosen 2)") == std::vector<EnvText>{{"(size 4)"}});
    CHECK(label_of(e, "(chosen 1)") == std::vector<EnvText>{{"<absent>"}});
    CHECK(label_of(e, "(done 4)") == std::vector<EnvText>{{"(size 4)"}});
}

TEST_CASE("engine/engine: `(= ?x TERM)` binds, and compares once bound") {
    auto r = run_quantified("fact (n 3)\nfact (n 4)\n"
                 "rule double when (n ?a) (= ?b (+ ?a ?a)) then (twice ?a ?b)\n"
                 "rule square-is-double when (n ?a) (= (* ?a ?a) (+ ?a ?a)) then (fixed ?a)\n");
    Engine& e = *r;
    CHECK(label_of(e, "(twice 3 6)") == std::vector<EnvText>{{}});
    CHECK(label_of(e, "(twice 4 8)") == std::vector<EnvText>{{}});
    CHECK(label_of(e, "(fixed 3)") == std::vector<EnvText>{{"<absent>"}});
}
