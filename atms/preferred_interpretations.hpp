// atms/preferred_interpretations.hpp
// Provides:   for_each_preferred_interpretation(), the generic query behind a preference between
//             interpretations (the rule language's `prefer`, docs/RULES.md): of the interpretations
//             of some choice sets over a base environment, those whose picks in the ranked sets no
//             other interpretation beats, i.e. ranks no worse in every ranked set and better in one
//             (a Pareto preference, atms/pareto_front.hpp). The free sets carry no preference: each
//             preferred pick of the ranked sets is completed in every consistent way.
// Ownership:  returns values; interns environments in the Atms.
// Complexity: the ranked sets are enumerated first, an assignment kept only if some choice of the
//             free sets completes it consistently; only the assignments that survive the preference
//             are completed, so free sets are never enumerated under dominated ones (a chain of
//             free sets behind one ranked set stays linear). O(n^2 k) for the front of n feasible
//             assignments of k ranked sets.
// Knows nothing of what is ranked, nor of rules or mechanics.
#pragma once
#include "atms/atms.hpp"
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace qm::atms {

// A choice set with a rank per member (smaller is preferred); ranks[i] is members[i]'s.
struct RankedChoiceSet {
    std::vector<AssumptionId> members;
    std::vector<std::int64_t> ranks;
};

// Calls visit(full) for each preferred interpretation, full being the interpretation joined with
// base (valid during the call only); visit returns false to stop completing the current preferred
// pick of the ranked sets (a caller that stops at a limit keeps returning false). Order: the preferred picks of the
// ranked sets in the order for_each_interpretation finds them, each completed in that order.
// Returns the number of feasible assignments of the ranked sets (those that some pick of the free
// sets completes consistently), preferred or not. No ranked sets: every interpretation is preferred.
// Pre: every members/ranks pair has equal sizes; assumptions issued by atms; no assumption in two sets.
std::size_t for_each_preferred_interpretation(Atms& atms, std::span<const RankedChoiceSet> ranked,
                                              std::span<const std::vector<AssumptionId>> free, EnvId base,
                                              const std::function<bool(const Environment&)>& visit);

}  // namespace qm::atms
