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

// Runs one top-level rule over the whole text (qm/x3_sexpr.hpp). False (after reporting) on any
// syntax error, or on a text of only blanks and comments.
template <class Rule, class Attr>
bool run(const Rule& rule, const std::string& what, const SourceText& src, PositionTable& positions, Diagnostics& diags,
         Attr& out) {
    if (qm::sexpr::skip_blanks(src.text(), 0) == src.text().size()) {
        diags.error(src.locate(0), "empty input: expected " + what);
        return false;
    }
    return x3_parse::parse_sexpr(rule, what, src, positions, diags, parser::punctuation, out);
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
