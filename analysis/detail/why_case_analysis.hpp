// analysis/detail/why_case_analysis.hpp (internal to analysis/)
// Provides:   explain_by_cases(), the answer for a motion that is inconsistent with every choice of
//             the other motions of its kinematic chain (Law 1) though no nogood of it and the
//             situation alone excludes it: a refutation by case analysis over the chain's other
//             choice sets (the generic ATMS query atms/case_refutation.hpp), whose nogoods are the
//             reasons; the motions of other objects the scene's description alone rules out are
//             said once in a note instead of as reasons.
// Ownership:  fills the WhyAnswer; the State is borrowed (responsible sets re-analyse in its engine).
#pragma once
#include "analysis/detail/why_motion.hpp"

namespace qm::analysis::detail {

// Pre: no interpretation of m.sets over m.with_choice_id is consistent.
void explain_by_cases(Analysis::State& st, WhyAnswer& w, const WhyMotion& m);

}  // namespace qm::analysis::detail
