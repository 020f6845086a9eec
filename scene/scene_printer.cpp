// scene/scene_printer.cpp: writes a checked Scene back in either notation (scene/scene_printer.hpp).
#include "scene/scene_printer.hpp"
#include "scene/direction_text.hpp"

#include <algorithm>
#include <sstream>
#include <utility>

namespace qm::scene {

std::string print_pattern(const DirectionPattern& p) {
    std::string out = "(";
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (i) out += ' ';
        out += p[i].sign ? std::string(1, sign_char(*p[i].sign)) : "?" + p[i].variable;
    }
    return out + ")";
}

namespace {

// `obj (dir) (origin) [cause]`, the body shared by every force form.
std::string force_body(const Scene& s, const Force& f) {
    std::string out = s.objects[f.object].name + " " + thesis_text(f.direction) + " " + thesis_text(f.origin);
    if (s.causes[f.cause].is_explicit) out += " " + s.causes[f.cause].name;
    return out;
}

// `(name normal origin)` for a face; `(name side1 side2 origin)` for a corner (Definition 18).
std::string surface_body(const Scene& s, const Surface& f) {
    if (f.corner)
        return "(" + f.name + " " + s.surfaces[f.corner->first].name + " " + s.surfaces[f.corner->second].name + " " +
               thesis_text(f.origin) + ")";
    return "(" + f.name + " " + thesis_text(f.normal) + " " + thesis_text(f.origin) + ")";
}

std::string motion_body(const Scene& s, const Motion& m) {
    return s.objects[m.object].name + " " + thesis_text(m.translation) + " " + thesis_text(m.rotation);
}

// One object's faces (corners == false) or corners, in SurfaceId order.
struct Group {
    const Object* object;
    std::vector<SurfaceId> members;
};

// Groups of the objects that have faces (or corners), in the order of their first member, so that
// they are printed (and so re-read) in the scene's SurfaceId order; the reader gives the faces
// their ids before the corners.
std::vector<Group> surface_groups(const Scene& s, bool corners) {
    std::vector<Group> out;
    for (const auto& o : s.objects) {
        Group g{&o, {}};
        for (SurfaceId id : o.surfaces)
            if (s.surfaces[id].is_corner() == corners) g.members.push_back(id);
        if (!g.members.empty()) out.push_back(std::move(g));
    }
    std::sort(out.begin(), out.end(), [](const Group& a, const Group& b) { return a.members[0] < b.members[0]; });
    return out;
}

bool any_constraints(const Scene& s, bool translational) {
    for (const auto& o : s.objects)
        if (!(translational ? o.trans_constraints : o.rot_constraints).empty()) return true;
    return false;
}

}  // namespace

std::string print_scene(const Scene& s) {
    std::ostringstream os;
    os << "(Defscenario " << s.dimensions << ' ' << s.name << "\n  Individuals (";
    for (std::uint32_t i = 0; i < s.objects.size(); ++i) os << (i ? " " : "") << s.objects[ObjectId{i}].name;
    os << ")\n  Descriptions (";
    for (const auto& o : s.objects) os << "(" << o.description << ' ' << o.name << ")";
    os << ")\n";
    for (bool corners : {false, true}) {
        const auto groups = surface_groups(s, corners);
        if (corners && groups.empty()) continue;  // Surfaces is always written, Corners only when used
        os << (corners ? "  Corners (" : "  Surfaces (");
        for (const Group& g : groups) {
            os << "\n    (" << g.object->name;
            for (SurfaceId id : g.members) os << "\n      " << surface_body(s, s.surfaces[id]);
            os << ")";
        }
        os << ")\n";
    }
    for (bool translational : {true, false}) {
        if (!any_constraints(s, translational)) continue;
        os << (translational ? "  Translational-Constraints (" : "  Rotational-Constraints (");
        for (const auto& o : s.objects) {
            const auto& list = translational ? o.trans_constraints : o.rot_constraints;
            if (list.empty()) continue;
            os << "(" << o.name;
            for (const auto& p : list) os << ' ' << print_pattern(p);
            os << ")";
        }
        os << ")\n";
    }
    if (!s.linkages.empty()) {
        os << "  Linkages (";
        for (const auto& l : s.linkages) os << "(" << s.objects[l.first].name << ' ' << s.objects[l.second].name << ")";
        os << ")\n";
    }
    os << "  Forces (";
    for (const auto& f : s.forces) os << "\n    (" << force_body(s, f) << ")";
    os << "))\n(Defstates";
    for (const auto& sit : s.situations) {
        os << "\n  (";
        bool first = true;
        auto sep = [&]() -> const char* { return std::exchange(first, false) ? "" : "\n   "; };
        for (const auto& c : sit.contacts)
            os << sep() << "(Contact " << s.surfaces[c.first].name << ' ' << s.surfaces[c.second].name << ")";
        for (const auto& f : sit.forces) os << sep() << "(Force " << force_body(s, f) << ")";
        for (const auto& m : sit.motions) os << sep() << "(Motion " << motion_body(s, m) << ")";
        os << ")";
    }
    os << ")\n";
    return os.str();
}

std::string print_scene_keywords(const Scene& s) {
    std::ostringstream os;
    os << s.name << ' ' << s.dimensions << "\nIndividuals : (";
    for (std::uint32_t i = 0; i < s.objects.size(); ++i) os << (i ? ", " : "") << s.objects[ObjectId{i}].name;
    os << ")\nDescriptions : ";
    for (std::uint32_t i = 0; i < s.objects.size(); ++i)
        os << (i ? ", " : "") << s.objects[ObjectId{i}].description << "(" << s.objects[ObjectId{i}].name << ")";
    os << "\n";
    for (bool translational : {true, false}) {
        if (!any_constraints(s, translational)) continue;
        os << (translational ? "Translational-Constraints : " : "Rotational-Constraints : ");
        bool first = true;
        for (const auto& o : s.objects) {
            const auto& list = translational ? o.trans_constraints : o.rot_constraints;
            if (list.empty()) continue;
            os << (std::exchange(first, false) ? "" : ", ") << o.name;
            for (const auto& p : list) os << ' ' << print_pattern(p);
        }
        os << "\n";
    }
    for (bool corners : {false, true}) {
        bool any = false;
        for (const Group& g : surface_groups(s, corners)) {
            os << (std::exchange(any, true) ? "\n  " : corners ? "Corners : " : "Surfaces : ") << g.object->name << ' ';
            for (std::size_t i = 0; i < g.members.size(); ++i) os << (i ? ", " : "") << surface_body(s, s.surfaces[g.members[i]]);
        }
        if (any) os << "\n";
    }
    if (!s.linkages.empty()) {
        os << "Linkages : ";
        for (std::size_t i = 0; i < s.linkages.size(); ++i)
            os << (i ? ", " : "") << "(" << s.objects[s.linkages[i].first].name << ' '
               << s.objects[s.linkages[i].second].name << ")";
        os << "\n";
    }
    if (!s.forces.empty()) {
        os << "Forces : ";
        for (std::size_t i = 0; i < s.forces.size(); ++i) os << (i ? ", " : "") << force_body(s, s.forces[i]);
        os << "\n";
    }
    for (const auto& sit : s.situations) {
        os << "Situation :";
        bool first = true;
        auto sep = [&]() -> const char* { return std::exchange(first, false) ? " " : ", "; };
        for (const auto& c : sit.contacts)
            os << sep() << "Contact (" << s.surfaces[c.first].name << ' ' << s.surfaces[c.second].name << ")";
        for (const auto& f : sit.forces) os << sep() << "Force (" << force_body(s, f) << ")";
        for (const auto& m : sit.motions) os << sep() << "Motion (" << motion_body(s, m) << ")";
        os << "\n";
    }
    return os.str();
}

}  // namespace qm::scene
