// analysis/motion_selection.cpp
// The preferred combinations are the ATMS's preferred interpretations of the chain's Law 1 choice
// sets (atms/preferred_interpretations.hpp): the ranked sets (objects with a force) are enumerated
// first and only the assignments that survive the preference are completed, so the motions of
// objects that nothing drives are never enumerated under dominated ones (a train of gears driven
// at one end is linear, not exponential).
#include "analysis/motion_selection.hpp"
#include "atms/preferred_interpretations.hpp"
#include "scene/direction_text.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::analysis {
namespace {

std::uint32_t picked(const atms::Environment& env, const std::vector<atms::AssumptionId>& set) {
    auto it = std::find_if(set.begin(), set.end(), [&](atms::AssumptionId a) { return env.contains(a); });
    QM_ASSERT(it != set.end(), "an interpretation picks one assumption of every choice set");
    return static_cast<std::uint32_t>(it - set.begin());
}

// Records the combination an interpretation (joined with its base) picks; false, and `truncated`,
// once `limit` combinations are held (both enumerations below stop there).
bool record_combination(ChainOutcome& out, std::span<const ObjectChoices> chain, const atms::Environment& full,
                        std::size_t limit) {
    if (out.motions.combinations.size() >= limit) {
        out.truncated = true;
        return false;
    }
    std::vector<ObjectMotion> combination;
    combination.reserve(chain.size());
    for (const ObjectChoices& c : chain)
        combination.push_back({c.trans_dirs[picked(full, c.trans)], c.rot_dirs[picked(full, c.rot)]});
    out.motions.combinations.push_back(std::move(combination));
    return true;
}

}  // namespace

ChainOutcome solve_chain(atms::Atms& atms, std::span<const ObjectChoices> chain, std::span<const MotionRanks> ranks,
                         atms::EnvId base, std::size_t limit) {
    QM_REQUIRE(chain.size() == ranks.size(), "one ranks record per object");
    std::vector<atms::RankedChoiceSet> ranked;
    std::vector<std::vector<atms::AssumptionId>> free;
    auto add = [&](const std::vector<atms::AssumptionId>& set, const std::optional<std::vector<std::int64_t>>& r) {
        if (r) ranked.push_back({set, *r});
        else free.push_back(set);
    };
    for (std::size_t o = 0; o < chain.size(); ++o) {
        add(chain[o].trans, ranks[o].trans);
        add(chain[o].rot, ranks[o].rot);
    }
    ChainOutcome out;
    for (const ObjectChoices& c : chain) out.motions.objects.push_back(c.object);
    out.consistent = atms::for_each_preferred_interpretation(
        atms, ranked, free, base, [&](const atms::Environment& full) { return record_combination(out, chain, full, limit); });
    std::sort(out.motions.combinations.begin(), out.motions.combinations.end(), combination_less);
    return out;
}

ChainOutcome consistent_combinations(atms::Atms& atms, std::span<const ObjectChoices> chain, atms::EnvId base,
                                     std::size_t limit) {
    std::vector<std::vector<atms::AssumptionId>> sets;
    ChainOutcome out;
    for (const ObjectChoices& c : chain) {
        sets.push_back(c.trans);
        sets.push_back(c.rot);
        out.motions.objects.push_back(c.object);
    }
    atms.for_each_interpretation(sets, base, [&](const atms::Environment& env) {
        return record_combination(out, chain, join(env, atms.env(base)), limit);
    });
    out.consistent = out.motions.combinations.size();
    std::sort(out.motions.combinations.begin(), out.motions.combinations.end(), combination_less);
    return out;
}

bool combination_less(const std::vector<ObjectMotion>& a, const std::vector<ObjectMotion>& b) {
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        if (a[i].translation != b[i].translation) return canonical_less(a[i].translation, b[i].translation);
        if (a[i].rotation != b[i].rotation) return canonical_less(a[i].rotation, b[i].rotation);
    }
    return a.size() < b.size();
}

}  // namespace qm::analysis
