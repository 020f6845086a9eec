// engine/firing.hpp
// Provides:   Firing, the record of one rule firing (or one top-level `fact`/`assume`, or one
//             closed-world bookkeeping step): what the ATMS knows only as an InformantId. The engine
//             keeps one Firing per InformantId, so explanations can name the rule, its file:line and
//             the binding of the firing.
// Ownership:  stored by the Engine, indexed by InformantId; never removed. `where` points into the
//             engine's program (a rule's or a program item's location) or into the engine's own
//             list of the locations given with facts: valid for the engine's lifetime (a firing is
//             made for every rule firing, and copying the rule file's name into each was a heap
//             block apiece).
// Knows nothing of the ATMS's internals: the informant id is the index.
#pragma once
#include "engine/binding.hpp"
#include "engine/compiled_rule.hpp"
#include <optional>
#include <string>

namespace qm::engine {
struct Firing {
    enum class Kind : std::uint8_t {
        rule,          // a rule firing; rule and binding are set
        premise,       // a `fact` item or Engine::add_premise
        assumption,    // an `assume` item or Engine::add_assumption
        closed_world   // a nogood {closed-world of C, X} for an assumption X outside C (docs/RULES.md)
    } kind = Kind::rule;
    std::optional<RuleId> rule;
    Binding binding;
    std::optional<std::uint32_t> context;  // the context of a non-monotonic rule's firing
    const SourceLocation* where = nullptr;  // the rule's (or the item's) location; never null once recorded
};
}  // namespace qm::engine
