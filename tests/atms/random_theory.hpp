// tests/atms/random_theory.hpp
// Test helper (not a test): seeded random Horn theories and a brute-force oracle that enumerates
// every environment over the assumptions and forward chains from premises + environment. Shared
// by the label, explanation and facade tests, which check the ATMS against it.
#pragma once
#include "atms/atms.hpp"
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace qm::atms::test {

struct Clause {
    std::vector<NodeId> antecedents;
    NodeId consequent;
};

struct RandomTheory {
    Atms atms;
    std::vector<NodeId> assumptions;  // index i holds AssumptionId{i}
    std::vector<NodeId> premises;
    std::vector<NodeId> derived;
    std::vector<Clause> pending;      // clauses not yet given to the ATMS, in the order to add
    std::vector<Clause> added;

    // Builds the nodes and a shuffled list of clauses; adds no clause yet.
    RandomTheory(std::uint32_t seed, int n_assumptions, int n_derived, int n_clauses) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        for (int i = 0; i < n_assumptions; ++i) assumptions.push_back(atms.add_assumption(DatumId{0}));
        const int n_premises = pick(0, 2);
        for (int i = 0; i < n_premises; ++i) premises.push_back(atms.add_premise(DatumId{1}));
        for (int i = 0; i < n_derived; ++i) derived.push_back(atms.add_node(DatumId{2}));
        std::vector<NodeId> sources = assumptions;
        sources.insert(sources.end(), premises.begin(), premises.end());
        sources.insert(sources.end(), derived.begin(), derived.end());
        for (int c = 0; c < n_clauses; ++c) {
            Clause clause;
            const int roll = pick(0, 99);
            if (roll < 15) clause.consequent = atms.contradiction();
            else if (roll < 20) clause.consequent = assumptions[static_cast<std::size_t>(pick(0, n_assumptions - 1))];
            else clause.consequent = derived[static_cast<std::size_t>(pick(0, n_derived - 1))];
            const int k = pick(clause.consequent == atms.contradiction() ? 1 : 0, 3);
            for (int i = 0; i < k; ++i)
                clause.antecedents.push_back(sources[static_cast<std::size_t>(pick(0, static_cast<int>(sources.size()) - 1))]);
            pending.push_back(clause);
        }
    }

    bool add_next() {
        if (pending.empty()) return false;
        Clause c = pending.front();
        pending.erase(pending.begin());
        atms.justify(InformantId{static_cast<std::uint32_t>(added.size())}, c.antecedents, c.consequent);
        added.push_back(c);
        return true;
    }
};

// Brute-force oracle over the clauses added so far.
struct Oracle {
    int n;                                       // number of assumptions
    std::size_t nodes;
    std::vector<std::uint8_t> derived_;          // [mask * nodes + node]: node derivable from mask
    std::vector<bool> inconsistent;              // [mask]

    [[nodiscard]] bool derived(std::uint32_t mask, NodeId node) const {
        return derived_[mask * nodes + node.value] != 0;
    }

    explicit Oracle(const RandomTheory& t)
        : n(static_cast<int>(t.assumptions.size())), nodes(t.atms.node_count()) {
        const std::uint32_t masks = 1U << n;
        derived_.assign(masks * nodes, 0);
        inconsistent.assign(masks, false);
        for (std::uint32_t m = 0; m < masks; ++m) {
            std::uint8_t* d = derived_.data() + m * nodes;
            for (NodeId p : t.premises) d[p.value] = 1;
            for (int i = 0; i < n; ++i)
                if (m & (1U << i)) d[t.assumptions[static_cast<std::size_t>(i)].value] = 1;
            for (bool changed = true; changed;) {
                changed = false;
                for (const Clause& c : t.added) {
                    if (d[c.consequent.value] != 0) continue;
                    if (std::all_of(c.antecedents.begin(), c.antecedents.end(),
                                    [&](NodeId a) { return d[a.value] != 0; })) {
                        d[c.consequent.value] = 1;
                        changed = true;
                    }
                }
            }
            inconsistent[m] = d[t.atms.contradiction().value] != 0;
        }
    }

    // Minimal masks among those satisfying pred, sorted.
    template <class Pred>
    std::vector<std::uint32_t> minimal(Pred pred) const {
        std::vector<std::uint32_t> good, out;
        for (std::uint32_t m = 0; m < (1U << n); ++m)
            if (pred(m)) good.push_back(m);
        for (std::uint32_t m : good)
            if (std::none_of(good.begin(), good.end(), [&](std::uint32_t o) { return o != m && (o & m) == o; }))
                out.push_back(m);
        return out;
    }
    std::vector<std::uint32_t> label(NodeId node) const {
        return minimal([&](std::uint32_t m) { return !inconsistent[m] && derived(m, node); });
    }
    std::vector<std::uint32_t> nogoods() const {
        return minimal([&](std::uint32_t m) { return static_cast<bool>(inconsistent[m]); });
    }
};

inline std::uint32_t mask_of(const Environment& e) {
    std::uint32_t m = 0;
    for (AssumptionId a : e.assumptions()) m |= 1U << a.value;
    return m;
}

inline std::vector<std::uint32_t> masks_of(const Atms& atms, const std::vector<EnvId>& envs) {
    std::vector<std::uint32_t> out;
    for (EnvId e : envs) out.push_back(mask_of(atms.env(e)));
    std::sort(out.begin(), out.end());
    return out;
}

inline EnvId env_of_mask(Atms& atms, std::uint32_t m) {
    std::vector<AssumptionId> as;
    for (std::uint32_t i = 0; i < 32; ++i)
        if (m & (1U << i)) as.push_back(AssumptionId{i});
    return atms.environment(as);
}
}  // namespace qm::atms::test
