// envision/state_space.hpp
// Provides:   enumerate_states(), the mechanical states of one kinematic chain (thesis Def 35,
//             Figure 8.4, 8.2.2-8.2.3) as the ATMS interpretations of the choice sets the laws
//             declare (rules/clock/states.rules: a place per pair, a motion per object) under the
//             nogoods the laws derive (Law 2, linkage, fixed parts, correlation), and the chain's
//             tables (chain_tables.hpp). The choice sets are searched pair by pair along the chain
//             (8.2.3: each pair's places, then the motions of its parts not yet chosen), so a
//             nogood prunes a partial choice at once and the motions of linked parts are never
//             enumerated freely; the full product is never formed.
// Ownership:  value types out; the state-space engine lives only during the call.
// Invariants: states are sorted by place vector (pairs in chain order, place ids ascending), then
//             by motions (objects in chain order, - before 0 before +), so ids are stable across
//             runs; their net_force is left empty.
// Errors:     rule programs that do not declare the choice sets, or errors while running them,
//             or whose preference or settling the tables cannot read (a `prefer` on motions
//             without a (step-allows O H) assumption for each motion, an assumption of the
//             settling vocabulary concluded as a plain fact or made for only some motions):
//             located diagnostics, at the `prefer` or the rule. More states than the limit allows:
//             qm::LimitReached{states} (qm/limit_reached.hpp), thrown as soon as one state too many
//             is found, after a progress report with the states found.
#pragma once
#include "bridge/place_facts.hpp"
#include "envision/chain.hpp"
#include "envision/chain_tables.hpp"
#include "envision/laws.hpp"
#include "envision/progress.hpp"
#include "envision/state.hpp"
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace qm::envision {

struct StateSpace {
    std::vector<State> states;
    ChainTables tables;
    std::size_t nogoods = 0;  // minimal nogoods of the state-space engine (for --stats)
};

// The state-space engine of a chain, run: the laws over the chain's places, with the assumptions
// that stand for each pair's places and each part's motions (for questions: which nogoods exclude
// a combination).
struct StateSpaceEngine {
    std::unique_ptr<engine::Engine> engine;
    std::vector<std::map<std::uint32_t, atms::AssumptionId>> place;  // per pair: place id -> (at P PLACE)
    std::vector<std::map<std::int8_t, atms::AssumptionId>> motion;   // per object: motion -> (motion O M)
};
[[nodiscard]] std::optional<StateSpaceEngine> state_space_engine(const Laws& laws, const geometry::Mechanism& m,
                                                                 std::span<const bridge::PairPlaces> pairs, const Chain& chain,
                                                                 Diagnostics& diagnostics);

// The most states over all chains, and how many the chains before this one have.
struct StateLimit {
    std::size_t max_states = 0;
    std::size_t found_before = 0;
};

[[nodiscard]] std::optional<StateSpace> enumerate_states(const Laws& laws, const geometry::Mechanism& m,
                                                         std::span<const bridge::PairPlaces> pairs, const Chain& chain,
                                                         StateLimit limit, const ProgressFn& progress, Diagnostics& diagnostics);

}  // namespace qm::envision
