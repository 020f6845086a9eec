// engine/consistency.hpp
// Provides:   Refutations, whether an environment (a set of assumptions) is consistent with a
//             program's laws and, if not, which rule refutes it: the `false` that derives a nogood
//             within it. A driver that must tell many times whether some combination of its
//             hypotheses can hold (the envisioner: an object's situation in a step and its motion
//             after, rules/clock/settling.rules) reads the answers once, for every combination, and
//             looks them up.
// Semantics:  env is refuted iff some nogood of the engine's ATMS is a subset of it. Its refuting
//             rule is that of the least (by EnvId) minimal nogood within env: the rule of a
//             justification of the contradiction whose antecedents each hold in that nogood (some
//             label environment is a subset of it), the first such in the contradiction's list; a
//             nogood no such justification derives (a choice set's exclusion, the closed world of a
//             context) is cited by the last step of the ATMS's explanation of it. A firing that is
//             no rule's has an empty rule name and the location of the item that made it.
// Ownership:  holds a reference to the engine, which must outlive it; remembers the rule of each
//             nogood it has cited (an explanation costs a walk over the justifications).
// Knows nothing of what the assumptions stand for, nor of mechanics.
#pragma once
#include "atms/atms.hpp"
#include "engine/engine.hpp"
#include <map>
#include <optional>
#include <string>

namespace qm::engine {

struct RefutingRule {
    std::string rule;        // the rule's name; empty when no rule concluded the nogood
    SourceLocation where;    // the rule's (or the item's) location
};

class Refutations {
public:
    explicit Refutations(Engine& e) : e_(e) {}
    // nullopt if env is consistent. Pre: env issued by the engine's ATMS.
    [[nodiscard]] std::optional<RefutingRule> of(atms::EnvId env);

private:
    [[nodiscard]] RefutingRule cite(const Firing& f) const;
    Engine& e_;
    std::map<atms::EnvId, RefutingRule> by_nogood_;
};

}  // namespace qm::engine
