// atms/case_refutation.hpp
// Provides:   refute_by_cases(), a refutation of an environment by case analysis over choice sets:
//             a proof that no interpretation of the sets over `start` (start + one member of each
//             set, atms/interpretations.hpp) is consistent, made of the nogoods it needs. At each
//             step the search branches on the set with the fewest members left open by the nogoods
//             (a forced choice is settled first) and backjumps: when the refutation below one member
//             does not use that member, it refutes the whole step, and the other members' cases are
//             not searched (their nogoods are not part of the proof). So a nogood the argument never
//             needs (one excluding a member of a set that is never reached) is left out.
// Ownership:  pure function over a borrowed Atms; returns values.
// Complexity: worst case exponential in the number of sets; bounded by RefutationOptions::node_budget
//             search steps, after which it gives up (gave_up in the result).
// Knows nothing of what the assumptions stand for, nor of rules or mechanics.
#pragma once
#include "atms/atms.hpp"
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace qm::atms {

struct RefutationOptions {
    // Search steps (case splits) before giving up; a refutation found within it is returned.
    std::size_t node_budget = 200000;
    // Where several nogoods close a case, those containing this assumption are preferred (after
    // those the proof already uses); none: the smallest, then the first given.
    std::optional<AssumptionId> prefer;
};

struct Refutation {
    std::vector<EnvId> nogoods;  // the proof's nogoods, each one of those given, in the order the search met them
    Environment involved;        // the assumptions of start the proof rests on: the nogoods' assumptions
                                 // less the members of the sets it branched on
};

struct RefutationResult {
    std::optional<Refutation> proof;  // none: some interpretation is consistent, or the search gave up
    bool gave_up = false;             // the node budget was exhausted
};

// Refutes `start` by cases over `choice_sets`, using only `nogoods` (a caller passes those within
// its scope: e.g. the minimal nogoods within start plus the sets' members). If some nogood is within
// start, the proof is that nogood alone. Pre: every id was issued by atms; no assumption is in two
// sets.
[[nodiscard]] RefutationResult refute_by_cases(const Atms& atms, std::span<const std::vector<AssumptionId>> choice_sets,
                                               std::span<const EnvId> nogoods, const Environment& start,
                                               const RefutationOptions& options = {});

}  // namespace qm::atms
