// scene/what_if.cpp: --given, --without, `given` and `whatif`: their meaning on the scene model and
// their checks (docs/ANALYSIS.md "What if").
#include "scene/what_if.hpp"
#include "scene/direction_text.hpp"
#include "scene/scene_parser.hpp"
#include <algorithm>

namespace qm::scene {
namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

const char* take_away_expected = "expected 'Contact A B' or 'Force OBJ [CAUSE]' to take away, but found '";

}  // namespace

bool can_take_away(const QueryFact& q) noexcept {
    return q.kind == QueryFact::Kind::contact || q.kind == QueryFact::Kind::force;
}

bool names_contact(const QueryFact& q, SurfaceId first, SurfaceId second) noexcept {
    return q.kind == QueryFact::Kind::contact &&
           ((first == *q.first && second == *q.second) || (first == *q.second && second == *q.first));
}

bool names_force(const QueryFact& q, ObjectId object, CauseId cause) noexcept {
    return q.kind == QueryFact::Kind::force && object == *q.object && (!q.cause || cause == *q.cause);
}

bool replaced_by(const Motion& m, std::span<const Motion> given) noexcept {
    return std::any_of(given.begin(), given.end(), [&](const Motion& g) { return g.object == m.object; });
}

bool has_item(const Scene& scene, std::size_t s, const QueryFact& q) {
    const Situation& situation = scene.situations[s - 1];
    if (q.kind == QueryFact::Kind::contact)
        return std::any_of(situation.contacts.begin(), situation.contacts.end(),
                           [&](const Contact& c) { return names_contact(q, c.first, c.second); });
    // `Force OBJ` names scene-level forces too: they act in every situation.
    auto on = [&](const Force& f) { return names_force(q, f.object, f.cause); };
    return std::any_of(scene.forces.begin(), scene.forces.end(), on) ||
           std::any_of(situation.forces.begin(), situation.forces.end(), on);
}

std::string item_text(const Scene& scene, const QueryFact& q) {
    if (q.kind == QueryFact::Kind::contact)
        return "Contact (" + scene.surfaces[*q.first].name + " " + scene.surfaces[*q.second].name + ")";
    if (q.cause) return "force of cause '" + scene.causes[*q.cause].name + "' on '" + scene.objects[*q.object].name + "'";
    return "force on '" + scene.objects[*q.object].name + "'";
}

std::vector<Motion> read_givens(const Scene& scene, std::span<const std::string> texts, Diagnostics& diags) {
    std::vector<Motion> given;
    std::vector<std::string> given_text;  // each as written, aligned with `given`
    for (const std::string& g : texts)
        if (auto m = parse_given(scene, g, diags, "--given")) {
            auto same = std::find_if(given.begin(), given.end(), [&](const Motion& x) { return x.object == m->object; });
            if (same != given.end()) {
                // One motion per object at a time (Law 1): the second would replace or contradict the first.
                diags.error({"--given", 1, 1}, "expected one --given per object, but '" + scene.objects[m->object].name +
                                                   "' is given twice ('" + given_text[static_cast<std::size_t>(same - given.begin())] +
                                                   "' and '" + g + "')");
                continue;
            }
            given.push_back(*m);
            given_text.push_back(g);
        }
    return given;
}

std::vector<QueryFact> read_withouts(const Scene& scene, std::span<const std::string> texts, std::optional<std::size_t> only,
                                     Diagnostics& diags) {
    const std::size_t situations = scene.situations.size();
    const bool only_ok = only.value_or(1) <= situations;
    std::vector<QueryFact> without;
    for (const std::string& w : texts)
        if (auto q = parse_query_fact(scene, w, diags, "--without")) {
            // Taking away what is not there changes nothing: most likely a misspelt or misplaced item.
            bool present = false;
            for (std::size_t s = 1; s <= situations && can_take_away(*q); ++s)
                if ((!only || s == *only) && has_item(scene, s, *q)) present = true;
            if (!can_take_away(*q))
                diags.error({"--without", 1, 1}, take_away_expected + w + "'");
            else if (!present && only_ok)
                diags.error({"--without", 1, 1}, "expected a contact or force of the scene to take away, but " +
                                                     (only ? "situation " + std::to_string(*only) : std::string("no situation")) +
                                                     (only ? " has no " : " has a ") + item_text(scene, *q));
            else without.push_back(*q);
        }
    return without;
}

std::vector<QueryFact> read_whatif(const Scene& scene, std::size_t s, const std::string& text, Diagnostics& diags) {
    std::vector<QueryFact> without;
    const std::string items = text.rfind("without ", 0) == 0 ? text.substr(8) : text;
    for (std::size_t from = 0; from <= items.size();) {
        const auto semi = items.find(';', from);
        const std::string part = trim(items.substr(from, semi == std::string::npos ? std::string::npos : semi - from));
        if (auto q = parse_query_fact(scene, part, diags, "whatif")) {
            if (!can_take_away(*q))
                diags.error({"whatif", 1, 1}, take_away_expected + part + "'");
            else if (!has_item(scene, s, *q))
                diags.error({"whatif", 1, 1}, "expected a contact or force of situation " + std::to_string(s) +
                                                  " to take away, but it has no " + item_text(scene, *q));
            else without.push_back(*q);
        }
        if (semi == std::string::npos) break;
        from = semi + 1;
    }
    return without;
}

void replace_given_motions(Scene& scene, std::span<const Motion> given, std::span<const std::string> texts, Diagnostics& diags) {
    for (std::size_t k = 0; k < given.size(); ++k)
        for (std::size_t s = 0; s < scene.situations.size(); ++s)
            std::erase_if(scene.situations[s].motions, [&](const Motion& m) {
                if (m.object != given[k].object) return false;
                diags.add({Severity::note, m.where,
                           "--given '" + texts[k] + "' replaces this Motion (" + scene.objects[m.object].name + " " +
                               thesis_text(m.translation) + " " + thesis_text(m.rotation) + ") in situation " + std::to_string(s + 1),
                           {}, {}});
                return true;
            });
}

Scene what_if_scene(const Scene& scene, std::size_t s, std::span<const QueryFact> without, std::span<const Motion> given) {
    Scene changed = scene;
    Situation only = changed.situations[s - 1];
    // A given motion replaces any other of the same object (one motion at a time, Law 1).
    std::erase_if(only.motions, [&](const Motion& m) { return replaced_by(m, given); });
    only.motions.insert(only.motions.end(), given.begin(), given.end());
    auto taken = [&](auto pred) { return std::any_of(without.begin(), without.end(), pred); };
    std::erase_if(only.contacts, [&](const Contact& c) {
        return taken([&](const QueryFact& q) { return names_contact(q, c.first, c.second); });
    });
    auto force_taken = [&](const Force& f) {
        return taken([&](const QueryFact& q) { return names_force(q, f.object, f.cause); });
    };
    std::erase_if(only.forces, force_taken);
    std::erase_if(changed.forces, force_taken);
    changed.situations = {only};
    return changed;
}

std::string what_if_note(const Scene& scene, std::size_t s, std::span<const QueryFact> without) {
    std::string taken;
    for (const QueryFact& q : without)
        if (has_item(scene, s, q))
            taken += (taken.empty() ? "" : ", ") + (q.kind == QueryFact::Kind::contact ? item_text(scene, q)
                                                    : q.cause                          ? "the " + item_text(scene, q)
                                                                                       : "every " + item_text(scene, q));
    return taken.empty() ? taken : "what-if: analysed without " + taken + " (--without)";
}

}  // namespace qm::scene
