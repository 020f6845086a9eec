// engine/predicate_check.hpp
// Provides:   check_predicates(), the checks of a ProgramSpec that follow predicates from where facts
//             come from to where they are used, so that a misspelling cannot silently switch a law
//             off (docs/RULES.md "Checks"):
//               - error: a condition (atom, `not`, quantified or aggregated atom) or an `output` on a
//                 predicate that no rule concludes, no `fact`/`assume` states and no `input` declares
//                 (a driver asserts it), with "did you mean" when a known predicate or builtin test
//                 is near (`open-half-plain` -> `open-half-plane`);
//               - error: an `input`/`output` whose arguments are not all variables;
//               - warning: a rule that can never fire: a condition it needs (an atom, or an atom of
//                 `exists`) is on a predicate whose only sources are rules that can never fire;
//               - warning (only in programs that declare an `output`): an unused rule, one whose
//                 conclusions no used rule reads and no driver reads back (a rule concluding `false`
//                 or declaring a choice set is always used: it shapes the interpretations).
//             Arity mismatches stay with rule_checker.hpp.
// Errors:     only into diagnostics; never throws for bad input.
// Knows nothing of the ATMS or of mechanics.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/rule_spec.hpp"
#include "qm/diagnostics.hpp"

namespace qm::engine {
// Appends the findings; returns true when none of them is an error.
bool check_predicates(const ProgramSpec& spec, Diagnostics& diagnostics,
                      const BuiltinRegistry& builtins = default_builtins());
}  // namespace qm::engine
