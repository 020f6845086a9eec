// analysis/kinematic_set.cpp: the kinematically consistent combinations of a situation (thesis
// Figure 7.14's "consistent combinations of motions": what blocking, pushing, linkages and given
// motions alone allow, before the forces choose; docs/ANALYSIS.md "Kinematic and selected"). They
// are the interpretations of each kinematic chain's Law 1 choice sets in the situation with every
// force taken away, with no nearness preference: the driver takes the forces away as a what-if
// does, and knows no law.
#include "analysis/detail/analysis_state.hpp"
#include "scene/kinematic_chains.hpp"
#include "scene/direction_text.hpp"
#include <algorithm>
#include <map>
#include <set>

namespace qm::analysis {
namespace {

struct Canonical {
    bool operator()(const Direction& a, const Direction& b) const { return scene::canonical_less(a, b); }
};
using Dirs = std::set<Direction, Canonical>;

std::string alternatives(const Dirs& ds) {
    std::string out;
    std::size_t i = 0;
    for (const Direction& d : ds) out += (i++ == 0 ? "" : i == ds.size() ? " or " : ", ") + thesis_text(d);
    return out;
}

// A stable verdict that holds only because the forces select not moving among motions blocking and
// pushing allow says so: which objects the forces hold, and in which directions.
void stability_note(SituationResult& r, const Scene& scene) {
    if (!r.stable || !r.kinematic_computed) return;
    std::map<ObjectId, std::pair<Dirs, Dirs>> moving;
    for (const ChainMotions& chain : r.kinematic)
        for (const auto& combination : chain.combinations)
            for (std::size_t k = 0; k < chain.objects.size(); ++k) {
                auto it = moving.try_emplace(chain.objects[k]).first;
                if (!scene::is_zero(combination[k].translation)) it->second.first.insert(combination[k].translation);
                if (!scene::is_zero(combination[k].rotation)) it->second.second.insert(combination[k].rotation);
            }
    std::string held;
    std::size_t objects = 0;
    for (const auto& [o, dirs] : moving) {
        if (dirs.first.empty() && dirs.second.empty()) continue;
        if (++objects > 3) continue;
        held += (objects > 1 ? "; " : "") + scene.objects[o].name;
        if (!dirs.first.empty()) held += " translate " + alternatives(dirs.first);
        if (!dirs.second.empty()) held += std::string(dirs.first.empty() ? "" : " or") + " rotate " + alternatives(dirs.second);
    }
    if (objects == 0) return;
    if (objects > 3) held += "; and " + std::to_string(objects - 3) + " more objects";
    const std::uint64_t n = r.kinematic_count();
    r.notes.push_back("stable only because of the forces: blocking and pushing alone would let " + held + " (" +
                      (r.kinematic_complete ? "" : "at least ") + std::to_string(n) + " kinematically consistent combination" +
                      (n == 1 ? "" : "s") + ", --kinematic lists them); the forces select not moving");
}

}  // namespace

void Analysis::State::add_kinematic(SituationResult& r, std::size_t s, std::span<const QueryFact> without,
                                    std::span<const atms::AssumptionId> added) {
    kinematic_set(r, s, without, added);
    stability_note(r, scene);
}

void Analysis::State::kinematic_set(SituationResult& r, std::size_t s, std::span<const QueryFact> without,
                                    std::span<const atms::AssumptionId> added) {
    std::vector<QueryFact> forceless(without.begin(), without.end());
    std::vector<ObjectId> pushed;  // objects some force acts on in this situation
    auto push = [&](const SceneItem* item) {
        if (item && item->kind == SceneItem::Kind::force && item->object &&
            std::find(pushed.begin(), pushed.end(), *item->object) == pushed.end())
            pushed.push_back(*item->object);
    };
    for (const SceneItem* item : facts->items(s))
        if (std::none_of(without.begin(), without.end(), [&](const QueryFact& q) { return facts->matches(*item, q); })) push(item);
    std::vector<atms::AssumptionId> added_contacts;  // a what-if's added items, less its forces
    for (atms::AssumptionId a : added) {
        const SceneItem* item = facts->item(a);
        push(item);
        if (item && item->kind == SceneItem::Kind::contact) added_contacts.push_back(a);
    }
    // No force: nothing is ranked, so the forces select every consistent combination.
    if (pushed.empty()) {
        r.kinematic = r.chains;
        r.kinematic_complete = r.complete;
        return;
    }
    for (ObjectId o : pushed) forceless.push_back(QueryFact{QueryFact::Kind::force, o, {}, {}, {}, {}});
    if (facts->granularity() == Granularity::situation) {
        // One assumption stands for all the items: only a fresh analysis can leave the forces out,
        // which costs as much as the analysis itself, so it is done only when asked for.
        r.kinematic_computed = false;
        if (!options.kinematic) return;
        Diagnostics ignored;
        auto state = restricted(s, forceless, {}, ignored);
        if (!state) return;
        r.kinematic = state->results.front().chains;
        r.kinematic_complete = state->results.front().complete;
        r.kinematic_computed = true;
        return;
    }
    Diagnostics ignored;
    auto context = run(s, forceless, ignored, added_contacts);
    if (!context) {
        r.kinematic_computed = false;
        return;
    }
    const std::size_t limit =
        options.kinematic ? options.combination_limit : std::min(options.combination_limit, AnalysisOptions::kinematic_count_cap);
    for (const std::vector<ObjectId>& chain : scene::kinematic_chains(scene.objects.size(), pairs(s, context->environment))) {
        std::vector<ObjectChoices> members;
        for (ObjectId o : chain) members.push_back(choices[o]);
        ChainOutcome outcome = consistent_combinations(engine->atms(), members, context->environment, limit);
        if (outcome.truncated) r.kinematic_complete = false;
        r.kinematic.push_back(std::move(outcome.motions));
    }
}

}  // namespace qm::analysis
