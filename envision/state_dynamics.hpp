// envision/state_dynamics.hpp
// Provides:   state_dynamics(), what the laws conclude in one mechanical state (thesis Figure 8.5
//             steps 1.1-1.3): the net force on each object (8.3.1: forces gathered, propagated
//             through contact and linkage, added with Law 5) and the steps the state may take, each
//             with every pair's possible next places and every object's possible next motions
//             (rules/clock/transition_order.rules). One engine per state: the state is its premises
//             (current-place, current-motion), the chain's description those of the current places
//             only (place kind, normals, the adjacency under the current motion, the forces there),
//             and the external forces are assumptions; the laws run in the context of those forces
//             (docs/RULES.md, "Semantics": `not` and aggregates are decided in it).
// Ownership:  value types out; the engine lives during the call (or is handed back for questions).
// Errors:     laws that give a pair or an object no option in a step, or a step no duration or
//             cause the envisioner knows: located diagnostics (the rule files are input too).
#pragma once
#include "bridge/place_facts.hpp"
#include "envision/chain.hpp"
#include "envision/chain_tables.hpp"
#include "envision/laws.hpp"
#include "envision/state.hpp"
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace qm::envision {

struct PlaceOption {
    geometry::PlaceId place{0};
    How how = How::stay;
};

struct StepOptions {
    std::string name;                                // e.g. instant-kinematic
    Duration duration = Duration::interval;
    std::uint8_t cause = 0;                          // Cause::kinematic or Cause::dynamic
    std::vector<std::vector<PlaceOption>> places;    // per pair of the chain
    std::vector<std::vector<std::int8_t>> motions;   // per object of the chain
};

struct StateDynamics {
    std::vector<std::int8_t> net_force;  // per object (ambiguous_sign for `?`)
    std::vector<StepOptions> steps;      // in name order
};

// The engine of one state, run: for reading more of what the laws concluded there.
struct StateEngine {
    std::unique_ptr<engine::Engine> engine;
    atms::EnvId environment{};  // where the state's conclusions hold (forces + closed world)
};

// Pre: state belongs to chain; without names forces of the mechanism.
[[nodiscard]] std::optional<StateEngine> run_state(const Laws& laws, const geometry::Mechanism& m,
                                                   std::span<const bridge::PairPlaces> pairs, const Chain& chain,
                                                   const State& state, std::span<const bridge::ForceRef> without,
                                                   Diagnostics& diagnostics);
[[nodiscard]] std::optional<StateDynamics> read_dynamics(StateEngine& run, const geometry::Mechanism& m,
                                                         std::span<const bridge::PairPlaces> pairs, const Chain& chain,
                                                         Diagnostics& diagnostics);

}  // namespace qm::envision
