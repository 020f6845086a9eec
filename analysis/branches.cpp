// analysis/branches.cpp: the laws' choice sets that are not Law 1's, and the union of a group's motions
// over its consistent branches.
#include "analysis/branches.hpp"
#include <algorithm>

namespace qm::analysis {
BranchSets branch_sets(std::span<const std::vector<atms::AssumptionId>> choice_sets,
                       std::span<const atms::AssumptionId> motions) {
    std::vector<atms::AssumptionId> law1(motions.begin(), motions.end());
    std::sort(law1.begin(), law1.end());
    std::vector<std::vector<atms::AssumptionId>> sets;
    for (const auto& set : choice_sets)
        if (std::none_of(set.begin(), set.end(), [&](atms::AssumptionId a) { return std::binary_search(law1.begin(), law1.end(), a); }))
            sets.push_back(set);
    return atms::index_choice_sets(std::move(sets));
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
