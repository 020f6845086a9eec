// support/qm/sexpr_text.hpp
// Provides:   the text helpers of the project's s-expression readers (Alex scenes, metric scenes),
//             all about `;`-commented text: skip_blanks (blanks and comments from an offset),
//             token_at (the token at an offset, quoted, for "but found ..."), and
//             check_parentheses (reports a `)` that closes nothing, or the innermost `(` left open,
//             before the grammar runs, so that the message is about the parenthesis itself rather
//             than a confusing "expected ..." further on).
// Ownership:  pure functions.
#pragma once
#include "qm/diagnostics.hpp"
#include "qm/source_text.hpp"
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace qm::sexpr {

// Skips blanks and `;` comments (to the end of the line) from offset i.
inline std::size_t skip_blanks(const std::string& t, std::size_t i) {
    while (i < t.size()) {
        if (std::isspace(static_cast<unsigned char>(t[i]))) {
            ++i;
        } else if (t[i] == ';') {
            while (i < t.size() && t[i] != '\n') ++i;
        } else {
            break;
        }
    }
    return i;
}

// The token starting at offset i, quoted, for "but found ..." (or "end of input"). A character of
// `punctuation` is a token of its own; a token ends at a blank, punctuation or `;`; unprintable
// bytes are shown as `?`.
inline std::string token_at(const std::string& t, std::size_t i, std::string_view punctuation) {
    if (i >= t.size()) return "end of input";
    if (punctuation.find(t[i]) != std::string_view::npos) return std::string("'") + t[i] + "'";
    std::size_t e = i;
    while (e < t.size() && e - i < 40 && !std::isspace(static_cast<unsigned char>(t[e])) &&
           punctuation.find(t[e]) == std::string_view::npos && t[e] != ';')
        ++e;
    std::string tok = t.substr(i, e - i);
    for (char& c : tok)
        if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    return "'" + tok + "'";
}

// True when every `(` outside comments is closed; else reports the first `)` that closes nothing
// and the innermost `(` left open, and returns false.
inline bool check_parentheses(const SourceText& src, Diagnostics& diags) {
    const std::string& t = src.text();
    std::vector<std::size_t> open;
    bool ok = true;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] == ';') {
            while (i < t.size() && t[i] != '\n') ++i;
        } else if (t[i] == '(') {
            open.push_back(i);
        } else if (t[i] == ')') {
            if (open.empty()) {
                src.error(diags, i, "unbalanced parentheses: this ')' closes nothing");
                ok = false;
            } else {
                open.pop_back();
            }
        }
    }
    if (!open.empty()) {
        src.error(diags, open.back(),
                  "unbalanced parentheses: this '(' is never closed (" + std::to_string(open.size()) + " unclosed in all)");
        ok = false;
    }
    return ok;
}

}  // namespace qm::sexpr
