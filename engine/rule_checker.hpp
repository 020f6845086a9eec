// engine/rule_checker.hpp
// Provides:   check_program(), the semantic checks of a read ProgramSpec that the compiler
//             (rule_compiler.cpp: unknown builtins, builtin arity, unbound variables, ground facts)
//             and stratify_rules.cpp (negation/aggregation through recursion) do not make:
//               - a predicate used with different numbers of arguments (facts, assumptions,
//                 conditions, negations, quantified and aggregated atoms, consequents): every use
//                 after the first with another arity is an error that names the first use;
//               - two rules with the same name (explanations and `why` name rules, so a duplicate
//                 would make them ambiguous): the second is an error naming the first;
//               - an atom whose predicate is a builtin test (`fact (< 1 2)`, `not (< ?x 3)`, a test
//                 among the atoms of a quantifier): in a condition `(< ...)` is always the test, so
//                 no fact of such a predicate could ever be matched.
//               - a `prefer` whose chosen atom is not distinct variables, whose rank atom is not
//                 those variables and exactly one more (the rank), or a second `prefer` of one
//                 predicate (docs/RULES.md "Preferences"); a warning where no `exactly one`
//                 assumes the chosen predicate (the preference chooses nothing);
//             (Where facts come from, unknown predicates and rules that never fire are
//             predicate_check.hpp's, which load_rule_files() (rule_folder.hpp) runs after these.)
//             Each finding is a located error in diagnostics; several are reported in one run.
// Errors:     only into diagnostics; never throws for bad input.
// Knows nothing of the ATMS.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/rule_spec.hpp"
#include "qm/diagnostics.hpp"

namespace qm::engine {
// Appends one error per finding; returns true when spec passed every check.
bool check_program(const ProgramSpec& spec, Diagnostics& diagnostics,
                   const BuiltinRegistry& builtins = default_builtins());
}  // namespace qm::engine
