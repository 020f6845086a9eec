// atms/interpretations.hpp
// Provides:   enumerate_interpretations(), the backtracking search behind Atms::interpretations
//             (de Kleer 1986, section 6; BPS atms.lisp `interpretations`): every consistent
//             base + one assumption from each choice set, pruning a branch as soon as the partial
//             choice contains a nogood, so the full product is never formed.
// Ownership:  pure function; the visitor receives an Environment valid only during the call (one
//             object is refilled for each interpretation, so enumerating allocates nothing per step).
// Knows nothing of nodes or labels: consistency comes from the NogoodDatabase alone.
#pragma once
#include "atms/environment.hpp"
#include "atms/ids.hpp"
#include "atms/nogood_database.hpp"
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace qm::atms {
// Calls visit for each interpretation in lexicographic order of choices (first set slowest);
// visit returns false to stop. Returns the number of interpretations visited. A set the base
// already picks from contributes that pick only (no interpretation if the base holds two of its
// members); an assumption repeated within a set is visited twice (results are not deduplicated).
// Pre (checked here, first): every assumption < assumption_count; no assumption in two sets.
std::size_t enumerate_interpretations(const NogoodDatabase& nogoods, std::size_t assumption_count,
                                      std::span<const std::vector<AssumptionId>> choice_sets,
                                      const Environment& base,
                                      const std::function<bool(const Environment&)>& visit);
}  // namespace qm::atms
