// tests/atms/at_most_one_test.cpp: Atms::add_at_most_one, the native form of a choice set's
// exclusions, checked on seeded random Horn theories with constraints of 1 to 8 members
// (overlapping ones too) declared between the theory's steps (500 theories, 60 of them checked after
// every step; longer soaks: raise the seed range) against the brute-force oracle (random_theory.hpp)
// that treats an environment holding two members of a constraint as inconsistent: labels,
// consistency, minimal nogoods (also those within an environment), nogood explanations and
// interpretations, in order, with and without a base.
#include "atms/atms.hpp"

#include "random_theory.hpp"
#include <algorithm>
#include <bit>
#include <doctest/doctest.h>
#include <random>
#include <set>

using namespace qm::atms;
using namespace qm::atms::test;

namespace {
constexpr std::uint32_t constraint_informant = 100000;

// Random constraints over the tracked assumptions, drawn from their own generator.
struct Constraints {
    std::mt19937 rng;
    std::vector<std::uint32_t> masks;               // oracle bits of each constraint
    std::vector<std::vector<AssumptionId>> members;  // in declaration order
    std::vector<JustId> records;

    explicit Constraints(std::uint32_t seed) : rng(seed * 7919U + 1) {}
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

    // Maybe declares one constraint on t.
    void maybe_declare(RandomTheory& t, int percent) {
        if (t.assumptions.empty() || pick(1, 100) > percent) return;
        const int n = static_cast<int>(t.assumptions.size());
        const int k = pick(1, std::min(8, n));
        std::vector<int> order(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
        std::shuffle(order.begin(), order.end(), rng);
        std::vector<AssumptionId> set;
        std::uint32_t mask = 0;
        for (int i = 0; i < k; ++i) {
            const auto bit = static_cast<std::size_t>(order[static_cast<std::size_t>(i)]);
            set.push_back(t.tracked()[bit]);
            mask |= 1U << bit;
        }
        if (pick(0, 3) == 0) set.push_back(set.front());  // a repeated member collapses
        const InformantId why{constraint_informant + static_cast<std::uint32_t>(masks.size())};
        records.push_back(t.atms.add_at_most_one(why, set));
        masks.push_back(mask);
        members.push_back(set);
    }
};

// Every step of a nogood explanation is well founded from env's assumptions; a pair step names
// two members of one constraint, both in env, with that constraint's informant.
void check_nogood_explanation(RandomTheory& t, const Constraints& c, EnvId env) {
    const Explanation x = t.atms.explain_nogood(env);
    REQUIRE(x.node == t.atms.contradiction());
    std::set<NodeId> known;
    for (NodeId p : x.premises) known.insert(p);
    for (AssumptionId a : x.assumptions) {
        REQUIRE(t.atms.env(env).contains(a));
        known.insert(t.atms.node_of(a));
    }
    for (JustId j : x.steps) {
        const Justification& just = t.atms.justification(j);
        for (NodeId a : just.antecedents) REQUIRE(known.count(a) == 1);
        REQUIRE((just.kind == Justification::Kind::at_most_one) == (just.informant.value >= constraint_informant));
        if (just.informant.value >= constraint_informant) {
            const auto& set = c.members[just.informant.value - constraint_informant];
            REQUIRE(just.antecedents.size() == 2);
            for (NodeId a : just.antecedents) {
                REQUIRE(std::find(set.begin(), set.end(), *t.atms.assumption_of(a)) != set.end());
                REQUIRE(t.atms.env(env).contains(*t.atms.assumption_of(a)));
            }
        }
        known.insert(just.consequent);
    }
    REQUIRE(known.count(t.atms.contradiction()) == 1);
}

// Interpretations of random disjoint choice sets over the tracked assumptions, on a random base,
// against every product filtered by the oracle (exactly one per set, counting the base).
void check_interpretations(RandomTheory& t, const Oracle& oracle, std::mt19937& rng) {
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    std::vector<int> order(static_cast<std::size_t>(oracle.n));
    for (int i = 0; i < oracle.n; ++i) order[static_cast<std::size_t>(i)] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::vector<AssumptionId>> sets;
    std::vector<std::vector<std::uint32_t>> bits;
    for (std::size_t i = 0; i < order.size();) {
        const auto k = static_cast<std::size_t>(pick(1, 3));
        sets.emplace_back();
        bits.emplace_back();
        for (std::size_t j = i; j < std::min(order.size(), i + k); ++j) {
            sets.back().push_back(t.tracked()[static_cast<std::size_t>(order[j])]);
            bits.back().push_back(1U << order[j]);
        }
        i += k;
        if (pick(0, 2) == 0) break;  // not every assumption in a set
    }
    const std::uint32_t base = static_cast<std::uint32_t>(pick(0, (1 << oracle.n) - 1)) & static_cast<std::uint32_t>(pick(0, (1 << oracle.n) - 1));
    std::vector<std::uint32_t> expected;
    // Products in lexicographic order of the choices, first set slowest.
    auto product = [&](auto&& self, std::size_t d, std::uint32_t acc) -> void {
        if (d == bits.size()) {
            bool one_each = true;
            for (const auto& set : bits) {
                std::uint32_t mask = 0;
                for (std::uint32_t b : set) mask |= b;
                one_each = one_each && std::popcount(acc & mask) == 1;
            }
            if (one_each && !oracle.inconsistent[acc] && std::find(expected.begin(), expected.end(), acc) == expected.end())
                expected.push_back(acc);
            return;
        }
        for (std::uint32_t b : bits[d]) self(self, d + 1, acc | b);
    };
    product(product, 0, base);
    const EnvId base_env = t.env_of_mask(base);
    std::vector<std::uint32_t> got;
    for (EnvId e : t.atms.interpretations(sets, base_env)) got.push_back(t.mask_of(t.atms.env(e)));
    REQUIRE(got == expected);
}

void check_constraints_against_oracle(RandomTheory& t, const Constraints& c, std::mt19937& rng) {
    const Oracle oracle(t, c.masks);
    std::vector<EnvId> every_env;
    for (std::uint32_t m = 0; m < (1U << oracle.n); ++m) every_env.push_back(t.env_of_mask(m));
    const std::vector<NodeId>* groups[] = {&t.assumptions, &t.premises, &t.derived};
    for (const auto* group : groups)
        for (NodeId n : *group) REQUIRE(t.masks_of(t.atms.label(n)) == oracle.label(n));
    for (std::uint32_t m = 0; m < every_env.size(); ++m) REQUIRE(t.atms.is_consistent(every_env[m]) == !oracle.inconsistent[m]);
    const std::vector<std::uint32_t> nogoods = oracle.nogoods();
    REQUIRE(t.masks_of(t.atms.minimal_nogoods()) == nogoods);
    // The parts: stated ones and each constraint's pairs make up the whole.
    std::vector<EnvId> parts = t.atms.stated_nogoods();
    for (JustId r : c.records)
        for (EnvId e : t.atms.at_most_one_nogoods(r)) parts.push_back(e);
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    REQUIRE(t.masks_of(parts) == nogoods);
    for (std::uint32_t m = 0; m < every_env.size(); m += 7) {
        std::vector<std::uint32_t> inside;
        for (std::uint32_t g : nogoods)
            if ((g & m) == g) inside.push_back(g);
        REQUIRE(t.masks_of(t.atms.minimal_nogoods_within(t.atms.env(every_env[m]))) == inside);
    }
    for (EnvId ng : t.atms.minimal_nogoods()) check_nogood_explanation(t, c, ng);
    for (std::uint32_t m = 0; m < every_env.size(); m += 11)
        if (oracle.inconsistent[m]) check_nogood_explanation(t, c, every_env[m]);
    check_interpretations(t, oracle, rng);
}

TheoryShape shape_of(std::uint32_t seed) {
    TheoryShape shape;
    shape.assumptions = 4 + static_cast<int>(seed % 5);
    shape.derived = 8 + static_cast<int>(seed % 9);
    shape.clauses = 15 + static_cast<int>(seed % 20);
    shape.interleave = seed % 3 != 0;
    shape.max_padding = seed % 4 == 1 ? 90 : 0;
    shape.justify_assumptions = true;
    return shape;
}
}  // namespace

TEST_CASE("atms/at_most_one: labels, nogoods, explanations and interpretations equal the brute-force oracle") {
    std::size_t theories = 0, constraints = 0;
    for (std::uint32_t seed = 1; seed <= 500; ++seed) {
        CAPTURE(seed);
        RandomTheory t(seed, shape_of(seed));
        Constraints c(seed);
        std::mt19937 rng(seed);
        const bool every_step = seed <= 60;
        do {
            c.maybe_declare(t, 12);
            if (every_step) check_constraints_against_oracle(t, c, rng);
        } while (t.add_next());
        c.maybe_declare(t, 50);
        check_constraints_against_oracle(t, c, rng);
        ++theories;
        constraints += c.masks.size();
    }
    MESSAGE("theories: " << theories << ", constraints: " << constraints);
}

TEST_CASE("atms/at_most_one: a large constraint is one record, and its pairs are still nogoods") {
    Atms atms;
    std::vector<AssumptionId> members;
    std::vector<NodeId> nodes;
    for (int i = 0; i < 5000; ++i) {
        nodes.push_back(atms.add_assumption(DatumId{static_cast<std::uint32_t>(i)}));
        members.push_back(*atms.assumption_of(nodes.back()));
    }
    // A node derived from two members loses its label when the constraint arrives.
    const NodeId both = atms.add_node(DatumId{9});
    atms.justify(InformantId{1}, {nodes[10], nodes[4000]}, both);
    REQUIRE(atms.is_in(both));
    const std::size_t justs = atms.justification_count();
    const JustId record = atms.add_at_most_one(InformantId{2}, members);
    CHECK(atms.justification_count() == justs + 1);
    CHECK(atms.justification(record).kind == Justification::Kind::at_most_one);
    CHECK(atms.justification(record).antecedents.size() == 5000);
    CHECK(atms.justifications(atms.contradiction()).empty());
    CHECK_FALSE(atms.is_in(both));
    CHECK(atms.stated_nogoods().empty());
    CHECK_FALSE(atms.is_consistent(atms.environment({members[3], members[4999]})));
    CHECK(atms.is_consistent(atms.environment({members[3]})));
    const auto within = atms.minimal_nogoods_within(Environment::of(std::vector{members[1], members[2], members[3]}));
    CHECK(within.size() == 3);
    const Explanation x = atms.explain_nogood(atms.environment({members[7], members[4321]}));
    REQUIRE(x.steps.size() == 1);
    CHECK(atms.justification(x.steps[0]).informant == InformantId{2});
    CHECK(atms.justification(x.steps[0]).antecedents == std::vector<NodeId>{nodes[7], nodes[4321]});
    // The interpretations of the members as one choice set: every member alone.
    const std::vector<std::vector<AssumptionId>> sets{members};
    CHECK(atms.for_each_interpretation(sets, atms.empty_environment(), [](const Environment&) { return true; }) == 5000);
    CHECK(atms.interpretations(sets, atms.environment({members[12]})).size() == 1);
}

TEST_CASE("atms/at_most_one: a member that is nogood on its own takes its pairs out of the minimal nogoods") {
    Atms atms;
    std::vector<AssumptionId> members;
    std::vector<NodeId> nodes;
    for (int i = 0; i < 6; ++i) {
        nodes.push_back(atms.add_assumption(DatumId{static_cast<std::uint32_t>(i)}));
        members.push_back(*atms.assumption_of(nodes.back()));
    }
    const JustId record = atms.add_at_most_one(InformantId{2}, members);
    CHECK(atms.at_most_one_nogoods(record).size() == 15);
    atms.add_nogood(InformantId{3}, {nodes[0]});
    CHECK(atms.at_most_one_nogoods(record).size() == 10);
    CHECK(atms.minimal_nogoods().size() == 11);
    CHECK(atms.stated_nogoods().size() == 1);
    // A stated nogood holding two members is retired by a constraint declared after it.
    const NodeId x = atms.add_assumption(DatumId{7});
    atms.add_nogood(InformantId{4}, {nodes[1], x});
    CHECK(atms.stated_nogoods().size() == 2);
    const NodeId y = atms.add_assumption(DatumId{8});
    atms.add_at_most_one(InformantId{5}, std::vector{*atms.assumption_of(x), *atms.assumption_of(y), members[1]});
    CHECK(atms.stated_nogoods().size() == 1);
}

TEST_CASE("atms/at_most_one: fewer than two members constrain nothing; Pre is checked") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const AssumptionId aa = *atms.assumption_of(a);
    const JustId r = atms.add_at_most_one(InformantId{0}, std::vector{aa, aa});
    CHECK(atms.at_most_one_nogoods(r).empty());
    CHECK(atms.minimal_nogoods().empty());
    CHECK(atms.is_consistent(atms.environment({aa})));
    CHECK_THROWS(atms.add_at_most_one(InformantId{0}, std::vector{AssumptionId{7}}));
    const JustId horn = atms.justify(InformantId{1}, {a}, atms.add_node(DatumId{1}));
    CHECK_THROWS(atms.at_most_one_nogoods(horn));
}
