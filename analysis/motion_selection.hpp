// analysis/motion_selection.hpp
// Provides:   solve_chain(), the motions of one kinematic chain in one situation: every consistent
//             combination of motions (the interpretations of the chain's Law 1 choice sets over the
//             situation's environment, found by the ATMS with nogood pruning), then, where objects
//             have a force on them, the combinations no other combination beats in nearness
//             (section 6.2, Definition 38; docs/ANALYSIS.md "Which motions a force produces").
//             The preference is the laws' (`prefer` in rules/nearness.rules, read by
//             engine/preferences.hpp) and the selection the ATMS's generic query
//             (atms/preferred_interpretations.hpp): this file only maps choice sets to motions.
// Ownership:  returns values.
// Invariants: combinations come back in canonical order (object by object, translation then
//             rotation, + before 0 before -).
#pragma once
#include "analysis/analysis.hpp"
#include "atms/atms.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace qm::analysis {

// One object's Law 1 choice sets: assumption i stands for direction i.
struct ObjectChoices {
    ObjectId object{};
    std::vector<atms::AssumptionId> trans, rot;
    std::vector<Direction> trans_dirs, rot_dirs;
};

// The laws' ranks of an object's Law 1 choice sets, member by member (engine::choice_set_ranks);
// none: the set is not ranked (the object has no force), any consistent motion of it is as good as
// any other.
struct MotionRanks {
    std::optional<std::vector<std::int64_t>> trans, rot;
};

struct ChainOutcome {
    ChainMotions motions;
    std::size_t consistent = 0;   // consistent assignments of the ranked objects' motions
    bool truncated = false;       // enumeration stopped at the limit
};

// Every consistent combination of the chain's motions over base (its Law 1 choice sets' interpretations,
// no preference): the kinematically consistent combinations of Figure 7.14 when base holds no force.
// Stops after limit (truncated). Pre: every assumption was issued by atms.
[[nodiscard]] ChainOutcome consistent_combinations(atms::Atms& atms, std::span<const ObjectChoices> chain, atms::EnvId base,
                                                   std::size_t limit);

// Canonical order of combinations: object by object, translation then rotation, + before 0 before -.
[[nodiscard]] bool combination_less(const std::vector<ObjectMotion>& a, const std::vector<ObjectMotion>& b);

// Pre: chain and ranks are aligned, each ranks vector as long as its set; every assumption was
// issued by atms. Interns environments.
[[nodiscard]] ChainOutcome solve_chain(atms::Atms& atms, std::span<const ObjectChoices> chain,
                                       std::span<const MotionRanks> ranks, atms::EnvId base, std::size_t limit);

}  // namespace qm::analysis
