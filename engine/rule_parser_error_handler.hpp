// engine/rule_parser_error_handler.hpp
// Provides:   the per-parse state the X3 grammar reads through x3::with<state_tag> (ParseState; the
//             handlers of qm/x3_parse.hpp: `annotate` stores each node's start offset in its tag,
//             `first_failure` records the first expectation failure of an item and makes the rule
//             fail, so no exception leaves a parse), and syntax_error(), which turns a recorded
//             failure into the diagnostic `expected WHAT but found TOKEN` with the source line.
// Ownership:  ParseState points into the caller's SourceText and BuiltinRegistry for one parse.
// Knows nothing of the ATMS. Included by rule_parser_def.hpp and rule_parser.cpp only.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/rule_parser_source.hpp"
#include "qm/diagnostics.hpp"
#include "qm/x3_parse.hpp"
#include <boost/spirit/home/x3.hpp>
#include <string>
#include <string_view>
#include <type_traits>

namespace qm::engine::parser {
namespace x3 = boost::spirit::x3;
using x3_parse::Iterator;
using x3_parse::annotate;
using x3_parse::first_failure;
using x3_parse::state_tag;

struct ParseState {
    Iterator begin;                              // start of the whole text (offsets count from here)
    const BuiltinRegistry* builtins = nullptr;
    int depth = 0;                               // calls and sets currently open
    bool failed = false;                         // an expectation failed in the current item
    std::size_t failure = 0;                     // where (offset, before blanks are skipped)
    std::string expected;                        // the name of what was expected there

    // A node's tag is its start offset (the rule reader needs no position table).
    [[nodiscard]] int position_id(std::size_t offset) const noexcept { return static_cast<int>(offset); }
    void expectation_failed(Iterator where, const std::string& what) {
        failure = static_cast<std::size_t>(where - begin);
        expected = what;
    }
};

// The lexical classes of docs/RULES.md, spelled out (no locale): blanks, and the characters that
// may appear in a word (anything but blanks, punctuation, '#' and '"').
[[nodiscard]] constexpr bool is_blank(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}
[[nodiscard]] constexpr bool is_word_char(char c) noexcept {
    return !is_blank(c) && std::string_view("()[]{}:#\"").find(c) == std::string_view::npos;
}
// The offset of the first character at or after `offset` that is neither blank nor in a comment.
[[nodiscard]] std::size_t skip_blanks(std::string_view text, std::size_t offset) noexcept;

// Names of expectations that fail inside a token (no blanks may be skipped before "found").
inline constexpr const char* closing_quote_name = "a closing '\"' on the same line";
inline constexpr const char* top_item_name =
    "'rule', 'fact', 'assume', 'include', 'input', 'output', 'cite' or 'prefer' at the start of a line";

// The diagnostic for a failure at `failure` (an offset in src) where `expected` was expected, in the
// item that starts at `item_start`: `expected EXPECTED but found TOKEN`, located at the token (at the
// end of the last line for the end of the file), with the source line. When a closing bracket was
// expected and the bracket it would close opened on an earlier line, the message says where.
// `end_of_input` names the end of src in "but found ..." ("the end of the file" for rule files).
[[nodiscard]] Diagnostic syntax_error(const SourceText& src, std::size_t failure, const std::string& expected,
                                      std::size_t item_start, const char* end_of_input = "the end of the file");

}  // namespace qm::engine::parser
