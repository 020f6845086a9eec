// engine/rule_parser.hpp
// Provides:   the Spirit X3 parser of the rule language (grammar in rule_parser_def.hpp, reference in
//             docs/RULES.md): parse_rule_items() reads the top-level items of one file into the AST of
//             rule_parser_ast.hpp; parse_rule_atom() reads a single atom, as `qm-atms run --why` takes.
//             Includes are not followed here (rule_spec_reader.hpp does that).
// Ownership:  results are values owned by the caller; nothing refers back to the SourceText.
// Errors:     bad input never throws. Each syntax error becomes one located diagnostic
//             `expected ... but found ...` carrying its source line (for the caret); parsing then
//             resumes at the next top-level item (a line starting with `rule`, `fact`, `assume` or
//             `include` in column 1), so one call reports the first error of every bad item.
// Limits:     calls and sets nest at most max_term_nesting deep (deeper is a syntax error, not a stack
//             overflow); a text must be shorter than max_rule_text_bytes (positions are ints in X3).
// Knows nothing of the ATMS. The grammar is instantiated once, in rule_parser.cpp.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/rule_parser_ast.hpp"
#include "engine/rule_parser_source.hpp"
#include "qm/diagnostics.hpp"
#include <cstddef>
#include <optional>
#include <vector>

namespace qm::engine {

inline constexpr int max_term_nesting = 64;
inline constexpr std::size_t max_rule_text_bytes = std::size_t{1} << 26;  // 64 MiB

// `builtins` decides which parenthesised conditions are tests, e.g. `(< ?x 3)`, rather than atoms.
[[nodiscard]] std::vector<ast::Item> parse_rule_items(const SourceText& src, const BuiltinRegistry& builtins,
                                                      Diagnostics& diagnostics);

// The whole of src must be one atom, e.g. `(trans-motion block (+ 0))`; empty (with one diagnostic)
// otherwise.
[[nodiscard]] std::optional<ast::Atom> parse_rule_atom(const SourceText& src, const BuiltinRegistry& builtins,
                                                       Diagnostics& diagnostics);

}  // namespace qm::engine
