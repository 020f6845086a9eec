// tests/atms/label_update_test.cpp
// The four label properties (de Kleer 1986: sound, consistent, minimal, complete) checked against
// a brute-force oracle on seeded random Horn theories, justifications added incrementally in
// random order: the label must equal the oracle's minimal consistent deriving environments.
#include "atms/label_update.hpp"

#include "random_theory.hpp"
#include <doctest/doctest.h>
#include <algorithm>

using namespace qm::atms;
using namespace qm::atms::test;

namespace {
void check_against_oracle(RandomTheory& t) {
    const Oracle oracle(t);
    const std::vector<NodeId>* groups[] = {&t.assumptions, &t.premises, &t.derived};
    for (const auto* group : groups) {
        for (NodeId n : *group) {
            // Equality with the oracle's minimal consistent deriving envs is soundness, consistency,
            // minimality and completeness at once.
            REQUIRE(masks_of(t.atms, t.atms.label(n)) == oracle.label(n));
        }
    }
    CHECK(t.atms.label(t.atms.contradiction()).empty());
    REQUIRE(masks_of(t.atms, t.atms.minimal_nogoods()) == oracle.nogoods());
    std::vector<bool> consistent;
    for (std::uint32_t m = 0; m < (1U << oracle.n); ++m) consistent.push_back(t.atms.is_consistent(env_of_mask(t.atms, m)));
    std::vector<bool> expected(oracle.inconsistent.size());
    std::transform(oracle.inconsistent.begin(), oracle.inconsistent.end(), expected.begin(), [](bool b) { return !b; });
    REQUIRE(consistent == expected);
}
}  // namespace

TEST_CASE("atms/label_update: labels equal the brute-force oracle after every addition") {
    for (std::uint32_t seed = 1; seed <= 120; ++seed) {
        CAPTURE(seed);
        RandomTheory t(seed, 5 + static_cast<int>(seed % 3), 10 + static_cast<int>(seed % 11), 25);
        check_against_oracle(t);
        while (t.add_next()) check_against_oracle(t);
    }
}

TEST_CASE("atms/label_update: labels equal the brute-force oracle on thousands of theories") {
    for (std::uint32_t seed = 1000; seed < 2500; ++seed) {
        CAPTURE(seed);
        RandomTheory t(seed, 5 + static_cast<int>(seed % 4), 10 + static_cast<int>(seed % 11),
                       15 + static_cast<int>(seed % 25));
        while (t.add_next()) {
        }
        check_against_oracle(t);
    }
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
