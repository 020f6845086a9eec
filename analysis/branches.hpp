// analysis/branches.hpp
// Provides:   BranchSets, the laws' choice sets other than Law 1's motions: the branches by which the
//             laws resolve an ambiguity (section 2.3: "we resolve this ambiguity by branching";
//             rules/cause_comparison.rules asks which of two opposing causes prevails);
//             solve_group(), the motions of a group of kinematic chains enumerated together with
//             some of these sets (which ones: the generic query atms/choice_set_groups.hpp, over
//             the nodes each chain's selection reads): for each consistent choice of its branches,
//             the combinations that are not dominated (solve_chain) under the nearness ranks that
//             hold there, united (docs/ANALYSIS.md "Branches").
// Ownership:  values; the Atms is borrowed for the call.
// Invariants: a group with no sets is solved by solve_chain in the situation's environment exactly
//             as without branches.
// Knows no mechanics: a branch is an ATMS choice set.
#pragma once
#include "analysis/motion_selection.hpp"
#include "atms/atms.hpp"
#include "atms/choice_set_groups.hpp"
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace qm::analysis {

// The choice sets that are not Law 1's, with the set of each assumption.
using BranchSets = atms::ChoiceSetIndex;

// Every choice set none of whose assumptions is in `motions` (the Law 1 sets' assumptions).
[[nodiscard]] BranchSets branch_sets(std::span<const std::vector<atms::AssumptionId>> choice_sets,
                                     std::span<const atms::AssumptionId> motions);

// The group's motions: for each interpretation B of `sets` over env, solve_chain(members, ranks(B))
// in B; the union, without repeats, in canonical order. `ranks(i, B)` is member i's ranks in B.
// No sets: exactly solve_chain(members, ranks(env)) in env. The limit counts the union.
// Pre: as solve_chain; sets' assumptions issued by atms.
[[nodiscard]] ChainOutcome solve_group(atms::Atms& atms, std::span<const ObjectChoices> members,
                                       std::span<const std::vector<atms::AssumptionId>> sets, atms::EnvId env,
                                       const std::function<MotionRanks(std::size_t, atms::EnvId)>& ranks, std::size_t limit);

}  // namespace qm::analysis
