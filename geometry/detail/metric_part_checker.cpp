// geometry/detail/metric_part_checker.cpp: a metric scene's parts, drawn or generated, placed,
// with their degree of freedom and symmetry (docs/METRIC_SCENE_FORMAT.md, "Parts").
#include "geometry/detail/metric_checker.hpp"
#include "geometry/part_generators.hpp"
#include "geometry/detail/metric_keywords.hpp"
#include "qm/assert.hpp"
#include "geometry/profile_check.hpp"
#include "geometry/segment_queries.hpp"

#include <map>

namespace qm::geometry::detail {

// Appends the profile(s) a drawing item stands for; false if the item is not a drawing.
bool Checker::draw(const mast::PartItem& item, std::vector<DrawnProfile>& drawn) {
    const auto& v = item.get();
    if (const auto* p = boost::get<mast::PolygonItem>(&v)) {
        if (p->points.size() < 3) {
            error(*p, "a polygon needs at least 3 points");
            return true;
        }
        DrawnProfile d{{}, p, {}};
        for (std::size_t i = 0; i < p->points.size(); ++i) {
            d.profile.segments.push_back(Segment::line(point(p->points[i]), point(p->points[(i + 1) % p->points.size()])));
            d.segment_nodes.push_back(&p->points[i]);
        }
        drawn.push_back(std::move(d));
        return true;
    }
    if (const auto* c = boost::get<mast::CircleItem>(&v)) {
        const double r = value(c->radius);
        if (!(r > 0)) {
            error(c->radius, "a circle's radius must be positive, not " + num(r));
            return true;
        }
        drawn.push_back({circle_profile(point(c->centre), r), c, {c, c}});
        return true;
    }
    if (const auto* pr = boost::get<mast::ProfileItem>(&v)) {
        DrawnProfile d{{}, pr, {}};
        Eigen::Vector2d at = point(pr->start);
        for (const auto& st : pr->steps) {
            if (const auto* l = boost::get<mast::LineStep>(&st.get())) {
                const Eigen::Vector2d to(value(l->x), value(l->y));
                d.profile.segments.push_back(Segment::line(at, to));
                d.segment_nodes.push_back(l);
                at = to;
            } else if (const auto* a = boost::get<mast::ArcStep>(&st.get())) {
                const Eigen::Vector2d to(value(a->x), value(a->y)), c(value(a->cx), value(a->cy));
                d.profile.segments.push_back(Segment::arc(at, to, c, lower(a->sense.text) == "ccw"));
                d.segment_nodes.push_back(a);
                at = to;
            }
        }
        drawn.push_back(std::move(d));
        return true;
    }
    return false;
}

void Checker::part(const mast::PartEntry& e, Mechanism& m) {
    const std::string name = lower(e.name.text);
    if (m.find_part(name)) {
        error(e.name, "part '" + name + "' is declared twice (first at line " + std::to_string(m.part_where[m.find_part(name)->value].line) + ")");
        return;
    }
    const bool was_ok = ok;
    ok = true;
    std::vector<DrawnProfile> drawn;
    const mast::GeneratorItem* generator = nullptr;
    const mast::AtItem* at = nullptr;
    const mast::TurnItem* turn = nullptr;
    const mast::DofItem* dof = nullptr;
    const mast::SymmetryItem* symmetry = nullptr;
    auto once = [&](auto*& slot, const auto* item, const char* what) {
        if (slot) error(*item, std::string("part '") + name + "' has two " + what + " items");
        else slot = item;
    };
    int drawings = 0;
    bool unknown = false;  // an item naming no keyword: what the part lacks may be in it, misspelt
    for (const auto& item : e.items) {
        if (draw(item, drawn)) {
            ++drawings;
            continue;
        }
        const auto& v = item.get();
        if (const auto* g = boost::get<mast::GeneratorItem>(&v); g && !find_generator(lower(g->generator.text))) {
            error(g->generator, unknown_word_message(part_item_keywords(), g->generator.text));
            unknown = true;
        } else if (g) once(generator, g, "generated shapes");
        else if (const auto* a = boost::get<mast::AtItem>(&v)) once(at, a, "(at ...)");
        else if (const auto* t = boost::get<mast::TurnItem>(&v)) once(turn, t, "(turn ...)");
        else if (const auto* d = boost::get<mast::DofItem>(&v)) once(dof, d, "degree-of-freedom");
        else if (const auto* s = boost::get<mast::SymmetryItem>(&v)) once(symmetry, s, "(symmetry ...)");
    }
    // The shape, in the part's own frame.
    Shape shape;
    if (generator && !drawn.empty()) {
        error(*generator, "part '" + name + "' is both generated and drawn; give one or the other");
    } else if (generator) {
        const Generator* g = find_generator(lower(generator->generator.text));
        QM_ASSERT(g != nullptr, "only a known generator is kept as the part's generator");
        {
            std::vector<std::pair<std::string, double>> params;
            std::map<std::string, const mast::Param*> given;
            for (const auto& p : generator->params) {
                const std::string pn = lower(p.name.text);
                if (given.count(pn)) error(p, "parameter '" + pn + "' is given twice");
                given[pn] = &p;
                params.emplace_back(pn, value(p.value));
            }
            const ShapeResult r = ok ? make_shape(*g, params) : ShapeResult{};  // no shape from non-finite values
            if (!ok) {
            } else if (r.shape) {
                shape = *r.shape;
            } else {
                const Node* blame = generator;
                if (r.bad_param >= 0) {
                    const auto it = given.find(g->params[static_cast<std::size_t>(r.bad_param)].name);
                    if (it != given.end()) blame = it->second;
                }
                for (const auto& [pn, p] : given)  // an unknown parameter: point at it
                    if (r.error.find("'" + pn + "'") != std::string::npos) blame = p;
                error(*blame, std::string(g->name) + ": " + r.error);
            }
        }
    } else if (drawings == 0 && !unknown) {
        error(e, "part '" + name + "' has no shape: draw it with (polygon ...), (circle ...) or (profile ...), or generate it, e.g. (spur-gear (teeth 12))");
    } else {
        Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
        for (const auto& d : drawn) extend_bounds(d.profile, lo, hi);
        const double eps = 1e-9 * std::max((hi - lo).norm(), 1e-300);
        for (auto& d : drawn) {
            if (d.profile.segments.empty()) continue;
            if (auto problem = check_profile(d.profile, eps)) {
                const Node* blame = d.item;
                if (problem->segment >= 0 && static_cast<std::size_t>(problem->segment) < d.segment_nodes.size())
                    blame = d.segment_nodes[static_cast<std::size_t>(problem->kind == ProfileProblem::Kind::self_intersecting && problem->other >= 0 ? problem->other : problem->segment)];
                error(*blame, "part '" + name + "': " + problem->message);
                continue;
            }
            shape.profiles.push_back(counter_clockwise(d.profile));
        }
        if (ok)
            if (auto apart = check_profiles_apart(shape.profiles, eps)) error(*drawn[static_cast<std::size_t>(apart->other)].item, "part '" + name + "': " + apart->message);
    }
    // Placement: turn about the frame's origin, then move it to (at x y).
    Eigen::Isometry2d place = Eigen::Isometry2d::Identity();
    const Eigen::Vector2d origin = at ? Eigen::Vector2d(value(at->x), value(at->y)) : Eigen::Vector2d::Zero();
    place.translate(origin);
    if (turn) place.rotate(value(turn->degrees) * degree);
    Part p;
    p.name = name;
    for (const auto& profile : shape.profiles) p.profiles.push_back(transformed(profile, place));
    const double size = std::max(p.size(), 1e-300);
    if (!dof) {
        if (!unknown) error(e, "part '" + name + "' needs its degree of freedom: (fixed), (rotation [pivot]) or (translation (dx dy) (limits lo hi))");
    } else {
        const std::string kind = lower(dof->keyword.text);
        if (kind == "fixed") {
            p.dof.kind = PolygonDof::Kind::fixed;
        } else if (kind == "rotation") {
            p.dof.kind = PolygonDof::Kind::rotation;
            p.dof.pivot = dof->vector ? point(*dof->vector) : origin;
        } else {
            p.dof.kind = PolygonDof::Kind::translation;
            const Eigen::Vector2d axis = point(*dof->vector);
            if (!(axis.norm() > 0)) error(*dof->vector, "a translation axis must not be (0 0)");
            else p.dof.axis = axis.normalized();
            p.lo = value(dof->limits->lo);
            p.hi = value(dof->limits->hi);
            if (!(p.lo < p.hi)) error(*dof->limits, "translation limits must have lo < hi, not " + num(p.lo) + " and " + num(p.hi));
        }
    }
    // Symmetry: a generated wheel keeps its n-fold symmetry when it turns about its own centre;
    // a drawing may declare one, which is checked.
    if (p.rotates() && (p.dof.pivot - origin).norm() <= 1e-9 * size) p.symmetry = shape.symmetry;
    if (symmetry) {
        const auto n = whole(symmetry->n, 1, 10000, "a symmetry");
        if (!p.rotates()) {
            error(*symmetry, "(symmetry n) needs a part that rotates");
        } else if (n && ok) {
            const Eigen::Isometry2d t = Eigen::Translation2d(p.dof.pivot) * Eigen::Rotation2Dd(2 * std::numbers::pi / *n) * Eigen::Translation2d(-p.dof.pivot);
            double worst = 0;
            for (const auto& profile : p.profiles)
                for (const auto& s : profile.segments)
                    for (double u : {0.0, 0.5}) {
                        double d = 1e300;
                        for (const auto& other : p.profiles)
                            for (const auto& s2 : other.segments) d = std::min(d, closest_point(s2, t * s.point_at(u)).distance);
                        worst = std::max(worst, d);
                    }
            if (worst > 1e-7 * size)
                error(*symmetry, "part '" + name + "' is not " + std::to_string(*n) + "-fold symmetric about its pivot (a point turned by 360/" +
                                     std::to_string(*n) + " degrees lands " + num(worst) + " off its outline)");
            else p.symmetry = *n;
        }
    }
    if (ok) {
        m.parts.push_back(std::move(p));
        m.part_where.push_back(where(e));
    } else {
        // Keep the name known, so later references to it are not reported as unknown.
        Part placeholder;
        placeholder.name = name;
        m.parts.push_back(std::move(placeholder));
        m.part_where.push_back(where(e));
    }
    ok = ok && was_ok;
}

}  // namespace qm::geometry::detail
