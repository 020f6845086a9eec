// analysis/branches.cpp: which chains a branching choice set reaches (read off the labels of what their
// selection reads), which sets a nogood couples (union-find), and the union of a group's motions
// over its consistent branches.
#include "analysis/branches.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <numeric>

namespace qm::analysis {
namespace {

struct UnionFind {
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
    std::size_t find(std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
    std::vector<std::size_t> parent;
};

// The branching sets of the assumptions of e outside env; nullopt if one of them is no branch.
std::optional<std::vector<std::uint32_t>> branch_part(const BranchSets& b, const atms::Environment& e,
                                                      const atms::Environment& env) {
    std::vector<std::uint32_t> out;
    for (atms::AssumptionId a : e.assumptions()) {
        if (env.contains(a)) continue;
        auto s = b.of(a);
        if (!s) return std::nullopt;
        out.push_back(*s);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace

BranchSets branch_sets(std::span<const std::vector<atms::AssumptionId>> choice_sets,
                       std::span<const atms::AssumptionId> motions) {
    BranchSets out;
    std::vector<atms::AssumptionId> law1(motions.begin(), motions.end());
    std::sort(law1.begin(), law1.end());
    for (const auto& set : choice_sets) {
        if (std::any_of(set.begin(), set.end(), [&](atms::AssumptionId a) { return std::binary_search(law1.begin(), law1.end(), a); }))
            continue;
        const auto index = static_cast<std::uint32_t>(out.sets.size());
        for (atms::AssumptionId a : set) {
            if (out.set_of.size() <= a.value) out.set_of.resize(a.value + 1);
            QM_REQUIRE(!out.set_of[a.value], "no assumption is in two choice sets");
            out.set_of[a.value] = index;
        }
        out.sets.push_back(set);
    }
    return out;
}

std::vector<ChainGroup> group_chains(const atms::Atms& atms, const BranchSets& branches, atms::EnvId env,
                                     std::span<const std::vector<atms::NodeId>> chain_nodes) {
    const std::size_t chains = chain_nodes.size(), sets = branches.sets.size();
    // Nodes 0..chains-1 are chains, chains.. are sets.
    UnionFind uf(chains + sets);
    std::vector<bool> reached(sets, false);
    const atms::Environment& world = atms.env(env);
    if (!branches.empty()) {
        for (std::size_t c = 0; c < chains; ++c)
            for (atms::NodeId n : chain_nodes[c])
                for (atms::EnvId l : atms.label(n))
                    if (auto part = branch_part(branches, atms.env(l), world))
                        for (std::uint32_t s : *part) {
                            uf.join(c, chains + s);
                            reached[s] = true;
                        }
        // Sets that a nogood (within env) couples: their choices are not independent. (The pairs
        // of a choice set's own at-most-one constraint lie within one set: they couple nothing.)
        if (std::any_of(reached.begin(), reached.end(), [](bool r) { return r; }))
            for (atms::EnvId ng : atms.stated_nogoods())
                if (auto part = branch_part(branches, atms.env(ng), world); part && part->size() > 1)
                    for (std::size_t i = 1; i < part->size(); ++i) uf.join(chains + (*part)[0], chains + (*part)[i]);
    }
    std::vector<ChainGroup> out;
    std::vector<std::optional<std::size_t>> group_of(chains + sets);
    for (std::size_t c = 0; c < chains; ++c) {
        auto& g = group_of[uf.find(c)];
        if (!g) {
            g = out.size();
            out.emplace_back();
        }
        out[*g].chains.push_back(c);
    }
    for (std::size_t s = 0; s < sets; ++s)
        if (auto g = group_of[uf.find(chains + s)]) out[*g].sets.push_back(static_cast<std::uint32_t>(s));
    return out;
}

ChainOutcome solve_group(atms::Atms& atms, std::span<const ObjectChoices> members,
                         std::span<const std::vector<atms::AssumptionId>> sets, atms::EnvId env,
                         const std::function<MotionRanks(std::size_t, atms::EnvId)>& ranks, std::size_t limit) {
    auto solve_in = [&](atms::EnvId where) {
        std::vector<MotionRanks> near;
        for (std::size_t i = 0; i < members.size(); ++i) near.push_back(ranks(i, where));
        return solve_chain(atms, members, near, where, limit);
    };
    if (sets.empty()) return solve_in(env);
    // The consistent branches first (interning environments while enumerating is not allowed).
    std::vector<std::vector<atms::AssumptionId>> branches;
    atms.for_each_interpretation(sets, env, [&](const atms::Environment& e) {
        branches.push_back(e.assumptions());
        return true;
    });
    ChainOutcome out;
    for (const ObjectChoices& c : members) out.motions.objects.push_back(c.object);
    for (const auto& b : branches) {
        ChainOutcome one = solve_in(atms.environment(b));
        out.truncated = out.truncated || one.truncated;
        out.consistent += one.consistent;
        auto& all = out.motions.combinations;
        all.insert(all.end(), std::make_move_iterator(one.motions.combinations.begin()),
                   std::make_move_iterator(one.motions.combinations.end()));
    }
    auto& all = out.motions.combinations;
    std::sort(all.begin(), all.end(), combination_less);
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (all.size() > limit) {
        all.resize(limit);
        out.truncated = true;
    }
    return out;
}

}  // namespace qm::analysis
