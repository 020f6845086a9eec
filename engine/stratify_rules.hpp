// engine/stratify_rules.hpp
// Provides:   stratify_rules(), which assigns each compiled rule the stratum it runs in: a rule runs
//             no earlier than the predicates it uses positively, and strictly after the predicates it
//             uses under `not` or aggregates (so those are complete when it runs). Returns the number
//             of strata. (The front end's checker reports unstratifiable programs with the cycle;
//             this pass only orders rules for the runtime, and reports a cycle itself if it meets one.)
// Knows nothing of the ATMS.
#pragma once
#include "engine/compiled_rule.hpp"
#include "engine/value_table.hpp"
#include "qm/diagnostics.hpp"

namespace qm::engine {
// Sets CompiledRule::stratum for every rule. Reports a located error per rule whose negation or
// aggregate depends on its own conclusions. Returns max stratum + 1 (at least 1).
std::uint32_t stratify_rules(CompiledProgram& program, const ValueTable& values, Diagnostics& diagnostics);
}  // namespace qm::engine
