// atms/case_refutation.cpp: the case analysis of refute_by_cases, a depth-first search over the
// choice sets with most-constrained-set-first branching and backjumping (a case whose refutation
// does not use the case's own member refutes its whole step).
#include "atms/case_refutation.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace qm::atms {
namespace {

class Refuter {
public:
    Refuter(const Atms& atms, std::span<const std::vector<AssumptionId>> sets, std::span<const EnvId> nogoods,
            const RefutationOptions& options)
        : atms_(atms), sets_(sets), nogoods_(nogoods), options_(options) {
        for (std::size_t i = 0; i < nogoods_.size(); ++i)
            for (AssumptionId a : atms_.env(nogoods_[i]).assumptions()) by_assumption_[a.value].push_back(i);
    }

    RefutationResult refute(const Environment& start) {
        for (std::size_t i = 0; i < nogoods_.size(); ++i)
            if (atms_.env(nogoods_[i]).subset_of(start)) return {leaf(i), false};
        std::vector<char> assigned(sets_.size(), 0);
        std::optional<Refutation> proof = node(start, assigned);
        return {std::move(proof), gave_up_};
    }

private:
    Refutation leaf(std::size_t i) {
        used_.insert(i);
        return {{nogoods_[i]}, atms_.env(nogoods_[i])};
    }
    // The nogood that closes `env` (which has c, and had no nogood without it): among those with
    // c, one already used, else one with the preferred assumption, else the smallest.
    [[nodiscard]] std::optional<std::size_t> closing(const Environment& env, AssumptionId c) const {
        auto it = by_assumption_.find(c.value);
        if (it == by_assumption_.end()) return std::nullopt;
        std::optional<std::size_t> best;
        auto rank = [&](std::size_t i) {
            const Environment& x = atms_.env(nogoods_[i]);
            const bool preferred = options_.prefer && x.contains(*options_.prefer);
            return std::tuple(used_.count(i) ? 0 : 1, preferred ? 0 : 1, x.size(), i);
        };
        for (std::size_t i : it->second)
            if (atms_.env(nogoods_[i]).subset_of(env) && (!best || rank(i) < rank(*best))) best = i;
        return best;
    }
    std::optional<Refutation> node(const Environment& env, std::vector<char>& assigned) {
        if (++nodes_ > options_.node_budget) gave_up_ = true;
        if (gave_up_) return std::nullopt;
        // The set with the fewest open members (then the fewest closed ones), first such.
        std::optional<std::size_t> pick;
        std::vector<std::optional<std::size_t>> closed, pick_closed;
        std::size_t best_open = 0, best_closed = 0;
        for (std::size_t k = 0; k < sets_.size(); ++k) {
            if (assigned[k]) continue;
            closed.clear();
            std::size_t open = 0;
            for (AssumptionId c : sets_[k]) {
                closed.push_back(closing(env.with(c), c));
                if (!closed.back()) ++open;
            }
            const std::size_t shut = sets_[k].size() - open;
            if (!pick || open < best_open || (open == best_open && shut < best_closed)) {
                pick = k;
                best_open = open;
                best_closed = shut;
                pick_closed = closed;
            }
        }
        if (!pick) return std::nullopt;  // every set chosen, no nogood met: consistent
        const std::vector<AssumptionId>& set = sets_[*pick];
        assigned[*pick] = 1;
        std::vector<std::size_t> order;  // open members first: one of them may refute the whole step
        for (std::size_t i = 0; i < set.size(); ++i)
            if (!pick_closed[i]) order.push_back(i);
        for (std::size_t i = 0; i < set.size(); ++i)
            if (pick_closed[i]) order.push_back(i);
        Refutation all;
        for (std::size_t i : order) {
            std::optional<Refutation> p = pick_closed[i] ? leaf(*pick_closed[i]) : node(env.with(set[i]), assigned);
            if (!p) {
                assigned[*pick] = 0;
                return std::nullopt;
            }
            if (!p->involved.contains(set[i])) {  // this step's member plays no part: backjump
                assigned[*pick] = 0;
                return p;
            }
            for (EnvId ng : p->nogoods)
                if (std::find(all.nogoods.begin(), all.nogoods.end(), ng) == all.nogoods.end()) all.nogoods.push_back(ng);
            all.involved = join(all.involved, p->involved);
        }
        for (AssumptionId c : set) all.involved.erase(c);
        assigned[*pick] = 0;
        return all;
    }

    const Atms& atms_;
    std::span<const std::vector<AssumptionId>> sets_;
    std::span<const EnvId> nogoods_;
    const RefutationOptions& options_;
    std::map<std::uint32_t, std::vector<std::size_t>> by_assumption_;
    std::set<std::size_t> used_;
    std::size_t nodes_ = 0;
    bool gave_up_ = false;
};

}  // namespace

RefutationResult refute_by_cases(const Atms& atms, std::span<const std::vector<AssumptionId>> choice_sets,
                                 std::span<const EnvId> nogoods, const Environment& start,
                                 const RefutationOptions& options) {
    return Refuter(atms, choice_sets, nogoods, options).refute(start);
}

}  // namespace qm::atms
