// analysis/inert_contacts.cpp: Analysis::inert_contacts, the contacts of a situation the laws can do
// nothing with. The laws of blocking and pushing read a contact only through `touch`
// (rules/contact.rules); a contact from which no `touch` follows, in either direction, constrains
// and pushes nothing, so the objects behave as if it were not there. The usual cause is a corner
// against a surface it cannot touch (Definition 25, rules/corners.rules), which a scene can state
// but the laws rule out: silently dropping it would let an object fall through what the scene
// says it rests on (docs/SCENE_FORMAT.md, "Contacts the laws cannot use").
#include "analysis/analysis.hpp"
#include "analysis/detail/analysis_state.hpp"
#include "scene/vocabulary.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace qm::analysis {
namespace v = scene::vocabulary;

std::vector<Diagnostic> Analysis::inert_contacts(std::size_t situation) {
    QM_REQUIRE(situation >= 1 && situation <= state_->results.size(), "situation index out of range");
    State& st = *state_;
    engine::Engine& e = *st.engine;
    const atms::EnvId env = st.runs[situation - 1].environment;
    auto touches = [&](SurfaceId a, SurfaceId b) {
        const engine::ValueId pa = e.values().symbol(st.scene.surfaces[a].name);
        const engine::ValueId pb = e.values().symbol(st.scene.surfaces[b].name);
        for (engine::FactId f : e.facts().with_argument(st.facts->predicate(v::touch), 0, pa)) {
            const engine::Fact& fact = e.facts().fact(f);
            if (fact.args.size() >= 2 && fact.args[0] == pa && fact.args[1] == pb && e.atms().holds_in(e.node(f), env))
                return true;
        }
        return false;
    };
    std::vector<Diagnostic> out;
    // The situation's first contact item between each pair of surfaces (either way round), by hash:
    // a search of the items for every contact would be quadratic in the situation's size.
    auto pair_key = [](SurfaceId a, SurfaceId b) {
        return (std::uint64_t{std::min(a, b).value} << 32) | std::max(a, b).value;
    };
    std::unordered_map<std::uint64_t, const SceneItem*> contact_item;
    for (const SceneItem* x : st.facts->items(situation))
        if (x->kind == SceneItem::Kind::contact) contact_item.emplace(pair_key(x->first, x->second), x);
    for (const Contact& c : st.scene.situations[situation - 1].contacts) {
        auto it = contact_item.find(pair_key(c.first, c.second));
        if (it == contact_item.end()) continue;
        const SceneItem* item = it->second;
        if (item->assumption && !e.atms().env(env).contains(*item->assumption)) continue;  // taken away (--without)
        if (touches(item->first, item->second) || touches(item->second, item->first)) continue;
        const Surface& a = st.scene.surfaces[item->first];
        const Surface& b = st.scene.surfaces[item->second];
        std::string why;
        if (a.is_corner() != b.is_corner()) {
            const Surface& corner = a.is_corner() ? a : b;
            const Surface& face = a.is_corner() ? b : a;
            why = "by Definition 25 corner '" + corner.name + "' can touch only a surface whose normal may point into "
                  "the space its sides '" + st.scene.surfaces[corner.corner->first].name + "' and '" +
                  st.scene.surfaces[corner.corner->second].name + "' block, and the normal of '" + face.name +
                  "' does not (rules/corners.rules)";
        } else if (a.is_corner()) {
            why = "by Definition 26 neither corner can touch a side of the other (rules/corners.rules)";
        } else {
            why = "no law turns it into a touch (rules/contact.rules)";
        }
        out.push_back({Severity::warning, c.where,
                       item->text + " in situation " + std::to_string(situation) +
                           " constrains and pushes nothing, as if it were not there: " + why,
                       {}, {}});
    }
    return out;
}

}  // namespace qm::analysis
