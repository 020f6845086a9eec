// envision/behaviour_graph.cpp: cycles and terminal states with Boost.Graph.
#include "envision/behaviour_graph.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/strong_components.hpp>

namespace qm::envision {

BehaviourGraph behaviour_graph(std::size_t state_count, std::span<const Transition> transitions) {
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
    for (auto& m : members)
        if (m.size() > 1 || (m.size() == 1 && loops[m.front().value])) out.cycles.push_back(std::move(m));
    std::sort(out.cycles.begin(), out.cycles.end());
    for (std::uint32_t s = 0; s < state_count; ++s)
        if (!has_out[s]) out.terminal.push_back(StateId{s});
    return out;
}

}  // namespace qm::envision
