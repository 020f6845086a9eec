// envision/verify.cpp: the envisionment's invariants, from the geometry (Law 2, 8.1.3, 9.1.5).
#include "envision/verify.hpp"

#include <algorithm>

namespace qm::envision {
namespace g = qm::geometry;

namespace {

const g::Adjacency* adjacency(const bridge::PairPlaces& pair, g::PlaceId place, g::QualDirection v) {
    for (const auto& a : pair.vocabulary.adjacency)
        if (a.from == place && a.motion == v) return &a;
    return nullptr;
}

// A motion with a component along a bounded axis cannot lead a place back to itself (it would
// wrap, and only a periodic axis wraps): a free motion there must reach another place.
bool only_itself_along_bounded(const bridge::PairPlaces& pair, g::PlaceId place, g::QualDirection v) {
    bool bounded = false;
    for (std::size_t i = 0; i < 2; ++i) bounded = bounded || (v.s[i] != 0 && !pair.request.cspace.axes[i].periodic);
    if (!bounded) return false;
    for (const auto& a : pair.vocabulary.adjacency)
        if (a.from == place && a.motion == v && (a.constrained || a.to != place)) return false;
    return true;
}

class Checker {
public:
    Checker(const g::Mechanism& m, const Envisionment& e, const ChainEnvisionment& c) : m_(m), e_(e), c_(c) {
        const std::size_t n = c.chain.objects.size();
        bounded_.assign(n, false);
        for (const std::size_t k : c.chain.pairs) {
            const auto& p = e.pairs[k];
            for (std::size_t i = 0; i < 2; ++i)
                if (!p.request.cspace.axes[i].periodic) bounded_[c.chain.object_index(i == 0 ? p.spec.a : p.spec.b)] = true;
        }
    }

    void run(std::vector<std::string>& out) {
        std::vector<bool> has_out(c_.states.size(), false);
        for (const auto& t : c_.transitions) has_out[t.from.value] = true;
        for (std::uint32_t i = 0; i < c_.states.size(); ++i) {
            const StateId id{i};
            if (!c_.is_shown(id)) continue;
            const State& s = c_.states[id];
            const bool moving = std::any_of(s.motions.begin(), s.motions.end(), [](std::int8_t x) { return x != 0; });
            if (!has_out[i] && moving) problem(out, id, "is terminal, yet a part moves");
            if (!has_out[i] && !moving)
                for (std::size_t o = 0; o < s.motions.size(); ++o)
                    if (o < s.net_force.size() && (s.net_force[o] == 1 || s.net_force[o] == -1) && !held(s, o))
                        problem(out, id, "is terminal, yet nothing holds the net force " + std::string(sign_word(s.net_force[o])) + " on " +
                                             name(o) + " (its motion that way is not into blocked space at any of its places)");
            for (std::size_t k = 0; k < c_.chain.pairs.size(); ++k) {
                const auto& p = e_.pairs[c_.chain.pairs[k]];
                const g::QualDirection v{{s.motions[c_.chain.object_index(p.spec.a)], s.motions[c_.chain.object_index(p.spec.b)]}};
                if (v.s[0] == 0 && v.s[1] == 0) continue;
                if (!adjacency(p, s.places[k], v))
                    problem(out, id, "has pair " + p.name + " moving " + g::to_string(v) + " with neither a next place nor a constraint at place " +
                                         std::to_string(s.places[k].value));
                else if (only_itself_along_bounded(p, s.places[k], v))
                    problem(out, id, "has pair " + p.name + " moving " + g::to_string(v) + " along a bounded axis, and place " +
                                         std::to_string(s.places[k].value) + " leads only back to itself");
            }
            if (s.may_rest && moving) problem(out, id, "is a possible rest, yet a part moves");
        }
        for (const auto& cycle : c_.graph.cycles)
            if (const auto o = one_way(cycle))
                problem(out, cycle.front(), "is on a behavioural cycle in which " + name(*o) + " moves one way throughout along a bounded coordinate");
        // A transient cycle kept by a pair's places (bridge::places_go_round) has its part moving
        // one way throughout; the places' values are the geometry's own.
        for (const auto& t : c_.graph.transient) {
            const bool kept = t.pair && std::all_of(t.states.begin(), t.states.end(), [&](StateId s) { return c_.states[s].motions[t.object] == t.motion; });
            if (!kept && !one_way(t.states))
                problem(out, t.states.front(), "is on a transient cycle in which no part moves one way throughout along a coordinate that cannot come round");
        }
    }

private:
    // Whether o's motion along its force, with its shaft-mates', is into blocked space at a place,
    // alone, or together with the pair's other part moving along its own definite force where that
    // part alone is free (two parts pressed into each other at their contact).
    [[nodiscard]] bool held(const State& s, std::size_t o) const {
        const g::PartId part = c_.chain.objects[o];
        for (std::size_t k = 0; k < c_.chain.pairs.size(); ++k) {
            const auto& p = e_.pairs[c_.chain.pairs[k]];
            g::QualDirection v{{0, 0}}, both{{0, 0}};
            bool touches = false;
            for (std::size_t i = 0; i < 2; ++i) {
                const g::PartId x = i == 0 ? p.spec.a : p.spec.b;
                if (x == part || m_.same_shaft(x, part)) {
                    v.s[i] = both.s[i] = s.net_force[o];
                    touches = true;
                } else if (const std::size_t other = c_.chain.object_index(x); other < s.net_force.size() &&
                                                                              (s.net_force[other] == 1 || s.net_force[other] == -1)) {
                    both.s[i] = s.net_force[other];
                }
            }
            if (!touches) continue;
            const auto blocked = [&](g::QualDirection w) {
                const g::Adjacency* a = adjacency(p, s.places[k], w);
                return a && a->constrained;
            };
            if (blocked(v)) return true;
            // Pressed together: each free to go its own way alone, not both at once.
            const g::QualDirection other{{static_cast<std::int8_t>(both.s[0] - v.s[0]), static_cast<std::int8_t>(both.s[1] - v.s[1])}};
            if (other != g::QualDirection{{0, 0}} && blocked(both) && !blocked(other)) return true;
        }
        return false;
    }
    [[nodiscard]] std::optional<std::size_t> one_way(const std::vector<StateId>& states) const {
        for (std::size_t o = 0; o < bounded_.size(); ++o) {
            if (!bounded_[o]) continue;
            const std::int8_t first = c_.states[states.front()].motions[o];
            if (first != 0 && std::all_of(states.begin(), states.end(), [&](StateId s) { return c_.states[s].motions[o] == first; })) return o;
        }
        return std::nullopt;
    }
    [[nodiscard]] std::string name(std::size_t o) const { return m_.parts[c_.chain.objects[o]].name; }
    void problem(std::vector<std::string>& out, StateId s, const std::string& what) const {
        out.push_back("chain " + std::to_string(c_.chain.index + 1) + ": state #" + std::to_string(s.value) + " " + state_name(e_, c_, s) + " " + what);
    }

    const g::Mechanism& m_;
    const Envisionment& e_;
    const ChainEnvisionment& c_;
    std::vector<bool> bounded_;
};

}  // namespace

std::vector<std::string> verify(const g::Mechanism& m, const Envisionment& e) {
    std::vector<std::string> out;
    for (const auto& c : e.chains) Checker(m, e, c).run(out);
    return out;
}

}  // namespace qm::envision
