// alex/scene_checker.cpp: raw AST -> checked Scene (alex/scene_checker.hpp). Implements the
// well-formedness conditions of the scene description of thesis section 6.1 / Figure 6.1, with
// corners (section 3.1.1, Definition 18) and linkages (Definition 21).
#include "alex/scene_checker.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <tuple>

namespace qm::alex {
namespace {

std::string lower(const std::string& s) {
    std::string out = s;
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string plural(std::size_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// Reports located errors and converts the leaves (names, signs, directions) of the AST.
class Context {
public:
    Context(const PositionTable& pos, const SourceText& src, Diagnostics& diags) : pos_(pos), src_(src), diags_(diags) {}

    SourceLocation where(const ast::x3::position_tagged& node) const { return src_.locate(pos_.offset_of(node)); }
    std::size_t offset(const ast::x3::position_tagged& node) const { return pos_.offset_of(node); }

    void error(const ast::x3::position_tagged& node, std::string message, std::vector<std::string> notes = {}) {
        const std::size_t off = pos_.offset_of(node);
        diags_.add({Severity::error, src_.locate(off), std::move(message), src_.line_at(off), std::move(notes)});
        ++errors_;
    }
    [[nodiscard]] std::size_t errors() const noexcept { return errors_; }

    std::string at(const ast::x3::position_tagged& node) const {
        const SourceLocation l = where(node);
        return "line " + std::to_string(l.line) + ", column " + std::to_string(l.column);
    }

    // One sign token; variables (`?x`) only when allowed (constraint entries).
    std::optional<PatternSlot> slot(const ast::SignToken& t, bool allow_variable) {
        const std::string& s = t.text;
        if (s == "+") return PatternSlot{Sign::plus, {}};
        if (s == "0") return PatternSlot{Sign::zero, {}};
        if (s == "-") return PatternSlot{Sign::minus, {}};
        if (s.size() > 1 && s[0] == '?') {
            const bool ok_name = std::all_of(s.begin() + 1, s.end(), [](char c) {
                return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
            });
            if (!ok_name) {
                error(t, "bad variable '" + s + "': a variable is '?' followed by letters, digits, '-' or '_'");
            } else if (!allow_variable) {
                error(t, "variable '" + s + "' is allowed only in constraint entries; write a sign '+', '0' or '-'");
            } else {
                return PatternSlot{std::nullopt, lower(s.substr(1))};
            }
            return std::nullopt;
        }
        if (s == "--")
            error(t, "bad sign '--': a sign is '+', '0' or '-' (the thesis' OCR prints '-' as '--'; write '-')");
        else if (s.size() > 1 && s.find_first_not_of("+-0") == std::string::npos)
            error(t, "bad sign '" + s + "': a sign is one of '+', '0', '-'; separate the signs of a direction by blanks");
        else
            error(t, "bad sign '" + s + "': expected '+', '0' or '-'");
        return std::nullopt;
    }

    std::optional<DirectionPattern> pattern(const ast::Direction& d, std::size_t arity, const std::string& role,
                                            bool allow_variables) {
        DirectionPattern out;
        bool ok = true;
        for (const auto& t : d.parts) {
            auto s = slot(t, allow_variables);
            if (s) out.push_back(*s);
            else ok = false;
        }
        if (ok && d.parts.size() != arity) {
            error(d, role + " needs " + plural(arity, "sign") + " in a " + std::to_string(dims_) + "-D scene but has " +
                         std::to_string(d.parts.size()));
            ok = false;
        }
        return ok ? std::optional(out) : std::nullopt;
    }

    std::optional<Direction> direction(const ast::Direction& d, std::size_t arity, const std::string& role) {
        auto p = pattern(d, arity, role, false);
        if (!p) return std::nullopt;
        Direction out;
        for (const auto& s : *p) out.push_back(*s.sign);
        return out;
    }

    void set_dimensions(int d) { dims_ = d; }

private:
    const PositionTable& pos_;
    const SourceText& src_;
    Diagnostics& diags_;
    std::size_t errors_ = 0;
    int dims_ = 2;
};

class SceneChecker {
public:
    SceneChecker(const PositionTable& pos, const SourceText& src, Diagnostics& diags) : cx_(pos, src, diags) {}

    std::optional<Scene> run(const ast::Scenario& s) {
        scene_.name = lower(s.name.text);
        scene_.where = cx_.where(s.name);
        dimensions(s.dimensions);
        collect_sections(s);
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

private:
    void dimensions(const ast::Dimensions& d) {
        if (d.text == "2" || d.text == "3") {
            scene_.dimensions = d.text[0] - '0';
        } else {
            cx_.error(d, "the number of dimensions must be 2 or 3 but found '" + d.text + "'");
        }
        cx_.set_dimensions(scene_.dimensions);
    }

    // Each section kind may appear once (Figure 6.1); situations may repeat (keyword notation).
    template <class T>
    void once(const T& section, const T*& slot, std::vector<const T*>& all, const char* keyword) {
        if (slot) {
            cx_.error(section, std::string("duplicate ") + keyword + " section",
                      {std::string("the first ") + keyword + " section is at " + cx_.at(*slot)});
            return;
        }
        slot = &section;
        all.push_back(&section);
    }

    void collect_sections(const ast::Scenario& s) {
        const ast::Descriptions* d1 = nullptr;
        const ast::Surfaces* s1 = nullptr;
        const ast::TransConstraints* t1 = nullptr;
        const ast::RotConstraints* r1 = nullptr;
        const ast::Forces* f1 = nullptr;
        const ast::Corners* c1 = nullptr;
        const ast::Linkages* l1 = nullptr;
        std::vector<const ast::Individuals*> ind;
        for (const auto& section : s.sections) {
            const auto& v = section.get();
            if (const auto* p = boost::get<ast::Individuals>(&v)) once(*p, individuals_, ind, "Individuals");
            else if (const auto* p = boost::get<ast::Descriptions>(&v)) once(*p, d1, descriptions_, "Descriptions");
            else if (const auto* p = boost::get<ast::Surfaces>(&v)) once(*p, s1, surfaces_, "Surfaces");
            else if (const auto* p = boost::get<ast::TransConstraints>(&v)) once(*p, t1, trans_, "Translational-Constraints");
            else if (const auto* p = boost::get<ast::RotConstraints>(&v)) once(*p, r1, rot_, "Rotational-Constraints");
            else if (const auto* p = boost::get<ast::Forces>(&v)) once(*p, f1, forces_, "Forces");
            else if (const auto* p = boost::get<ast::Corners>(&v)) once(*p, c1, corners_, "Corners");
            else if (const auto* p = boost::get<ast::Linkages>(&v)) once(*p, l1, linkages_, "Linkages");
            else if (const auto* p = boost::get<ast::Situation>(&v)) situations_.push_back(p);
        }
        for (const auto& sit : s.situations) situations_.push_back(&sit);
    }

    void individuals(const ast::Individuals& ind) {
        if (ind.names.empty()) cx_.error(ind, "Individuals names no object");
        for (const auto& n : ind.names) {
            const std::string name = lower(n.text);
            if (auto prev = scene_.find_object(name)) {
                cx_.error(n, "duplicate object '" + name + "'",
                          {"'" + name + "' is first declared at " + loc(scene_.objects[*prev].where)});
                continue;
            }
            Object o;
            o.name = name;
            o.where = cx_.where(n);
            scene_.objects.push_back(std::move(o));
        }
    }

    std::optional<ObjectId> object(const ast::Name& n, const char* section) {
        const std::string name = lower(n.text);
        auto id = scene_.find_object(name);
        if (!id) cx_.error(n, "object '" + name + "' in " + section + " is not declared in Individuals");
        return id;
    }

    void descriptions(const ast::Descriptions& d) {
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
        }
    }

    // The owner of one object's group in Surfaces or Corners; empty (after reporting) when the
    // object is undeclared or its group was already given.
    template <class Group>
    std::optional<ObjectId> group_owner(const Group& g, std::map<ObjectId, const Group*>& groups, const char* section,
                                        const char* what) {
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

    void surfaces(const ast::Surfaces& s) {
        std::map<ObjectId, const ast::ObjectSurfaces*> groups;
        for (const auto& g : s.entries) {
            auto id = group_owner(g, groups, "Surfaces", "surfaces");
            for (const auto& e : g.surfaces) surface(e, id);
        }
    }

    // `second` reuses the name declared at `first` (Definition 18 makes corners surfaces, so one
    // namespace serves both). The first declaration in the source is the one kept.
    void duplicate_surface(const ast::Name& first, std::optional<ObjectId> first_owner, const ast::Name& second,
                           std::optional<ObjectId> second_owner) {
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
    void index_corner_names() {
        for (const auto* c : corners_)
            for (const auto& g : c->entries)
                for (const auto& e : g.corners)
                    first_corner_.emplace(lower(e.name.text), std::pair(&e.name, scene_.find_object(lower(g.object.text))));
    }

    SurfaceId add_surface(Surface s, const ast::Name& n) {
        const ObjectId owner = s.object;
        const SurfaceId id = scene_.surfaces.push_back(std::move(s));
        scene_.objects[owner].surfaces.push_back(id);
        surface_names_.push_back(&n);
        return id;
    }

    void surface(const ast::SurfaceEntry& e, std::optional<ObjectId> owner) {
        const std::string name = lower(e.name.text);
        auto normal = cx_.direction(e.normal, scene_.translation_arity(), "a surface normal");
        auto origin = cx_.direction(e.origin, scene_.translation_arity(), "a direction to the centre of rotation");
        if (normal && std::all_of(normal->begin(), normal->end(), [](Sign x) { return x == Sign::zero; }))
            cx_.error(e.normal, "surface '" + name + "' has a zero normal; a surface normal points out of its object");
        if (auto prev = scene_.find_surface(name))
            return duplicate_surface(*surface_names_[prev->value], scene_.surfaces[*prev].object, e.name, owner);
        if (auto k = first_corner_.find(name); k != first_corner_.end() && cx_.offset(*k->second.first) < cx_.offset(e.name))
            return duplicate_surface(*k->second.first, k->second.second, e.name, owner);
        if (!owner || !normal || !origin) return;
        add_surface({name, *owner, *normal, *origin, std::nullopt, cx_.where(e.name)}, e.name);
    }

    // Corners (section 3.1.1): declared group by group, then their sides are resolved, so that a
    // side naming a corner declared anywhere is reported as a corner rather than as unknown.
    void corners(const ast::Corners& c) {
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
    std::optional<SurfaceId> corner(const ast::CornerEntry& e, std::optional<ObjectId> owner) {
        const std::string name = lower(e.name.text);
        auto origin = cx_.direction(e.origin, scene_.translation_arity(), "a direction to the centre of rotation");
        if (auto prev = scene_.find_surface(name)) {  // a face before it, or a corner declared before it
            duplicate_surface(*surface_names_[prev->value], scene_.surfaces[*prev].object, e.name, owner);
            return std::nullopt;
        }
        if (!owner || !origin) return std::nullopt;
        return add_surface({name, *owner, {}, *origin, CornerSides{}, cx_.where(e.name)}, e.name);
    }

    // Definition 18: Corner(x, s1, s2) names two surfaces of x's object that meet at x. `k` is
    // the corner's id when it was kept.
    void corner_sides(const ast::CornerEntry& e, ObjectId owner, std::optional<SurfaceId> k) {
        const std::string corner = lower(e.name.text);
        auto side = [&](const ast::Name& n) -> std::optional<SurfaceId> {
            const std::string name = lower(n.text);
            auto s = scene_.find_surface(name);
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

    // Definition 21: two different objects, each pair once (a linkage is symmetric).
    void linkages(const ast::Linkages& l) {
        for (const auto& e : l.entries) {
            auto a = object(e.first, "Linkages");
            auto b = object(e.second, "Linkages");
            if (!a || !b) continue;
            const std::string& an = scene_.objects[*a].name;
            const std::string& bn = scene_.objects[*b].name;
            if (*a == *b) {
                cx_.error(e.second, "object '" + an + "' is linked to itself; a linkage joins two different objects");
                continue;
            }
            auto same = [&](const Linkage& x) {
                return (x.first == *a && x.second == *b) || (x.first == *b && x.second == *a);
            };
            auto it = std::find_if(scene_.linkages.begin(), scene_.linkages.end(), same);
            if (it != scene_.linkages.end()) {
                cx_.error(e, "the linkage of '" + an + "' and '" + bn + "' is listed twice",
                          {"the first is at " + loc(it->where)});
                continue;
            }
            scene_.linkages.push_back({*a, *b, cx_.where(e)});
        }
    }

    void constraints(const std::vector<ast::ConstraintEntry>& entries, bool translational) {
        const char* section = translational ? "Translational-Constraints" : "Rotational-Constraints";
        for (const auto& e : entries) {
            auto id = object(e.object, section);
            if (e.directions.empty()) cx_.error(e, "constraint entry names no direction");
            for (const auto& d : e.directions) {
                auto p = translational
                             ? cx_.pattern(d, scene_.translation_arity(), "a translational constraint", true)
                             : cx_.pattern(d, scene_.rotation_arity(), "a rotational constraint", true);
                if (!p || !id) continue;
                auto& list = translational ? scene_.objects[*id].trans_constraints : scene_.objects[*id].rot_constraints;
                list.push_back(std::move(*p));
            }
        }
    }

    std::optional<Force> check_force(const ast::ForceEntry& e) {
        ++force_entries_;
        auto id = object(e.object, "a force");
        auto dir = cx_.direction(e.direction, scene_.translation_arity(), "a force direction");
        auto origin = cx_.direction(e.origin, scene_.translation_arity(), "a direction to the centre of rotation");
        CauseId cause;
        if (e.cause) {
            const std::string name = lower(e.cause->text);
            auto c = scene_.find_cause(name);
            cause = c ? *c : scene_.causes.push_back({name, true});
        } else {
            cause = scene_.causes.push_back({"force#" + std::to_string(force_entries_), false});
        }
        if (!id || !dir || !origin) return std::nullopt;
        return Force{*id, *dir, *origin, cause, cx_.where(e)};
    }

    std::optional<SurfaceId> surface_ref(const ast::Name& n) {
        const std::string name = lower(n.text);
        auto id = scene_.find_surface(name);
        if (!id) cx_.error(n, "unknown surface '" + name + "'");
        return id;
    }

    struct DescriptorVisitor {
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
            }
        }
        void operator()(const ast::ForceEntry& e) const {
            if (auto f = c.check_force(e)) out.forces.push_back(*f);
        }
        void operator()(const ast::MotionEntry& e) const {
            if (auto m = c.motion(e)) out.motions.push_back(*m);
        }
    };

public:
    std::optional<Motion> motion(const ast::MotionEntry& e) {
        auto id = object(e.object, "a motion");
        auto t = cx_.direction(e.translation, scene_.translation_arity(), "a translational motion");
        auto r = cx_.direction(e.rotation, scene_.rotation_arity(), "a rotational motion");
        if (!id || !t || !r) return std::nullopt;
        return Motion{*id, *t, *r, cx_.where(e)};
    }

private:
    void situation(const ast::Situation& s) {
        Situation out;
        out.where = cx_.where(s);
        for (const auto& d : s.descriptors) boost::apply_visitor(DescriptorVisitor{*this, out}, d.get());
        scene_.situations.push_back(std::move(out));
    }

    static std::string loc(const SourceLocation& l) {
        return "line " + std::to_string(l.line) + ", column " + std::to_string(l.column);
    }

    Context cx_;
    Scene scene_;
    std::size_t force_entries_ = 0;
    const ast::Individuals* individuals_ = nullptr;
    std::vector<const ast::Descriptions*> descriptions_;
    std::vector<const ast::Surfaces*> surfaces_;
    std::vector<const ast::TransConstraints*> trans_;
    std::vector<const ast::RotConstraints*> rot_;
    std::vector<const ast::Forces*> forces_;
    std::vector<const ast::Corners*> corners_;
    std::vector<const ast::Linkages*> linkages_;
    std::vector<const ast::Name*> surface_names_;  // the declaring name of each SurfaceId
    std::map<std::string, std::pair<const ast::Name*, std::optional<ObjectId>>> first_corner_;
    std::vector<const ast::Situation*> situations_;

    friend std::optional<Motion> qm::alex::check_given(const ast::MotionEntry&, const Scene&, const PositionTable&,
                                                        const SourceText&, Diagnostics&);
    friend std::optional<QueryFact> qm::alex::check_query(const ast::QueryFact&, const Scene&, const PositionTable&,
                                                           const SourceText&, Diagnostics&);
};

}  // namespace

std::optional<Scene> check_scene(const ast::Scenario& scenario, const PositionTable& positions, const SourceText& src,
                                 Diagnostics& diags) {
    return SceneChecker(positions, src, diags).run(scenario);
}

std::optional<Motion> check_given(const ast::MotionEntry& given, const Scene& scene, const PositionTable& positions,
                                  const SourceText& src, Diagnostics& diags) {
    SceneChecker c(positions, src, diags);
    c.scene_ = scene;
    c.cx_.set_dimensions(scene.dimensions);
    auto m = c.motion(given);
    return c.cx_.errors() > 0 ? std::nullopt : m;
}

std::optional<QueryFact> check_query(const ast::QueryFact& fact, const Scene& scene, const PositionTable& positions,
                                     const SourceText& src, Diagnostics& diags) {
    SceneChecker c(positions, src, diags);
    c.scene_ = scene;
    c.cx_.set_dimensions(scene.dimensions);
    const std::string pred = lower(fact.predicate.text);
    using K = QueryFact::Kind;
    static const std::map<std::string, K> kinds = {
        {"translational-motion", K::translational_motion}, {"rotational-motion", K::rotational_motion},
        {"translational-freedom", K::translational_freedom}, {"rotational-freedom", K::rotational_freedom},
        {"contact", K::contact}, {"force", K::force}};
    auto it = kinds.find(pred);
    if (it == kinds.end()) {
        c.cx_.error(fact.predicate, "unknown predicate '" + fact.predicate.text +
                                        "': expected Translational-Motion, Rotational-Motion, Translational-Freedom, "
                                        "Rotational-Freedom, Contact or Force");
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
        if (fact.second) c.cx_.error(*fact.second, pred + " takes one object but found a second name");
        if (out.kind == K::force) {
            if (fact.direction) c.cx_.error(*fact.direction, "Force names only an object");
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

}  // namespace qm::alex
