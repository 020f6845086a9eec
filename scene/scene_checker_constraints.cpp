// scene/scene_checker_constraints.cpp: the scene checker's external constraints, forces and
// linkages (scene/detail/scene_checker.hpp). Constraint entries are direction patterns in which
// `?x` matches any sign (section 6.1, Figure 7.2); a force is a direction and the direction from
// its point of application to the centre of rotation, with a cause for same-cause cancellation
// (section 5, Figure 5.2); a linkage joins two objects that are one body (Definition 21).
#include "scene/detail/scene_checker.hpp"

#include <algorithm>
#include <set>

namespace qm::scene::detail {

void SceneChecker::constraints(const std::vector<ast::ConstraintEntry>& entries, bool translational) {
    const char* section = translational ? "Translational-Constraints" : "Rotational-Constraints";
    for (const auto& e : entries) {
        auto id = object(e.object, section);
        if (e.directions.empty()) cx_.error(e, "constraint entry names no direction");
        for (const auto& d : e.directions) {
            auto p = translational ? cx_.pattern(d, scene_.translation_arity(), "a translational constraint", true)
                                   : cx_.pattern(d, scene_.rotation_arity(), "a rotational constraint", true);
            if (!p || !id) continue;
            Object& o = scene_.objects[*id];
            (translational ? o.trans_constraints : o.rot_constraints).push_back(std::move(*p));
            (translational ? o.trans_constraints_at : o.rot_constraints_at).push_back(cx_.where(d));
        }
    }
}

namespace {
bool is_bare(const std::vector<ast::Section>& sections, std::size_t i) {
    return i < sections.size() && boost::get<ast::BareConstraints>(&sections[i].get()) != nullptr;
}
bool is_surfaces(const std::vector<ast::Section>& sections, std::size_t i) {
    return i < sections.size() && boost::get<ast::Surfaces>(&sections[i].get()) != nullptr;
}
}  // namespace

// Figure 6.1: `Surfaces "(" ... ")" [<translational constraints>] [<rotational constraints>]`.
// Two lists after Surfaces are the translational, then the rotational constraints. One list is
// whichever its directions' arity says: in 2-D a translation has 2 signs and a rotation 1; in
// 3-D both have 3, so a lone list cannot be told and needs its keyword.
std::optional<bool> SceneChecker::bare_kind(const std::vector<ast::Section>& sections, std::size_t i) {
    const auto& list = boost::get<ast::BareConstraints>(sections[i].get());
    const bool first = i > 0 && is_surfaces(sections, i - 1);
    const bool second = i > 1 && is_bare(sections, i - 1) && is_surfaces(sections, i - 2);
    if (!first && !second) {
        if (i > 2 && is_bare(sections, i - 1) && is_bare(sections, i - 2) && is_surfaces(sections, i - 3))
            cx_.error(list, "a third constraint list without its keyword after Surfaces; Figure 6.1 allows two, "
                            "the translational and then the rotational constraints");
        else
            cx_.error(list, "a constraint list without its keyword must follow Surfaces (Figure 6.1: Surfaces, "
                            "then the translational and the rotational constraints); elsewhere write "
                            "Translational-Constraints or Rotational-Constraints before it");
        return std::nullopt;
    }
    if (second) return false;
    if (is_bare(sections, i + 1)) return true;
    if (list.entries.empty()) return std::nullopt;  // `()`: no constraint, whichever kind it is
    std::set<std::size_t> arities;
    for (const auto& e : list.entries)
        for (const auto& d : e.directions) arities.insert(d.parts.size());
    const std::string write = "; write Translational-Constraints or Rotational-Constraints before it";
    if (scene_.dimensions == 3) {
        cx_.error(list, "in a 3-D scene translations and rotations both have 3 signs, so a single constraint list "
                        "without its keyword after Surfaces could be either" + write);
        return std::nullopt;
    }
    if (arities == std::set<std::size_t>{2}) return true;
    if (arities == std::set<std::size_t>{1}) return false;
    std::string found = "no direction";
    if (!arities.empty()) {
        found = "directions of ";
        std::size_t n = 0;
        for (std::size_t a : arities)
            found += (n++ == 0 ? "" : n == arities.size() ? " and " : ", ") + std::to_string(a);
        found += " signs";
    }
    cx_.error(list, "a single constraint list without its keyword after Surfaces is read by the arity of its "
                    "directions (2 signs: translational, 1 sign: rotational), but this one has " + found + write);
    return std::nullopt;
}

std::optional<Force> SceneChecker::check_force(const ast::ForceEntry& e) {
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

// Definition 21: two different objects, each pair once (a linkage is symmetric).
void SceneChecker::linkages(const ast::Linkages& l) {
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
                      {"the first is at " + line_column(it->where)});
            continue;
        }
        scene_.linkages.push_back({*a, *b, cx_.where(e)});
    }
}

}  // namespace qm::scene::detail
