// engine/rule_parser.cpp: the single translation unit instantiating the X3 grammar of
// rule_parser_def.hpp, and the item loop that resumes after a syntax error.
#include "engine/rule_parser.hpp"

#include "engine/rule_parser_def.hpp"

#include <cstring>

namespace qm::engine {
namespace {

using parser::Iterator;
namespace x3 = boost::spirit::x3;

// Does the line starting at `at` begin with a top-level keyword (a whole word in column 1)?
bool starts_item(const std::string& t, std::size_t at) {
    for (const char* k : {"rule", "fact", "assume", "include", "input", "output", "cite", "prefer"}) {
        const std::size_t n = std::strlen(k);
        if (t.compare(at, n, k) == 0 && (at + n == t.size() || !parser::is_word_char(t[at + n]))) return true;
    }
    return false;
}

// The first line start at or after `from` that begins a top-level item, or the end of the text.
// Comments and strings never span lines, so a line start is never inside one.
std::size_t next_item(const std::string& t, std::size_t from) {
    std::size_t i = from;
    while (i < t.size()) {
        if ((i == 0 || t[i - 1] == '\n') && starts_item(t, i)) return i;
        i = t.find('\n', i);
        if (i == std::string::npos) return t.size();
        ++i;
    }
    return t.size();
}

bool too_large(const SourceText& src, Diagnostics& diagnostics) {
    if (src.text().size() < max_rule_text_bytes) return false;
    diagnostics.error(src.locate(0), "the text is too large: " + std::to_string(src.text().size()) +
                                         " bytes, at most " + std::to_string(max_rule_text_bytes - 1) + " are read");
    return true;
}

}  // namespace

std::vector<ast::Item> parse_rule_items(const SourceText& src, const BuiltinRegistry& builtins,
                                        Diagnostics& diagnostics) {
    std::vector<ast::Item> items;
    if (too_large(src, diagnostics)) return items;
    const std::string& t = src.text();
    parser::ParseState st;
    st.begin = t.begin();
    st.builtins = &builtins;
    const auto entry = x3::with<parser::state_tag>(st)[parser::item_entry];
    std::size_t at = parser::skip_blanks(t, 0);
    while (at < t.size()) {
        st.failed = false;
        st.depth = 0;
        Iterator first = t.begin() + static_cast<std::ptrdiff_t>(at);
        ast::Item item;
        if (x3::phrase_parse(first, t.end(), entry, parser::skipper, item)) {
            items.push_back(std::move(item));
            at = parser::skip_blanks(t, static_cast<std::size_t>(first - t.begin()));
            continue;
        }
        if (!st.failed) {  // item_entry is an expectation, so this is not expected to happen
            st.failure = at;
            st.expected = parser::top_item_name;
        }
        diagnostics.add(parser::syntax_error(src, st.failure, st.expected, at));
        // Resume at the next item; an error found at an item's keyword resumes right there.
        at = next_item(t, std::max(parser::skip_blanks(t, st.failure), at + 1));
    }
    return items;
}

std::optional<ast::Atom> parse_rule_atom(const SourceText& src, const BuiltinRegistry& builtins,
                                         Diagnostics& diagnostics) {
    if (too_large(src, diagnostics)) return std::nullopt;
    const std::string& t = src.text();
    parser::ParseState st;
    st.begin = t.begin();
    st.builtins = &builtins;
    Iterator first = t.begin();
    ast::Atom atom;
    if (x3::phrase_parse(first, t.end(), x3::with<parser::state_tag>(st)[parser::atom_entry], parser::skipper, atom))
        return atom;
    if (!st.failed) {
        st.failure = 0;
        st.expected = "an atom like (p ?x)";
    }
    diagnostics.add(parser::syntax_error(src, st.failure, st.expected, 0, "the end of the text"));
    return std::nullopt;
}

}  // namespace qm::engine
