// geometry/metric_scene_checker.cpp: raw metric scene AST -> Mechanism, with located errors
// (docs/METRIC_SCENE_FORMAT.md, "Checks"): settings, linkages, pairs, forces and
// the whole; parts are checked in detail/metric_part_checker.cpp.
#include "geometry/metric_scene_checker.hpp"

#include "geometry/detail/metric_checker.hpp"

#include "qm/spelling.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <map>

namespace qm::geometry {
namespace detail {

void Checker::settings(const mast::SettingsSection& s, MechanismSettings& out) {
    std::map<std::string, const mast::Setting*> seen;
    for (const auto& e : s.entries) {
        const std::string key = lower(e.key.text);
        if (seen.count(key)) {
            error(e, "setting '" + key + "' is given twice (first at line " + std::to_string(where(*seen[key]).line) + ")");
            continue;
        }
        seen[key] = &e;
        // `least` keeps a positive tolerance above what double arithmetic can resolve: below it
        // bisection stops making progress and arcs would need more chords than memory holds.
        auto one = [&](double& target, bool zero_allowed, double least, double below) {
            if (e.values.size() != 1) return error(e, "setting '" + key + "' takes one number");
            const double x = value(e.values[0]);
            if (zero_allowed ? !(x >= 0) : !(x > 0)) return error(e.values[0], key + " must be " + (zero_allowed ? "at least 0" : "positive") + ", not " + num(x));
            if (!zero_allowed && x < least) return error(e.values[0], key + " must be at least " + num(least) + " (finer than double precision can resolve), not " + num(x));
            if (!(x < below)) return error(e.values[0], key + " must be below " + num(below) + ", not " + num(x));
            target = x;
        };
        constexpr double unbounded = std::numeric_limits<double>::infinity();
        if (key == "chordal-tolerance") one(out.chordal_tolerance, false, min_chordal_tolerance, 0.5);
        else if (key == "contact-tolerance") one(out.contact_tolerance, false, min_contact_tolerance, 0.5);
        else if (key == "boundary-tolerance") one(out.boundary_tolerance, false, min_boundary_tolerance, 0.1);
        else if (key == "normal-zero-tolerance") one(out.normal_zero_tolerance, false, min_normal_zero_tolerance, 1.0);
        else if (key == "merge-epsilon") one(out.merge_epsilon, true, 0.0, unbounded);
        else if (key == "gap-epsilon") one(out.gap_epsilon, true, 0.0, unbounded);
        else if (key == "grid") {
            if (e.values.empty() || e.values.size() > 2) {
                error(e, "setting 'grid' takes one or two whole numbers (samples per axis)");
                continue;
            }
            const auto n0 = whole(e.values[0], 2, 4096, "a grid size");
            const auto n1 = e.values.size() == 2 ? whole(e.values[1], 2, 4096, "a grid size") : n0;
            if (n0 && n1) out.grid = {*n0, *n1};
        } else {
            constexpr std::array<std::string_view, 7> settings = {"chordal-tolerance", "contact-tolerance", "boundary-tolerance",
                                                                  "normal-zero-tolerance", "merge-epsilon", "gap-epsilon", "grid"};
            const std::string near = did_you_mean(key, settings);
            error(e.key, "unknown setting '" + e.key.text + "'" +
                             (near.empty() ? "; the settings are chordal-tolerance, contact-tolerance, boundary-tolerance, "
                                             "normal-zero-tolerance, merge-epsilon, gap-epsilon, grid"
                                           : near));
        }
    }
}

void Checker::linkages(const mast::LinkagesSection& s, Mechanism& m) {
    for (const auto& e : s.entries) {
        Linkage l;
        l.where = where(e);
        std::vector<const mast::Name*> names = {&e.first};
        for (const auto& n : e.rest) names.push_back(&n);
        bool good = true;
        for (const auto* n : names) {
            const auto id = m.find_part(lower(n->text));
            if (!id) {
                error(*n, "unknown part '" + n->text + "'");
                good = false;
                continue;
            }
            if (std::find(l.parts.begin(), l.parts.end(), *id) != l.parts.end()) {
                error(*n, "part '" + lower(n->text) + "' is named twice in this linkage");
                good = false;
                continue;
            }
            if (const auto other = m.shaft_of(*id)) {
                error(*n, "part '" + lower(n->text) + "' is already on the shaft of the linkage at line " + std::to_string(m.linkages[*other].where.line));
                good = false;
                continue;
            }
            l.parts.push_back(*id);
        }
        if (!good || l.parts.size() < 2) {
            if (good) error(e, "a linkage needs at least two parts");
            continue;
        }
        // Parts on one shaft move as one body: the same degree of freedom. A part that failed
        // its own checks is a placeholder whose degree of freedom is not known.
        if (std::any_of(l.parts.begin(), l.parts.end(), [&](PartId id) { return m.parts[id].profiles.empty(); })) continue;
        const Part& first = m.parts[l.parts[0]];
        for (std::size_t i = 1; i < l.parts.size(); ++i) {
            const Part& p = m.parts[l.parts[i]];
            const double eps = 1e-9 * std::max({first.size(), p.size(), 1e-300});
            std::string why;
            if (first.dof.kind != p.dof.kind) why = "they do not move the same way (one is fixed, turns or slides and the other not)";
            else if (p.fixed()) why = "fixed parts need no linkage";
            else if (p.rotates() && (p.dof.pivot - first.dof.pivot).norm() > eps)
                why = "'" + first.name + "' turns about (" + num(first.dof.pivot.x()) + " " + num(first.dof.pivot.y()) + ") but '" + p.name +
                      "' about (" + num(p.dof.pivot.x()) + " " + num(p.dof.pivot.y()) + "); parts on one shaft share their pivot";
            else if (p.translates() && ((p.dof.axis - first.dof.axis).norm() > 1e-9 || std::abs(p.lo - first.lo) > eps || std::abs(p.hi - first.hi) > eps))
                why = "parts on one slide share their axis and limits";
            if (!why.empty()) {
                error(*names[i], "'" + first.name + "' and '" + p.name + "' cannot share a shaft: " + why);
                good = false;
            }
        }
        if (good) m.linkages.push_back(std::move(l));
    }
}

void Checker::pairs(const mast::PairsSection& s, Mechanism& m) {
    m.pairs_declared = true;
    for (const auto& e : s.entries) {
        const auto a = m.find_part(lower(e.a.text)), b = m.find_part(lower(e.b.text));
        if (!a) error(e.a, "unknown part '" + e.a.text + "'");
        if (!b) error(e.b, "unknown part '" + e.b.text + "'");
        if (!a || !b) continue;
        const Part& pa = m.parts[*a];
        const Part& pb = m.parts[*b];
        if (*a == *b) {
            error(e.b, "a part cannot form a kinematic pair with itself ('" + pa.name + "')");
            continue;
        }
        // A part that failed its own checks (a placeholder) has no known degree of freedom.
        if (pa.profiles.empty() || pb.profiles.empty()) continue;
        if (m.same_shaft(*a, *b)) {
            error(e.b, "'" + pa.name + "' and '" + pb.name + "' share a shaft (Linkages), so they move as one body and cannot collide: they cannot form a kinematic pair");
            continue;
        }
        if (pa.fixed() && pb.fixed()) {
            error(e, "'" + pa.name + "' and '" + pb.name + "' are both fixed: a kinematic pair needs a part that moves");
            continue;
        }
        bool dup = false;
        for (const auto& q : m.pairs) dup = dup || (q.a == *a && q.b == *b) || (q.a == *b && q.b == *a);
        if (dup) {
            error(e, "the pair '" + pa.name + "' '" + pb.name + "' is declared twice");
            continue;
        }
        PairSpec spec;
        spec.a = *a;
        spec.b = *b;
        spec.where = where(e);
        for (const auto& item : e.items) {
            if (const auto* g = boost::get<mast::GridItem>(&item.get())) {
                if (spec.grid) error(*g, "the pair has two (grid ...) items");
                const auto n0 = whole(g->n0, 2, 4096, "a grid size"), n1 = whole(g->n1, 2, 4096, "a grid size");
                if (n0 && n1) spec.grid = std::array<int, 2>{*n0, *n1};
            } else if (const auto* w = boost::get<mast::WindowItem>(&item.get())) {
                const auto id = m.find_part(lower(w->part.text));
                if (!id || (*id != *a && *id != *b)) {
                    error(w->part, "a window names one of the pair's parts ('" + pa.name + "' or '" + pb.name + "'), not '" + w->part.text + "'");
                    continue;
                }
                const int k = *id == *a ? 0 : 1;
                if (!m.parts[*id].rotates()) {
                    error(*w, "a window restricts a rotation; '" + m.parts[*id].name + "' does not rotate");
                    continue;
                }
                const double lo = value(w->lo), hi = value(w->hi);
                if (!(lo < hi) || hi - lo >= 360) {
                    error(*w, "a window needs lo < hi and less than 360 degrees, not " + num(lo) + " to " + num(hi));
                    continue;
                }
                if (spec.window[static_cast<std::size_t>(k)]) error(*w, "'" + m.parts[*id].name + "' has two windows in this pair");
                spec.window[static_cast<std::size_t>(k)] = AxisWindow{lo * degree, hi * degree};
            }
        }
        m.pairs.push_back(spec);
    }
}

void Checker::forces(const mast::ForcesSection& s, Mechanism& m) {
    for (const auto& e : s.entries) {
        ExternalForce f;
        f.cause = lower(e.cause.text);
        f.where = where(e);
        const auto id = m.find_part(lower(e.part.text));
        if (!id) {
            error(e.part, "unknown part '" + e.part.text + "'");
            continue;
        }
        f.part = *id;
        const Part& p = m.parts[*id];
        const mast::TorqueItem* torque = nullptr;
        const mast::DirectionItem* direction = nullptr;
        const mast::AtItem* at = nullptr;
        const mast::WhenItem* when = nullptr;
        auto once = [&](auto*& slot, const auto* item, const char* what) {
            if (slot) error(*item, std::string("the force has two ") + what + " items");
            else slot = item;
        };
        for (const auto& item : e.items) {
            const auto& v = item.get();
            if (const auto* t = boost::get<mast::TorqueItem>(&v)) once(torque, t, "(torque ...)");
            else if (const auto* d = boost::get<mast::DirectionItem>(&v)) once(direction, d, "(direction ...)");
            else if (const auto* a = boost::get<mast::AtItem>(&v)) once(at, a, "(at ...)");
            else if (const auto* w = boost::get<mast::WhenItem>(&v)) once(when, w, "(when ...)");
        }
        if ((torque != nullptr) == (direction != nullptr)) {
            error(e, "a force is either (torque +|-) or (direction dx dy), exactly one of them");
            continue;
        }
        if (torque) {
            f.kind = ExternalForce::Kind::torque;
            if (torque->sign.text == "+") f.torque_sign = 1;
            else if (torque->sign.text == "-") f.torque_sign = -1;
            else error(torque->sign, "a torque's sign is + (counter-clockwise) or - (clockwise), not '" + torque->sign.text + "'");
            if (!p.rotates() && !p.profiles.empty()) error(*torque, "a torque needs a part that rotates; '" + p.name + "' does not");
            if (at) error(*at, "a torque acts about the pivot; (at ...) belongs to a (direction ...) force");
        } else {
            f.kind = ExternalForce::Kind::push;
            f.direction = {value(direction->x), value(direction->y)};
            if (!(f.direction.norm() > 0)) error(*direction, "a force's direction must not be (0 0)");
            if (at) f.at = Eigen::Vector2d(value(at->x), value(at->y));
        }
        if (when) {
            double lo = value(when->lo), hi = value(when->hi);
            if (!(lo < hi)) error(*when, "(when lo hi) needs lo < hi, not " + num(lo) + " and " + num(hi));
            if (p.rotates()) {
                if (hi - lo > 360) error(*when, "a rotation range spans at most 360 degrees");
                lo *= degree;
                hi *= degree;
            } else if (p.fixed() && !p.profiles.empty()) {
                error(*when, "(when ...) depends on the part's position; '" + p.name + "' is fixed");
            }
            f.when = std::make_pair(lo, hi);
        }
        m.forces.push_back(f);
    }
}

}  // namespace detail

using detail::Checker;
using detail::lower;
using detail::degree;
using detail::num;

std::optional<Mechanism> check_mechanism(const mast::MechanismFile& file, const MetricPositions& positions, const MetricSource& src,
                                         Diagnostics& diags) {
    Checker c{positions, src, diags};
    Mechanism m;
    m.name = lower(file.name.text);
    m.where = c.where(file);
    const mast::SettingsSection* settings = nullptr;
    const mast::PartsSection* parts = nullptr;
    const mast::PairsSection* pairs = nullptr;
    const mast::LinkagesSection* linkages = nullptr;
    const mast::ForcesSection* forces = nullptr;
    auto once = [&](auto*& slot, const auto* section, const char* what) {
        if (slot) c.error(*section, std::string("section ") + what + " is given twice (first at line " + std::to_string(c.where(*slot).line) + ")");
        else slot = section;
    };
    for (const auto& s : file.sections) {
        const auto& v = s.get();
        if (const auto* x = boost::get<mast::SettingsSection>(&v)) once(settings, x, "Settings");
        else if (const auto* x = boost::get<mast::PartsSection>(&v)) once(parts, x, "Parts");
        else if (const auto* x = boost::get<mast::PairsSection>(&v)) once(pairs, x, "Pairs");
        else if (const auto* x = boost::get<mast::LinkagesSection>(&v)) once(linkages, x, "Linkages");
        else if (const auto* x = boost::get<mast::ForcesSection>(&v)) once(forces, x, "Forces");
    }
    if (settings) c.settings(*settings, m.settings);
    if (!parts || parts->entries.empty()) {
        c.error(file, "a metric scene needs a Parts section with at least one part");
    } else {
        for (const auto& e : parts->entries) c.part(e, m);
    }
    // Parts that failed their checks are placeholders without profiles: the references below
    // still resolve, so the other sections are checked too (every error in one run, in source
    // order), but nothing that needs a part's shape or motion is checked on a placeholder.
    if (linkages) c.linkages(*linkages, m);
    if (pairs) c.pairs(*pairs, m);
    if (forces) c.forces(*forces, m);
    c.limits(m);
    if (!c.ok) return std::nullopt;
    m.source = src;
    return m;
}

std::optional<Configuration> check_configuration(const std::vector<mast::ConfigEntry>& entries, const Mechanism& m,
                                                 const MetricPositions& positions, const MetricSource& src, Diagnostics& diags) {
    Checker c{positions, src, diags};
    Configuration out;
    out.q.assign(m.parts.size(), 0.0);
    std::map<std::size_t, const mast::ConfigEntry*> shaft_given;  // shaft key -> entry
    for (const auto& e : entries) {
        const auto id = m.find_part(lower(e.part.text));
        if (!id) {
            std::string moving;
            for (const auto& p : m.parts)
                if (!p.fixed()) moving += std::string(moving.empty() ? "" : ", ") + p.name;
            c.error(e.part, "unknown part '" + e.part.text + "'" + (moving.empty() ? std::string() : "; the moving parts are " + moving));
            continue;
        }
        const Part& p = m.parts[*id];
        if (p.fixed()) {
            c.error(e.part, "part '" + p.name + "' is fixed: it has no coordinate");
            continue;
        }
        const auto shaft = m.shaft_of(*id);
        const std::size_t key = shaft ? m.parts.size() + *shaft : id->value;
        if (shaft_given.count(key)) {
            c.error(e, "'" + p.name + "' is given a second value (its shaft was given one at column " + std::to_string(c.where(*shaft_given[key]).column) + ")");
            continue;
        }
        shaft_given[key] = &e;
        double q = c.value(e.value);
        if (p.rotates()) {
            q *= degree;
        } else if (q < p.lo || q > p.hi) {
            c.error(e.value, "offset " + num(q) + " of '" + p.name + "' is outside its limits [" + num(p.lo) + ", " + num(p.hi) + "]");
            continue;
        }
        if (shaft)
            for (PartId other : m.linkages[*shaft].parts) out.q[other.value] = q;
        else
            out.q[id->value] = q;
    }
    if (!c.ok) return std::nullopt;
    return out;
}

}  // namespace qm::geometry
