// engine/rule_parser_error_handler.cpp: wording and placement of syntax errors.
#include "engine/rule_parser_error_handler.hpp"

#include <cstdio>
#include <vector>

namespace qm::engine::parser {
namespace {

constexpr std::size_t max_token_bytes = 40;

// Bytes outside printable ASCII are shown as \xNN, so a message is always plain text.
std::string printable(std::string_view s) {
    std::string out;
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7f) {
            out += c;
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(u));
            out += buf;
        }
    }
    return out;
}

// The token starting at `at`, for "but found ...".
std::string describe(std::string_view t, std::size_t at, const char* end_of_input) {
    if (at >= t.size()) return end_of_input;
    if (t[at] == '\n') return "the end of the line";
    std::size_t end = at + 1;
    if (t[at] == '(' || t[at] == '[') {  // with the word after it: "found '(p'" says more than "'('"
        while (end < t.size() && is_word_char(t[end])) ++end;
    } else if (t[at] == '"') {
        while (end < t.size() && t[end] != '"' && t[end] != '\n') ++end;
        if (end < t.size() && t[end] == '"') ++end;
    } else if (is_word_char(t[at])) {
        while (end < t.size() && is_word_char(t[end])) ++end;
    }
    std::string_view token = t.substr(at, end - at);
    if (token.size() > max_token_bytes) return "'" + printable(token.substr(0, max_token_bytes)) + "...'";
    return "'" + printable(token) + "'";
}

// The innermost bracket opened in [from, to) and not closed there; npos if none.
std::size_t unclosed_opener(std::string_view t, std::size_t from, std::size_t to) {
    std::vector<std::size_t> open;
    for (std::size_t i = from; i < to && i < t.size(); ++i) {
        const char c = t[i];
        if (c == '#') {
            while (i < to && i < t.size() && t[i] != '\n') ++i;
        } else if (c == '"') {
            for (++i; i < to && i < t.size() && t[i] != '"' && t[i] != '\n';) ++i;
        } else if (c == '(' || c == '[' || c == '{') {
            open.push_back(i);
        } else if ((c == ')' || c == ']' || c == '}') && !open.empty()) {
            open.pop_back();
        }
    }
    return open.empty() ? std::string_view::npos : open.back();
}

char closer_expected(const std::string& expected) {
    for (const char* closer : {"')'", "']'", "'}'"})
        if (expected.size() >= 3 && expected.compare(expected.size() - 3, 3, closer) == 0) return closer[1];
    return 0;
}

bool is_top_keyword(const std::string& found) {
    return found == "'rule'" || found == "'fact'" || found == "'assume'" || found == "'include'" || found == "'input'" ||
           found == "'output'" || found == "'cite'";
}

}  // namespace

std::size_t skip_blanks(std::string_view text, std::size_t offset) noexcept {
    std::size_t i = offset;
    while (i < text.size()) {
        if (is_blank(text[i])) {
            ++i;
        } else if (text[i] == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else {
            break;
        }
    }
    return i;
}

Diagnostic syntax_error(const SourceText& src, std::size_t failure, const std::string& expected,
                        std::size_t item_start, const char* end_of_input) {
    const std::string& t = src.text();
    // Inside a string the failure is at the line end itself; elsewhere the token comes after blanks.
    const std::size_t at = expected == closing_quote_name ? std::min(failure, t.size()) : skip_blanks(t, failure);
    const std::string found = describe(t, at, end_of_input);
    std::size_t shown = at;
    if (at >= t.size()) {  // the end of the file: point just after the last character written
        shown = t.size();
        while (shown > 0 && is_blank(t[shown - 1])) --shown;
    }
    const SourceLocation where = src.locate(shown);
    std::string message = "expected " + expected;
    if (const char closer = closer_expected(expected)) {
        const std::size_t open = unclosed_opener(t, item_start, at);
        const char opener = closer == ')' ? '(' : closer == ']' ? '[' : '{';
        if (open != std::string_view::npos && t[open] == opener) {
            const SourceLocation o = src.locate(open);
            if (o.line != where.line)
                message += " to close the '" + std::string(1, opener) + "' at " + std::to_string(o.line) + ":" +
                           std::to_string(o.column);
        }
    }
    message += " but found " + found;
    if (expected == top_item_name && is_top_keyword(found) && where.column != 1)
        message += " in column " + std::to_string(where.column);
    return make_diagnostic(Severity::error, where, std::move(message), src.line(where.line));
}

}  // namespace qm::engine::parser
