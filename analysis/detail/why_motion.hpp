// analysis/detail/why_motion.hpp (internal to analysis/)
// Provides:   WhyMotion, a motion --why is asked about that no predicted combination has, with the
//             part of the ATMS its answer searches: the other choice sets of its kinematic chain
//             (Law 1's, and the laws' branches enumerated with the chain: docs/ANALYSIS.md
//             "Branches") and the minimal nogoods within them. Filled by the driver
//             (analysis/why_query.cpp), read by analysis/why_case_analysis.cpp and why_nearness.cpp.
// Ownership:  values, but `result` points into the State's results.
#pragma once
#include "analysis/detail/analysis_state.hpp"
#include <vector>

namespace qm::analysis::detail {

struct WhyMotion {
    std::size_t situation = 0;          // 1-based
    atms::EnvId env{};                  // the situation's context environment
    const SituationResult* result = nullptr;  // the situation's result
    ObjectId object{};
    bool translational = true;
    Direction direction;
    atms::AssumptionId choice{};        // the motion's Law 1 assumption
    atms::Environment with_choice;      // env's assumptions and choice
    atms::EnvId with_choice_id{};       // with_choice, interned
    std::vector<std::vector<atms::AssumptionId>> sets;  // the chain's other choice sets
    bool branched = false;              // some of sets are branches of the laws
    atms::Environment scope;            // env's assumptions and every choice of the chain
    std::vector<atms::EnvId> relevant;  // the minimal nogoods within scope
};

}  // namespace qm::analysis::detail
