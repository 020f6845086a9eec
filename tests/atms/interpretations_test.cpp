// tests/atms/interpretations_test.cpp: interpretation enumeration against brute-force products
// (N-queens, through the rule engine: tests/cli/run_command_test.cpp).
#include "atms/interpretations.hpp"

#include "atms/atms.hpp"
#include <algorithm>
#include <bit>
#include <doctest/doctest.h>
#include <random>

using namespace qm::atms;

namespace {
std::uint64_t mask_of(const Environment& e) {
    std::uint64_t m = 0;
    for (AssumptionId a : e.assumptions()) m |= std::uint64_t{1} << a.value;
    return m;
}

// All base + one-per-set products in lexicographic order, filtered by the nogood masks.
void brute_force(const std::vector<std::vector<AssumptionId>>& sets, std::size_t depth, std::uint64_t acc,
                 const std::vector<std::uint64_t>& nogoods, std::vector<std::uint64_t>& out) {
    if (depth == sets.size()) {
        // Exactly one member of every set, counting what the base holds.
        const bool one_each = std::all_of(sets.begin(), sets.end(), [&](const std::vector<AssumptionId>& set) {
            std::uint64_t mask = 0;
            for (AssumptionId a : set) mask |= std::uint64_t{1} << a.value;
            return std::popcount(acc & mask) == 1;
        });
        if (one_each && std::none_of(nogoods.begin(), nogoods.end(), [&](std::uint64_t n) { return (n & acc) == n; }) &&
            std::find(out.begin(), out.end(), acc) == out.end())
            out.push_back(acc);
        return;
    }
    for (AssumptionId a : sets[depth]) brute_force(sets, depth + 1, acc | (std::uint64_t{1} << a.value), nogoods, out);
}
}  // namespace

TEST_CASE("atms/interpretations: random choice sets and nogoods agree with brute force") {
    // Half the rounds spread the assumption ids over several words (unused assumptions between
    // them), and some nogoods are derived through a justification rather than stated directly.
    std::mt19937 rng(17);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    for (int round = 0; round < 1000; ++round) {
        CAPTURE(round);
        Atms atms;
        const int k = pick(4, 14);
        std::vector<NodeId> nodes;
        std::vector<AssumptionId> ids;  // ids[i] is the brute force's bit i
        for (int i = 0; i < k; ++i) {
            for (int pad = round % 2 == 0 ? 0 : pick(0, 60); pad > 0; --pad) atms.add_assumption(DatumId{1});
            nodes.push_back(atms.add_assumption(DatumId{0}));
            ids.push_back(*atms.assumption_of(nodes.back()));
        }
        auto bit_of = [&](AssumptionId a) {
            return std::uint64_t{1} << (std::find(ids.begin(), ids.end(), a) - ids.begin());
        };
        auto bits = [&](const Environment& e) {
            std::uint64_t m = 0;
            for (AssumptionId a : e.assumptions()) m |= bit_of(a);
            return m;
        };
        // Partition a random subset of the assumptions into choice sets (some possibly empty).
        std::vector<AssumptionId> order = ids;
        std::shuffle(order.begin(), order.end(), rng);
        std::vector<std::vector<AssumptionId>> sets(static_cast<std::size_t>(pick(0, 5)));
        for (AssumptionId a : order)
            if (!sets.empty() && pick(0, 5) > 0) sets[static_cast<std::size_t>(pick(0, static_cast<int>(sets.size()) - 1))].push_back(a);
        std::vector<std::uint64_t> nogood_masks;
        const int n_nogoods = pick(0, 8);
        for (int i = 0; i < n_nogoods; ++i) {
            std::vector<NodeId> ants;
            std::uint64_t m = 0;
            for (int j = pick(1, 3); j > 0; --j) {
                const int a = pick(0, k - 1);
                ants.push_back(nodes[static_cast<std::size_t>(a)]);
                m |= std::uint64_t{1} << a;
            }
            if (ants.size() >= 2 && pick(0, 1) == 0) {
                // x <- first antecedents; nogood(x, last): the same assumptions, through x.
                const NodeId x = atms.add_node(DatumId{2});
                atms.justify(InformantId{0}, std::span<const NodeId>(ants.data(), ants.size() - 1), x);
                atms.add_nogood(InformantId{0}, {x, ants.back()});
            } else {
                atms.add_nogood(InformantId{0}, ants);
            }
            nogood_masks.push_back(m);
        }
        // A random base of 0-2 assumptions.
        std::vector<AssumptionId> base_as;
        std::uint64_t base_mask = 0;
        for (int j = pick(0, 2); j > 0; --j) {
            const AssumptionId a = ids[static_cast<std::size_t>(pick(0, k - 1))];
            base_as.push_back(a);
            base_mask |= bit_of(a);
        }
        const EnvId base = atms.environment(base_as);
        std::vector<std::vector<AssumptionId>> bit_sets;  // the sets with ids replaced by bit indexes
        for (const auto& set : sets) {
            auto& b = bit_sets.emplace_back();
            for (AssumptionId a : set)
                b.push_back(AssumptionId{static_cast<std::uint32_t>(std::find(ids.begin(), ids.end(), a) - ids.begin())});
        }
        std::vector<std::uint64_t> expected;
        brute_force(bit_sets, 0, base_mask, nogood_masks, expected);
        std::vector<std::uint64_t> got;
        for (EnvId e : atms.interpretations(sets, base)) got.push_back(bits(atms.env(e)));
        REQUIRE(got == expected);
        // Without a base.
        expected.clear();
        brute_force(bit_sets, 0, 0, nogood_masks, expected);
        got.clear();
        for (EnvId e : atms.interpretations(sets)) got.push_back(bits(atms.env(e)));
        REQUIRE(got == expected);
        // Every interpretation is consistent and picks one assumption per set.
        for (EnvId e : atms.interpretations(sets)) {
            CHECK(atms.is_consistent(e));
            for (const auto& set : sets)
                CHECK(std::count_if(set.begin(), set.end(), [&](AssumptionId a) { return atms.env(e).contains(a); }) == 1);
        }
    }
}

TEST_CASE("atms/interpretations: the streaming form counts and stops early") {
    Atms atms;
    std::vector<std::vector<AssumptionId>> sets(3);
    for (auto& s : sets)
        for (int i = 0; i < 3; ++i) s.push_back(*atms.assumption_of(atms.add_assumption(DatumId{0})));
    std::size_t calls = 0;
    CHECK(atms.for_each_interpretation(sets, atms.empty_environment(), [&](const Environment&) {
        ++calls;
        return true;
    }) == 27);
    CHECK(calls == 27);
    calls = 0;
    CHECK(atms.for_each_interpretation(sets, atms.empty_environment(), [&](const Environment&) {
        return ++calls < 5;
    }) == 5);
    CHECK(calls == 5);
    // Streaming interns nothing.
    const std::size_t envs = atms.environment_count();
    (void)atms.for_each_interpretation(sets, atms.empty_environment(), [](const Environment&) { return true; });
    CHECK(atms.environment_count() == envs);
}

TEST_CASE("atms/interpretations: edge cases: no sets, an empty set, an inconsistent base") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId b = atms.add_assumption(DatumId{0});
    const AssumptionId aa = *atms.assumption_of(a), ab = *atms.assumption_of(b);
    CHECK(atms.interpretations({}) == std::vector<EnvId>{atms.empty_environment()});
    const std::vector<std::vector<AssumptionId>> with_empty{{aa}, {}};
    CHECK(atms.interpretations(with_empty).empty());
    atms.add_nogood(InformantId{0}, {a, b});
    const std::vector<std::vector<AssumptionId>> one{{aa}};
    CHECK(atms.interpretations(one, atms.environment({ab})).empty());
    CHECK(atms.interpretations({}, atms.environment({aa, ab})).empty());
}

TEST_CASE("atms/interpretations: precondition violations are InternalError") {
    Atms atms;
    const AssumptionId a = *atms.assumption_of(atms.add_assumption(DatumId{0}));
    const AssumptionId b = *atms.assumption_of(atms.add_assumption(DatumId{0}));
    const std::vector<std::vector<AssumptionId>> twice{{a, b}, {b}};
    CHECK_THROWS_AS((void)atms.interpretations(twice), qm::InternalError);
    const std::vector<std::vector<AssumptionId>> unknown{{a, AssumptionId{9}}};
    CHECK_THROWS_AS((void)atms.interpretations(unknown), qm::InternalError);
    const std::vector<std::vector<AssumptionId>> fine{{a}};
    CHECK_THROWS_AS((void)atms.interpretations(fine, EnvId{77}), qm::InternalError);
}

TEST_CASE("atms/interpretations: enumerate_interpretations works on a bare nogood database") {
    NogoodDatabase db;
    db.add(EnvId{0}, Environment::of(std::vector{AssumptionId{0}, AssumptionId{2}}));
    const std::vector<std::vector<AssumptionId>> sets{{AssumptionId{0}, AssumptionId{1}}, {AssumptionId{2}, AssumptionId{3}}};
    std::vector<std::uint64_t> seen;
    const std::size_t n = enumerate_interpretations(db, 4, sets, Environment{}, [&](const Environment& e) {
        seen.push_back(mask_of(e));
        return true;
    });
    CHECK(n == 3);
    CHECK(seen == std::vector<std::uint64_t>{0b1001, 0b0110, 0b1010});
}

TEST_CASE("atms/interpretations: a base that picks from a set keeps that pick, and two picks give none") {
    // Without the mutual-exclusion nogoods a rule engine would add, the search itself must keep
    // exactly one member per set: base {a} over {a, b} is {a} alone, never {a, b}.
    Atms atms;
    std::vector<AssumptionId> ids;
    for (std::uint32_t i = 0; i < 4; ++i) ids.push_back(*atms.assumption_of(atms.add_assumption(DatumId{i})));
    const std::vector<std::vector<AssumptionId>> sets{{ids[0], ids[1]}, {ids[2], ids[3]}};
    const auto with_a = atms.interpretations(sets, atms.environment({ids[0]}));
    REQUIRE(with_a.size() == 2);
    for (EnvId e : with_a) {
        CHECK(atms.env(e).contains(ids[0]));
        CHECK(!atms.env(e).contains(ids[1]));
    }
    CHECK(atms.interpretations(sets, atms.environment({ids[0], ids[1]})).empty());
    CHECK(atms.interpretations(sets, atms.environment({ids[0], ids[3]})).size() == 1);
}
