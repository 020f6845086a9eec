// engine/stratify_rules.hpp
// Provides:   stratify_rules(), which assigns each compiled rule the stratum it runs in: a rule runs
//             no earlier than the predicates it uses positively, and strictly after the predicates it
//             uses under `not` or aggregates (so those are complete when it runs). Returns the number
//             of strata. A program that cannot be stratified gets one located error per rule whose
//             `not` or aggregate depends on the rule's own conclusions, naming the predicates and rules
//             of the cycle (docs/RULES.md, "unstratifiable").
// Knows nothing of the ATMS.
#pragma once
#include "engine/compiled_rule.hpp"
#include "engine/value_table.hpp"
#include "qm/diagnostics.hpp"

namespace qm::engine {
// Sets CompiledRule::stratum for every rule. Reports a located error (at the `not` or aggregate) per
// rule whose negation or aggregate depends on its own conclusions. Returns max stratum + 1 (>= 1).
std::uint32_t stratify_rules(CompiledProgram& program, const ValueTable& values, Diagnostics& diagnostics);
}  // namespace qm::engine
