// envision/envisionment.cpp: the envisioner's pipeline (thesis Figures 8.1, 8.4, 8.5).
#include "envision/envisionment.hpp"
#include "envision/behaviour_query.hpp"
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
    for (const auto& part : m.parts) e.parts.push_back(part.name);
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
        // One engine per state, its forces and motions premises. (One engine per place vector with
        // its states as contexts was measured slower: the contexts' labels cost more than the
        // engines, docs/PERFORMANCE.md.)
        for (std::uint32_t i = 0; i < c.states.size(); ++i) {
            const StateId id{i};
            const State* const only[] = {&c.states[id]};
            PlaceVectorEngine engine(*laws, m, e.pairs, c.chain, only, options.without, /*labelled=*/false);
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
        c.tables = std::move(space->tables);
        c.graph = behaviour_graph(c.states.size(), c.transitions);
        e.chains.push_back(std::move(c));
    }
    return e;
}

std::size_t ChainEnvisionment::shown_count() const {
    return shown.empty() ? states.size() : static_cast<std::size_t>(std::count(shown.begin(), shown.end(), true));
}

void restrict_to_reachable(Envisionment& e, std::size_t chain, StateId from) {
    ChainEnvisionment c = std::move(e.chains[chain]);
    c.shown = reachable_from(c, from);
    std::erase_if(c.transitions, [&](const Transition& t) { return !c.shown[t.from.value]; });
    // The reachable set is closed under transitions: its cycles are whole components of the graph.
    std::erase_if(c.graph.cycles, [&](const std::vector<StateId>& cycle) { return !c.shown[cycle.front().value]; });
    std::erase_if(c.graph.terminal, [&](StateId s) { return !c.shown[s.value]; });
    e.chains.clear();
    e.chains.push_back(std::move(c));
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
