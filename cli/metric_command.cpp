// cli/metric_command.cpp: metric scenes at the command line: the Alex scene at a configuration
// (built by bridge/scene_at_config, printed here) and the place vocabularies of the pairs.
#include "metric_command.hpp"
#include "command_options.hpp"
#include "geometry_usage.hpp"

#include "bridge/pair_places.hpp"

#include "bridge/scene_at_config.hpp"
#include "scene/scene_printer.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_cache.hpp"
#include "geometry/place_json.hpp"
#include "geometry/place_text.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "qm/json.hpp"
#include "qm/printable_text.hpp"

#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

namespace qm::cli {
namespace {

namespace g = qm::geometry;

void warn(Diagnostics& diags, const g::Mechanism& m, const SourceLocation& where, std::string message) {
    diags.add(Severity::warning, where, std::move(message), m.source ? m.source->line_of(where) : std::string_view());
}

std::string axis_text(const g::Mechanism& m, g::PartId p, const g::CSpaceAxis& axis) {
    const g::Part& part = m.parts[p];
    std::ostringstream os;
    os.precision(10);
    os << part.name << ": ";
    if (part.fixed()) return os.str() + "fixed";
    // In the units a person types (--config, the scene's `turn`): degrees for a rotation.
    const double scale = part.rotates() ? 180.0 / std::numbers::pi : 1.0;
    os << (part.rotates() ? "rotation" : "translation") << ' ' << axis.lo * scale << ".." << axis.hi * scale
       << (part.rotates() ? " degrees" : "") << (axis.periodic ? " periodic" : "");
    return os.str();
}

int usage_error(std::ostream& err, const std::string& what) {
    err << "qm-atms: " << what << "\n" << metric_usage();
    return 2;
}

// `; Alex scene of PATH at 'CONFIG' (qm-atms --emit-def)`: the path and CONFIG as typed may hold
// line breaks or other control characters, which would end the `;` comment early and leave the
// rest as text the reader refuses; they are written as escapes (qm/printable_text.hpp).
std::string emitted_scene_comment(const std::string& path, const std::string& config) {
    return "; Alex scene of " + printable_text(path) + " at " +
           (config.empty() ? std::string("the drawn configuration") : "'" + printable_text(config) + "'") + " (qm-atms --emit-def)\n";
}

}  // namespace

int emit_def_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    CommandOptions cl(metric_usage());
    std::vector<std::string> given;
    cl.positionals(given);
    if (auto status = cl.parse(args, out, err)) return *status;
    if (given.empty() || given.size() > 2) return cl.error(err, "--emit-def takes a metric scene and an optional CONFIG");
    Diagnostics diags;
    const std::string config = given.size() > 1 ? given[1] : std::string();
    const auto scene = bridge::read_scene_at_config(given[0], config, diags);
    diags.print(err);
    if (!scene || diags.has_errors()) return 2;
    out << emitted_scene_comment(given[0], config) << scene::print_scene(*scene);
    return 0;
}

int places_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    CommandOptions cl(metric_usage());
    std::vector<std::string> scenes;
    std::optional<std::string> svg, cache_text;
    bool json = false, no_cache = false;
    cl.positionals(scenes);
    cl.flag("--json", json);
    cl.single("--svg", "a folder to draw each pair's configuration space in", svg);
    cl.place_cache(cache_text, no_cache);
    if (auto status = cl.parse(args, out, err)) return *status;
    if (scenes.empty()) return cl.error(err, "--places takes a metric scene");
    if (scenes.size() > 1) return cl.error(err, "--places takes one metric scene, not '" + scenes[0] + "' and '" + scenes[1] + "'");
    const bool use_cache = !no_cache;
    std::optional<std::filesystem::path> svg_dir, cache_dir;
    if (svg) svg_dir = *svg;
    if (cache_text) cache_dir = *cache_text;
    Diagnostics diags;
    const auto m = g::read_mechanism_file(scenes[0], diags);
    if (!m) return bad_input(diags, err);
    const std::optional<g::PlaceCache> cache = bridge::open_place_cache(use_cache, cache_dir);
    if (svg_dir) {
        std::error_code ec;
        std::filesystem::create_directories(*svg_dir, ec);
        if (ec) return usage_error(err, "cannot create the SVG directory '" + svg_dir->string() + "'");
    }
    const auto selection = g::kinematic_pairs(*m);
    if (!g::check_grid_limit(*m, selection, diags)) return bad_input(diags, err);
    std::ostringstream text, js;
    text << "mechanism " << m->name << ": " << selection.modelled.size() << " kinematic pair" << (selection.modelled.size() == 1 ? "" : "s") << '\n';
    js << "{\"schema\":\"qm-metric-places/1\",\"mechanism\":";
    write_json_string(js, m->name);
    js << ",\"pairs\":[";
    for (std::size_t k = 0; k < selection.modelled.size(); ++k) {
        const auto& pair = selection.modelled[k];
        auto found = bridge::pair_places(*m, pair, {.cache = cache ? &*cache : nullptr, .space = svg_dir.has_value(), .oracle = svg_dir.has_value()}, diags);
        if (!found) return bad_input(diags, err);
        auto& places = *found;
        if (svg_dir) {  // the picture needs the sampled space, which the cache does not keep
            const std::string name = m->parts[pair.a].name + "--" + m->parts[pair.b].name + ".svg";
            std::ofstream os(*svg_dir / name);
            g::write_cspace_svg(os, *places.oracle, *places.space, places.vocabulary, bridge::cspace_svg_options(*m, pair, 720, 540));
            if (!os) return usage_error(err, "cannot write '" + (*svg_dir / name).string() + "'");
        }
        if (places.no_place)
            warn(diags, *m, pair.where,
                 "'" + m->parts[pair.a].name + "' and '" + m->parts[pair.b].name +
                     "' have no free space on the sampled grid, and are not drawn in contact: they overlap everywhere (check the pivots) or their play is below a grid cell");
        const auto& request = places.request;
        const auto& vocabulary = places.vocabulary;
        const bool from_cache = places.from_cache;
        text << "pair " << m->parts[pair.a].name << ' ' << m->parts[pair.b].name << " (q0 = " << axis_text(*m, pair.a, request.cspace.axes[0])
             << "; q1 = " << axis_text(*m, pair.b, request.cspace.axes[1]) << ")" << (from_cache ? " from cache" : "") << '\n';
        const auto svg = bridge::cspace_svg_options(*m, pair, 720, 540);
        const std::array<g::AxisUnit, 2> units{svg.axes[0].unit, svg.axes[1].unit};
        g::write_place_text(text, vocabulary, units);
        js << (k ? "," : "") << "{\"parts\":[";
        write_json_string(js, m->parts[pair.a].name);
        js << ',';
        write_json_string(js, m->parts[pair.b].name);
        js << "],\"from_cache\":" << (from_cache ? "true" : "false") << ",\"vocabulary\":";
        g::write_place_json(js, request.cspace, vocabulary, units);
        js << '}';
    }
    js << "],\"skipped\":[";
    for (std::size_t k = 0; k < selection.skipped.size(); ++k) {
        const auto& s = selection.skipped[k];
        text << "no configuration space for " << m->parts[s.a].name << ' ' << m->parts[s.b].name << ": " << s.reason << '\n';
        js << (k ? "," : "") << "{\"parts\":[";
        write_json_string(js, m->parts[s.a].name);
        js << ',';
        write_json_string(js, m->parts[s.b].name);
        js << "],\"reason\":";
        write_json_string(js, s.reason);
        js << '}';
    }
    js << "],\"linkages\":[";
    for (std::size_t k = 0; k < m->linkages.size(); ++k) {
        text << "linkage";
        js << (k ? "," : "") << '[';
        for (std::size_t i = 0; i < m->linkages[k].parts.size(); ++i) {
            text << ' ' << m->parts[m->linkages[k].parts[i]].name;
            js << (i ? "," : "");
            write_json_string(js, m->parts[m->linkages[k].parts[i]].name);
        }
        text << '\n';
        js << ']';
    }
    js << "]}\n";
    diags.print(err);
    out << (json ? js.str() : text.str());
    return 0;
}

}  // namespace qm::cli
