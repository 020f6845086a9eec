// engine/consistency.hpp
// Provides:   whether an environment (a set of assumptions) is consistent with a program's laws and,
//             if not, which rule refutes it: the `false` that derives a nogood within it. A driver
//             that must tell many times whether some combination of its hypotheses can hold (the
//             envisioner: an object's situation in a step and its motion after, rules/clock/
//             settling.rules) reads the answers once, for every combination, and looks them up.
// Semantics:  env is refuted iff some nogood of the engine's ATMS is a subset of it. The refuting
//             rule is the informant of the last step of the ATMS's explanation of that nogood (the
//             justification of the contradiction): its rule's name and location; a nogood no rule
//             concluded (the closed world of a context, a choice set's exclusion) has no rule name,
//             and its location is that of the item that made it.
// Ownership:  returns values; reads the engine (the explanation may intern environments).
// Knows nothing of what the assumptions stand for, nor of mechanics.
#pragma once
#include "atms/atms.hpp"
#include "engine/engine.hpp"
#include <optional>
#include <string>

namespace qm::engine {

struct RefutingRule {
    std::string rule;        // the rule's name; empty when no rule concluded the nogood
    SourceLocation where;    // the rule's (or the item's) location
};

// nullopt if env is consistent. Pre: env issued by e's ATMS.
[[nodiscard]] std::optional<RefutingRule> refuting_rule(Engine& e, atms::EnvId env);

}  // namespace qm::engine
