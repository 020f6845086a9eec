// support/qm/x3_sexpr.hpp
// Provides:   what the two s-expression readers (Alex scenes, scene/scene_parser*; metric scenes,
//             geometry/metric_scene_parser*) share on top of qm/x3_parse.hpp:
//             - skipper: blanks and `;` comments to the end of the line;
//             - SexprParseState: the per-parse state, which reports the first expectation failure
//               as `expected WHAT but found TOKEN` located at the token, with its source line;
//             - parse_sexpr(): one top-level rule over a whole text, after the parenthesis check
//               (qm/sexpr_text.hpp); false, after reporting, on any syntax error.
// Ownership:  a SexprParseState points into the caller's text, positions and diagnostics for one parse.
#pragma once
#include "qm/diagnostics.hpp"
#include "qm/sexpr_text.hpp"
#include "qm/source_text.hpp"
#include "qm/x3_ascii.hpp"
#include "qm/x3_parse.hpp"
#include <string>
#include <string_view>

namespace qm::x3_parse {

inline const auto sexpr_skipper = x3_ascii::blank | x3::lexeme[';' >> *(x3::char_ - x3::eol) >> (x3::eol | x3::eoi)];

struct SexprParseState {
    Iterator begin;
    PositionTable* positions = nullptr;
    Diagnostics* diags = nullptr;
    const SourceText* src = nullptr;
    std::string_view punctuation;  // characters that are tokens of their own, for "but found ..."
    bool failed = false;

    int position_id(std::size_t offset) { return positions->add(offset); }
    void expectation_failed(Iterator where, const std::string& what) const {
        const std::string& t = src->text();
        const std::size_t at = sexpr::skip_blanks(t, static_cast<std::size_t>(where - begin));
        src->error(*diags, at, "expected " + what + " but found " + sexpr::token_at(t, at, punctuation));
    }
};

// Runs `rule` over the whole text of src. `what` names the rule for a failure no expectation
// reported. Pre: `punctuation` outlives the call.
template <class Rule, class Attr>
bool parse_sexpr(const Rule& rule, const std::string& what, const SourceText& src, PositionTable& positions,
                 Diagnostics& diags, std::string_view punctuation, Attr& out) {
    if (!sexpr::check_parentheses(src, diags)) return false;
    const std::string& t = src.text();
    SexprParseState st{t.begin(), &positions, &diags, &src, punctuation, false};
    auto first = t.begin();
    bool ok = false;
    try {
        ok = x3::phrase_parse(first, t.end(), x3::with<state_tag>(st)[rule], sexpr_skipper, out);
    } catch (const x3::expectation_failure<Iterator>& x) {
        // Only reachable if a failure escapes the top rule's handler; report it the same way.
        if (!st.failed) st.expectation_failed(x.where(), x.which());
        st.failed = true;
    }
    if (!ok && !st.failed) st.expectation_failed(first, what);
    return ok && !st.failed;
}

}  // namespace qm::x3_parse
