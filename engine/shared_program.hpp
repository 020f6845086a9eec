// engine/shared_program.hpp
// Provides:   SharedProgram, a compiled program together with what an engine derives from it before
//             it matches anything (each rule's match plan, the rules that new facts of each predicate
//             wake), made once by share_program() and then only read. Any number of engines, in any
//             threads, may run over one: a driver that makes an engine per state (envision/) pays
//             for neither a copy of the program nor its planning per engine.
// Ownership:  immutable once made; engines hold it by shared_ptr<const SharedProgram>.
// Invariants: plans[r] == plan_matching(program.rules[r]) for every rule r; by_trigger[p] lists, in
//             ascending order and once each, the rules with a `match` condition, or a `for all` or
//             `exists` atom, of predicate p.
// Knows nothing of the ATMS or of any particular program.
#pragma once
#include "engine/compiled_rule.hpp"
#include "engine/match_plan.hpp"
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace qm::engine {

struct SharedProgram {
    CompiledProgram program;
    IdVector<RuleId, MatchPlan> plans;
    std::unordered_map<std::uint32_t, std::vector<RuleId>> by_trigger;  // predicate -> rules, ascending
};

[[nodiscard]] std::shared_ptr<const SharedProgram> share_program(CompiledProgram program);

}  // namespace qm::engine
