// cli/metric_command.cpp: metric scenes at the command line, and the conversion of the geometry's
// contacts and forces at a configuration into an Alex scene (thesis 2.4, 3.1.1, 8.2.1).
#include "metric_command.hpp"

#include "pair_places.hpp"

#include "scene/scene_parser.hpp"
#include "scene/scene_printer.hpp"
#include "geometry/contact_detection.hpp"
#include "geometry/contact_place.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/external_force.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_cache.hpp"
#include "geometry/place_json.hpp"
#include "geometry/place_text.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "qm/assert.hpp"
#include "qm/json.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

namespace qm::cli {
namespace {

namespace g = qm::geometry;
namespace a = qm::scene;

a::Sign sign_of(std::int8_t s) { return s > 0 ? a::Sign::plus : s < 0 ? a::Sign::minus : a::Sign::zero; }
a::Direction direction_of(g::QualDirection d) { return {sign_of(d.s[0]), sign_of(d.s[1])}; }
a::DirectionPattern pattern_of(g::QualDirection d) { return {a::PatternSlot{sign_of(d.s[0]), {}}, a::PatternSlot{sign_of(d.s[1]), {}}}; }
// (?x ?y): every translation; (?r): every rotation.
a::DirectionPattern any_translation() { return {a::PatternSlot{std::nullopt, "x"}, a::PatternSlot{std::nullopt, "y"}}; }
a::DirectionPattern any_rotation() { return {a::PatternSlot{std::nullopt, "r"}}; }

void warn(Diagnostics& diags, const g::Mechanism& m, const SourceLocation& where, std::string message) {
    diags.add(Severity::warning, where, std::move(message), m.source ? m.source->line_of(where) : std::string_view());
}

// Builds the Alex model of the mechanism at one configuration.
class AlexBuilder {
public:
    AlexBuilder(const g::Mechanism& m, const g::Configuration& q) : m_(m), q_(q) {
        scene_.name = m.name;
        scene_.dimensions = 2;
        // One object per part, except that parts on one shaft are one rigid body (Def 21): the
        // first part named in the linkage stands for all.
        for (std::uint32_t i = 0; i < m.parts.size(); ++i) {
            const g::PartId p{i};
            const auto shaft = m.shaft_of(p);
            if (shaft && m.linkages[*shaft].parts.front() != p) continue;
            object_[p.value] = scene_.objects.push_back(object_for(p));
        }
        for (std::uint32_t i = 0; i < m.parts.size(); ++i) {
            const g::PartId p{i};
            if (const auto shaft = m.shaft_of(p)) object_[p.value] = object_.at(m.linkages[*shaft].parts.front().value);
        }
        scene_.situations.emplace_back();
    }

    // Surfaces, corners and contacts of one pair's contacts. A convex corner is written as an Alex
    // corner between its two sides (Def 18); how it constrains, alone against a face or against
    // another corner (section 3.1.1, Defs 25-26), is the laws' business (rules/corners.rules).
    void add_contacts(const g::PairSpec& pair, const g::ContactResult& r) {
        for (const auto& c : r.contacts) {
            const a::SurfaceId x = feature(pair.a, c.first, r.tolerance), y = feature(pair.b, c.second, r.tolerance);
            a::Contact k;
            k.first = x;
            k.second = y;
            auto& list = scene_.situations.front().contacts;
            if (std::find(list.begin(), list.end(), k) == list.end()) list.push_back(k);
        }
    }

    void add_forces() {
        for (const auto& f : m_.forces) {
            const g::Part& part = m_.parts[f.part];
            const double q = q_.at(f.part);
            if (!g::force_active(f, part, q)) continue;
            a::Force out;
            out.object = object_.at(f.part.value);
            out.cause = cause(f.cause);
            if (f.kind == g::ExternalForce::Kind::torque) {
                // A torque as a force applied right of the centre, pushing up (+) or down (-).
                out.direction = {a::Sign::zero, f.torque_sign > 0 ? a::Sign::plus : a::Sign::minus};
                out.origin = {a::Sign::minus, a::Sign::zero};
            } else {
                out.direction = direction_of(g::qualitative(f.direction, m_.settings.normal_zero_tolerance));
                const auto p = g::application_point(f, part, q);
                out.origin = p ? direction_of(g::origin_direction(part, q, *p, zero_length(part))) : a::Direction{a::Sign::zero, a::Sign::zero};
            }
            scene_.situations.front().forces.push_back(out);
        }
    }

    [[nodiscard]] const a::Scene& scene() const { return scene_; }

private:
    double zero_length(const g::Part& p) const { return m_.settings.contact_tolerance * p.size(); }

    a::Object object_for(g::PartId p) const {
        const g::Part& part = m_.parts[p];
        a::Object o;
        o.name = part.name;
        if (part.fixed()) {
            o.trans_constraints.push_back(any_translation());
            o.rot_constraints.push_back(any_rotation());
        } else if (part.rotates()) {
            o.trans_constraints.push_back(any_translation());  // pinned: turns only
        } else {
            // Slides along its axis only: every other translation is constrained, and so is the
            // way out past a limit it stands at.
            const g::QualDirection along = g::qualitative(part.dof.axis, m_.settings.normal_zero_tolerance);
            const double q = q_.at(p), slack = 1e-9 * std::max(1.0, part.hi - part.lo);
            for (std::int8_t x = -1; x <= 1; ++x)
                for (std::int8_t y = -1; y <= 1; ++y) {
                    const g::QualDirection d{{x, y}};
                    if (d == g::QualDirection{}) continue;
                    const bool free = (d == along && q < part.hi - slack) || (d == g::negated(along) && q > part.lo + slack);
                    if (!free) o.trans_constraints.push_back(pattern_of(d));
                }
            o.rot_constraints.push_back(any_rotation());
        }
        return o;
    }

    a::CauseId cause(const std::string& name) {
        if (auto c = scene_.find_cause(name)) return *c;
        return scene_.causes.push_back({name, true});
    }

    // The Alex surface for a feature of a part with the given normal (an Alex surface is a set of
    // qualitatively equivalent points, so one feature may need several).
    a::SurfaceId surface(g::PartId p, const g::ContactFeature& f, const Eigen::Vector2d& normal, double tol) {
        const g::Part& part = m_.parts[p];
        const int k = g::global_segment(part, f.profile, f.segment) + 1;
        const std::string base = part.name + (f.kind == g::FeatureKind::corner ? "-c" : "-s") + std::to_string(k);
        a::Surface s;
        s.object = object_.at(p.value);
        s.normal = direction_of(g::qualitative(normal, m_.settings.normal_zero_tolerance));
        s.origin = direction_of(g::origin_direction(part, q_.at(p), f.point, std::max(tol, zero_length(part))));
        for (int n = 1;; ++n) {
            s.name = n == 1 ? base : base + "-" + std::to_string(n);
            const auto existing = scene_.find_surface(s.name);
            if (!existing) break;
            if (scene_.surfaces[*existing].normal == s.normal && scene_.surfaces[*existing].origin == s.origin) return *existing;
        }
        const a::SurfaceId id = scene_.surfaces.push_back(s);
        scene_.objects[s.object].surfaces.push_back(id);
        return id;
    }

    a::SurfaceId feature(g::PartId p, const g::ContactFeature& f, double tol) {
        return f.kind == g::FeatureKind::corner ? corner(p, f, tol) : surface(p, f, f.normal, tol);
    }

    // The Alex corner of a corner feature: its two sides as faces, and the corner between them,
    // with its own origin direction.
    a::SurfaceId corner(g::PartId p, const g::ContactFeature& f, double tol) {
        const g::Part& part = m_.parts[p];
        g::ContactFeature before = f, after = f;
        before.kind = after.kind = g::FeatureKind::surface;
        before.segment = f.previous;
        before.normal = f.sides[0];
        after.normal = f.sides[1];
        const a::SurfaceId first = surface(p, before, before.normal, tol), second = surface(p, after, after.normal, tol);
        a::Surface s;
        s.object = object_.at(p.value);
        s.corner = a::CornerSides{first, second};
        s.origin = direction_of(g::origin_direction(part, q_.at(p), f.point, std::max(tol, zero_length(part))));
        const std::string base = part.name + "-c" + std::to_string(g::global_segment(part, f.profile, f.segment) + 1);
        for (int n = 1;; ++n) {
            s.name = n == 1 ? base : base + "-" + std::to_string(n);
            const auto existing = scene_.find_surface(s.name);
            if (!existing) break;
            if (scene_.surfaces[*existing].corner == s.corner && scene_.surfaces[*existing].origin == s.origin) return *existing;
        }
        const a::SurfaceId id = scene_.surfaces.push_back(s);
        scene_.objects[s.object].surfaces.push_back(id);
        return id;
    }

    const g::Mechanism& m_;
    const g::Configuration& q_;
    a::Scene scene_;
    std::map<std::uint32_t, a::ObjectId> object_;
};

struct SceneText {
    a::Scene scene;
    std::string text;
};

std::optional<SceneText> scene_at(const std::string& path, const std::string& config, Diagnostics& diags) {
    const auto m = g::read_mechanism_file(path, diags);
    if (!m) return std::nullopt;
    const auto q = g::parse_configuration(*m, config, diags);
    if (!q) return std::nullopt;
    AlexBuilder builder(*m, *q);
    const g::ContactRequest request{m->settings.contact_tolerance, m->settings.normal_zero_tolerance};
    bool ok = true;
    for (const auto& pair : g::kinematic_pairs(*m).modelled) {
        const auto oracle = pair_oracle_or_error(*m, pair, diags);
        if (!oracle) return std::nullopt;
        const auto r = g::detect_contacts(*oracle, {q->at(pair.a), q->at(pair.b)}, request);
        if (r.status == g::ContactStatus::overlapping) {
            m->error(diags, pair.where, r.message + (config.empty() ? " (as drawn)" : " (CONFIG '" + config + "')"));
            ok = false;
            continue;
        }
        builder.add_contacts(pair, r);
    }
    if (!ok) return std::nullopt;
    builder.add_forces();
    std::string text = "; Alex scene of " + path + " at " + (config.empty() ? std::string("the drawn configuration") : "'" + config + "'") +
                       " (qm-atms --emit-def)\n" + a::print_scene(builder.scene());
    // Read back through the Alex reader: the result is a checked scene, and a printing or
    // naming mistake here is caught as an internal failure, not passed on.
    Diagnostics again;
    auto checked = a::read_scene(path + "@" + (config.empty() ? "drawn" : config), text, again);
    if (!checked) {
        std::ostringstream os;
        again.print(os);
        throw InternalError("the Alex scene written for " + path + " does not read back:\n" + os.str());
    }
    return SceneText{std::move(*checked), std::move(text)};
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

}  // namespace

std::optional<qm::scene::Scene> metric_scene_at(const std::string& path, const std::string& config, Diagnostics& diags) {
    auto r = scene_at(path, config, diags);
    if (!r) return std::nullopt;
    return std::move(r->scene);
}

const char* metric_usage() noexcept {
    return "       qm-atms --emit-def METRIC-SCENE [CONFIG]   Alex scene of a metric scene at CONFIG ('part=value, ...')\n"
           "       qm-atms --places METRIC-SCENE [--json] [--svg DIR] [--cache DIR | --no-cache]\n"
           "                                                  place vocabulary of each kinematic pair\n";
}

int emit_def_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    if (args.empty() || args.size() > 2) return usage_error(err, "--emit-def takes a metric scene and an optional CONFIG");
    Diagnostics diags;
    const auto r = scene_at(args[0], args.size() > 1 ? args[1] : std::string(), diags);
    diags.print(err);
    if (!r || diags.has_errors()) return 2;
    out << r->text;
    return 0;
}

int places_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    if (args.empty()) return usage_error(err, "--places takes a metric scene");
    bool json = false, use_cache = true;
    std::optional<std::filesystem::path> svg_dir, cache_dir;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--json") json = true;
        else if (args[i] == "--no-cache") use_cache = false;
        else if ((args[i] == "--svg" || args[i] == "--cache") && i + 1 < args.size()) (args[i] == "--svg" ? svg_dir : cache_dir) = args[i + 1], ++i;
        else return usage_error(err, "unknown or incomplete option '" + args[i] + "' for --places");
    }
    Diagnostics diags;
    const auto m = g::read_mechanism_file(args[0], diags);
    if (!m) {
        diags.print(err);
        return 2;
    }
    const std::optional<g::PlaceCache> cache = open_place_cache(use_cache, cache_dir);
    if (svg_dir) {
        std::error_code ec;
        std::filesystem::create_directories(*svg_dir, ec);
        if (ec) return usage_error(err, "cannot create the SVG directory '" + svg_dir->string() + "'");
    }
    const auto selection = g::kinematic_pairs(*m);
    if (!g::check_grid_limit(*m, selection, diags)) {
        diags.print(err);
        return 2;
    }
    std::ostringstream text, js;
    text << "mechanism " << m->name << ": " << selection.modelled.size() << " kinematic pair" << (selection.modelled.size() == 1 ? "" : "s") << '\n';
    js << "{\"schema\":\"qm-metric-places/1\",\"mechanism\":";
    write_json_string(js, m->name);
    js << ",\"pairs\":[";
    for (std::size_t k = 0; k < selection.modelled.size(); ++k) {
        const auto& pair = selection.modelled[k];
        auto found = pair_places(*m, pair, cache, svg_dir.has_value(), diags);
        if (!found) {
            diags.print(err);
            return 2;
        }
        auto& places = *found;
        if (svg_dir) {  // the picture needs the sampled space, which the cache does not keep
            const std::string name = m->parts[pair.a].name + "--" + m->parts[pair.b].name + ".svg";
            std::ofstream os(*svg_dir / name);
            g::write_cspace_svg(os, *places.oracle, *places.space, places.vocabulary, cspace_svg_options(*m, pair, 720, 540));
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
        const auto svg = cspace_svg_options(*m, pair, 720, 540);
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
