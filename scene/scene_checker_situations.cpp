// scene/scene_checker_situations.cpp: the scene checker's situations (the configuration
// descriptors of Figure 6.1: contacts between surfaces of two objects, forces, given motions),
// and the checks of a `--given` motion and of a query fact against a checked Scene
// (scene/scene_checker.hpp, scene/detail/scene_checker.hpp).
#include "scene/scene_checker.hpp"

#include "scene/detail/scene_checker.hpp"
#include "scene/direction_text.hpp"
#include "qm/spelling.hpp"

#include <algorithm>

namespace qm::scene {

std::string normals_not_opposite(const Scene& scene, SurfaceId a, SurfaceId b) {
    const Surface& x = scene.surfaces[a];
    const Surface& y = scene.surfaces[b];
    if (x.corner || y.corner || x.normal.empty() || y.normal.empty()) return {};  // a corner takes the other's reverse (3.1.1)
    Direction reverse = y.normal;
    for (Sign& s : reverse) s = s == Sign::plus ? Sign::minus : s == Sign::minus ? Sign::plus : Sign::zero;
    if (x.normal == reverse) return {};
    return "Contact (" + x.name + " " + y.name + "): the surface normals " + thesis_text(x.normal) + " of '" + x.name +
           "' and " + thesis_text(y.normal) + " of '" + y.name +
           "' are not opposite, but those of two surfaces in contact are (section 3.1.1): the laws will use each "
           "surface's own normal; check the surfaces named or their normals";
}

namespace detail {

std::optional<SurfaceId> SceneChecker::surface_ref(const ast::Name& n) {
    const std::string name = lower(n.text);
    auto id = find_surface(name);
    if (!id) {
        std::vector<std::string_view> names;
        for (const Surface& s : scene_.surfaces) names.push_back(s.name);
        cx_.error(n, "unknown surface '" + name + "'" + did_you_mean(name, names));
    }
    return id;
}

std::optional<Motion> SceneChecker::motion(const ast::MotionEntry& e) {
    auto id = object(e.object, "a motion");
    auto t = cx_.direction(e.translation, scene_.translation_arity(), "a translational motion");
    auto r = cx_.direction(e.rotation, scene_.rotation_arity(), "a rotational motion");
    if (!id || !t || !r) return std::nullopt;
    return Motion{*id, *t, *r, cx_.where(e)};
}

struct SceneChecker::DescriptorVisitor {
    SceneChecker& c;
    Situation& out;
    void operator()(const ast::ContactEntry& e) const {
        auto a = c.surface_ref(e.first);
        auto b = c.surface_ref(e.second);
        if (!a || !b) return;
        if (*a == *b) {
            c.cx_.error(e.second, "a surface cannot be in contact with itself");
        } else if (c.scene_.owner(*a) == c.scene_.owner(*b)) {
            c.cx_.error(e, "surfaces '" + c.scene_.surfaces[*a].name + "' and '" + c.scene_.surfaces[*b].name +
                               "' both belong to '" + c.scene_.objects[c.scene_.owner(*a)].name +
                               "'; a contact joins two different objects");
        } else {
            out.contacts.push_back({*a, *b, c.cx_.where(e)});
            if (std::string why = normals_not_opposite(c.scene_, *a, *b); !why.empty()) c.cx_.warning(e, why);
        }
    }
    void operator()(const ast::ForceEntry& e) const {
        if (auto f = c.check_force(e)) out.forces.push_back(*f);
    }
    // One current motion per object: a second Motion of the same object in one situation would
    // leave no consistent combination (Law 1), or repeat the first, so it is an error like other
    // duplicates.
    void operator()(const ast::MotionEntry& e) const {
        auto m = c.motion(e);
        if (!m) return;
        auto first = std::find_if(out.motions.begin(), out.motions.end(), [&](const Motion& x) { return x.object == m->object; });
        if (first == out.motions.end()) {
            out.motions.push_back(*m);
            return;
        }
        const std::string name = c.scene_.objects[m->object].name;
        const bool same = first->translation == m->translation && first->rotation == m->rotation;
        c.cx_.error(e, same ? "the motion of '" + name + "' is given twice in one situation"
                            : "two different motions of '" + name + "' in one situation: an object has one motion at "
                              "a time (Law 1), so no combination of motions would be consistent",
                    {"the first Motion of '" + name + "' in this situation is at " + line_column(first->where)});
    }
};

void SceneChecker::situation(const ast::Situation& s) {
    Situation out;
    out.where = cx_.where(s);
    // Most descriptors of a large situation are contacts; sized once rather than by doubling.
    out.contacts.reserve(s.descriptors.size());
    for (const auto& d : s.descriptors) boost::apply_visitor(DescriptorVisitor{*this, out}, d.get());
    scene_.situations.push_back(std::move(out));
}

}  // namespace detail

std::optional<Motion> check_given(const ast::MotionEntry& given, const Scene& scene, const PositionTable& positions,
                                  const SourceText& src, Diagnostics& diags) {
    detail::SceneChecker c(positions, src, diags);
    c.adopt(scene);
    auto m = c.motion(given);
    return c.cx_.errors() > 0 ? std::nullopt : m;
}

std::optional<AddedForce> check_force_text(const ast::ForceEntry& entry, const Scene& scene, const PositionTable& positions,
                                           const SourceText& src, Diagnostics& diags) {
    detail::SceneChecker c(positions, src, diags);
    c.adopt(scene);
    auto f = c.check_force(entry);
    if (!f || c.cx_.errors() > 0) return std::nullopt;
    AddedForce out{*f, std::nullopt};
    // check_force numbers a cause the scene lacks after the adopted scene's causes: a named new
    // cause, or an implicit one for an entry without a name.
    if (f->cause.value >= scene.causes.size()) {
        const std::string implicit = "with#" + std::to_string(f->cause.value + 1);
        out.new_cause = entry.cause ? Cause{detail::lower(entry.cause->text), true} : Cause{implicit, false};
    }
    return out;
}

std::optional<QueryFact> check_query(const ast::QueryFact& fact, const Scene& scene, const PositionTable& positions,
                                     const SourceText& src, Diagnostics& diags) {
    detail::SceneChecker c(positions, src, diags);
    c.adopt(scene);
    const std::string pred = detail::lower(fact.predicate.text);
    using K = QueryFact::Kind;
    static const std::map<std::string, K> kinds = {
        {"translational-motion", K::translational_motion}, {"rotational-motion", K::rotational_motion},
        {"translational-freedom", K::translational_freedom}, {"rotational-freedom", K::rotational_freedom},
        {"contact", K::contact}, {"force", K::force}};
    auto it = kinds.find(pred);
    if (it == kinds.end()) {
        static const std::vector<std::string_view> spelled = {"Translational-Motion", "Rotational-Motion",
                                                             "Translational-Freedom", "Rotational-Freedom", "Contact", "Force"};
        std::vector<std::string> lowered;
        for (std::string_view k : spelled) lowered.push_back(detail::lower(std::string(k)));
        std::string hint;
        if (auto near = nearest_spelling(pred, lowered))
            hint = "; did you mean '" + std::string(spelled[static_cast<std::size_t>(std::find(lowered.begin(), lowered.end(), *near) - lowered.begin())]) + "'?";
        c.cx_.error(fact.predicate, "unknown predicate '" + fact.predicate.text +
                                        "': expected Translational-Motion, Rotational-Motion, Translational-Freedom, "
                                        "Rotational-Freedom, Contact or Force" + hint);
        return std::nullopt;
    }
    QueryFact out;
    out.kind = it->second;
    if (out.kind == K::contact) {
        if (!fact.second) c.cx_.error(fact.first, "Contact needs two surfaces");
        if (fact.direction) c.cx_.error(*fact.direction, "Contact takes no direction");
        auto a = c.surface_ref(fact.first);
        auto b = fact.second ? c.surface_ref(*fact.second) : std::nullopt;
        out.first = a;
        out.second = b;
    } else {
        out.object = c.object(fact.first, "the fact");
        if (fact.second && out.kind != K::force) c.cx_.error(*fact.second, pred + " takes one object but found a second name");
        if (out.kind == K::force) {
            if (fact.direction) c.cx_.error(*fact.direction, "Force names an object and, optionally, a cause");
            if (fact.second && out.object) {
                // `Force obj CAUSE`: the force(s) of that named cause on obj.
                const std::string cause = detail::lower(fact.second->text);
                auto id = scene.find_cause(cause);
                auto mine = [&](const Force& f) { return f.object == *out.object && id && f.cause == *id; };
                const bool on_object = std::any_of(scene.forces.begin(), scene.forces.end(), mine) ||
                                       std::any_of(scene.situations.begin(), scene.situations.end(), [&](const Situation& s) {
                                           return std::any_of(s.forces.begin(), s.forces.end(), mine);
                                       });
                if (!id || !scene.causes[*id].is_explicit || !on_object)
                    c.cx_.error(*fact.second, "no force on '" + scene.objects[*out.object].name + "' has the cause '" +
                                                  fact.second->text + "': expected a cause named at the end of a force entry");
                else out.cause = id;
            }
        } else if (!fact.direction) {
            c.cx_.error(fact.first, pred + " needs a direction after the object, like (" + fact.first.text + " (0 +))");
        } else {
            const bool rot = out.kind == K::rotational_motion || out.kind == K::rotational_freedom;
            auto d = c.cx_.direction(*fact.direction, rot ? scene.rotation_arity() : scene.translation_arity(),
                                     rot ? "a rotation" : "a translation");
            if (d) out.direction = *d;
        }
    }
    if (c.cx_.errors() > 0) return std::nullopt;
    return out;
}

}  // namespace qm::scene
