// bridge/detail/alex_scene_builder.cpp: the Alex scene model of a mechanism at one configuration,
// item by item (thesis 2.4, 3.1.1, 8.2.1; bridge/scene_at_config.hpp's table).
#include "bridge/detail/alex_scene_builder.hpp"

#include "geometry/external_force.hpp"
#include "geometry/qualitative_sign.hpp"

#include <algorithm>
#include <vector>

namespace qm::bridge::detail {
namespace {

namespace g = qm::geometry;
namespace a = qm::scene;

a::Sign sign_of(std::int8_t s) { return s > 0 ? a::Sign::plus : s < 0 ? a::Sign::minus : a::Sign::zero; }
a::Direction direction_of(g::QualDirection d) { return {sign_of(d.s[0]), sign_of(d.s[1])}; }
a::DirectionPattern pattern_of(g::QualDirection d) { return {a::PatternSlot{sign_of(d.s[0]), {}}, a::PatternSlot{sign_of(d.s[1]), {}}}; }
// (?x ?y): every translation; (?r): every rotation.
a::DirectionPattern any_translation() { return {a::PatternSlot{std::nullopt, "x"}, a::PatternSlot{std::nullopt, "y"}}; }
a::DirectionPattern any_rotation() { return {a::PatternSlot{std::nullopt, "r"}}; }

// The order in which print_scene writes the surfaces, and so the reader numbers them: the faces,
// object by object (objects in the order of their first face), then the corners likewise.
std::vector<a::SurfaceId> printed_order(const a::Scene& s) {
    std::vector<a::SurfaceId> out;
    for (bool corners : {false, true}) {
        std::vector<std::vector<a::SurfaceId>> groups;
        for (const a::Object& o : s.objects) {
            std::vector<a::SurfaceId> members;
            for (a::SurfaceId id : o.surfaces)
                if (s.surfaces[id].is_corner() == corners) members.push_back(id);
            if (!members.empty()) groups.push_back(std::move(members));
        }
        std::sort(groups.begin(), groups.end(), [](const auto& x, const auto& y) { return x.front() < y.front(); });
        for (const auto& members : groups) out.insert(out.end(), members.begin(), members.end());
    }
    return out;
}

}  // namespace

AlexSceneBuilder::AlexSceneBuilder(const g::Mechanism& m, const g::Configuration& q) : m_(m), q_(q) {
    scene_.name = m.name;
    scene_.dimensions = 2;
    scene_.where = m.where;
    // One object per part, except that parts on one shaft are one rigid body (Def 21): the first
    // part named in the linkage stands for all.
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
    scene_.situations.front().where = m.where;
}

double AlexSceneBuilder::zero_length(const g::Part& p) const { return m_.settings.contact_tolerance * p.size(); }

a::Object AlexSceneBuilder::object_for(g::PartId p) const {
    const g::Part& part = m_.parts[p];
    a::Object o;
    o.name = part.name;
    o.where = p.value < m_.part_where.size() ? m_.part_where[p.value] : m_.where;
    if (part.fixed()) {
        o.trans_constraints.push_back(any_translation());
        o.rot_constraints.push_back(any_rotation());
    } else if (part.rotates()) {
        o.trans_constraints.push_back(any_translation());  // pinned: turns only
    } else {
        // Slides along its axis only: every other translation is constrained, and so is the way
        // out past a limit it stands at.
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

a::CauseId AlexSceneBuilder::cause(const std::string& name) {
    if (auto c = scene_.find_cause(name)) return *c;
    return scene_.causes.push_back({name, true});
}

void AlexSceneBuilder::add_contacts(const g::PairSpec& pair, const g::ContactResult& r) {
    for (const auto& c : r.contacts) {
        a::Contact k;
        k.first = feature(pair.a, c.first, c.second, r.tolerance, pair.where);
        k.second = feature(pair.b, c.second, c.first, r.tolerance, pair.where);
        k.where = pair.where;
        auto& list = scene_.situations.front().contacts;
        if (std::find(list.begin(), list.end(), k) == list.end()) list.push_back(k);
    }
}

void AlexSceneBuilder::add_forces() {
    for (const auto& f : m_.forces) {
        const g::Part& part = m_.parts[f.part];
        const double q = q_.at(f.part);
        if (!g::force_active(f, part, q)) continue;
        a::Force out;
        out.object = object_.at(f.part.value);
        out.cause = cause(f.cause);
        out.where = f.where;
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

a::SurfaceId AlexSceneBuilder::feature(g::PartId p, const g::ContactFeature& f, const g::ContactFeature& other, double tol,
                                       const SourceLocation& where) {
    // The contact's normal: a face's own, or, for a corner, the face it touches (3.1.1: the corner
    // takes the reverse of that face's normal). Two corners have no one normal (Def 26).
    std::optional<Eigen::Vector2d> normal;
    if (f.kind == g::FeatureKind::surface) normal = f.normal;
    else if (other.kind == g::FeatureKind::surface) normal = other.normal;
    return f.kind == g::FeatureKind::corner ? corner(p, f, normal, tol, where) : surface(p, f, normal, tol, where);
}

a::SurfaceId AlexSceneBuilder::named(a::Surface s, const std::string& base) {
    for (int n = 1;; ++n) {
        s.name = n == 1 ? base : base + "-" + std::to_string(n);
        const auto existing = scene_.find_surface(s.name);
        if (!existing) break;
        if (scene_.surfaces[*existing] == s) return *existing;
    }
    const a::SurfaceId id = scene_.surfaces.push_back(s);
    scene_.objects[s.object].surfaces.push_back(id);
    return id;
}

g::QualDirection AlexSceneBuilder::origin(g::PartId p, const Eigen::Vector2d& point, const std::optional<Eigen::Vector2d>& contact_normal,
                                          double tol) const {
    const g::Part& part = m_.parts[p];
    const double zero = std::max(tol, zero_length(part));
    if (!contact_normal) return g::origin_direction(part, q_.at(p), point, zero);
    return g::origin_direction_at_contact(part, q_.at(p), point, *contact_normal, zero, m_.settings.normal_zero_tolerance);
}

// A point of a segment: an Alex surface with the segment's normal there (an Alex surface is a set
// of qualitatively equivalent points, so one segment may need several).
a::SurfaceId AlexSceneBuilder::surface(g::PartId p, const g::ContactFeature& f, const std::optional<Eigen::Vector2d>& contact_normal,
                                       double tol, const SourceLocation& where) {
    const g::Part& part = m_.parts[p];
    a::Surface s;
    s.object = object_.at(p.value);
    s.normal = direction_of(g::qualitative(f.normal, m_.settings.normal_zero_tolerance));
    s.origin = direction_of(origin(p, f.point, contact_normal, tol));
    s.where = where;
    return named(std::move(s), part.name + "-s" + std::to_string(g::global_segment(part, f.profile, f.segment) + 1));
}

// A convex corner: its two sides as faces, and the corner between them, with its own origin
// direction (Def 18).
a::SurfaceId AlexSceneBuilder::corner(g::PartId p, const g::ContactFeature& f, const std::optional<Eigen::Vector2d>& contact_normal,
                                      double tol, const SourceLocation& where) {
    const g::Part& part = m_.parts[p];
    g::ContactFeature before = f, after = f;
    before.kind = after.kind = g::FeatureKind::surface;
    before.segment = f.previous;
    before.normal = f.sides[0];
    after.normal = f.sides[1];
    a::Surface s;
    s.object = object_.at(p.value);
    s.corner = a::CornerSides{surface(p, before, std::nullopt, tol, where), surface(p, after, std::nullopt, tol, where)};
    s.origin = direction_of(origin(p, f.point, contact_normal, tol));
    s.where = where;
    return named(std::move(s), part.name + "-c" + std::to_string(g::global_segment(part, f.profile, f.segment) + 1));
}

a::Scene AlexSceneBuilder::finish() && {
    const std::vector<a::SurfaceId> order = printed_order(scene_);
    std::vector<a::SurfaceId> renamed(order.size(), a::SurfaceId{0});
    for (std::uint32_t i = 0; i < order.size(); ++i) renamed[order[i].value] = a::SurfaceId{i};
    IdVector<a::SurfaceId, a::Surface> surfaces;
    for (a::SurfaceId old : order) {
        a::Surface s = scene_.surfaces[old];
        if (s.corner) s.corner = a::CornerSides{renamed[s.corner->first.value], renamed[s.corner->second.value]};
        surfaces.push_back(std::move(s));
    }
    scene_.surfaces = std::move(surfaces);
    for (a::Object& o : scene_.objects) {
        for (a::SurfaceId& id : o.surfaces) id = renamed[id.value];
        std::sort(o.surfaces.begin(), o.surfaces.end());
    }
    for (a::Situation& sit : scene_.situations)
        for (a::Contact& c : sit.contacts) c = a::Contact{renamed[c.first.value], renamed[c.second.value], c.where};
    return std::move(scene_);
}

}  // namespace qm::bridge::detail
