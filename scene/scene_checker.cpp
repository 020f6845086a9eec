// scene/scene_checker.cpp: raw AST -> checked Scene (scene/scene_checker.hpp). Implements the
// well-formedness conditions of the scene description of thesis section 6.1 / Figure 6.1, with
// corners (section 3.1.1, Definition 18) and linkages (Definition 21). This file holds the
// driver (section order and multiplicity, dimensions, Individuals, Descriptions); the other
// concerns are in scene_checker_{directions,surfaces,constraints,situations}.cpp
// (scene/detail/scene_checker.hpp).
#include "scene/scene_checker.hpp"

#include "scene/detail/scene_checker.hpp"
#include "qm/spelling.hpp"

namespace qm::scene {
namespace detail {

std::optional<Scene> SceneChecker::run(const ast::Scenario& s) {
    scene_.name = lower(s.name.text);
    scene_.where = cx_.where(s.name);
    dimensions(s.dimensions);
    collect_sections(s);
    contact_list(s);
    reserve_tables();
    if (!individuals_) {
        cx_.error(s.name, "scene '" + s.name.text + "' has no Individuals section");
    } else {
        individuals(*individuals_);
    }
    for (const auto* d : descriptions_) descriptions(*d);
    index_corner_names();
    for (const auto* d : surfaces_) surfaces(*d);
    // After every Surfaces entry, whatever the section order: a corner's sides are surfaces,
    // and corners take the SurfaceIds after the faces' (the order the printers write).
    for (const auto* c : corners_) corners(*c);
    for (const auto* c : trans_) constraints(c->entries, true);
    for (const auto* c : rot_) constraints(c->entries, false);
    for (const auto* f : forces_)
        for (const auto& e : f->entries)
            if (auto force = check_force(e)) scene_.forces.push_back(*force);
    for (const auto* l : linkages_) linkages(*l);
    for (const auto* sit : situations_) situation(*sit);
    if (cx_.errors() > 0) return std::nullopt;
    return std::move(scene_);
}

// The tables are sized from the AST before they are filled: grown by doubling, the objects' and
// surfaces' tables and their name indexes held up to twice what they used, a sixth of the peak
// memory of reading a large scene, which is reached while the AST is alive.
void SceneChecker::reserve_tables() {
    std::size_t surfaces = 0;
    for (const auto* d : surfaces_)
        for (const auto& g : d->entries) surfaces += g.surfaces.size();
    for (const auto* c : corners_)
        for (const auto& g : c->entries) surfaces += g.corners.size();
    if (individuals_) {
        scene_.objects.reserve(individuals_->names.size());
        object_ids_.reserve(individuals_->names.size());
    }
    scene_.surfaces.reserve(surfaces);
    surface_ids_.reserve(surfaces);
    surface_names_.reserve(surfaces);
    scene_.situations.reserve(situations_.size());
}

void SceneChecker::adopt(const Scene& scene) {
    scene_ = scene;
    cx_.set_dimensions(scene.dimensions);
    for (std::uint32_t i = 0; i < scene_.objects.size(); ++i) object_ids_.emplace(scene_.objects[ObjectId{i}].name, ObjectId{i});
    for (std::uint32_t i = 0; i < scene_.surfaces.size(); ++i)
        surface_ids_.emplace(scene_.surfaces[SurfaceId{i}].name, SurfaceId{i});
}

std::optional<ObjectId> SceneChecker::find_object(const std::string& name) const {
    auto it = object_ids_.find(name);
    if (it == object_ids_.end()) return std::nullopt;
    return it->second;
}

std::optional<SurfaceId> SceneChecker::find_surface(const std::string& name) const {
    auto it = surface_ids_.find(name);
    if (it == surface_ids_.end()) return std::nullopt;
    return it->second;
}

void SceneChecker::dimensions(const ast::Dimensions& d) {
    if (d.text == "2" || d.text == "3") {
        scene_.dimensions = d.text[0] - '0';
    } else {
        cx_.error(d, "the number of dimensions must be 2 or 3 but found '" + d.text + "'");
    }
    cx_.set_dimensions(scene_.dimensions);
}

// Each section kind may appear once (Figure 6.1); situations may repeat (keyword notation).
template <class T>
void SceneChecker::once(const T& section, const T*& slot, std::vector<const T*>& all, const char* keyword,
                        const std::string& reading) {
    if (slot) {
        cx_.error(section, std::string("duplicate ") + keyword + " section" + reading,
                  {std::string("the first ") + keyword + " section is at " + cx_.at(*slot)});
        return;
    }
    slot = &section;
    all.push_back(&section);
}

// A bare constraint list of the kind decided is registered as a keyworded copy of itself (same
// position), so that it counts against the keyworded sections as Figure 6.1 intends.
void SceneChecker::bare(const ast::BareConstraints& b, std::optional<bool> translational,
                        const ast::TransConstraints*& t1, const ast::RotConstraints*& r1) {
    if (!translational) return;
    const std::string reading = " (a list without its keyword after Surfaces is read as one, Figure 6.1)";
    if (*translational) {
        ast::TransConstraints& t = bare_trans_.emplace_back();
        static_cast<ast::x3::position_tagged&>(t) = b;
        t.entries = b.entries;
        once(t, t1, trans_, "Translational-Constraints", reading);
    } else {
        ast::RotConstraints& r = bare_rot_.emplace_back();
        static_cast<ast::x3::position_tagged&>(r) = b;
        r.entries = b.entries;
        once(r, r1, rot_, "Rotational-Constraints", reading);
    }
}

void SceneChecker::collect_sections(const ast::Scenario& s) {
    const ast::Descriptions* d1 = nullptr;
    const ast::Surfaces* s1 = nullptr;
    const ast::TransConstraints* t1 = nullptr;
    const ast::RotConstraints* r1 = nullptr;
    const ast::Forces* f1 = nullptr;
    const ast::Corners* c1 = nullptr;
    const ast::Linkages* l1 = nullptr;
    std::vector<const ast::Individuals*> ind;
    for (std::size_t i = 0; i < s.sections.size(); ++i) {
        const auto& v = s.sections[i].get();
        if (const auto* p = boost::get<ast::Individuals>(&v)) once(*p, individuals_, ind, "Individuals");
        else if (const auto* p = boost::get<ast::Descriptions>(&v)) once(*p, d1, descriptions_, "Descriptions");
        else if (const auto* p = boost::get<ast::Surfaces>(&v)) once(*p, s1, surfaces_, "Surfaces");
        else if (const auto* p = boost::get<ast::TransConstraints>(&v)) once(*p, t1, trans_, "Translational-Constraints");
        else if (const auto* p = boost::get<ast::RotConstraints>(&v)) once(*p, r1, rot_, "Rotational-Constraints");
        else if (const auto* p = boost::get<ast::Forces>(&v)) once(*p, f1, forces_, "Forces");
        else if (const auto* p = boost::get<ast::Corners>(&v)) once(*p, c1, corners_, "Corners");
        else if (const auto* p = boost::get<ast::Linkages>(&v)) once(*p, l1, linkages_, "Linkages");
        else if (const auto* p = boost::get<ast::Situation>(&v)) situations_.push_back(p);
        else if (const auto* p = boost::get<ast::SituationList>(&v))
            for (const auto& sit : p->situations) situations_.push_back(&sit);
        else if (const auto* p = boost::get<ast::BareConstraints>(&v)) bare(*p, bare_kind(s.sections, i), t1, r1);
    }
    for (const auto& sit : s.situations) situations_.push_back(&sit);
}

// Figures 7.12 and 7.16 end with `CONTACT (a b), (c d)` and no other situation: the contacts of
// the one situation analysed (Figure 7.17 needs both of 7.16's contacts at once). Beside other
// situations it could be one more or part of the last, so it is then an error.
void SceneChecker::contact_list(const ast::Scenario& s) {
    if (!s.contact_list) return;
    if (!situations_.empty()) {
        cx_.error(*s.contact_list,
                  "a closing CONTACT list is read as the scene's only situation (Figures 7.12, 7.16), but this "
                  "scene has other situations; write it as 'Situation : Contact (a b), Contact (c d)'",
                  {"the first other situation is at " + cx_.at(*situations_.front())});
        return;
    }
    situations_.push_back(&*s.contact_list);
}

void SceneChecker::individuals(const ast::Individuals& ind) {
    if (ind.names.empty()) cx_.error(ind, "Individuals names no object");
    for (const auto& n : ind.names) {
        const std::string name = lower(n.text);
        if (auto prev = find_object(name)) {
            cx_.error(n, "duplicate object '" + name + "'",
                      {"'" + name + "' is first declared at " + line_column(scene_.objects[*prev].where)});
            continue;
        }
        Object o;
        o.name = name;
        o.where = cx_.where(n);
        object_ids_.emplace(name, scene_.objects.push_back(std::move(o)));
    }
}

std::optional<ObjectId> SceneChecker::object(const ast::Name& n, const char* section) {
    const std::string name = lower(n.text);
    auto id = find_object(name);
    if (!id) {
        std::vector<std::string_view> names;
        for (const Object& o : scene_.objects) names.push_back(o.name);
        cx_.error(n, "object '" + name + "' in " + section + " is not declared in Individuals" + did_you_mean(name, names));
    }
    return id;
}

void SceneChecker::descriptions(const ast::Descriptions& d) {
    std::map<std::string, const ast::Description*> seen;
    for (const auto& e : d.entries) {
        const std::string kind = lower(e.kind.text);
        if (kind != "rigid-ob") cx_.error(e.kind, "unknown object description '" + e.kind.text + "' (only rigid-ob is known)");
        auto id = object(e.object, "Descriptions");
        if (!id) continue;
        const std::string name = scene_.objects[*id].name;
        if (auto it = seen.find(name); it != seen.end()) {
            cx_.error(e, "object '" + name + "' is described twice", {"the first description is at " + cx_.at(*it->second)});
            continue;
        }
        seen.emplace(name, &e);
        scene_.objects[*id].description = kind;
        scene_.objects[*id].described_at = cx_.where(e);
    }
}

}  // namespace detail

std::optional<Scene> check_scene(const ast::Scenario& scenario, const PositionTable& positions, const SourceText& src,
                                 Diagnostics& diags) {
    return detail::SceneChecker(positions, src, diags).run(scenario);
}

}  // namespace qm::scene
