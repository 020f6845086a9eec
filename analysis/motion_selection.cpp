// analysis/motion_selection.cpp
// The search: the choice sets of objects with a force on them (ranked) are enumerated first, each
// assignment kept only if some choice of the other objects' motions completes it consistently;
// the non-dominated assignments are then completed in every consistent way. So the motions of
// objects that nothing drives are enumerated only under the assignments that survive, never under
// dominated ones (a train of gears driven at one end is linear, not exponential).
#include "analysis/motion_selection.hpp"
#include "scene/direction_text.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::analysis {
namespace {

// a dominates b: at least as near everywhere, nearer somewhere.
bool dominates(const std::vector<int>& a, const std::vector<int>& b) {
    bool better = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] > b[i]) return false;
        better |= a[i] < b[i];
    }
    return better;
}

struct Set {
    std::size_t object;   // index in the chain
    bool translation;
    const std::vector<atms::AssumptionId>* assumptions;
    const std::map<Direction, int>* ranks;  // null: unranked
};

std::uint32_t picked(const atms::Environment& env, const std::vector<atms::AssumptionId>& set) {
    auto it = std::find_if(set.begin(), set.end(), [&](atms::AssumptionId a) { return env.contains(a); });
    QM_ASSERT(it != set.end(), "an interpretation picks one assumption of every choice set");
    return static_cast<std::uint32_t>(it - set.begin());
}

// Records the combination an interpretation env (joined with base) picks; false, and `truncated`,
// once `limit` combinations are held (both enumerations below stop there).
bool record_combination(ChainOutcome& out, std::span<const ObjectChoices> chain, const atms::Environment& env,
                        const atms::Environment& base, std::size_t limit) {
    if (out.motions.combinations.size() >= limit) {
        out.truncated = true;
        return false;
    }
    const atms::Environment full = join(env, base);
    std::vector<ObjectMotion> combination;
    combination.reserve(chain.size());
    for (const ObjectChoices& c : chain)
        combination.push_back({c.trans_dirs[picked(full, c.trans)], c.rot_dirs[picked(full, c.rot)]});
    out.motions.combinations.push_back(std::move(combination));
    return true;
}

}  // namespace

ChainOutcome solve_chain(atms::Atms& atms, std::span<const ObjectChoices> chain, std::span<const Nearness> nearness,
                         atms::EnvId base, std::size_t limit) {
    QM_REQUIRE(chain.size() == nearness.size(), "one nearness record per object");
    std::vector<Set> ranked, free;
    for (std::size_t o = 0; o < chain.size(); ++o) {
        const auto* tr = nearness[o].trans.empty() ? nullptr : &nearness[o].trans;
        const auto* rr = nearness[o].rot.empty() ? nullptr : &nearness[o].rot;
        (tr ? ranked : free).push_back({o, true, &chain[o].trans, tr});
        (rr ? ranked : free).push_back({o, false, &chain[o].rot, rr});
    }
    auto sets_of = [](const std::vector<Set>& s) {
        std::vector<std::vector<atms::AssumptionId>> out;
        for (const Set& x : s) out.push_back(*x.assumptions);
        return out;
    };
    const auto ranked_sets = sets_of(ranked), free_sets = sets_of(free);

    ChainOutcome out;
    // 1. Assignments of the ranked sets that some assignment of the others completes.
    struct Front {
        std::vector<atms::AssumptionId> picks;
        std::vector<int> rank;
    };
    std::vector<Front> feasible;
    atms.for_each_interpretation(ranked_sets, base, [&](const atms::Environment& env) {
        Front f;
        for (const Set& s : ranked) {
            const std::uint32_t i = picked(env, *s.assumptions);
            f.picks.push_back((*s.assumptions)[i]);
            const auto& dirs = s.translation ? chain[s.object].trans_dirs : chain[s.object].rot_dirs;
            auto r = s.ranks->find(dirs[i]);
            f.rank.push_back(r == s.ranks->end() ? 6 : r->second);
        }
        feasible.push_back(std::move(f));
        return true;
    });
    std::erase_if(feasible, [&](const Front& f) {
        std::vector<atms::AssumptionId> members = atms.env(base).assumptions();
        members.insert(members.end(), f.picks.begin(), f.picks.end());
        const atms::EnvId with = atms.environment(members);
        return atms.for_each_interpretation(free_sets, with, [](const atms::Environment&) { return false; }) == 0;
    });
    // 2. The non-dominated ones (section 6.2, Def 38).
    std::vector<const Front*> best;
    for (const Front& f : feasible)
        if (std::none_of(feasible.begin(), feasible.end(), [&](const Front& g) { return dominates(g.rank, f.rank); }))
            best.push_back(&f);
    // 3. Every consistent completion of each.
    for (const ObjectChoices& c : chain) out.motions.objects.push_back(c.object);
    for (const Front* f : best) {
        std::vector<atms::AssumptionId> members = atms.env(base).assumptions();
        members.insert(members.end(), f->picks.begin(), f->picks.end());
        const atms::EnvId with = atms.environment(members);
        atms.for_each_interpretation(free_sets, with, [&](const atms::Environment& env) {
            return record_combination(out, chain, env, atms.env(with), limit);
        });
    }
    out.consistent = feasible.size();
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
        return record_combination(out, chain, env, atms.env(base), limit);
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
