// tests/atms/random_theory.hpp
// Test helper (not a test): seeded random Horn theories grown one step at a time, and a brute-force
// oracle that enumerates every environment over the theory's assumptions and forward chains from
// premises + environment. Shared by the label update, consumer and explanation tests, which check
// the ATMS against it.
//
// A step adds one clause (a justification, possibly of an assumption node, or a nogood) or, when
// the shape asks for interleaving, one new assumption, premise or derived node, so labels are
// checked under incremental addition of all four. With padding, unused assumptions are created
// between the tracked ones, so tracked assumption ids spread over several 64-bit words.
#pragma once
#include "atms/atms.hpp"
#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace qm::atms::test {

struct Clause {
    std::vector<NodeId> antecedents;
    NodeId consequent;
};

struct TheoryShape {
    int assumptions = 6;      // tracked assumptions (the oracle enumerates 2^assumptions envs); <= 12
    int derived = 12;         // derived nodes
    int clauses = 25;         // clauses (justifications and nogoods)
    bool interleave = false;  // false: all nodes first, then one clause per step; true: nodes and
                              // clauses in random order (starting from one assumption, one node)
    int max_padding = 0;      // before each tracked assumption, 0..max_padding unused ones
    bool justify_assumptions = true;  // false: a clause that would conclude an assumption node
                                      // concludes a derived node instead (same random draws)
};

struct RandomTheory {
    Atms atms;
    std::vector<NodeId> assumptions;  // tracked; assumptions[i] is the oracle's bit i
    std::vector<NodeId> premises;
    std::vector<NodeId> derived;
    std::vector<Clause> added;
    std::size_t steps = 0;

    RandomTheory(std::uint32_t seed, TheoryShape shape) : shape_(shape), rng_(seed) {
        if (!shape_.interleave) {
            for (int i = 0; i < shape_.assumptions; ++i) new_assumption();
            for (int i = pick(0, 2); i > 0; --i) new_premise();
            for (int i = 0; i < shape_.derived; ++i) new_derived();
        } else {
            new_assumption();
            new_derived();
            premise_budget_ = pick(0, 2);
        }
    }
    RandomTheory(std::uint32_t seed, int n_assumptions, int n_derived, int n_clauses)
        : RandomTheory(seed, TheoryShape{n_assumptions, n_derived, n_clauses, false, 0}) {}

    // Performs the next step; false when the theory is complete.
    bool add_next() {
        const int nodes_left = static_cast<int>(shape_.assumptions - assumptions.size()) +
                               static_cast<int>(shape_.derived - derived.size()) + premise_budget_;
        const int clauses_left = shape_.clauses - clauses_;
        if (nodes_left + clauses_left == 0) return false;
        ++steps;
        if (pick(1, nodes_left + clauses_left) <= nodes_left) {
            int r = pick(1, nodes_left);
            if ((r -= shape_.assumptions - static_cast<int>(assumptions.size())) <= 0) new_assumption();
            else if ((r -= shape_.derived - static_cast<int>(derived.size())) <= 0) new_derived();
            else {
                --premise_budget_;
                new_premise();
            }
            return true;
        }
        ++clauses_;
        Clause clause;
        const int roll = pick(0, 99);
        if (roll < 15) clause.consequent = atms.contradiction();
        else if (roll < 20 && shape_.justify_assumptions) clause.consequent = any_of(assumptions);
        else clause.consequent = any_of(derived);
        std::vector<NodeId> sources = assumptions;
        sources.insert(sources.end(), premises.begin(), premises.end());
        sources.insert(sources.end(), derived.begin(), derived.end());
        const int k = pick(clause.consequent == atms.contradiction() ? 1 : 0, 3);
        for (int i = 0; i < k; ++i) clause.antecedents.push_back(any_of(sources));
        atms.justify(InformantId{static_cast<std::uint32_t>(added.size())}, clause.antecedents, clause.consequent);
        added.push_back(clause);
        return true;
    }

    // The oracle bits of an environment; an untracked (padding) assumption sets bit 31, which no
    // oracle mask has, so a label holding one can never match.
    [[nodiscard]] std::uint32_t mask_of(const Environment& e) const {
        std::uint32_t m = 0;
        for (AssumptionId a : e.assumptions()) {
            const auto it = std::find(tracked_.begin(), tracked_.end(), a);
            m |= it == tracked_.end() ? (1U << 31) : 1U << (it - tracked_.begin());
        }
        return m;
    }
    [[nodiscard]] const std::vector<AssumptionId>& tracked() const noexcept { return tracked_; }
    [[nodiscard]] std::vector<std::uint32_t> masks_of(const std::vector<EnvId>& envs) const {
        std::vector<std::uint32_t> out;
        for (EnvId e : envs) out.push_back(mask_of(atms.env(e)));
        std::sort(out.begin(), out.end());
        return out;
    }
    EnvId env_of_mask(std::uint32_t m) {
        std::vector<AssumptionId> as;
        for (std::size_t i = 0; i < tracked_.size(); ++i)
            if (m & (1U << i)) as.push_back(tracked_[i]);
        return atms.environment(as);
    }

private:
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    NodeId any_of(const std::vector<NodeId>& v) { return v[static_cast<std::size_t>(pick(0, static_cast<int>(v.size()) - 1))]; }
    void new_assumption() {
        for (int i = pick(0, shape_.max_padding); i > 0; --i) atms.add_assumption(DatumId{3});
        assumptions.push_back(atms.add_assumption(DatumId{0}));
        tracked_.push_back(*atms.assumption_of(assumptions.back()));
    }
    void new_premise() { premises.push_back(atms.add_premise(DatumId{1})); }
    void new_derived() { derived.push_back(atms.add_node(DatumId{2})); }

    TheoryShape shape_;
    std::mt19937 rng_;
    std::vector<AssumptionId> tracked_;
    int premise_budget_ = 0;
    int clauses_ = 0;
};

// Brute-force oracle over the theory as it stands, and over at-most-one constraints given as masks
// of tracked assumptions (an environment holding two members of one is inconsistent).
struct Oracle {
    int n;                                       // number of tracked assumptions
    std::size_t nodes;
    std::vector<std::uint8_t> derived_;          // [mask * nodes + node]: node derivable from mask
    std::vector<bool> inconsistent;              // [mask]

    [[nodiscard]] bool derived(std::uint32_t mask, NodeId node) const {
        return derived_[mask * nodes + node.value] != 0;
    }

    explicit Oracle(const RandomTheory& t, const std::vector<std::uint32_t>& at_most_one = {})
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
            inconsistent[m] = d[t.atms.contradiction().value] != 0 ||
                              std::any_of(at_most_one.begin(), at_most_one.end(),
                                          [&](std::uint32_t g) { return std::popcount(m & g) >= 2; });
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
    // Sound + consistent + complete + minimal: exactly the minimal consistent deriving envs.
    std::vector<std::uint32_t> label(NodeId node) const {
        return minimal([&](std::uint32_t m) { return !inconsistent[m] && derived(m, node); });
    }
    std::vector<std::uint32_t> nogoods() const {
        return minimal([&](std::uint32_t m) { return static_cast<bool>(inconsistent[m]); });
    }
};
}  // namespace qm::atms::test
