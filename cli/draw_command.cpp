// cli/draw_command.cpp: `qm-atms draw` (thesis Figures 9.11-9.13: the parts drawn at a place).
#include "draw_command.hpp"
#include "command_options.hpp"
#include "geometry_usage.hpp"

#include "bridge/pair_places.hpp"
#include "state_drawing.hpp"

#include "geometry/mechanism_drawing.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_sample.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

namespace qm::cli {

namespace {

namespace g = qm::geometry;

struct DrawArgs {
    std::string scene, config, place, svg, history;
    bool has_config = false, has_history = false, has_size = false, use_cache = true;
    std::optional<std::filesystem::path> cache_dir;
    int width = 720, height = 540;
    std::size_t columns = 4;  // --history: drawings a row
};

int usage_error(std::ostream& err, const std::string& what) {
    err << "qm-atms: " << what << "\n" << draw_usage();
    return 2;
}

// "WxH", each 100..4000 pixels.
bool parse_size(const std::string& text, int& width, int& height) {
    const auto x = text.find('x');
    if (x == std::string::npos) return false;
    auto number = [](std::string_view s, int& v) {
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        return ec == std::errc() && end == s.data() + s.size() && v >= 100 && v <= 4000;
    };
    return number(std::string_view(text).substr(0, x), width) && number(std::string_view(text).substr(x + 1), height);
}

// The command line (usage in cli/geometry_usage.cpp). nullopt: `a` read; otherwise the exit status
// to return (0 after --help or --version). An option that would change nothing is refused.
std::optional<int> parse_args(std::span<const std::string> args, DrawArgs& a, std::ostream& out, std::ostream& err) {
    CommandOptions cl(draw_usage());
    std::vector<std::string> scenes;
    std::optional<std::string> config, place, history, columns, svg, cache, size;
    bool no_cache = false;
    cl.positionals(scenes);
    cl.single("--config", "a configuration, e.g. --config 'cam=30, follower=0.1'", config);
    cl.single("--place", "a place PAIR:ID, e.g. --place cam--follower:3", place);
    cl.single("--history", "states one after another, e.g. --history '#0 #1 #2'", history);
    cl.single("--columns", "a number of drawings a row, 1 to 99", columns);
    cl.single("--svg", "a file to write the drawing to", svg);
    cl.single("--size", "WIDTHxHEIGHT, each 100 to 4000 pixels", size);
    cl.place_cache(cache, no_cache);
    if (auto status = cl.parse(args, out, err)) return status;
    if (scenes.empty()) return cl.error(err, "draw takes a metric scene");
    if (scenes.size() > 1) return cl.error(err, "draw takes one metric scene, not '" + scenes[0] + "' and '" + scenes[1] + "'");
    a.scene = scenes[0];
    if (columns) {
        const std::string& n = *columns;
        if (n.empty() || n.size() > 2 || n.find_first_not_of("0123456789") != std::string::npos || std::stoi(n) < 1)
            return cl.bad_value(err, "--columns", n);
        a.columns = static_cast<std::size_t>(std::stoi(n));
    }
    if (size && !parse_size(*size, a.width, a.height)) return cl.bad_value(err, "--size", *size);
    if (!svg) return cl.error(err, "draw needs --svg FILE");
    if (int(config.has_value()) + int(place.has_value()) + int(history.has_value()) > 1)
        return cl.error(err, "draw takes one of --config, --place and --history");
    if (columns && !history) return cl.error(err, "--columns lays out the drawings of a --history: give it with --history");
    if ((cache || no_cache) && !place && !history)
        return cl.error(err, std::string(cache ? "--cache" : "--no-cache") +
                                 " chooses where the place vocabularies of --place or --history come from; a drawing at a configuration needs none");
    a.config = config.value_or(""), a.has_config = config.has_value();
    a.place = place.value_or("");
    a.history = history.value_or(""), a.has_history = history.has_value();
    a.svg = *svg;
    a.use_cache = !no_cache;
    if (cache) a.cache_dir = *cache;
    a.has_size = size.has_value();
    if (a.has_history && !a.has_size) a.width = 340, a.height = 300;  // one drawing of a strip
    return std::nullopt;
}

std::string value_text(const g::Part& p, double q) {
    std::ostringstream os;
    os.precision(4);
    if (p.rotates()) os << q * 180.0 / std::numbers::pi << "\u00b0";
    else os << q;
    return p.name + "=" + os.str();
}

// "cseg, normal (- -)", "join (fsd-end), normals (- -) (0 +)", "face".
std::string place_text(const g::Place& p) {
    std::string out = g::to_string(p.kind);
    if (p.kind == g::PlaceKind::join) out += std::string(" (") + g::to_string(p.join_kind) + (p.concave ? *p.concave ? ", concave" : ", convex" : "") + ")";
    if (!p.normals.empty()) out += p.normals.size() == 1 ? ", normal" : ", normals";
    for (const auto& n : p.normals) out += " " + g::to_string(n);
    return out;
}

// The pair's parts at the sample configuration of place `text` ("A--B:ID").
int draw_place(const g::Mechanism& m, const DrawArgs& a, std::ostream& os, std::ostream& err, std::string& title) {
    const auto colon = a.place.rfind(':');
    const auto pair = colon == std::string::npos ? std::nullopt : bridge::find_pair(m, std::string_view(a.place).substr(0, colon));
    if (!pair) return usage_error(err, "--place takes PAIR:ID with PAIR a kinematic pair of " + a.scene + " written A--B (as --places names it), not '" + a.place + "'");
    Diagnostics diags;
    const auto cache = bridge::open_place_cache(a.use_cache, a.cache_dir);
    const auto found = bridge::pair_places(m, *pair, {.cache = cache ? &*cache : nullptr, .oracle = true}, diags);
    diags.print(err);
    if (!found) return 2;
    const auto& places = *found;
    const std::string id_text = a.place.substr(colon + 1);
    std::size_t id = 0;
    auto [end, ec] = std::from_chars(id_text.data(), id_text.data() + id_text.size(), id);
    if (ec != std::errc() || end != id_text.data() + id_text.size() || id >= places.vocabulary.places.size())
        return usage_error(err, "pair " + a.place.substr(0, colon) + " has places 0 to " + std::to_string(places.vocabulary.places.size()) +
                                    " (exclusive), not '" + id_text + "'");
    const g::Place& place = places.vocabulary.places[id];
    const Eigen::Vector2d s = g::sample_configuration(places.request.cspace, place);
    g::Configuration q{std::vector<double>(m.parts.size(), 0.0)};
    for (int k = 0; k < 2; ++k) {
        const g::PartId p = k == 0 ? pair->a : pair->b;
        if (!m.parts[p].fixed()) q.q[p.value] = s[k];
    }
    const std::vector<g::PartId> drawn{pair->a, pair->b};
    const g::ContactRequest request{m.settings.contact_tolerance, m.settings.normal_zero_tolerance};
    const auto contacts = g::detect_contacts(*places.oracle, {q.at(pair->a), q.at(pair->b)}, request);
    title = m.name + ": " + a.place.substr(0, colon) + " place " + std::to_string(id) + " (" + place_text(place) + ") at " +
            value_text(m.parts[pair->a], q.at(pair->a)) + ", " + value_text(m.parts[pair->b], q.at(pair->b));
    const auto marks = contacts.status == g::ContactStatus::ok ? g::contact_marks(m, *pair, contacts, 0, 1) : std::vector<g::ContactMark>{};
    g::write_parts_svg(os, g::drawn_parts(m, q, drawn), marks, {a.width, a.height, title, true, m.settings.normal_zero_tolerance});
    return 0;
}

// A history: the envisionment, then one drawing of the chain per state (cli/state_drawing.hpp).
int draw_history(const g::Mechanism& m, const DrawArgs& a, std::ostream& os, std::ostream& err) {
    Diagnostics diags;
    const auto e = envision_for_drawing(m, a.use_cache, a.cache_dir, diags);
    if (!e || diags.has_errors()) return bad_input(diags, err);
    const auto h = parse_history(*e, a.history, diags);
    diags.print(err);
    if (!h) return 2;
    write_history_svg(os, m, *e, *h, a.width, a.height, a.columns);
    return 0;
}

}  // namespace

int draw_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    DrawArgs a;
    if (auto status = parse_args(args, a, out, err)) return *status;
    Diagnostics diags;
    const auto m = g::read_mechanism_file(a.scene, diags);
    if (!m) return bad_input(diags, err);
    std::ostringstream svg;
    std::string title;
    if (a.has_history) {
        if (const int status = draw_history(*m, a, svg, err)) return status;
    } else if (!a.place.empty()) {
        if (const int status = draw_place(*m, a, svg, err, title)) return status;
    } else {
        const auto q = g::parse_configuration(*m, a.config, diags);
        if (!q) return bad_input(diags, err);
        std::vector<g::PartId> drawn;
        for (std::uint32_t i = 0; i < m->parts.size(); ++i) drawn.push_back(g::PartId{i});
        const auto contacts = g::mechanism_contacts(*m, *q, drawn);
        for (const auto& pair : contacts.overlapping)
            diags.add(Severity::warning, pair.where,
                       "'" + m->parts[pair.a].name + "' and '" + m->parts[pair.b].name + "' overlap at " +
                           (a.config.empty() ? std::string("the drawn configuration") : "'" + a.config + "'") + " (drawn all the same)",
                      m->source ? m->source->line_of(pair.where) : std::string_view());
        diags.print(err);
        title = m->name + (a.config.empty() ? std::string(" as drawn") : " at " + a.config);
        g::write_parts_svg(svg, g::drawn_parts(*m, *q, drawn), contacts.marks, {a.width, a.height, title, true, m->settings.normal_zero_tolerance});
    }
    std::ofstream file(a.svg);
    file << svg.str();
    if (!file) return usage_error(err, "cannot write '" + a.svg + "'");
    return 0;
}

}  // namespace qm::cli
