// envision/successors.cpp: hypothesised next states, collisions, consistency along the chain
// (thesis Figure 8.5 step 1.4, 8.3.4, 8.3.5).
#include "envision/successors.hpp"
#include "atms/pareto_front.hpp"

#include <algorithm>
#include <map>

namespace qm::envision {
namespace g = qm::geometry;

namespace {

struct Hypothesis {
    std::vector<PlaceOption> places;   // per pair
    std::vector<std::int8_t> motions;  // per object
};

class Builder {
public:
    Builder(StateId from, const StateIndex& states, const Chain& chain, std::span<const bridge::PairPlaces> pairs,
            const ChainTables& tables)
        : from_(from), current_(states[from]), states_(states), tables_(tables) {
        for (const std::size_t k : chain.pairs)
            parts_.emplace_back(chain.object_index(pairs[k].spec.a), chain.object_index(pairs[k].spec.b));
    }

    void step(const StepOptions& s) {
        // A pair that may wrap may also stay: the two reach the same state, so keep the wrap.
        std::vector<std::vector<PlaceOption>> places = s.places;
        for (std::size_t k = 0; k < places.size(); ++k) {
            auto& opts = places[k];
            const bool wraps = std::any_of(opts.begin(), opts.end(), [](const PlaceOption& o) { return o.how == How::wrap; });
            if (wraps)
                opts.erase(std::remove_if(opts.begin(), opts.end(),
                                          [&](const PlaceOption& o) { return o.how == How::stay && o.place == current_.places[k]; }),
                           opts.end());
        }
        Hypothesis h{std::vector<PlaceOption>(places.size()), std::vector<std::int8_t>(s.motions.size())};
        combine(s, places, 0, h);
    }

    [[nodiscard]] std::vector<Transition> transitions() const {
        std::vector<Transition> out;
        for (const auto& [key, causes] : found_) out.push_back({from_, key.first, key.second, causes});
        return out;
    }

private:
    // Odometer over the pairs' options, then the objects'.
    void combine(const StepOptions& s, const std::vector<std::vector<PlaceOption>>& places, std::size_t i, Hypothesis& h) {
        if (i < places.size()) {
            for (const auto& o : places[i]) {
                h.places[i] = o;
                combine(s, places, i + 1, h);
            }
            return;
        }
        const std::size_t o = i - places.size();
        if (o < s.motions.size()) {
            for (const auto m : s.motions[o]) {
                h.motions[o] = m;
                combine(s, places, i + 1, h);
            }
            return;
        }
        settle(s, h);
    }

    // Each pair's arrival (collision, end of axis), then the chain's consistency.
    void settle(const StepOptions& s, const Hypothesis& h) {
        std::vector<const std::vector<g::QualDirection>*> afters;
        for (std::size_t k = 0; k < h.places.size(); ++k) {
            const auto& list = tables_.arrival(k, h.places[k].place, h.places[k].how, pair_motion(k, h.motions));
            if (list.empty()) return;  // the laws give no way on: no such next state
            afters.push_back(&list);
        }
        std::vector<g::QualDirection> chosen(afters.size());
        choose(s, h, afters, 0, chosen);
    }

    void choose(const StepOptions& s, const Hypothesis& h, const std::vector<const std::vector<g::QualDirection>*>& afters,
                std::size_t k, std::vector<g::QualDirection>& chosen) {
        if (k < afters.size()) {
            for (const auto a : *afters[k]) {
                chosen[k] = a;
                choose(s, h, afters, k + 1, chosen);
            }
            return;
        }
        // Motions fixed by the step (a change of motion) and by arrivals (a collision).
        std::vector<std::optional<std::int8_t>> fixed(h.motions.size());
        for (std::size_t o = 0; o < h.motions.size(); ++o)
            if (h.motions[o] != current_.motions[o]) fixed[o] = h.motions[o];
        std::uint8_t causes = s.cause;
        bool wraps = false, changes = false;
        for (std::size_t k = 0; k < chosen.size(); ++k) {
            const auto& opt = h.places[k];
            wraps = wraps || opt.how == How::wrap;
            if (opt.place != current_.places[k] || opt.how == How::wrap) causes |= Cause::kinematic;
            changes = changes || opt.place != current_.places[k];
            if (chosen[k] == pair_motion(k, h.motions)) continue;
            causes |= Cause::collision;
            const auto [a, b] = parts_[k];
            for (const auto& [o, x] : {std::pair{a, chosen[k].s[0]}, std::pair{b, chosen[k].s[1]}}) {
                if (fixed[o] && *fixed[o] != x) return;  // two collisions disagree (5.3.3: never at once)
                fixed[o] = x;
            }
        }
        for (std::size_t o = 0; o < fixed.size(); ++o) changes = changes || (fixed[o] && *fixed[o] != current_.motions[o]);
        if (!changes && !wraps) return;  // nothing happens: no transition
        std::vector<g::PlaceId> places;
        for (const auto& opt : h.places) places.push_back(opt.place);
        std::vector<StateId> candidates;
        std::vector<std::vector<int>> ranks;
        for (const StateId id : states_.with_places(places)) {
            const State& t = states_[id];
            bool ok = true;
            std::vector<int> r;
            for (std::size_t o = 0; o < fixed.size() && ok; ++o) {
                if (fixed[o]) ok = t.motions[o] == *fixed[o];
                else r.push_back(tables_.rank(h.motions[o], t.motions[o]));
            }
            if (!ok) continue;
            candidates.push_back(id);
            ranks.push_back(std::move(r));
        }
        for (const std::size_t i : atms::pareto_front(ranks)) {
            if (candidates[i] == from_ && !wraps) continue;
            found_[{candidates[i], s.duration}] |= causes;
        }
    }

    g::QualDirection pair_motion(std::size_t k, const std::vector<std::int8_t>& motions) const {
        return g::QualDirection{{motions[parts_[k].first], motions[parts_[k].second]}};
    }

    StateId from_;
    const State& current_;
    const StateIndex& states_;
    const ChainTables& tables_;
    std::vector<std::pair<std::size_t, std::size_t>> parts_;  // per pair: its parts' object indices
    std::map<std::pair<StateId, Duration>, std::uint8_t> found_;
};

}  // namespace

std::vector<Transition> successors(StateId from, const StateIndex& states, const Chain& chain,
                                   std::span<const bridge::PairPlaces> pairs, const ChainTables& tables,
                                   const StateDynamics& dynamics) {
    Builder b(from, states, chain, pairs, tables);
    for (const auto& s : dynamics.steps) b.step(s);
    return b.transitions();
}

}  // namespace qm::envision
