// engine/match_plan.hpp
// Provides:   MatchPlan, what the matcher needs to know about a compiled rule's conditions that
//             does not depend on the facts, computed once per rule in time linear in its size:
//             - seed_first_safe[i]: a `match` condition i may be seeded first (its fact's variables
//               bound before the conditions written ahead of it) without changing any answer;
//             - repeat_of[i]: an earlier condition identical to condition i (both `match`, or both a
//               builtin test), whose answer condition i repeats: once the earlier one has matched
//               fact F (or held), condition i matches F alone (or holds), so it is not looked up again;
//             - order[s]: the order in which to match the rule's leading `match` and test
//               conditions (its prefix) when seeded at condition s (order[n]: unseeded), so that each
//               is looked up through the index of an argument already bound (bound first, written
//               order among equals); empty where that order is the written one. The matcher sorts
//               what a reordered prefix finds back into written order, so answers and their order
//               do not depend on it.
// Ownership:  a plain value, built from a CompiledRule and used with that rule only.
// Invariants: sizes equal the rule's condition count (order: plus one); a non-empty order[s] is a
//             permutation of the prefix that starts with s when s < n; repeat_of[i] < i and names a condition of the
//             same kind that is not itself a repeat.
// Knows nothing of the ATMS or of facts.
#pragma once
#include "engine/compiled_rule.hpp"
#include <cstdint>
#include <optional>
#include <vector>

namespace qm::engine {

struct MatchPlan {
    std::vector<std::uint8_t> seed_first_safe;               // per condition; 1 = safe (only for `match`)
    std::vector<std::optional<std::uint32_t>> repeat_of;     // per condition
    bool has_repeat = false;                                 // some repeat_of[i] is set
    std::uint32_t prefix = 0;                                // leading `match` and test conditions
    std::vector<std::vector<std::uint32_t>> order;           // per seed condition, then unseeded
};

[[nodiscard]] MatchPlan plan_matching(const CompiledRule& rule);

}  // namespace qm::engine
