// envision/successors.hpp
// Provides:   successors(), the transitions out of one state (thesis Figure 8.5 step 1.4): every
//             combination of one option per pair and per object of each step the laws allow
//             (state_dynamics.hpp) is a hypothesised next state; each pair's motion is carried
//             through its arrival at its next place (a collision or the end of an axis may change
//             it: collision.rules, a stop at the end of an axis too); every object keeps only the
//             motions after the step the laws allow given its situation in it (the outcomes of
//             the collisions that meet it, a motion the step does not allow that must change,
//             whether any state lets it: rules/clock/settling.rules, read once per chain into
//             ChainTables as a settling table and looked up here), and the chain is made consistent (8.3.4) by keeping, among the generated
//             states with the hypothesised places and those motions, the ones the laws' preference
//             keeps (rules/clock/nearness.rules: `prefer` on every object's motion, ranked given
//             the motions the step allows it; also read once per chain into ChainTables and applied
//             here by lookup: the Pareto front, atms/pareto_front.hpp); a hypothesis that matches no
//             generated state is dropped (8.3.5). This file holds no law: it decides no rank,
//             threshold, order of motions, nor which motion may follow which. A transition's causes
//             are its step's, a collision where the laws call an arrival one (`collision`), and a
//             kinematic one where a pair reaches its next place in a way the laws call a change of
//             place (`place-change`); a hypothesis that comes back to the state it left is a
//             transition only with such a change (a wheel round a periodic axis). A step that
//             another preempts (Law 4: the laws' `preempts`) gives its transitions only if that one
//             gives none.
// Ownership:  value types.
// Invariants: one transition per (target, duration), its causes the union of those found; sorted
//             by target, then duration.
#pragma once
#include "envision/chain.hpp"
#include "envision/chain_tables.hpp"
#include "envision/state_dynamics.hpp"
#include "envision/state_index.hpp"
#include <string>
#include <utility>
#include <vector>

namespace qm::envision {

[[nodiscard]] std::vector<Transition> successors(StateId from, const StateIndex& states, const Chain& chain,
                                                 std::span<const bridge::PairPlaces> pairs, const ChainTables& tables,
                                                 const StateDynamics& dynamics);

// Why `from` has no transition to `to` (--why-not): per step of the state, the reasons its
// hypotheses do not give `to` (a pair that cannot reach the place, a collision's outcome or a part's
// motion the settling laws refute, citing the refuting rule's name, file and line, a state the laws'
// preference keeps instead, citing the `prefer` declaration's file and line, or "this step allows
// it" when only a preemption stops it).
[[nodiscard]] std::vector<std::pair<std::string, std::vector<std::string>>> why_no_transition(
    StateId from, StateId to, const StateIndex& states, const Chain& chain, std::span<const bridge::PairPlaces> pairs,
    const std::vector<std::string>& object_names, const ChainTables& tables, const StateDynamics& dynamics);

}  // namespace qm::envision
