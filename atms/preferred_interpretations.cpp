// atms/preferred_interpretations.cpp
#include "atms/preferred_interpretations.hpp"
#include "atms/pareto_front.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::atms {

std::size_t for_each_preferred_interpretation(Atms& atms, std::span<const RankedChoiceSet> ranked,
                                              std::span<const std::vector<AssumptionId>> free, EnvId base,
                                              const std::function<bool(const Environment&)>& visit) {
    std::vector<std::vector<AssumptionId>> ranked_sets;
    ranked_sets.reserve(ranked.size());
    for (const RankedChoiceSet& s : ranked) {
        QM_REQUIRE(s.members.size() == s.ranks.size(), "one rank per member of a ranked choice set");
        ranked_sets.push_back(s.members);
    }
    // 1. The assignments of the ranked sets that some assignment of the free sets completes.
    std::vector<std::vector<AssumptionId>> picks;
    std::vector<std::vector<std::int64_t>> ranks;
    atms.for_each_interpretation(ranked_sets, base, [&](const Environment& env) {
        std::vector<AssumptionId> p;
        std::vector<std::int64_t> r;
        for (const RankedChoiceSet& s : ranked) {
            auto it = std::find_if(s.members.begin(), s.members.end(), [&](AssumptionId a) { return env.contains(a); });
            QM_ASSERT(it != s.members.end(), "an interpretation picks one assumption of every choice set");
            p.push_back(*it);
            r.push_back(s.ranks[static_cast<std::size_t>(it - s.members.begin())]);
        }
        picks.push_back(std::move(p));
        ranks.push_back(std::move(r));
        return true;
    });
    const std::vector<AssumptionId> base_members = atms.env(base).assumptions();  // a copy: interning may move envs
    auto with = [&](const std::vector<AssumptionId>& p) {
        std::vector<AssumptionId> members = base_members;
        members.insert(members.end(), p.begin(), p.end());
        return atms.environment(members);
    };
    std::vector<std::size_t> feasible;
    for (std::size_t i = 0; i < picks.size(); ++i)
        if (atms.for_each_interpretation(free, with(picks[i]), [](const Environment&) { return false; }) != 0)
            feasible.push_back(i);
    // 2. The feasible assignments that no other feasible one dominates.
    std::vector<std::vector<std::int64_t>> feasible_ranks;
    feasible_ranks.reserve(feasible.size());
    for (std::size_t i : feasible) feasible_ranks.push_back(std::move(ranks[i]));
    // 3. Every consistent completion of each.
    for (std::size_t f : pareto_front(feasible_ranks)) {
        const EnvId w = with(picks[feasible[f]]);
        atms.for_each_interpretation(free, w, [&](const Environment& env) { return visit(join(env, atms.env(w))); });
    }
    return feasible.size();
}

}  // namespace qm::atms
