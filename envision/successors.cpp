// envision/successors.cpp: hypothesised next states, collisions, consistency along the chain
// (thesis Figure 8.5 step 1.4, 8.3.3-8.3.5).
#include "envision/successors.hpp"
#include "atms/pareto_front.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include "qm/assert.hpp"

namespace qm::envision {
namespace g = qm::geometry;

namespace {

// A pair whose arrival changes its motion (a collision, the end of an axis): the motions its two
// parts may have after, each a branch of its own (5.3.3: no two collisions at once, each outcome
// its own history).
struct Arrival {
    std::size_t pair = 0;
    std::vector<g::QualDirection> after;
    std::vector<bool> collision;  // per after: the laws call it a collision (collision.rules)
};

class Builder {
public:
    Builder(StateId from, const StateIndex& states, const Chain& chain, std::span<const bridge::PairPlaces> pairs,
            const ChainTables& tables)
        : from_(from), current_(states[from]), states_(states), tables_(tables) {
        for (const std::size_t k : chain.pairs)
            parts_.emplace_back(chain.object_index(pairs[k].spec.a), chain.object_index(pairs[k].spec.b));
    }

    // Only the hypotheses that lead to `target`, and why each fails (for --why-not).
    void explain(StateId target, const std::vector<std::string>& pair_names, const std::vector<std::string>& object_names) {
        target_ = target;
        pair_names_ = pair_names;
        object_names_ = object_names;
    }
    [[nodiscard]] std::vector<std::string> reasons() { return std::exchange(reasons_, {}); }

    void step(const StepOptions& s) {
        allowed_.clear();
        for (const auto& options : s.motions) allowed_.push_back(ChainTables::allowed_mask(options));
        std::vector<std::vector<PlaceOption>> places = s.places;
        if (target_) {
            const State& t = states_[*target_];
            for (std::size_t k = 0; k < places.size(); ++k) {
                std::vector<PlaceOption> to;
                for (const auto& o : places[k])
                    if (o.place == t.places[k]) to.push_back(o);
                if (to.empty()) {
                    std::string options;
                    for (const auto& o : places[k]) options += (options.empty() ? "" : ", ") + std::to_string(o.place.value);
                    reasons_.push_back("pair " + pair_names_[k] + " cannot be at place " + std::to_string(t.places[k].value) +
                                       " after this step: its next places are " + options);
                    return;
                }
                places[k] = std::move(to);
            }
        }
        std::vector<PlaceOption> chosen(places.size());
        combine_places(s, places, 0, chosen);
    }

    // The transitions one step found (and forgets them).
    [[nodiscard]] std::map<std::pair<StateId, Duration>, std::uint8_t> take() { return std::exchange(found_, {}); }

private:
    // One next place per pair (8.3.2: "all combinations of the changes in place").
    void combine_places(const StepOptions& s, const std::vector<std::vector<PlaceOption>>& places, std::size_t k,
                        std::vector<PlaceOption>& chosen) {
        if (k < places.size()) {
            for (const auto& o : places[k]) {
                chosen[k] = o;
                combine_places(s, places, k + 1, chosen);
            }
            return;
        }
        // Each pair's arrival with each motion the step allows its parts.
        std::vector<Arrival> arrivals;
        for (std::size_t p = 0; p < chosen.size(); ++p) {
            Arrival a{p, {}, {}};
            bool unchanged = true;
            for (const auto ma : s.motions[parts_[p].first])
                for (const auto mb : s.motions[parts_[p].second]) {
                    const g::QualDirection v{{ma, mb}};
                    for (const auto after : tables_.arrival(p, chosen[p].place, chosen[p].how, v)) {
                        unchanged = unchanged && after == v;
                        const bool collision = tables_.collision(p, chosen[p].place, v, after);
                        const auto at = std::find(a.after.begin(), a.after.end(), after);
                        if (at == a.after.end()) {
                            a.after.push_back(after);
                            a.collision.push_back(collision);
                        } else if (collision) {
                            a.collision[static_cast<std::size_t>(at - a.after.begin())] = true;
                        }
                    }
                }
            if (a.after.empty()) {  // the laws give no way on: no such next state
                if (target_)
                    reasons_.push_back("pair " + pair_names_[p] + " arriving at place " + std::to_string(chosen[p].place.value) +
                                       " has no motion to go on with (the laws give no arrival there)");
                return;
            }
            if (!unchanged) arrivals.push_back(std::move(a));
        }
        std::vector<g::QualDirection> branch(arrivals.size());
        choose(s, chosen, arrivals, 0, branch);
    }

    void choose(const StepOptions& s, const std::vector<PlaceOption>& places, const std::vector<Arrival>& arrivals, std::size_t i,
                std::vector<g::QualDirection>& branch) {
        if (i < arrivals.size()) {
            for (const auto after : arrivals[i].after) {
                branch[i] = after;
                choose(s, places, arrivals, i + 1, branch);
            }
            return;
        }
        settle(s, places, arrivals, branch);
    }

    // The chain made consistent (8.3.4): among the states with these places, those in which every
    // object has a motion the laws allow after this step, given its situation in it (the motions
    // the step allows it, its motion now, the motion each collision of this branch fixes:
    // rules/clock/settling.rules, read once as a table: chain_tables.hpp); of those, the ones the
    // laws' preference keeps (rules/clock/nearness.rules: a `prefer` on every object's motion,
    // ranked given the motions the step allows it, also a table), a Pareto front.
    void settle(const StepOptions& s, const std::vector<PlaceOption>& places, const std::vector<Arrival>& arrivals,
                const std::vector<g::QualDirection>& branch) {
        const std::size_t n = current_.motions.size();
        std::vector<g::PlaceId> target;
        for (const auto& p : places) target.push_back(p.place);
        const auto at = states_.with_places(target);
        // Per object, the motions after this step the laws allow it (bit idx(m)): with collisions,
        // those every collision's outcome allows.
        next_.assign(n, 0);
        fixes_.assign(n, 0);
        reach_.assign(n, true);
        for (std::size_t i = 0; i < arrivals.size(); ++i) {
            const auto [a, b] = parts_[arrivals[i].pair];
            fixes_[a] |= ChainTables::bit(branch[i].s[0]);
            fixes_[b] |= ChainTables::bit(branch[i].s[1]);
        }
        const auto has = [](std::uint8_t mask, std::int8_t m) { return (mask >> (m + 1) & 1U) != 0; };
        // Whether some state with these places lets every colliding part move as its collisions
        // fix it, each other part whose motion the step does not allow taking one it allows or
        // staying as it is: the colliding parts' reach.
        if (!arrivals.empty()) {
            bool collision_reach = false;
            for (const StateId id : at) {
                const auto& t = states_[id].motions;
                bool ok = true;
                for (std::size_t p = 0; p < n && ok; ++p) {
                    if (fixes_[p] != 0) ok = fixes_[p] == ChainTables::bit(t[p]);
                    else if (!has(allowed_[p], current_.motions[p])) ok = has(allowed_[p], t[p]) || t[p] == current_.motions[p];
                }
                if (ok) {
                    collision_reach = true;
                    break;
                }
            }
            for (std::size_t o = 0; o < n; ++o)
                if (fixes_[o] != 0) {
                    reach_[o] = collision_reach;
                    next_[o] = allowed_next(o);
                }
        }
        // Per other object, whether some state with these places gives it a motion the step allows
        // it while each part a collision fixes moves as the laws then allow and each other part
        // whose motion the step does not allow takes one it allows or stays as it is.
        for (std::size_t o = 0; o < n; ++o) {
            if (fixes_[o] != 0) continue;
            reach_[o] = false;
            for (const StateId id : at) {
                const auto& t = states_[id].motions;
                if (!has(allowed_[o], t[o])) continue;
                bool others = true;
                for (std::size_t p = 0; p < n && others; ++p) {
                    if (p == o) continue;
                    if (fixes_[p] != 0) others = has(next_[p], t[p]);
                    else if (!has(allowed_[p], current_.motions[p])) others = has(allowed_[p], t[p]) || t[p] == current_.motions[p];
                }
                if (others) {
                    reach_[o] = true;
                    break;
                }
            }
        }
        for (std::size_t o = 0; o < n; ++o) {
            if (fixes_[o] == 0) next_[o] = allowed_next(o);
            if (next_[o] == 0) return;  // the laws leave o no motion after this step
        }
        if (target_) {
            const State& t = states_[*target_];
            for (std::size_t i = 0; i < arrivals.size(); ++i) {
                const auto [a, b] = parts_[arrivals[i].pair];
                std::uint8_t code = settling(a, t.motions[a]);
                if (code == 0) code = settling(b, t.motions[b]);
                if (code != 0) {
                    reasons_.push_back("arriving at place " + std::to_string(places[arrivals[i].pair].place.value) + ", pair " +
                                       pair_names_[arrivals[i].pair] + " moves on with " + g::to_string(branch[i]) +
                                       " in this outcome, not with the target's motions (" + cite(code) + ")");
                    return;
                }
            }
        }
        // The causes the laws give: the step's, a collision where an arrival is one, a change of
        // place where an option is one; a hypothesis with no change of place that comes back to
        // the state it left is no transition.
        bool changes_place = false;
        std::uint8_t causes = s.cause;
        for (std::size_t i = 0; i < arrivals.size(); ++i) {
            const auto& a = arrivals[i];
            const auto at = std::find(a.after.begin(), a.after.end(), branch[i]);
            if (a.collision[static_cast<std::size_t>(at - a.after.begin())]) causes |= Cause::collision;
        }
        for (const auto& p : places) changes_place = changes_place || tables_.place_change(p.how);
        if (changes_place) causes |= Cause::kinematic;
        std::vector<StateId> candidates;
        std::vector<std::vector<std::int64_t>> ranks;
        for (const StateId id : at) {
            const State& t = states_[id];
            bool ok = true;
            std::vector<std::int64_t> r;
            r.reserve(n);
            for (std::size_t o = 0; o < n && ok; ++o) {
                ok = (next_[o] >> (t.motions[o] + 1) & 1U) != 0;
                // The declared preference ranks every object's motion: where the settling laws leave
                // one motion (a collision's) or only some, the candidates tie there.
                r.push_back(tables_.preference_rank(o, allowed_[o], t.motions[o]));
            }
            if (!ok) continue;
            candidates.push_back(id);
            ranks.push_back(std::move(r));
        }
        if (target_) {
            explain_target(s, candidates, ranks);
            return;
        }
        for (const std::size_t i : atms::pareto_front(ranks)) {
            if (candidates[i] == from_ && !changes_place) continue;  // nothing happens: no transition
            found_[{candidates[i], s.duration}] |= causes;
        }
    }

    // The settling table's answer for object o after this step, given the collisions that fix it
    // (0: allowed; else the refuter's code).
    [[nodiscard]] std::uint8_t settling(std::size_t o, std::int8_t next) const {
        return tables_.settling(o, allowed_[o], current_.motions[o], fixes_[o], reach_[o], next);
    }
    [[nodiscard]] std::uint8_t allowed_next(std::size_t o) const {
        std::uint8_t mask = 0;
        for (std::int8_t m = -1; m <= 1; ++m)
            if (settling(o, m) == 0) mask = static_cast<std::uint8_t>(mask | ChainTables::bit(m));
        return mask;
    }
    // "rule NAME at FILE:LINE": the law that refutes a motion, for explanations.
    [[nodiscard]] std::string cite(std::uint8_t code) const {
        const auto& r = tables_.refuter(code);
        return (r.rule.empty() ? std::string("the laws") : "rule " + r.rule) + (r.where.empty() ? std::string() : " at " + r.where);
    }

    void explain_target(const StepOptions& s, const std::vector<StateId>& candidates, const std::vector<std::vector<std::int64_t>>& ranks) {
        const State& t = states_[*target_];
        const auto it = std::find(candidates.begin(), candidates.end(), *target_);
        if (it == candidates.end()) {
            for (std::size_t o = 0; o < t.motions.size(); ++o) {
                if (fixes_[o] != 0) continue;
                const std::uint8_t code = settling(o, t.motions[o]);
                if (code == 0) continue;
                std::string options;
                for (const auto x : s.motions[o]) options += std::string(options.empty() ? "" : " ") + sign_word(x);
                reasons_.push_back("part " + object_names_[o] + " cannot move " + sign_word(t.motions[o]) + " after this step: it moves " +
                                   sign_word(current_.motions[o]) + " now and the step allows it " + options + " (" + cite(code) + ")");
            }
            return;
        }
        const auto& mine = ranks[static_cast<std::size_t>(it - candidates.begin())];
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            const auto& other = ranks[i];
            bool le = true, lt = false;
            for (std::size_t k = 0; k < mine.size(); ++k) {
                le = le && other[k] <= mine[k];
                lt = lt || other[k] < mine[k];
            }
            if (le && lt) {
                reasons_.push_back("state #" + std::to_string(candidates[i].value) +
                                   " has these places too and the laws prefer it: it is nearer to what the step allows for every part (the `prefer` at " +
                                   tables_.preference_where + ")");
                return;
            }
        }
        reasons_.push_back(candidates[static_cast<std::size_t>(it - candidates.begin())] == from_
                               ? "this step changes nothing that would lead back to the state itself"
                               : "this step allows it");
    }

    StateId from_;
    const State& current_;
    const StateIndex& states_;
    const ChainTables& tables_;
    std::vector<std::pair<std::size_t, std::size_t>> parts_;  // per pair: its parts' object indices
    std::vector<std::uint8_t> allowed_;  // per object: the motions the current step allows it (ChainTables::allowed_mask)
    std::vector<std::uint8_t> next_;     // per object: the motions after the step the settling laws allow (settle)
    std::vector<std::uint8_t> fixes_;    // per object: the motions the branch's collisions fix it to, as a mask (settle)
    std::vector<bool> reach_;            // per object: whether a state with the branch's places has a motion the step allows it
    std::map<std::pair<StateId, Duration>, std::uint8_t> found_;
    std::optional<StateId> target_;
    std::vector<std::string> pair_names_, object_names_, reasons_;
};

}  // namespace

std::vector<std::pair<std::string, std::vector<std::string>>> why_no_transition(StateId from, StateId to, const StateIndex& states,
                                                                                const Chain& chain, std::span<const bridge::PairPlaces> pairs,
                                                                                const std::vector<std::string>& object_names,
                                                                                const ChainTables& tables, const StateDynamics& dynamics) {
    Builder b(from, states, chain, pairs, tables);
    std::vector<std::string> pair_names;
    for (const std::size_t k : chain.pairs) pair_names.push_back(pairs[k].name);
    b.explain(to, pair_names, object_names);
    std::vector<std::pair<std::string, std::vector<std::string>>> out;
    for (const auto& s : dynamics.steps) {
        b.step(s);
        auto reasons = b.reasons();
        std::sort(reasons.begin(), reasons.end());
        reasons.erase(std::unique(reasons.begin(), reasons.end()), reasons.end());
        out.emplace_back(s.name, std::move(reasons));
    }
    return out;
}

std::vector<Transition> successors(StateId from, const StateIndex& states, const Chain& chain,
                                   std::span<const bridge::PairPlaces> pairs, const ChainTables& tables,
                                   const StateDynamics& dynamics) {
    Builder b(from, states, chain, pairs, tables);
    const std::size_t n = dynamics.steps.size();
    std::vector<std::map<std::pair<StateId, Duration>, std::uint8_t>> found(n);
    for (std::size_t i = 0; i < n; ++i) {
        b.step(dynamics.steps[i]);
        found[i] = b.take();
    }
    // A step happens only if no step that preempts it can (Law 4, as the laws order them). The
    // preemptions form no cycle (steps that preempt come first), so one pass in that order settles it.
    std::vector<bool> kept(n, false), settled(n, false);
    for (std::size_t round = 0; round < n; ++round)
        for (std::size_t i = 0; i < n; ++i) {
            if (settled[i]) continue;
            bool ready = true, preempted = false;
            for (const auto& [s, t] : dynamics.preempts)
                if (t == i) {
                    ready = ready && settled[s];
                    preempted = preempted || (settled[s] && kept[s]);
                }
            if (!ready) continue;
            settled[i] = true;
            kept[i] = !preempted && !found[i].empty();
        }
    for (std::size_t i = 0; i < n; ++i)
        if (!settled[i]) throw InternalError("the laws' preemptions between steps form a cycle");
    std::map<std::pair<StateId, Duration>, std::uint8_t> merged;
    for (std::size_t i = 0; i < n; ++i)
        if (kept[i])
            for (const auto& [key, causes] : found[i]) merged[key] |= causes;
    std::vector<Transition> out;
    for (const auto& [key, causes] : merged) out.push_back({from, key.first, key.second, causes});
    return out;
}

}  // namespace qm::envision
