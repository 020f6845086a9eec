// tests/atms/explanation_test.cpp: explanations are well founded (no cycles; leaves are premises or
// assumptions of the environment) and replaying their steps from the leaves derives the node; nogood
// explanations derive the contradiction from the nogood's assumptions. Checked on every label env of
// every node of seeded random theories.
#include "atms/explanation.hpp"

#include "random_theory.hpp"
#include <doctest/doctest.h>
#include <set>

using namespace qm::atms;
using namespace qm::atms::test;

namespace {
void check_explanation(const Atms& atms, const Explanation& ex, NodeId node, EnvId env) {
    REQUIRE(ex.node == node);
    std::set<NodeId> known;
    for (NodeId p : ex.premises) {
        REQUIRE(atms.is_premise(p));
        known.insert(p);
    }
    for (AssumptionId a : ex.assumptions) {
        REQUIRE(atms.env(env).contains(a));
        known.insert(atms.node_of(a));
    }
    const bool leaf = known.count(node) == 1;
    std::set<NodeId> concluded;
    for (JustId j : ex.steps) {
        const Justification& just = atms.justification(j);
        for (NodeId a : just.antecedents) REQUIRE(known.count(a) == 1);  // well founded: no cycles
        REQUIRE(concluded.insert(just.consequent).second);              // each node derived once
        known.insert(just.consequent);
    }
    REQUIRE(known.count(node) == 1);  // replaying the steps derives the node
    if (!leaf) {
        REQUIRE(!ex.steps.empty());
        CHECK(atms.justification(ex.steps.back()).consequent == node);
    } else {
        CHECK(ex.steps.empty());
    }
    // Only needed steps: each consequent is the node or an antecedent of a later step.
    for (std::size_t i = 0; i < ex.steps.size(); ++i) {
        const NodeId c = atms.justification(ex.steps[i]).consequent;
        bool used = c == node;
        for (std::size_t k = i + 1; k < ex.steps.size() && !used; ++k) {
            const auto& ants = atms.justification(ex.steps[k]).antecedents;
            used = std::find(ants.begin(), ants.end(), c) != ants.end();
        }
        CHECK(used);
    }
}
}  // namespace

TEST_CASE("atms/explanation: explanations of every label env are well founded and derive the node") {
    for (std::uint32_t seed = 1; seed <= 400; ++seed) {
        CAPTURE(seed);
        TheoryShape shape{6, 15, 30, seed % 2 == 0, seed % 4 == 1 ? 70 : 0};
        RandomTheory t(seed, shape);
        while (t.add_next()) {
        }
        for (std::uint32_t n = 0; n < t.atms.node_count(); ++n) {
            const NodeId node{n};
            for (EnvId e : t.atms.label(node)) check_explanation(t.atms, t.atms.explain(node, e), node, e);
        }
        for (EnvId g : t.atms.minimal_nogoods()) {
            const Explanation ex = t.atms.explain_nogood(g);
            check_explanation(t.atms, ex, t.atms.contradiction(), g);
        }
        // A superset of a nogood is explained too, from assumptions inside it.
        const EnvId all = t.env_of_mask((1U << 6) - 1);
        if (!t.atms.is_consistent(all))
            check_explanation(t.atms, t.atms.explain_nogood(all), t.atms.contradiction(), all);
    }
}

TEST_CASE("atms/explanation: derive_explanation on a hand-made chain") {
    // p (premise), a (assumption 0): j0: p,a -> x; j1: x -> y; j2: q -> y (q underivable).
    const std::vector<Justification> justs{
        {InformantId{0}, {NodeId{0}, NodeId{1}}, NodeId{2}},
        {InformantId{1}, {NodeId{2}}, NodeId{3}},
        {InformantId{2}, {NodeId{4}}, NodeId{3}},
    };
    const std::vector<NodeId> premises{NodeId{0}};
    const std::vector<std::pair<NodeId, AssumptionId>> assumptions{{NodeId{1}, AssumptionId{0}}};
    const auto ex = derive_explanation(justs, 5, DerivationBase{premises, assumptions}, NodeId{3});
    REQUIRE(ex.has_value());
    CHECK(ex->steps == std::vector<JustId>{JustId{0}, JustId{1}});
    CHECK(ex->premises == premises);
    CHECK(ex->assumptions == std::vector<AssumptionId>{AssumptionId{0}});
    CHECK_FALSE(derive_explanation(justs, 5, DerivationBase{premises, {}}, NodeId{3}).has_value());
    CHECK_THROWS_AS((void)derive_explanation(justs, 5, DerivationBase{premises, {}}, NodeId{5}), qm::InternalError);
}

TEST_CASE("atms/explanation: explaining what does not hold is a clear error") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId b = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    atms.justify(InformantId{0}, {a}, x);
    const EnvId eb = atms.environment({*atms.assumption_of(b)});
    CHECK_THROWS_AS((void)atms.explain(x, eb), qm::InternalError);
    CHECK_THROWS_AS((void)atms.explain_nogood(eb), qm::InternalError);
    atms.add_nogood(InformantId{1}, {a, b});
    const EnvId ab = atms.environment({*atms.assumption_of(a), *atms.assumption_of(b)});
    // x is derivable in {a,b} but {a,b} is inconsistent, so x does not hold there.
    CHECK_THROWS_AS((void)atms.explain(x, ab), qm::InternalError);
    const Explanation why = atms.explain_nogood(ab);
    CHECK(why.steps.size() == 1);
    CHECK(atms.justification(why.steps[0]).informant == InformantId{1});
}
