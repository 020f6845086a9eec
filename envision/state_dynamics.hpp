// envision/state_dynamics.hpp
// Provides:   state_dynamics(), what the laws conclude in one mechanical state (thesis Figure 8.5
//             steps 1.1-1.3): the net force on each object (8.3.1: forces gathered, propagated
//             through contact and linkage, added with Law 5) and the steps the state may take, each
//             with every pair's possible next places and every object's possible next motions
//             (rules/clock/transition_order.rules). One engine per place vector: its places are
//             premises (current-place), with the chain's description at those places only (normals,
//             concavity, the adjacency from them, the forces there); the external forces and the
//             motions of the place vector's states (current-motion) are assumptions, and each state
//             is run as a context of the engine (its forces and its motions; docs/RULES.md,
//             "Semantics": `not` and aggregates are decided in it), so what does not depend on
//             the motions (forces passing through contacts) is derived once for all of them.
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
    std::vector<std::pair<std::size_t, std::size_t>> preempts;  // (s, t): step t only if step s cannot (indices into steps)
    bool may_rest = false;               // (may-rest): the state may also stay as it is (rules/clock/rest.rules)
};

// The engine of one place vector and its states.
class PlaceVectorEngine {
public:
    // Pre: every state belongs to chain and has the same places; without names forces of m.
    // labelled: the external forces as assumptions, so that labels name them (for questions);
    // else premises (the conclusions alone, faster: no context is needed for a single state).
    PlaceVectorEngine(const Laws& laws, const geometry::Mechanism& m, std::span<const bridge::PairPlaces> pairs,
                      const Chain& chain, std::span<const State* const> states, std::span<const bridge::ForceRef> without,
                      bool labelled = true);
    // Runs the laws in the context of states[i]: the environment where its conclusions hold, or
    // nothing after errors (reported into diagnostics).
    [[nodiscard]] std::optional<atms::EnvId> run(std::size_t i, Diagnostics& diagnostics);
    [[nodiscard]] engine::Engine& engine() noexcept { return *engine_; }

private:
    std::unique_ptr<engine::Engine> engine_;
    std::vector<atms::AssumptionId> forces_;
    std::vector<std::vector<atms::AssumptionId>> motions_;  // per state: its parts' motions
    bool contexts_ = true;  // run each state as a context (else once, generically)
};

// What the laws concluded for one state, read in the environment its context run returned.
[[nodiscard]] std::optional<StateDynamics> read_dynamics(engine::Engine& e, atms::EnvId environment, const geometry::Mechanism& m,
                                                         std::span<const bridge::PairPlaces> pairs, const Chain& chain,
                                                         Diagnostics& diagnostics);

}  // namespace qm::envision
