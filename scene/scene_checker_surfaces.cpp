// scene/scene_checker_surfaces.cpp: the scene checker's surfaces and corners
// (scene/detail/scene_checker.hpp). Surfaces are a normal and an origin direction (section 2.4);
// a corner is where two surfaces of its object meet (section 3.1.1, Definition 18), a surface of
// zero extent. Faces and corners share one namespace of surface names.
#include "scene/detail/scene_checker.hpp"

#include <algorithm>
#include <tuple>

namespace qm::scene::detail {

// The owner of one object's group in Surfaces or Corners; empty (after reporting) when the
// object is undeclared or its group was already given.
template <class Group>
std::optional<ObjectId> SceneChecker::group_owner(const Group& g, std::map<ObjectId, const Group*>& groups,
                                                  const char* section, const char* what) {
    auto id = object(g.object, section);
    if (!id) return id;
    if (auto it = groups.find(*id); it != groups.end()) {
        cx_.error(g.object, std::string("the ") + what + " of '" + scene_.objects[*id].name + "' are listed twice",
                  {"the first list is at " + cx_.at(*it->second)});
        return std::nullopt;
    }
    groups.emplace(*id, &g);
    return id;
}

void SceneChecker::surfaces(const ast::Surfaces& s) {
    std::map<ObjectId, const ast::ObjectSurfaces*> groups;
    for (const auto& g : s.entries) {
        auto id = group_owner(g, groups, "Surfaces", "surfaces");
        for (const auto& e : g.surfaces) surface(e, id);
    }
}

// `second` reuses the name declared at `first` (Definition 18 makes corners surfaces, so one
// namespace serves both). The first declaration in the source is the one kept.
void SceneChecker::duplicate_surface(const ast::Name& first, std::optional<ObjectId> first_owner,
                                     const ast::Name& second, std::optional<ObjectId> second_owner) {
    const std::string name = lower(second.text);
    const std::string note = "'" + name + "' is first declared at " + cx_.at(first);
    if (first_owner && second_owner && *first_owner != *second_owner)
        cx_.error(second, "surface '" + name + "' is owned by two objects, '" + scene_.objects[*first_owner].name +
                              "' and '" + scene_.objects[*second_owner].name + "'", {note});
    else
        cx_.error(second, "duplicate surface '" + name + "'", {note});
}

// The first corner declared under each name, with its group's object, so that a face declared
// after it (Surfaces may follow Corners) is the one reported, although faces are checked first.
void SceneChecker::index_corner_names() {
    for (const auto* c : corners_)
        for (const auto& g : c->entries)
            for (const auto& e : g.corners)
                first_corner_.emplace(lower(e.name.text), std::pair(&e.name, find_object(lower(g.object.text))));
}

SurfaceId SceneChecker::add_surface(Surface s, const ast::Name& n) {
    const ObjectId owner = s.object;
    const std::string name = s.name;
    const SurfaceId id = scene_.surfaces.push_back(std::move(s));
    surface_ids_.emplace(name, id);
    scene_.objects[owner].surfaces.push_back(id);
    surface_names_.push_back(&n);
    return id;
}

void SceneChecker::surface(const ast::SurfaceEntry& e, std::optional<ObjectId> owner) {
    const std::string name = lower(e.name.text);
    auto normal = cx_.direction(e.normal, scene_.translation_arity(), "a surface normal");
    auto origin = cx_.direction(e.origin, scene_.translation_arity(), "a direction to the centre of rotation");
    if (normal && std::all_of(normal->begin(), normal->end(), [](Sign x) { return x == Sign::zero; }))
        cx_.error(e.normal, "surface '" + name + "' has a zero normal; a surface normal points out of its object");
    if (auto prev = find_surface(name))
        return duplicate_surface(*surface_names_[prev->value], scene_.surfaces[*prev].object, e.name, owner);
    if (auto k = first_corner_.find(name); k != first_corner_.end() && cx_.offset(*k->second.first) < cx_.offset(e.name))
        return duplicate_surface(*k->second.first, k->second.second, e.name, owner);
    if (!owner || !normal || !origin) return;
    add_surface({name, *owner, *normal, *origin, std::nullopt, cx_.where(e.name)}, e.name);
}

// Corners (section 3.1.1): declared group by group, then their sides are resolved, so that a
// side naming a corner declared anywhere is reported as a corner rather than as unknown.
void SceneChecker::corners(const ast::Corners& c) {
    std::map<ObjectId, const ast::ObjectCorners*> groups;
    std::vector<std::tuple<const ast::CornerEntry*, ObjectId, std::optional<SurfaceId>>> declared;
    for (const auto& g : c.entries) {
        auto id = group_owner(g, groups, "Corners", "corners");
        for (const auto& e : g.corners) {
            auto k = corner(e, id);
            if (id) declared.emplace_back(&e, *id, k);  // sides checked even when the corner is not kept
        }
    }
    for (const auto& [e, owner, k] : declared) corner_sides(*e, owner, k);
}

// A corner has zero extent, hence no normal; its origin direction is a surface's (Def 18).
std::optional<SurfaceId> SceneChecker::corner(const ast::CornerEntry& e, std::optional<ObjectId> owner) {
    const std::string name = lower(e.name.text);
    auto origin = cx_.direction(e.origin, scene_.translation_arity(), "a direction to the centre of rotation");
    if (auto prev = find_surface(name)) {  // a face before it, or a corner declared before it
        duplicate_surface(*surface_names_[prev->value], scene_.surfaces[*prev].object, e.name, owner);
        return std::nullopt;
    }
    if (!owner || !origin) return std::nullopt;
    return add_surface({name, *owner, {}, *origin, CornerSides{}, cx_.where(e.name)}, e.name);
}

// Definition 18: Corner(x, s1, s2) names two surfaces of x's object that meet at x. `k` is
// the corner's id when it was kept.
void SceneChecker::corner_sides(const ast::CornerEntry& e, ObjectId owner, std::optional<SurfaceId> k) {
    const std::string corner = lower(e.name.text);
    auto side = [&](const ast::Name& n) -> std::optional<SurfaceId> {
        const std::string name = lower(n.text);
        auto s = find_surface(name);
        if (!s) {
            cx_.error(n, "unknown surface '" + name + "' named as a side of corner '" + corner + "'");
        } else if (scene_.surfaces[*s].is_corner()) {
            cx_.error(n, "side '" + name + "' of corner '" + corner +
                             "' is itself a corner; a corner's sides are surfaces of its object");
        } else if (scene_.surfaces[*s].object != owner) {
            cx_.error(n, "side '" + name + "' of corner '" + corner + "' belongs to '" +
                             scene_.objects[scene_.surfaces[*s].object].name + "', not to '" +
                             scene_.objects[owner].name + "'; a corner's sides are surfaces of its object");
        } else {
            return s;
        }
        return std::nullopt;
    };
    auto a = side(e.first);
    auto b = side(e.second);
    if (a && b && *a == *b)
        cx_.error(e.second, "corner '" + corner + "' names the side '" + scene_.surfaces[*a].name +
                                "' twice; a corner is where two different surfaces meet");
    if (a && b && k) scene_.surfaces[*k].corner = CornerSides{*a, *b};
}

}  // namespace qm::scene::detail
