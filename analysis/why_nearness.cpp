// analysis/why_nearness.cpp: --why's answer for a consistent motion the forces do not produce
// (analysis/detail/why_nearness.hpp): the nearness ranks of Definition 38 as reasons.
#include "analysis/detail/why_nearness.hpp"
#include "analysis/detail/why_derivation.hpp"
#include "analysis/detail/why_responsible.hpp"
#include "engine/preferences.hpp"
#include "scene/direction_text.hpp"
#include <algorithm>
#include <set>
#include <tuple>

namespace qm::analysis::detail {
namespace {

// The derivations of the nearness rank (Definition 38) of object o's motion d within `within`, if
// the laws rank it (the object has a net force; `prefer` in rules/nearness.rules): one, or where
// comparisons of causes branch (docs/LAWS.md, "Opposing causes") one per branch that `within` admits.
std::vector<Exclusion> rank_reasons(Analysis::State& st, ObjectId o, bool translational, const Direction& d,
                                    const atms::Environment& within) {
    const engine::Engine& e = *st.engine;
    const auto& atms = e.atms();
    const auto& set = translational ? st.choices[o].trans : st.choices[o].rot;
    const auto& dirs = translational ? st.choices[o].trans_dirs : st.choices[o].rot_dirs;
    const auto at = std::find(dirs.begin(), dirs.end(), d);
    std::vector<Exclusion> out;
    if (at == dirs.end()) return out;
    for (engine::FactId f : engine::rank_facts(e, set[static_cast<std::size_t>(at - dirs.begin())])) {
        const atms::NodeId n = e.node(f);
        for (atms::EnvId label_env : atms.label(n)) {
            if (!atms.env(label_env).subset_of(within)) continue;
            out.push_back(explain_holding(st, n, label_env));
        }
    }
    return out;
}

}  // namespace

void explain_by_nearness(Analysis::State& st, WhyAnswer& w, const WhyMotion& m) {
    const auto& atms = st.engine->atms();
    const SituationResult& result = *m.result;
    const ObjectId o = m.object;
    const WhyLimits& limits = st.options.why;
    // 3. Consistent, but not what the forces produce (section 6.2, Definition 38).
    std::set<std::string> together;
    auto add = [&](Exclusion x) {
        together.insert(x.responsible.begin(), x.responsible.end());
        w.exclusions.push_back(std::move(x));
    };
    std::string predicted_example;
    for (const ChainMotions& chain : result.chains)
        if (std::find(chain.objects.begin(), chain.objects.end(), o) != chain.objects.end() && !chain.combinations.empty())
            for (std::size_t j = 0; j < chain.objects.size(); ++j)
                predicted_example += " " + st.scene.objects[chain.objects[j]].name + " " +
                                     thesis_text(chain.combinations.front()[j].translation) + " " +
                                     thesis_text(chain.combinations.front()[j].rotation);
    if (auto mine = rank_reasons(st, o, m.translational, m.direction, m.scope); !mine.empty()) {
        for (Exclusion& x : mine) add(std::move(x));
        w.notes.push_back("consistent, but not produced by the forces: other consistent combinations are nearer to "
                          "every net force (section 6.2, Definition 38), e.g. the predicted" + predicted_example);
    } else {
        // Not ranked itself (no force drives it): every consistent combination with it needs motions
        // of the driven objects that are farther from their net forces than a predicted one's. The
        // reasons are the ranks of those motions no predicted combination has (from the first few
        // such combinations).
        std::set<std::tuple<std::uint32_t, bool, std::size_t>> seen;
        std::size_t visited = 0;
        std::vector<ObjectId> chain_objects;
        for (const ChainMotions& chain : result.chains)
            if (std::find(chain.objects.begin(), chain.objects.end(), o) != chain.objects.end()) chain_objects = chain.objects;
        atms.for_each_interpretation(m.sets, m.with_choice_id, [&](const atms::Environment& full) {
            for (ObjectId x : chain_objects)
                for (bool trans : {true, false}) {
                    const auto& xs = trans ? st.choices[x].trans : st.choices[x].rot;
                    const auto& xd = trans ? st.choices[x].trans_dirs : st.choices[x].rot_dirs;
                    for (std::size_t i = 0; i < xs.size(); ++i)
                        if (full.contains(xs[i]) && !predicted(st, result, x, trans, xd[i]) &&
                            seen.insert({x.value, trans, i}).second && w.exclusions.size() < limits.rank_reasons)
                            for (Exclusion& r : rank_reasons(st, x, trans, xd[i], full)) add(std::move(r));
                }
            return ++visited < limits.rank_combinations && w.exclusions.size() < limits.rank_reasons;
        });
        w.notes.push_back("consistent, but not produced by the forces: " + st.scene.objects[o].name +
                          " has no nearness rank of its own (no force drives it), and every consistent combination "
                          "with this motion needs motions of the driven objects that are farther from their net forces "
                          "(section 6.2, Definition 38) than those of a predicted combination, e.g." + predicted_example +
                          "; the reasons are the ranks of those motions");
    }
    set_responsible(st, w, together, m.situation, m.env, o, m.translational, m.direction, "the nearness ranks");
    coarse_note(st, w);
}

}  // namespace qm::analysis::detail
