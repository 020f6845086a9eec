// envision/behaviour_graph.cpp: cycles and terminal states with Boost.Graph.
#include "envision/behaviour_graph.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/strong_components.hpp>
#include <optional>

namespace qm::envision {

namespace {

// What makes a component transient: an object that moves the same way in every state of it along a
// coordinate that cannot come round (so it never comes back to where a lap began).
std::optional<TransientCycle> one_way(std::span<const State> states, const std::vector<StateId>& members, const std::vector<bool>& bounded,
                                      const KeptFromComingRound& kept) {
    // A bounded coordinate first: it needs no place to say so.
    for (const bool along_bounded : {true, false})
        for (std::size_t o = 0; o < bounded.size(); ++o) {
            if (bounded[o] != along_bounded || (!along_bounded && !kept)) continue;
            const std::int8_t m = states[members.front().value].motions[o];
            if (m == 0) continue;
            if (!std::all_of(members.begin(), members.end(), [&](StateId s) { return states[s.value].motions[o] == m; })) continue;
            if (along_bounded) return TransientCycle{members, o, m, std::nullopt};
            if (const auto pair = kept(members, o)) return TransientCycle{members, o, m, pair};
        }
    return std::nullopt;
}

}  // namespace

BehaviourGraph behaviour_graph(std::span<const State> states, std::span<const Transition> transitions, const std::vector<bool>& bounded,
                               const KeptFromComingRound& kept) {
    const std::size_t state_count = states.size();
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;
    Graph graph(state_count);
    std::vector<bool> has_out(state_count, false), loops(state_count, false);
    for (const auto& t : transitions) {
        QM_REQUIRE(t.from.value < state_count && t.to.value < state_count, "transition between unknown states");
        boost::add_edge(t.from.value, t.to.value, graph);
        has_out[t.from.value] = true;
        if (t.from == t.to && t.duration == Duration::interval) loops[t.from.value] = true;
    }
    std::vector<int> component(state_count);
    const int count = state_count == 0 ? 0 : boost::strong_components(graph, component.data());
    std::vector<std::vector<StateId>> members(static_cast<std::size_t>(count));
    for (std::uint32_t s = 0; s < state_count; ++s) members[static_cast<std::size_t>(component[s])].push_back(StateId{s});
    BehaviourGraph out;
    for (auto& m : members) {
        if (m.size() == 1 && !loops[m.front().value]) continue;
        if (auto w = one_way(states, m, bounded, kept)) out.transient.push_back(std::move(*w));
        else out.cycles.push_back(std::move(m));
    }
    std::sort(out.cycles.begin(), out.cycles.end());
    std::sort(out.transient.begin(), out.transient.end());
    for (std::uint32_t s = 0; s < state_count; ++s) {
        if (!has_out[s]) out.terminal.push_back(StateId{s});
        else if (states[s].may_rest) out.possible_rests.push_back(StateId{s});
    }
    return out;
}

}  // namespace qm::envision
