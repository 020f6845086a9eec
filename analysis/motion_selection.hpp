// analysis/motion_selection.hpp
// Provides:   solve_chain(), the motions of one kinematic chain in one situation: every consistent
//             combination of motions (the interpretations of the chain's Law 1 choice sets over the
//             situation's environment, found by the ATMS with nogood pruning), then, where objects
//             have a force on them, the combinations no other combination beats in nearness
//             (section 6.2, Definition 38; docs/ANALYSIS.md "Which motions a force produces").
//             The nearness ranks come from the laws (rules/nearness.rules); this file only keeps the
//             combinations that are not dominated, a generic preference, and knows no mechanics.
// Ownership:  returns values.
// Invariants: combinations come back in canonical order (object by object, translation then
//             rotation, + before 0 before -).
#pragma once
#include "analysis/analysis.hpp"
#include "atms/atms.hpp"
#include <map>
#include <span>
#include <vector>

namespace qm::analysis {

// One object's Law 1 choice sets: assumption i stands for direction i.
struct ObjectChoices {
    ObjectId object{};
    std::vector<atms::AssumptionId> trans, rot;
    std::vector<Direction> trans_dirs, rot_dirs;
};

// Definition 38 ranks of an object's motions; an empty map: the object has no force, any
// consistent motion of it is as good as any other.
struct Nearness {
    std::map<Direction, int> trans, rot;
};

struct ChainOutcome {
    ChainMotions motions;
    std::size_t consistent = 0;   // consistent assignments of the ranked objects' motions
    bool truncated = false;       // enumeration stopped at the limit
};

// Canonical order of combinations: object by object, translation then rotation, + before 0 before -.
[[nodiscard]] bool combination_less(const std::vector<ObjectMotion>& a, const std::vector<ObjectMotion>& b);

// Pre: chain and nearness are aligned; every assumption was issued by atms. Interns environments.
[[nodiscard]] ChainOutcome solve_chain(atms::Atms& atms, std::span<const ObjectChoices> chain,
                                       std::span<const Nearness> nearness, atms::EnvId base, std::size_t limit);

}  // namespace qm::analysis
