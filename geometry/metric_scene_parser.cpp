// geometry/metric_scene_parser.cpp: the single translation unit instantiating the X3 grammar of
// metric_scene_parser_def.hpp, and the entry points of metric_scene_parser.hpp.
#include "geometry/metric_scene_parser.hpp"

#include "geometry/metric_scene_checker.hpp"
#include "geometry/metric_scene_parser_def.hpp"

#include "qm/sexpr_text.hpp"
#include <fstream>
#include <sstream>

namespace qm::geometry {
namespace {

// Runs one top-level rule over the whole text (qm/x3_sexpr.hpp). False (after reporting) on any
// syntax error, or, unless allow_empty, on a text of only blanks and comments.
template <class Rule, class Attr>
bool run(const Rule& rule, const std::string& what, const MetricSource& src, MetricPositions& positions, Diagnostics& diags, Attr& out,
         bool allow_empty) {
    if (!allow_empty && qm::sexpr::skip_blanks(src.text(), 0) == src.text().size()) {
        src.error(diags, 0, "empty input: expected " + what);
        return false;
    }
    return x3_parse::parse_sexpr(rule, what, src, positions, diags, mparser::punctuation, out);
}

}  // namespace

std::optional<ParsedMechanism> parse_mechanism_ast(const MetricSource& src, Diagnostics& diags) {
    ParsedMechanism out;
    if (!run(mparser::mechanism_file, "a metric scene '(Defmechanism name ...)'", src, out.positions, diags, out.file, false))
        return std::nullopt;
    return out;
}

std::optional<Mechanism> read_mechanism(std::string file, std::string text, Diagnostics& diags) {
    const MetricSource src(std::move(file), std::move(text));
    auto parsed = parse_mechanism_ast(src, diags);
    if (!parsed) return std::nullopt;
    return check_mechanism(parsed->file, parsed->positions, src, diags);
}

std::optional<Mechanism> read_mechanism_file(const std::string& path, Diagnostics& diags) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diags.error({path, 1, 1}, "cannot read metric scene file '" + path + "'");
        return std::nullopt;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    return read_mechanism(path, ss.str(), diags);
}

std::optional<Configuration> parse_configuration(const Mechanism& m, std::string_view text, Diagnostics& diags, std::string origin) {
    const MetricSource src(std::move(origin), std::string(text));
    MetricPositions positions;
    std::vector<mast::ConfigEntry> entries;
    if (!run(mparser::config, "a configuration like 'wheel=10, pallets=-3'", src, positions, diags, entries, true)) return std::nullopt;
    return check_configuration(entries, m, positions, src, diags);
}

}  // namespace qm::geometry
