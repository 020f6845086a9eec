// support/qm/x3_ascii.hpp
// Provides:   the lexical pieces the project's Boost.Spirit X3 grammars share, spelled in ASCII:
//             blank, letter, digit, name_char (letters, digits, '-', '_'), and kw(), a
//             case-insensitive keyword not followed by a name character.
// Why:        x3::space/alpha/alnum/digit and x3::no_case classify through the C library, which
//             requires a char in 0..UCHAR_MAX (BOOST_ASSERT); a byte >= 0x80 in a signed char is not,
//             so any non-ASCII byte aborted a debug build (and is undefined behaviour in release).
//             These classes compare bytes and accept any input: a non-ASCII byte is simply not a
//             letter, so the reader reports it as a located syntax error.
// Used by:    the readers of Alex scenes, metric scenes and command-line queries (cli/query_text.cpp).
#pragma once
#include "qm/x3_words.hpp"
#include <boost/spirit/home/x3.hpp>
#include <string>

namespace qm::x3_ascii {
namespace x3 = boost::spirit::x3;

inline const auto blank = x3::char_(" \t\n\r\v\f");
inline const auto letter = x3::char_('a', 'z') | x3::char_('A', 'Z');
inline const auto digit = x3::char_('0', '9');
inline const auto name_char = letter | digit | x3::char_('-') | x3::char_('_');

// A case-insensitive keyword, not followed by a name character (ASCII case folding only).
struct keyword_parser : x3::parser<keyword_parser> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    explicit constexpr keyword_parser(const char* w) : word(w) {}
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx& ctx, RCtx&, Attr&) const {
        x3::skip_over(first, last, ctx);
        It it = first;
        for (const char* p = word; *p != '\0'; ++p, ++it) {
            if (it == last) return false;
            const char c = *it;
            if ((c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c) != *p) return false;
        }
        if (it != last) {
            const char c = *it;
            if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')
                return false;
        }
        first = it;
        return true;
    }
    const char* word;  // lower case
};
// Pre: s is lower case and outlives the parser (a literal).
inline keyword_parser kw(const char* s) { return keyword_parser(s); }

}  // namespace qm::x3_ascii

// What an expectation failure on a bare keyword names: the keyword in quotes.
template <>
struct boost::spirit::x3::get_info<qm::x3_ascii::keyword_parser> {
    using result_type = std::string;
    std::string operator()(const qm::x3_ascii::keyword_parser& p) const { return std::string("'") + p.word + "'"; }
};
