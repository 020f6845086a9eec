// scene/scene_parser.cpp: the single translation unit instantiating the X3 grammar of
// scene_parser_def.hpp, plus the entry points of scene/scene_parser.hpp.
#include "scene/scene_parser.hpp"

#include "scene/scene_checker.hpp"
#include "scene/scene_parser_def.hpp"

#include "qm/sexpr_text.hpp"
#include <fstream>
#include <sstream>

namespace qm::scene {
namespace {

// Runs one top-level rule over the whole text. False (after reporting) on any syntax error.
template <class Rule, class Attr>
bool run(const Rule& rule, const std::string& what, const SourceText& src, PositionTable& positions, Diagnostics& diags,
         Attr& out) {
    const std::string& t = src.text();
    if (parser::skip_blanks(t, 0) == t.size()) {
        diags.error(src.locate(0), "empty input: expected " + what);
        return false;
    }
    if (!qm::sexpr::check_parentheses(src, diags)) return false;
    parser::ParseState st{t.begin(), &positions, &diags, &src, false};
    auto first = t.begin();
    bool ok = false;
    try {
        ok = boost::spirit::x3::phrase_parse(first, t.end(), boost::spirit::x3::with<parser::state_tag>(st)[rule],
                                             parser::skipper, out);
    } catch (const boost::spirit::x3::expectation_failure<parser::Iterator>& x) {
        // Only reachable if a failure escapes the top rule's handler; report it the same way.
        if (!st.failed) parser::report_expected(st, x.where(), x.which());
        st.failed = true;
    }
    if (!ok && !st.failed) parser::report_expected(st, first, what);
    return ok && !st.failed;
}

std::string slurp(std::ifstream& in) {
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

std::optional<ParsedScene> parse_scene_ast(const SourceText& src, Diagnostics& diags) {
    ParsedScene out;
    if (!run(parser::scene_file, "a scene ('(Defscenario ...)' or a 'Name Dimensions' header)", src, out.positions,
             diags, out.scenario))
        return std::nullopt;
    return out;
}

std::optional<Scene> read_scene(std::string file, std::string text, Diagnostics& diags) {
    const SourceText src(std::move(file), std::move(text));
    auto parsed = parse_scene_ast(src, diags);
    if (!parsed) return std::nullopt;
    return check_scene(parsed->scenario, parsed->positions, src, diags);
}

std::optional<Scene> read_scene_file(const std::string& path, Diagnostics& diags) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diags.error({path, 1, 1}, "cannot read scene file '" + path + "'");
        return std::nullopt;
    }
    return read_scene(path, slurp(in), diags);
}

std::optional<Motion> parse_given(const Scene& scene, std::string_view text, Diagnostics& diags, std::string origin) {
    const SourceText src(std::move(origin), std::string(text));
    PositionTable positions;
    ast::MotionEntry given;
    if (!run(parser::given, "a motion like 'pallet (0 0) (+)'", src, positions, diags, given)) return std::nullopt;
    return check_given(given, scene, positions, src, diags);
}

std::optional<QueryFact> parse_query_fact(const Scene& scene, std::string_view text, Diagnostics& diags,
                                          std::string origin) {
    const SourceText src(std::move(origin), std::string(text));
    PositionTable positions;
    ast::QueryFact fact;
    if (!run(parser::query, "a fact like 'Rotational-Motion (follower (-))'", src, positions, diags, fact))
        return std::nullopt;
    return check_query(fact, scene, positions, src, diags);
}

}  // namespace qm::scene
