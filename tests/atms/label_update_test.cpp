// tests/atms/label_update_test.cpp
// The four label properties (de Kleer 1986: sound, consistent, minimal, complete) checked against
// a brute-force oracle on 3,500 seeded random Horn theories: 1,000 checked after every single step
// (a new assumption, premise or node, a justification, a nogood), 2,500 when complete. Each label
// must equal the oracle's minimal consistent deriving environments. weave() also by hand.
#include "atms/label_update.hpp"

#include "random_theory.hpp"
#include <doctest/doctest.h>
#include <algorithm>

using namespace qm::atms;
using namespace qm::atms::test;

namespace {
// Equality of each label with the oracle's minimal consistent deriving environments is soundness,
// consistency, minimality and completeness at once; holds_in, is_consistent and the minimal nogoods
// are checked on every environment over the tracked assumptions.
void check_against_oracle(RandomTheory& t) {
    const Oracle oracle(t);
    const std::vector<NodeId>* groups[] = {&t.assumptions, &t.premises, &t.derived};
    std::vector<EnvId> every_env;
    for (std::uint32_t m = 0; m < (1U << oracle.n); ++m) every_env.push_back(t.env_of_mask(m));
    for (const auto* group : groups) {
        for (NodeId n : *group) {
            const auto& label = t.atms.label(n);
            REQUIRE(std::is_sorted(label.begin(), label.end()));
            REQUIRE(t.masks_of(label) == oracle.label(n));
            for (std::uint32_t m = 0; m < every_env.size(); ++m)
                REQUIRE(t.atms.holds_in(n, every_env[m]) == (!oracle.inconsistent[m] && oracle.derived(m, n)));
        }
    }
    CHECK(t.atms.label(t.atms.contradiction()).empty());
    REQUIRE(t.masks_of(t.atms.minimal_nogoods()) == oracle.nogoods());
    for (std::uint32_t m = 0; m < every_env.size(); ++m)
        REQUIRE(t.atms.is_consistent(every_env[m]) == !oracle.inconsistent[m]);
}

struct Tally {
    std::size_t theories = 0, checks = 0;
};
}  // namespace

TEST_CASE("atms/label_update: labels equal the brute-force oracle after every step") {
    // Nodes (assumptions, premises, derived nodes) and clauses (justifications, justifications of
    // assumptions, nogoods) arrive in random order; half the theories spread their assumption ids
    // over several words.
    Tally tally;
    for (std::uint32_t seed = 1; seed <= 1000; ++seed) {
        CAPTURE(seed);
        TheoryShape shape;
        shape.assumptions = 4 + static_cast<int>(seed % 4);
        shape.derived = 8 + static_cast<int>(seed % 9);
        shape.clauses = 20 + static_cast<int>(seed % 16);
        shape.interleave = seed % 3 != 0;
        shape.max_padding = seed % 2 == 0 ? 0 : 90;
        RandomTheory t(seed, shape);
        check_against_oracle(t);
        while (t.add_next()) {
            check_against_oracle(t);
            ++tally.checks;
        }
        ++tally.theories;
    }
    MESSAGE("theories: " << tally.theories << ", oracle checks after single steps: " << tally.checks);
}

TEST_CASE("atms/label_update: labels equal the brute-force oracle on thousands of complete theories") {
    Tally tally;
    for (std::uint32_t seed = 1000; seed < 3500; ++seed) {
        CAPTURE(seed);
        TheoryShape shape;
        shape.assumptions = 5 + static_cast<int>(seed % 5);
        shape.derived = 10 + static_cast<int>(seed % 11);
        shape.clauses = 15 + static_cast<int>(seed % 30);
        shape.interleave = seed % 2 == 0;
        shape.max_padding = seed % 5 == 0 ? 150 : 0;
        RandomTheory t(seed, shape);
        while (t.add_next()) {
        }
        check_against_oracle(t);
        ++tally.theories;
    }
    MESSAGE("complete theories checked: " << tally.theories);
}

TEST_CASE("atms/label_update: weave forms minimal consistent unions") {
    NogoodDatabase nogoods;
    EnvironmentTable table;
    auto env = [&](std::initializer_list<std::uint32_t> ids) {
        std::vector<AssumptionId> as;
        for (auto i : ids) as.push_back(AssumptionId{i});
        return table.intern(Environment::of(as), nogoods);
    };
    const EnvId a = env({0}), b = env({1}), c = env({2}), ab = env({0, 1});
    nogoods.add(env({1, 2}), table[env({1, 2})]);
    table.mark_nogood(env({1, 2}));
    const Label l1{a, b};
    const Label l2{c, ab};
    const Label* labels[] = {&l1, &l2};
    // {} x {a,b} x {c,ab}: ac, ab, bc(nogood), ab -> minimal {ab, ac}.
    auto out = weave(table, nogoods, {table.intern(Environment{}, nogoods)}, labels);
    std::sort(out.begin(), out.end());
    std::vector<EnvId> expected{ab, env({0, 2})};
    std::sort(expected.begin(), expected.end());
    CHECK(out == expected);
    const Label empty;
    const Label* with_empty[] = {&l1, &empty};
    CHECK(weave(table, nogoods, {a}, with_empty).empty());
}
