// analysis/branches.hpp
// Provides:   BranchSets, the laws' choice sets other than Law 1's motions: the branches by which the
//             laws resolve an ambiguity (section 2.3: "we resolve this ambiguity by branching";
//             rules/cause_comparison.rules asks which of two opposing causes prevails);
//             group_chains(), which kinematic chains of a situation are enumerated together with which
//             of these sets; solve_group(), the motions of such a group: for each consistent choice
//             of its branches, the combinations that are not dominated (solve_chain) under the
//             nearness ranks that hold there, united (docs/ANALYSIS.md "Branches").
// Ownership:  values; the Atms is borrowed for the call.
// Invariants: a chain that no branching set reaches is a group of its own with no sets, solved by
//             solve_chain in the situation's environment exactly as without branches. Groups come
//             back ordered by their first object.
// Knows no mechanics: a branch is an ATMS choice set, and which chains it reaches is read off labels.
#pragma once
#include "analysis/motion_selection.hpp"
#include "atms/atms.hpp"
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace qm::analysis {

struct BranchSets {
    std::vector<std::vector<atms::AssumptionId>> sets;   // the choice sets that are not Law 1's
    std::vector<std::optional<std::uint32_t>> set_of;    // by AssumptionId value: its index in sets
    [[nodiscard]] bool empty() const noexcept { return sets.empty(); }
    [[nodiscard]] std::optional<std::uint32_t> of(atms::AssumptionId a) const {
        return a.value < set_of.size() ? set_of[a.value] : std::nullopt;
    }
};

// Every choice set none of whose assumptions is in `motions` (the Law 1 sets' assumptions).
[[nodiscard]] BranchSets branch_sets(std::span<const std::vector<atms::AssumptionId>> choice_sets,
                                     std::span<const atms::AssumptionId> motions);

struct ChainGroup {
    std::vector<std::size_t> chains;   // indices of the kinematic chains solved together, ascending
    std::vector<std::uint32_t> sets;   // indices into BranchSets::sets enumerated with them, ascending
};

// Chain c is reached by a set when one of its nodes (chain_nodes[c]: the facts its selection reads,
// the nearness ranks) holds in env plus assumptions of branching sets only, among them one of that
// set's. Chains reached by one set, or by sets that a minimal nogood within env couples, form one
// group, with all those sets. Pre: env and the nodes were issued by atms.
[[nodiscard]] std::vector<ChainGroup> group_chains(const atms::Atms& atms, const BranchSets& branches, atms::EnvId env,
                                                   std::span<const std::vector<atms::NodeId>> chain_nodes);

// The group's motions: for each interpretation B of `sets` over env, solve_chain(members, ranks(B))
// in B; the union, without repeats, in canonical order. `ranks(i, B)` is member i's ranks in B.
// No sets: exactly solve_chain(members, ranks(env)) in env. The limit counts the union.
// Pre: as solve_chain; sets' assumptions issued by atms.
[[nodiscard]] ChainOutcome solve_group(atms::Atms& atms, std::span<const ObjectChoices> members,
                                       std::span<const std::vector<atms::AssumptionId>> sets, atms::EnvId env,
                                       const std::function<MotionRanks(std::size_t, atms::EnvId)>& ranks, std::size_t limit);

}  // namespace qm::analysis
