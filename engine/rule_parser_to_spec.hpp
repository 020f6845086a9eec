// engine/rule_parser_to_spec.hpp
// Provides:   the step from the parser's AST (rule_parser_ast.hpp) to the parser-independent
//             ProgramSpec (rule_spec.hpp) that the checker and the compiler read: names stay text,
//             variables stay names, and every node's offset becomes a SourceLocation in `src`.
//             `include` items are not converted here: rule_spec_reader.hpp follows them.
// Ownership:  returns values; `src` must be the text the AST was parsed from.
// Knows nothing of the ATMS or of the builtins (the parser already told tests from atoms).
#pragma once
#include "engine/rule_parser_ast.hpp"
#include "engine/rule_parser_source.hpp"
#include "engine/rule_spec.hpp"

namespace qm::engine {
[[nodiscard]] TermSpec to_term_spec(const ast::Term& term, const SourceText& src);
[[nodiscard]] AtomSpec to_atom_spec(const ast::Atom& atom, const SourceText& src);
[[nodiscard]] RuleSpec to_rule_spec(const ast::Rule& rule, const SourceText& src);
// Appends a `fact`, `assume` or `rule` item to spec. Pre: item is not an `include`.
void add_item_to_spec(const ast::Item& item, const SourceText& src, ProgramSpec& spec);
}  // namespace qm::engine
