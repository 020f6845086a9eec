// envision/behaviour_graph.hpp
// Provides:   behaviour_graph(), the graph questions every envisionment answers (Boost.Graph): the
//             behavioural cycles (thesis 9.1.5, Figures 9.21-9.24: strongly connected components of
//             more than one state, and states with a transition to themselves over an interval) and
//             the terminal states (no transition out: "the mechanism stops", 9.2.3).
// Ownership:  value types; the graph is built and dropped inside the call.
// Invariants: each cycle's states ascending; cycles ordered by their first state; terminal
//             states ascending.
#pragma once
#include "envision/state.hpp"
#include <span>
#include <vector>

namespace qm::envision {

struct BehaviourGraph {
    std::vector<std::vector<StateId>> cycles;
    std::vector<StateId> terminal;
};

// Pre: every transition's states are < state_count.
[[nodiscard]] BehaviourGraph behaviour_graph(std::size_t state_count, std::span<const Transition> transitions);

}  // namespace qm::envision
