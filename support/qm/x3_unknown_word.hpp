// support/qm/x3_unknown_word.hpp
// Provides:   unknown_word(), the X3 parser a grammar puts last among the alternatives of a keyword
//             position (qm/keyword_slot.hpp). Where the text holds a word none of the alternatives
//             took, it reports unknown_word_message() at the word and fails; the expectation that
//             then fails adds nothing, as the state is marked failed (qm/x3_sexpr.hpp). Where the
//             text holds no word, it fails silently, and the enclosing expectation's own
//             `expected ... but found ...` stands.
// Contract:   the state (x3::with<state_tag>) is a SexprParseState; the slot outlives every parse.
#pragma once
#include "qm/keyword_slot.hpp"
#include "qm/x3_sexpr.hpp"
#include <boost/spirit/home/x3.hpp>
#include <string>

namespace qm::x3_parse {

struct unknown_word_parser : x3::parser<unknown_word_parser> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    const KeywordSlot* slot;
    bool heads_list;  // the keyword follows a '(' (it names an item), rather than standing alone

    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx& ctx, RCtx&, Attr&) const {
        It i = first;
        x3::skip_over(i, last, ctx);
        if (heads_list) {
            if (i == last || *i != '(') return false;
            ++i;
            x3::skip_over(i, last, ctx);
        }
        auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
        if (i == last || !letter(*i)) return false;
        const It start = i;
        while (i != last && (letter(*i) || (*i >= '0' && *i <= '9') || *i == '-' || *i == '_')) ++i;
        auto& st = x3::get<state_tag>(ctx);
        if (!st.failed) st.src->error(*st.diags, static_cast<std::size_t>(start - st.begin), unknown_word_message(*slot, std::string(start, i)));
        st.failed = true;
        return false;
    }
};

// heads_list: the keyword follows a '(', as the name of an item; else it stands alone.
inline unknown_word_parser unknown_word(const KeywordSlot& slot, bool heads_list) { return {{}, &slot, heads_list}; }

}  // namespace qm::x3_parse

// Never named by an expectation (it is always inside a rule), but described all the same.
template <>
struct boost::spirit::x3::get_info<qm::x3_parse::unknown_word_parser> {
    using result_type = std::string;
    std::string operator()(const qm::x3_parse::unknown_word_parser& p) const { return p.slot->what; }
};
