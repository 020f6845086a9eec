// engine/rule_printer.hpp
// Provides:   print_program(), the inverse of the rule reader: ProgramSpec -> rule-language text
//             (citations, inputs, outputs, facts, assumptions, then rules, each in spec order), and print_term() /
//             print_atom() for single pieces. Reading the printed text back gives the same spec
//             up to source locations (tests/engine/rule_printer_test.cpp checks this on every bundled
//             file and on seeded random specs), which is what the reader-equivalence checks rely on.
// Layout:     top-level items start in column 1; a rule's `when` and `then` lines are indented by two
//             spaces, as docs/RULES.md requires for the column-1 rule that separates items.
// Limits:     the spec must be one the language can express: names start with a letter, a direction
//             has at least one sign, a predicate is not a builtin test name. print_program() does not
//             check this (such specs come only from code, never from a file).
// Knows nothing of the ATMS.
#pragma once
#include "engine/rule_spec.hpp"
#include <string>

namespace qm::engine {
[[nodiscard]] std::string print_term(const TermSpec& term);
[[nodiscard]] std::string print_atom(const AtomSpec& atom);
[[nodiscard]] std::string print_program(const ProgramSpec& spec);
}  // namespace qm::engine
