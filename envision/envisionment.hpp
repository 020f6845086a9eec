// envision/envisionment.hpp
// Provides:   envision(), the Clock envisioner (thesis chapters 5, 8, 9; Figures 8.1, 8.4, 8.5):
//             the place vocabulary of every kinematic pair (cached), the kinematic chains, each
//             chain's mechanical states (ATMS interpretations under the laws' nogoods), the
//             transitions out of every state (one engine per state running the laws of
//             rules/clock/), and the behaviour graph's cycles and terminal states. Chains are
//             envisioned separately and never multiplied (9.1.3). With options.from, only the
//             transitions of the states it leads to are found, and only they are kept.
// Ownership:  Envisionment is a value type owning the pairs' vocabularies and the chains' states
//             and transitions; it refers to the mechanism by nothing (printers take both).
// Errors:     bad input (the scene's pairs, the laws' files, a --from that names no state):
//             located diagnostics, and nothing is returned. More states than options.max_states:
//             qm::LimitReached{states}, thrown after a progress report with the states found
//             (envision/progress.hpp); std::bad_alloc (under a memory limit) is thrown on from any
//             worker. InternalError for bugs.
// Knows no law: every consequence of a law comes from the rule files.
#pragma once
#include "bridge/place_facts.hpp"
#include "envision/behaviour_graph.hpp"
#include "envision/chain.hpp"
#include "envision/chain_tables.hpp"
#include "envision/laws.hpp"
#include "envision/progress.hpp"
#include "envision/state_index.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/place_cache.hpp"
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace qm::envision {

struct ChainEnvisionment {
    Chain chain;
    StateIndex states{{}};
    std::vector<Transition> transitions;  // sorted by from, to, duration
    ChainTables tables;                   // the laws' arrivals, nearness ranks and settling (for questions)
    BehaviourGraph graph;
    std::size_t nogoods = 0;              // minimal nogoods of the state space (Law 2, linkage, ..., and settling.rules')
    std::vector<bool> shown;              // empty: every state; else the states to print (--from)
    [[nodiscard]] bool is_shown(StateId s) const { return shown.empty() || shown[s.value]; }
    [[nodiscard]] std::size_t shown_count() const;
    double seconds_states = 0, seconds_transitions = 0;
};

struct Envisionment {
    std::string mechanism;
    std::vector<std::string> parts;         // the mechanism's part names, by PartId
    std::vector<bridge::PairPlaces> pairs;  // every modelled pair
    std::vector<ChainEnvisionment> chains;
    double seconds_places = 0;
};

struct EnvisionOptions {
    std::filesystem::path rules;                  // the laws' folder (rules/clock)
    const geometry::PlaceCache* cache = nullptr;  // null: compute every vocabulary
    std::size_t max_states = 1'000'000;           // over all chains
    std::vector<bridge::ForceRef> without;        // external forces taken away (what-if)
    unsigned threads = 2;                         // workers finding the states' transitions (1: none)
    ProgressFn progress;                          // called as envision/progress.hpp says
    // `--from`: a state (as find_state() reads it, errors located in "--from"); only what it leads
    // to is envisioned, on the fly (11.3.4), as restrict_to_reachable() leaves it.
    std::optional<std::string> from;
    // With `from`: that state's own transitions alone, every chain's states kept and nothing cut
    // down (`--next` asks no more).
    bool from_only = false;
};

[[nodiscard]] std::optional<Envisionment> envision(const geometry::Mechanism& m, const EnvisionOptions& options,
                                                   Diagnostics& diagnostics);

// Only what `from` leads to (thesis 11.2.1, `--from`): that chain alone, its states and transitions
// reachable from the state, and the cycles and terminal states among them. Ids are kept.
void restrict_to_reachable(Envisionment& e, std::size_t chain, StateId from);

// The state's name in the thesis' style (Figure 5.1, Appendix A): each pair's place as PAIR-PLACE,
// then each object's motion, e.g. `scape-wheel/pallets-36 - -`.
[[nodiscard]] std::string state_name(const Envisionment& e, const ChainEnvisionment& c, StateId s);

}  // namespace qm::envision
