// envision/envisionment.cpp: the envisioner's pipeline (thesis Figures 8.1, 8.4, 8.5).
#include "envision/envisionment.hpp"
#include "envision/pair_places.hpp"
#include "envision/state_dynamics.hpp"
#include "envision/state_space.hpp"
#include "envision/successors.hpp"

#include <algorithm>
#include <chrono>

namespace qm::envision {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::optional<Envisionment> envision(const geometry::Mechanism& m, const EnvisionOptions& options, Diagnostics& diagnostics) {
    const auto laws = Laws::load(options.rules, diagnostics);
    if (!laws) return std::nullopt;
    Envisionment e;
    e.mechanism = m.name;
    auto t0 = std::chrono::steady_clock::now();
    if (options.progress) options.progress({"place vocabularies", 0, 0});
    auto pairs = load_pair_places(m, options.cache, diagnostics);
    if (!pairs) return std::nullopt;
    e.pairs = std::move(*pairs);
    e.seconds_places = seconds_since(t0);
    std::size_t budget = options.max_states;
    for (auto& chain : kinematic_chains(m, e.pairs)) {
        ChainEnvisionment c;
        c.chain = std::move(chain);
        t0 = std::chrono::steady_clock::now();
        auto space = enumerate_states(*laws, m, e.pairs, c.chain, budget, options.progress, diagnostics);
        if (!space) return std::nullopt;
        budget -= space->states.size();
        c.states = StateIndex(std::move(space->states));
        c.nogoods = space->nogoods;
        c.seconds_states = seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
        const std::string phase = "chain " + std::to_string(c.chain.index + 1) + ": transitions";
        // One engine per state (one per place vector, its states as contexts, measured slower:
        // the contexts' labels cost more than the engines, docs/PERFORMANCE.md).
        for (std::uint32_t i = 0; i < c.states.size(); ++i) {
            const StateId id{i};
            const State* const only[] = {&c.states[id]};
            PlaceVectorEngine engine(*laws, m, e.pairs, c.chain, only, options.without);
            const auto env = engine.run(0, diagnostics);
            if (!env) return std::nullopt;
            const auto dynamics = read_dynamics(engine.engine(), *env, m, e.pairs, c.chain, diagnostics);
            if (!dynamics) return std::nullopt;
            c.states[id].net_force = dynamics->net_force;
            auto out = successors(id, c.states, c.chain, e.pairs, space->tables, *dynamics);
            c.transitions.insert(c.transitions.end(), out.begin(), out.end());
            if (options.progress && (i + 1) % 16 == 0) options.progress({phase, i + 1, c.states.size()});
        }
        c.seconds_transitions = seconds_since(t0);
        c.graph = behaviour_graph(c.states.size(), c.transitions);
        e.chains.push_back(std::move(c));
    }
    return e;
}

std::string state_name(const Envisionment& e, const ChainEnvisionment& c, StateId s) {
    const State& state = c.states[s];
    std::string out;
    for (std::size_t k = 0; k < c.chain.pairs.size(); ++k)
        out += (k ? " " : "") + e.pairs[c.chain.pairs[k]].name + "-" + std::to_string(state.places[k].value);
    for (const auto m : state.motions) out += std::string(" ") + sign_word(m);
    return out;
}

}  // namespace qm::envision
