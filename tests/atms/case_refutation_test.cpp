// tests/atms/case_refutation_test.cpp: refute_by_cases against brute force on seeded random theories
// (choice sets, a start environment, random nogoods stated directly or through derived nodes): a
// proof exists exactly when no pick of one member per set is consistent with start; a proof's
// nogoods are among those given, its `involved` lies within start, and the proof's nogoods alone
// refute every pick over `involved` (so backjumping dropped only cases it did not need). Also:
// backjumping leaves out a set whose members play no part, the preferred assumption, the budget.
#include "atms/case_refutation.hpp"

#include "atms/atms.hpp"
#include <algorithm>
#include <cstdint>
#include <doctest/doctest.h>
#include <random>

using namespace qm::atms;

namespace {

struct Theory {
    Atms atms;
    std::vector<NodeId> nodes;                    // every assumption node; nodes[i] is bit i
    std::vector<AssumptionId> ids;                // ids[i] is bit i
    std::vector<std::vector<AssumptionId>> sets;  // the choice sets
    std::uint32_t start_mask = 0;
    std::vector<std::uint32_t> nogood_masks;      // as stated (maybe not minimal)

    [[nodiscard]] std::uint32_t mask_of(const Environment& e) const {
        std::uint32_t m = 0;
        for (AssumptionId a : e.assumptions())
            m |= 1U << (std::find(ids.begin(), ids.end(), a) - ids.begin());
        return m;
    }
    [[nodiscard]] Environment env_of(std::uint32_t m) const {
        std::vector<AssumptionId> as;
        for (std::size_t i = 0; i < ids.size(); ++i)
            if (m & (1U << i)) as.push_back(ids[i]);
        return Environment::of(as);
    }
    [[nodiscard]] std::uint32_t set_mask(std::size_t s) const { return mask_of(Environment::of(sets[s])); }
};

void random_theory(std::uint32_t seed, Theory& t) {
    std::mt19937 rng(seed);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const int n = pick(3, 12);
    for (int i = 0; i < n; ++i) {
        for (int pad = seed % 2 == 0 ? 0 : pick(0, 50); pad > 0; --pad) t.atms.add_assumption(DatumId{1});
        t.nodes.push_back(t.atms.add_assumption(DatumId{0}));
        t.ids.push_back(*t.atms.assumption_of(t.nodes.back()));
    }
    // Each assumption goes to start, to one of the sets, or nowhere.
    t.sets.resize(static_cast<std::size_t>(pick(0, 4)));
    for (int i = 0; i < n; ++i) {
        const int where = pick(0, 5);
        if (where == 0) t.start_mask |= 1U << i;
        else if (where > 1 && !t.sets.empty())
            t.sets[static_cast<std::size_t>(pick(0, static_cast<int>(t.sets.size()) - 1))].push_back(t.ids[static_cast<std::size_t>(i)]);
    }
    std::erase_if(t.sets, [](const auto& s) { return s.empty(); });
    for (int k = pick(0, 10); k > 0; --k) {
        std::vector<NodeId> ants;
        std::uint32_t m = 0;
        for (int j = pick(1, 3); j > 0; --j) {
            const int a = pick(0, n - 1);
            ants.push_back(t.nodes[static_cast<std::size_t>(a)]);
            m |= 1U << a;
        }
        if (ants.size() >= 2 && pick(0, 2) == 0) {  // through a derived node
            const NodeId x = t.atms.add_node(DatumId{2});
            t.atms.justify(InformantId{0}, std::span<const NodeId>(ants.data(), ants.size() - 1), x);
            t.atms.add_nogood(InformantId{0}, {x, ants.back()});
        } else {
            t.atms.add_nogood(InformantId{0}, ants);
        }
        t.nogood_masks.push_back(m);
    }
}

// Every pick of one member per set, as masks added to base; calls f(mask) for each.
template <class F>
void each_pick(const Theory& t, std::size_t depth, std::uint32_t acc, F&& f) {
    if (depth == t.sets.size()) {
        f(acc);
        return;
    }
    for (AssumptionId a : t.sets[depth])
        each_pick(t, depth + 1, acc | (1U << (std::find(t.ids.begin(), t.ids.end(), a) - t.ids.begin())), f);
}

bool hits(const std::vector<std::uint32_t>& nogoods, std::uint32_t m) {
    return std::any_of(nogoods.begin(), nogoods.end(), [&](std::uint32_t n) { return (n & m) == n; });
}

}  // namespace

TEST_CASE("atms/case_refutation: a proof exactly when no pick is consistent, and the proof suffices") {
    int refuted = 0, consistent = 0, left_out = 0;
    for (std::uint32_t seed = 0; seed < 1500; ++seed) {
        CAPTURE(seed);
        Theory t;
        random_theory(seed, t);
        // The caller's nogoods: the minimal ones within start and the sets' members.
        std::uint32_t scope_mask = t.start_mask;
        for (std::size_t s = 0; s < t.sets.size(); ++s) scope_mask |= t.set_mask(s);
        const Environment scope = t.env_of(scope_mask);
        std::vector<EnvId> given;
        for (EnvId ng : t.atms.minimal_nogoods())
            if (t.atms.env(ng).subset_of(scope)) given.push_back(ng);
        bool expected_refuted = true;
        each_pick(t, 0, t.start_mask, [&](std::uint32_t m) {
            if (!hits(t.nogood_masks, m)) expected_refuted = false;
        });
        RefutationOptions options;
        if (seed % 3 == 0 && !t.ids.empty()) options.prefer = t.ids[seed % t.ids.size()];
        const RefutationResult r = refute_by_cases(t.atms, t.sets, given, t.env_of(t.start_mask), options);
        REQUIRE_FALSE(r.gave_up);
        REQUIRE(r.proof.has_value() == expected_refuted);
        if (!r.proof) {
            ++consistent;
            continue;
        }
        ++refuted;
        REQUIRE_FALSE(r.proof->nogoods.empty());
        std::vector<std::uint32_t> proof_masks;
        for (EnvId ng : r.proof->nogoods) {
            CHECK(std::find(given.begin(), given.end(), ng) != given.end());
            proof_masks.push_back(t.mask_of(t.atms.env(ng)));
        }
        std::vector<EnvId> unique = r.proof->nogoods;
        std::sort(unique.begin(), unique.end());
        CHECK(std::adjacent_find(unique.begin(), unique.end()) == unique.end());  // each once
        const std::uint32_t involved = t.mask_of(r.proof->involved);
        CHECK((involved & ~t.start_mask) == 0);
        // The proof's nogoods alone refute every pick over `involved` only.
        each_pick(t, 0, involved, [&](std::uint32_t m) { CHECK(hits(proof_masks, m)); });
        // `involved` is exactly what the proof's nogoods use of start.
        std::uint32_t used = 0;
        for (std::uint32_t m : proof_masks) used |= m;
        CHECK((used & t.start_mask) == involved);
        if (given.size() > r.proof->nogoods.size()) ++left_out;
    }
    // The seeds exercise both answers and proofs that leave nogoods out.
    MESSAGE("refuted ", refuted, ", consistent ", consistent, ", proofs leaving nogoods out ", left_out);
    CHECK(refuted > 100);
    CHECK(consistent > 100);
    CHECK(left_out > 20);
}

TEST_CASE("atms/case_refutation: backjumping leaves out a set whose members play no part") {
    Atms atms;
    auto assume = [&]() { return *atms.assumption_of(atms.add_assumption(DatumId{0})); };
    const AssumptionId q = assume(), a1 = assume(), a2 = assume(), b1 = assume(), b2 = assume(), c1 = assume(),
                       c2 = assume();
    auto node = [&](AssumptionId a) { return atms.node_of(a); };
    // q with any pick of B and C is nogood; A is free. A is first among equals, so it is split first.
    for (AssumptionId b : {b1, b2})
        for (AssumptionId c : {c1, c2}) atms.add_nogood(InformantId{0}, {node(q), node(b), node(c)});
    atms.add_nogood(InformantId{0}, {node(a2), node(b1)});  // a nogood the argument never needs
    const std::vector<std::vector<AssumptionId>> sets{{a1, a2}, {b1, b2}, {c1, c2}};
    const std::vector<EnvId> given = atms.minimal_nogoods();
    const RefutationResult r = refute_by_cases(atms, sets, given, Environment::of(std::vector{q}));
    REQUIRE(r.proof);
    CHECK(r.proof->nogoods.size() == 4);
    for (EnvId ng : r.proof->nogoods) {
        CHECK(atms.env(ng).contains(q));
        CHECK_FALSE(atms.env(ng).contains(a2));
    }
    CHECK(r.proof->involved == Environment::of(std::vector{q}));
}

TEST_CASE("atms/case_refutation: the preferred assumption's nogoods close a case first") {
    Atms atms;
    auto assume = [&]() { return *atms.assumption_of(atms.add_assumption(DatumId{0})); };
    const AssumptionId p = assume(), r1 = assume(), x = assume();
    auto node = [&](AssumptionId a) { return atms.node_of(a); };
    // Over start {p, r1}, the one member of the set {x} is closed by two nogoods of equal size.
    atms.add_nogood(InformantId{0}, {node(r1), node(x)});
    atms.add_nogood(InformantId{0}, {node(p), node(x)});
    const std::vector<std::vector<AssumptionId>> sets{{x}};
    const std::vector<EnvId> given = atms.minimal_nogoods();
    const Environment start = Environment::of(std::vector{p, r1});
    for (AssumptionId preferred : {p, r1}) {
        RefutationOptions options;
        options.prefer = preferred;
        const RefutationResult r = refute_by_cases(atms, sets, given, start, options);
        REQUIRE(r.proof);
        REQUIRE(r.proof->nogoods.size() == 1);
        CHECK(atms.env(r.proof->nogoods.front()).contains(preferred));
        CHECK(r.proof->involved == Environment::of(std::vector{preferred}));
    }
}

TEST_CASE("atms/case_refutation: the node budget stops the search, and a nogood within start needs none") {
    Atms atms;
    auto assume = [&]() { return *atms.assumption_of(atms.add_assumption(DatumId{0})); };
    const AssumptionId q = assume(), a1 = assume(), a2 = assume(), s = assume();
    auto node = [&](AssumptionId a) { return atms.node_of(a); };
    atms.add_nogood(InformantId{0}, {node(q), node(a1)});
    atms.add_nogood(InformantId{0}, {node(q), node(a2)});
    atms.add_nogood(InformantId{0}, {node(s)});
    const std::vector<std::vector<AssumptionId>> sets{{a1, a2}};
    const std::vector<EnvId> given = atms.minimal_nogoods();
    RefutationOptions none;
    none.node_budget = 0;
    const RefutationResult stopped = refute_by_cases(atms, sets, given, Environment::of(std::vector{q}), none);
    CHECK(stopped.gave_up);
    CHECK_FALSE(stopped.proof);
    const RefutationResult direct = refute_by_cases(atms, sets, given, Environment::of(std::vector{q, s}), none);
    CHECK_FALSE(direct.gave_up);
    REQUIRE(direct.proof);
    CHECK(direct.proof->nogoods.size() == 1);
    CHECK(direct.proof->involved == Environment::of(std::vector{s}));
    RefutationOptions one;
    one.node_budget = 1;
    const RefutationResult found = refute_by_cases(atms, sets, given, Environment::of(std::vector{q}), one);
    CHECK_FALSE(found.gave_up);
    REQUIRE(found.proof);
    CHECK(found.proof->nogoods.size() == 2);
}
