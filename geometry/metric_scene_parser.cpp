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

template <class Rule, class Attr>
bool run(const Rule& rule, const std::string& what, const MetricSource& src, MetricPositions& positions, Diagnostics& diags, Attr& out,
         bool allow_empty) {
    const std::string& t = src.text();
    if (!allow_empty && mparser::skip_blanks(t, 0) == t.size()) {
        src.error(diags, 0, "empty input: expected " + what);
        return false;
    }
    if (!qm::sexpr::check_parentheses(src, diags)) return false;
    mparser::ParseState st{t.begin(), &positions, &diags, &src, false};
    auto first = t.begin();
    bool ok = false;
    try {
        ok = boost::spirit::x3::phrase_parse(first, t.end(), boost::spirit::x3::with<mparser::state_tag>(st)[rule], mparser::skipper, out);
    } catch (const boost::spirit::x3::expectation_failure<mparser::Iterator>& x) {
        if (!st.failed) mparser::report_expected(st, x.where(), x.which());
        st.failed = true;
    }
    if (!ok && !st.failed) mparser::report_expected(st, first, what);
    return ok && !st.failed;
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
