// analysis/detail/why_nearness.hpp (internal to analysis/)
// Provides:   explain_by_nearness(), the answer for a motion that is consistent but not what the
//             forces produce (section 6.2, Definition 38): the derivations of its nearness ranks, or,
//             for an object no force drives, the ranks of the other objects' motions that every
//             consistent combination with it needs and no predicted one has (from the first few
//             such combinations: WhyLimits::rank_reasons, rank_combinations).
// Ownership:  fills the WhyAnswer; the State is borrowed.
#pragma once
#include "analysis/detail/why_motion.hpp"

namespace qm::analysis::detail {

// Pre: some interpretation of m.sets over m.with_choice_id is consistent; the result is complete.
void explain_by_nearness(Analysis::State& st, WhyAnswer& w, const WhyMotion& m);

}  // namespace qm::analysis::detail
