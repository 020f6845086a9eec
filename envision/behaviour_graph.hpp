// envision/behaviour_graph.hpp
// Provides:   behaviour_graph(), the graph questions every envisionment answers (Boost.Graph): the
//             behavioural cycles (thesis 9.1.5, Figures 9.21-9.24: strongly connected components of
//             more than one state, and states with a transition to themselves over an interval)
//             that can be traversed forever; the components that cannot (transient: some object
//             moves one way, never still and never back, in every state of it, along a coordinate
//             that cannot come round: bounded, or kept by the places of one of its pairs in the
//             component within values that leave some of its period out; each lap would take it
//             further along a stroke that ends); the terminal states
//             (no transition out: "the mechanism stops", 9.2.3) and the possible rests (states with
//             transitions out that may also stay, State::may_rest).
// Ownership:  value types; the graph is built and dropped inside the call.
// Invariants: each cycle's states ascending; cycles and transient cycles ordered by their first
//             state; terminal states and possible rests ascending and disjoint.
#pragma once
#include "envision/state.hpp"
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace qm::envision {

// A strongly connected component that cannot repeat: `object` (an index into the chain's objects)
// moves `motion` (-1 or +1) in every state of it, along a bounded coordinate (no `pair`) or along
// one that the places of pair `pair` (an index into the chain's pairs) keep from coming round.
struct TransientCycle {
    std::vector<StateId> states;
    std::size_t object = 0;
    std::int8_t motion = 0;
    std::optional<std::size_t> pair;
    friend bool operator<(const TransientCycle& a, const TransientCycle& b) { return a.states < b.states; }
};

struct BehaviourGraph {
    std::vector<std::vector<StateId>> cycles;
    std::vector<TransientCycle> transient;
    std::vector<StateId> terminal;
    std::vector<StateId> possible_rests;
    // Where behaviour may end: the terminal states and the possible rests.
    [[nodiscard]] std::size_t ends() const noexcept { return terminal.size() + possible_rests.size(); }
};

// The pair, if any, whose places in the states `members` keep `object`'s periodic coordinate from
// coming round (their values leave some of its period out).
using KeptFromComingRound = std::function<std::optional<std::size_t>(const std::vector<StateId>& members, std::size_t object)>;

// Pre: every transition's states index `states`; bounded has one entry per object of the states
// (whether that object's coordinate is bounded in some pair of the chain).
[[nodiscard]] BehaviourGraph behaviour_graph(std::span<const State> states, std::span<const Transition> transitions,
                                             const std::vector<bool>& bounded, const KeptFromComingRound& kept = {});

}  // namespace qm::envision
