// engine/rule_checker.hpp
// Provides:   check_program(), the semantic checks of a read ProgramSpec that the compiler
//             (rule_compiler.cpp: unknown builtins, builtin arity, unbound variables, ground facts)
//             and stratify_rules.cpp (negation/aggregation through recursion) do not make:
//               - a predicate used with different numbers of arguments (facts, assumptions,
//                 conditions, negations, quantified and aggregated atoms, consequents): every use
//                 after the first with another arity is an error that names the first use;
//               - two rules with the same name (explanations and `why` name rules, so a duplicate
//                 would make them ambiguous): the second is an error naming the first.
//             Each finding is a located error in diagnostics; several are reported in one run.
// Errors:     only into diagnostics; never throws for bad input.
// Knows nothing of the ATMS.
#pragma once
#include "engine/rule_spec.hpp"
#include "qm/diagnostics.hpp"

namespace qm::engine {
// Appends one error per finding; returns true when spec passed every check.
bool check_program(const ProgramSpec& spec, Diagnostics& diagnostics);
}  // namespace qm::engine
