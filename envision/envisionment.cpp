// envision/envisionment.cpp: the envisioner's pipeline (thesis Figures 8.1, 8.4, 8.5).
#include "envision/envisionment.hpp"
#include "envision/behaviour_query.hpp"
#include "bridge/pair_places.hpp"
#include "bridge/place_correlation.hpp"
#include "envision/state_dynamics.hpp"
#include "envision/state_query.hpp"
#include "envision/state_space.hpp"
#include "envision/successors.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>

namespace qm::envision {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Every state's transitions (Figure 8.5). One engine per state, its forces and motions premises.
// (One engine per place vector with its states as contexts was measured slower: the contexts'
// labels cost more than the engines, docs/PERFORMANCE.md.) The states are independent: workers
// take them in turn, each with its own engines and diagnostics; the results are put in state order.
// An exception in a worker (std::bad_alloc under a memory limit) stops them all and is rethrown here.
// `which`: the states to find them for (their transitions are appended in that order).
bool find_transitions(const Laws& laws, const geometry::Mechanism& m, const Envisionment& e, ChainEnvisionment& c,
                      const ChainTables& tables, const EnvisionOptions& options, const std::vector<StateId>& which,
                      Diagnostics& diagnostics) {
    const std::size_t n = which.size();
    Progress report{.phase = Progress::Phase::transitions, .chain = c.chain.index + 1, .states = n};
    if (options.progress) options.progress(report);
    std::vector<std::vector<Transition>> out(n);
    std::vector<std::vector<std::int8_t>> net(n);
    std::vector<char> rest(n, 0);
    std::atomic<std::size_t> next{0}, done{0}, found{0};
    std::atomic<bool> failed{false};
    std::exception_ptr thrown;
    std::mutex thrown_mutex;
    const unsigned workers = std::max(1u, std::min<unsigned>(options.threads, static_cast<unsigned>(std::max<std::size_t>(1, n / 64))));
    std::vector<Diagnostics> reported(workers);
    auto work = [&](unsigned w) {
        try {
            for (std::size_t i = next++; i < n && !failed; i = next++) {
                const StateId id = which[i];
                const State* const only[] = {&c.states[id]};
                PlaceVectorEngine engine(laws, m, e.pairs, c.chain, only, options.without, /*labelled=*/false);
                const auto env = engine.run(0, reported[w]);
                const auto dynamics = env ? read_dynamics(engine.engine(), *env, m, e.pairs, c.chain, reported[w]) : std::nullopt;
                if (!dynamics) {
                    failed = true;
                    return;
                }
                net[i] = dynamics->net_force;
                rest[i] = dynamics->may_rest ? 1 : 0;
                out[i] = successors(id, c.states, c.chain, e.pairs, tables, *dynamics);
                found += out[i].size();
                const std::size_t finished = ++done;
                if (w == 0 && options.progress && finished % 16 == 0) {
                    report.transitions = found;
                    report.done = finished;
                    options.progress(report);
                }
            }
        } catch (...) {
            failed = true;
            const std::lock_guard lock(thrown_mutex);
            if (!thrown) thrown = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    try {
        for (unsigned w = 1; w < workers; ++w) threads.emplace_back(work, w);
    } catch (const std::system_error&) {  // no thread to be had (a memory limit): the others do its share
    }
    work(0);
    for (auto& t : threads) t.join();
    if (thrown) {  // the caller still learns how far the phase got
        report.transitions = found;
        report.done = done;
        if (options.progress) options.progress(report);
        std::rethrow_exception(thrown);
    }
    for (const auto& r : reported)
        for (const auto& d : r.items()) diagnostics.add(d);
    if (failed) return false;
    for (std::size_t i = 0; i < n; ++i) {
        c.states[which[i]].net_force = std::move(net[i]);
        c.states[which[i]].may_rest = rest[i] != 0;
        c.transitions.insert(c.transitions.end(), out[i].begin(), out[i].end());
    }
    report.transitions = c.transitions.size();
    report.done = n;
    if (options.progress) options.progress(report);
    return true;
}

// Every state's transitions, in state order.
bool find_all_transitions(const Laws& laws, const geometry::Mechanism& m, const Envisionment& e, ChainEnvisionment& c,
                          const ChainTables& tables, const EnvisionOptions& options, Diagnostics& diagnostics) {
    std::vector<StateId> all(c.states.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = StateId{static_cast<std::uint32_t>(i)};
    return find_transitions(laws, m, e, c, tables, options, all, diagnostics);
}

// The transitions of the states `from` leads to, found on the fly (11.3.4): a breadth-first search
// whose every layer is found as the whole space's states are, so the others' are never computed.
// Sorted by state at the end, as the whole space's are. Progress is reported a layer at a time.
bool find_reachable_transitions(const Laws& laws, const geometry::Mechanism& m, const Envisionment& e, ChainEnvisionment& c,
                                const ChainTables& tables, const EnvisionOptions& options, StateId from, Diagnostics& diagnostics) {
    std::vector<bool> seen(c.states.size(), false);
    std::vector<StateId> layer{from};
    seen[from.value] = true;
    while (!layer.empty()) {
        const std::size_t before = c.transitions.size();
        if (!find_transitions(laws, m, e, c, tables, options, layer, diagnostics)) return false;
        std::vector<StateId> next;
        for (std::size_t t = before; t < c.transitions.size(); ++t)
            if (const StateId to = c.transitions[t].to; !seen[to.value]) {
                seen[to.value] = true;
                next.push_back(to);
            }
        std::sort(next.begin(), next.end(), [](StateId a, StateId b) { return a.value < b.value; });
        layer = std::move(next);
    }
    std::stable_sort(c.transitions.begin(), c.transitions.end(), [](const Transition& a, const Transition& b) { return a.from.value < b.from.value; });
    return true;
}

// Per object of the chain, whether its coordinate is bounded (an axis that is not periodic in
// some pair of the chain: a sliding part's stroke, a lever's swing).
std::vector<bool> bounded_objects(const Envisionment& e, const Chain& chain) {
    std::vector<bool> out(chain.objects.size(), false);
    for (const std::size_t k : chain.pairs) {
        const auto& pair = e.pairs[k];
        const auto& axes = pair.request.cspace.axes;
        if (!axes[0].periodic) out[chain.object_index(pair.spec.a)] = true;
        if (!axes[1].periodic) out[chain.object_index(pair.spec.b)] = true;
    }
    return out;
}

// The pair whose places, in the states of a component, keep an object's periodic coordinate within
// values that leave some of its period out: moving one way, it could not stay among them for ever.
KeptFromComingRound kept_by_places(const Envisionment& e, const ChainEnvisionment& c) {
    return [&e, &c](const std::vector<StateId>& members, std::size_t object) -> std::optional<std::size_t> {
        for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
            const auto& pair = e.pairs[c.chain.pairs[k]];
            for (int i = 0; i < 2; ++i) {
                if (c.chain.object_index(i == 0 ? pair.spec.a : pair.spec.b) != object) continue;
                std::vector<geometry::PlaceId> places;
                for (const StateId s : members) places.push_back(c.states[s].places[k]);
                std::sort(places.begin(), places.end());
                places.erase(std::unique(places.begin(), places.end()), places.end());
                if (!bridge::places_go_round(pair.vocabulary, places, i, pair.request.cspace.axes[static_cast<std::size_t>(i)])) return k;
            }
        }
        return std::nullopt;
    };
}

}  // namespace

std::optional<Envisionment> envision(const geometry::Mechanism& m, const EnvisionOptions& options, Diagnostics& diagnostics) {
    const auto laws = Laws::load(options.rules, diagnostics);
    if (!laws) return std::nullopt;
    Envisionment e;
    e.mechanism = m.name;
    for (const auto& part : m.parts) e.parts.push_back(part.name);
    auto t0 = std::chrono::steady_clock::now();
    if (options.progress) options.progress({});
    auto pairs = bridge::mechanism_places(m, {.cache = options.cache, .forces = true}, diagnostics);
    if (!pairs) return std::nullopt;
    e.pairs = std::move(*pairs);
    e.seconds_places = seconds_since(t0);
    // Each chain's states, then their transitions; with --from, which may name a state of any chain,
    // every chain's states first (they are cheap), then only the transitions of the states it leads to.
    StateLimit limit{.max_states = options.max_states};
    auto transitions_and_graph = [&](ChainEnvisionment& c, std::optional<StateId> from) {
        const auto t1 = std::chrono::steady_clock::now();
        const bool found = from ? find_reachable_transitions(*laws, m, e, c, c.tables, options, *from, diagnostics)
                                : find_all_transitions(*laws, m, e, c, c.tables, options, diagnostics);
        c.seconds_transitions = seconds_since(t1);
        if (found) c.graph = behaviour_graph(c.states.states(), c.transitions, bounded_objects(e, c.chain), kept_by_places(e, c));
        return found;
    };
    for (auto& chain : kinematic_chains(m, e.pairs)) {
        ChainEnvisionment c;
        c.chain = std::move(chain);
        t0 = std::chrono::steady_clock::now();
        auto space = enumerate_states(*laws, m, e.pairs, c.chain, limit, options.progress, diagnostics);
        if (!space) return std::nullopt;
        limit.found_before += space->states.size();
        c.states = StateIndex(std::move(space->states));
        c.nogoods = space->nogoods;
        c.tables = std::move(space->tables);
        c.seconds_states = seconds_since(t0);
        if (!options.from && !transitions_and_graph(c, std::nullopt)) return std::nullopt;
        e.chains.push_back(std::move(c));
    }
    if (!options.from) return e;
    const auto start = find_state(e, *options.from, options.from_only ? "--next" : "--from", diagnostics);
    if (!start) return std::nullopt;
    if (options.from_only) {
        if (!find_transitions(*laws, m, e, e.chains[start->chain], e.chains[start->chain].tables, options, {start->state}, diagnostics))
            return std::nullopt;
        return e;
    }
    if (!transitions_and_graph(e.chains[start->chain], start->state)) return std::nullopt;
    restrict_to_reachable(e, start->chain, start->state);
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
    std::erase_if(c.graph.transient, [&](const TransientCycle& cycle) { return !c.shown[cycle.states.front().value]; });
    std::erase_if(c.graph.terminal, [&](StateId s) { return !c.shown[s.value]; });
    std::erase_if(c.graph.possible_rests, [&](StateId s) { return !c.shown[s.value]; });
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
