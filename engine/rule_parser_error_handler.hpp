// engine/rule_parser_error_handler.hpp
// Provides:   the per-parse state the X3 grammar reads through x3::with<state_tag> (ParseState), the
//             on_error handler of the grammar's entry rules (it records the first expectation failure
//             of an item and makes the rule fail, so no exception leaves a parse), the on_success
//             handler that stores each node's start offset (annotate_offset), and syntax_error(), which
//             turns a recorded failure into the diagnostic `expected WHAT but found TOKEN` with the
//             source line.
// Ownership:  ParseState points into the caller's SourceText and BuiltinRegistry for one parse.
// Knows nothing of the ATMS. Included by rule_parser_def.hpp and rule_parser.cpp only.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/rule_parser_source.hpp"
#include "qm/diagnostics.hpp"
#include <boost/spirit/home/x3.hpp>
#include <boost/spirit/home/x3/support/ast/position_tagged.hpp>
#include <string>
#include <string_view>
#include <type_traits>

namespace qm::engine::parser {
namespace x3 = boost::spirit::x3;
using Iterator = std::string::const_iterator;

struct ParseState {
    Iterator begin;                              // start of the whole text (offsets count from here)
    const BuiltinRegistry* builtins = nullptr;
    int depth = 0;                               // calls and sets currently open
    bool failed = false;                         // an expectation failed in the current item
    std::size_t failure = 0;                     // where (offset, before blanks are skipped)
    std::string expected;                        // the name of what was expected there
};
struct state_tag;

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

// Records where each position_tagged node starts: the offset after leading blanks and comments.
struct annotate_offset {
    template <class It, class Attr, class Ctx>
    void on_success(const It& first, const It& last, Attr& node, const Ctx& ctx) const {
        if constexpr (std::is_base_of_v<x3::position_tagged, Attr>) {
            It f = first;
            x3::skip_over(f, last, ctx);
            node.id_first = static_cast<int>(f - x3::get<state_tag>(ctx).begin);
        }
    }
};

// The first expectation failure of an item is recorded; the entry rule then fails.
struct record_failure {
    template <class It, class Exception, class Ctx>
    x3::error_handler_result on_error(It&, const It&, const Exception& x, const Ctx& ctx) const {
        ParseState& st = x3::get<state_tag>(ctx);
        if (!st.failed) {
            st.failed = true;
            st.failure = static_cast<std::size_t>(x.where() - st.begin);
            st.expected = x.which();
        }
        return x3::error_handler_result::fail;
    }
};

// Names of expectations that fail inside a token (no blanks may be skipped before "found").
inline constexpr const char* closing_quote_name = "a closing '\"' on the same line";
inline constexpr const char* top_item_name = "'rule', 'fact', 'assume' or 'include' at the start of a line";

// The diagnostic for a failure at `failure` (an offset in src) where `expected` was expected, in the
// item that starts at `item_start`: `expected EXPECTED but found TOKEN`, located at the token (at the
// end of the last line for the end of the file), with the source line. When a closing bracket was
// expected and the bracket it would close opened on an earlier line, the message says where.
// `end_of_input` names the end of src in "but found ..." ("the end of the file" for rule files).
[[nodiscard]] Diagnostic syntax_error(const SourceText& src, std::size_t failure, const std::string& expected,
                                      std::size_t item_start, const char* end_of_input = "the end of the file");

}  // namespace qm::engine::parser
