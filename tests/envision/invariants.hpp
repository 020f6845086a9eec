// tests/envision/invariants.hpp: what every envisionment must be, checked apart from the laws and
// from envision/verify.cpp, which read the place vocabularies' adjacency. Here the pair's own
// geometry answers (the FCL oracle at a configuration of the place) and the graph is searched anew:
//   - a state with a part moving has a transition out (time does not stop while something moves);
//   - a terminal state and a possible rest have every part still;
//   - in a terminal state every definite net force is held: moving its part that way from a
//     configuration of the state's place in some pair that holds the part (its shaft-mates with
//     it, the pair's other part still) overlaps the parts or leaves the part's axis within half a
//     grid cell (a pocket of free space smaller than that is below the vocabulary's resolution);
//   - every strongly connected component (of more than one state, or a state with a transition to
//     itself) in which some part whose axis ends moves one way throughout is listed as transient;
//     every other one is listed as a behavioural cycle, or as transient with a part that turns one
//     way throughout (its pair's places keep it from coming round: their values are the
//     vocabulary's, which this does not read).
// Plain C++ over the envisionment's values and the geometry; no engine, no rule, no adjacency.
#pragma once
#include "envision/envisionment.hpp"
#include "envision/state_report.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/place_sample.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace qm::envision::testing {

// The components of more than one state, or of one state with a transition to itself (Tarjan's).
inline std::vector<std::vector<std::uint32_t>> components(std::size_t n, const std::vector<Transition>& transitions) {
    std::vector<std::vector<std::uint32_t>> out_edges(n);
    std::vector<bool> self(n, false);
    for (const auto& t : transitions) {
        out_edges[t.from.value].push_back(t.to.value);
        if (t.from == t.to) self[t.from.value] = true;
    }
    std::vector<int> index(n, -1), low(n, 0);
    std::vector<bool> on(n, false);
    std::vector<std::uint32_t> stack;
    std::vector<std::vector<std::uint32_t>> out;
    int next = 0;
    // Iterative, so a long chain of states does not overflow the call stack.
    for (std::uint32_t root = 0; root < n; ++root) {
        if (index[root] >= 0) continue;
        std::vector<std::pair<std::uint32_t, std::size_t>> work{{root, 0}};
        index[root] = low[root] = next++;
        stack.push_back(root);
        on[root] = true;
        while (!work.empty()) {
            auto& [v, i] = work.back();
            if (i < out_edges[v].size()) {
                const std::uint32_t w = out_edges[v][i++];
                if (index[w] < 0) {
                    index[w] = low[w] = next++;
                    stack.push_back(w);
                    on[w] = true;
                    work.push_back({w, 0});
                } else if (on[w]) {
                    low[v] = std::min(low[v], index[w]);
                }
                continue;
            }
            if (low[v] == index[v]) {
                std::vector<std::uint32_t> c;
                std::uint32_t w = 0;
                do {
                    w = stack.back();
                    stack.pop_back();
                    on[w] = false;
                    c.push_back(w);
                } while (w != v);
                std::sort(c.begin(), c.end());
                if (c.size() > 1 || self[c.front()]) out.push_back(std::move(c));
            }
            const std::uint32_t done = v;
            work.pop_back();
            if (!work.empty()) low[work.back().first] = std::min(low[work.back().first], low[done]);
        }
    }
    return out;
}

class InvariantChecker {
public:
    InvariantChecker(const geometry::Mechanism& m, const Envisionment& e) : m_(m), e_(e) {
        for (const auto& p : e.pairs) oracles_.push_back(geometry::pair_oracle(m, p.spec));
    }

    [[nodiscard]] std::vector<std::string> run() {
        std::vector<std::string> out;
        for (const auto& c : e_.chains) check(c, out);
        return out;
    }

private:
    void check(const ChainEnvisionment& c, std::vector<std::string>& out) const {
        const std::size_t n = c.states.size();
        std::vector<bool> leaves(n, false);
        for (const auto& t : c.transitions) leaves[t.from.value] = true;
        auto say = [&](std::uint32_t s, const std::string& what) {
            out.push_back("chain " + std::to_string(c.chain.index + 1) + ": #" + std::to_string(s) + " " +
                          state_name(e_, c, StateId{s}) + " " + what);
        };
        const std::set<StateId> rests(c.graph.possible_rests.begin(), c.graph.possible_rests.end());
        for (std::uint32_t s = 0; s < n; ++s) {
            const State& st = c.states[StateId{s}];
            const bool moving = std::any_of(st.motions.begin(), st.motions.end(), [](std::int8_t x) { return x != 0; });
            if (moving && !leaves[s]) say(s, "has a part moving and no transition out");
            if (moving && rests.count(StateId{s})) say(s, "is a possible rest with a part moving");
            if (leaves[s] || moving) continue;
            for (std::size_t o = 0; o < st.motions.size(); ++o)
                if (o < st.net_force.size() && (st.net_force[o] == 1 || st.net_force[o] == -1) && !held(c, st, o))
                    say(s, "is terminal, and nothing in the geometry holds " + m_.parts[c.chain.objects[o]].name + "'s net force " +
                               sign_word(st.net_force[o]));
        }
        // Cycles, from the transitions.
        std::vector<bool> bounded(c.chain.objects.size(), false);
        for (const std::size_t k : c.chain.pairs)
            for (std::size_t i = 0; i < 2; ++i)
                if (!e_.pairs[k].request.cspace.axes[i].periodic)
                    bounded[c.chain.object_index(i == 0 ? e_.pairs[k].spec.a : e_.pairs[k].spec.b)] = true;
        std::set<std::vector<std::uint32_t>> cycles, transient;
        for (const auto& x : c.graph.cycles) cycles.insert(values(x));
        for (const auto& x : c.graph.transient) transient.insert(values(x.states));
        for (const auto& comp : components(n, c.transitions)) {
            bool one_way = false;
            for (std::size_t o = 0; o < bounded.size() && !one_way; ++o) {
                const std::int8_t first = c.states[StateId{comp.front()}].motions[o];
                one_way = bounded[o] && first != 0 &&
                          std::all_of(comp.begin(), comp.end(), [&](std::uint32_t s) { return c.states[StateId{s}].motions[o] == first; });
            }
            bool turning = false;
            for (std::size_t o = 0; o < bounded.size() && !turning; ++o) {
                const std::int8_t first = c.states[StateId{comp.front()}].motions[o];
                turning = first != 0 && std::all_of(comp.begin(), comp.end(), [&](std::uint32_t s) { return c.states[StateId{s}].motions[o] == first; });
            }
            if (one_way && !transient.count(comp)) say(comp.front(), "is on a component that cannot repeat, not listed as transient");
            if (!one_way && !cycles.count(comp) && !(turning && transient.count(comp)))
                say(comp.front(), "is on a component that can repeat, not listed as a behavioural cycle");
        }
        if (cycles.size() + transient.size() != components(n, c.transitions).size()) say(0, "heads a chain whose cycles are miscounted");
    }

    static std::vector<std::uint32_t> values(const std::vector<StateId>& ids) {
        std::vector<std::uint32_t> v;
        for (const auto s : ids) v.push_back(s.value);
        std::sort(v.begin(), v.end());
        return v;
    }

    // Whether moving object o along its force, from the state's place in a pair that holds it,
    // overlaps the parts or leaves the axis within half a grid cell.
    [[nodiscard]] bool held(const ChainEnvisionment& c, const State& st, std::size_t o) const {
        const geometry::PartId part = c.chain.objects[o];
        for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
            const auto& p = e_.pairs[c.chain.pairs[k]];
            const auto& axes = p.request.cspace.axes;
            Eigen::Vector2d v(0, 0);  // half a cell along the force
            for (std::size_t i = 0; i < 2; ++i) {
                const geometry::PartId x = i == 0 ? p.spec.a : p.spec.b;
                if (x == part || m_.same_shaft(x, part)) v[static_cast<Eigen::Index>(i)] = st.net_force[o] * 0.5 * axes[i].step();
            }
            if (v.isZero()) continue;
            const geometry::Place& place = p.vocabulary.places[st.places[k].value];
            // A gap collapsed by 8.1.6 is in contact on both sides: its play, at most the gap
            // epsilon, is crossed first.
            if (place.gap) v *= 1 + p.request.gap_epsilon / v.norm();
            const Eigen::Vector2d from = geometry::sample_configuration(p.request.cspace, place);
            for (double t = 1e-6; t < 2; t *= 2) {
                const Eigen::Vector2d q = from + std::min(t, 1.0) * v;
                bool outside = false;
                for (std::size_t i = 0; i < 2; ++i) {
                    const double x = q[static_cast<Eigen::Index>(i)];
                    outside = outside || (!axes[i].periodic && (x < axes[i].lo || x > axes[i].hi));
                }
                if (outside || oracles_[c.chain.pairs[k]]->blocked(q)) return true;
            }
        }
        return false;
    }

    const geometry::Mechanism& m_;
    const Envisionment& e_;
    std::vector<std::unique_ptr<geometry::FclPairOracle>> oracles_;
};

inline std::vector<std::string> invariant_problems(const geometry::Mechanism& m, const Envisionment& e) {
    return InvariantChecker(m, e).run();
}

}  // namespace qm::envision::testing
