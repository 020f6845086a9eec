// envision/state_dynamics.cpp: one state's forces and possible steps (thesis Figure 8.5, 8.3.1-8.3.3).
#include "envision/state_dynamics.hpp"
#include "bridge/clock_vocabulary.hpp"
#include "envision/fact_reader.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace qm::envision {
namespace g = qm::geometry;
namespace v = qm::bridge::clock;

PlaceVectorEngine::PlaceVectorEngine(const Laws& laws, const g::Mechanism& m, std::span<const bridge::PairPlaces> pairs,
                                     const Chain& chain, std::span<const State* const> states, std::span<const bridge::ForceRef> without,
                                     bool labelled)
    : engine_(laws.state_engine()), contexts_(labelled || states.size() > 1) {
    QM_REQUIRE(!states.empty(), "a place vector engine needs a state");
    engine::Engine& e = *engine_;
    bridge::assert_parts(e, m, chain.objects, /*choices=*/false);
    bridge::assert_linkages(e, m, chain.objects);
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) {
        const bridge::PairPlaces& pair = pairs[chain.pairs[k]];
        // The adjacency under the motions of this place vector's states only.
        std::set<g::QualDirection> motions;
        for (const State* s : states) {
            QM_REQUIRE(s->places == states.front()->places, "the states of a place vector engine share their places");
            motions.insert(g::QualDirection{{s->motions[chain.object_index(pair.spec.a)], s->motions[chain.object_index(pair.spec.b)]}});
        }
        bridge::assert_pair(e, m, pair, {states.front()->places[k], std::nullopt, /*choice=*/false, /*kinds=*/true, motions});
        bridge::assert_current_place(e, pair, states.front()->places[k]);
    }
    const auto how = contexts_ ? bridge::ForceFacts::assumptions : bridge::ForceFacts::premises;
    for (const auto f : bridge::assert_forces(e, m, chain.objects, how, without))
        if (contexts_) forces_.push_back(*e.assumption(f));
    if (states.size() == 1) {  // one state: its motions are premises, the context is its forces
        for (std::size_t o = 0; o < chain.objects.size(); ++o) bridge::assert_current_motion(e, m, chain.objects[o], states.front()->motions[o]);
        motions_.emplace_back();
        return;
    }
    std::map<std::pair<std::size_t, std::int8_t>, atms::AssumptionId> assumed;
    for (const State* s : states) {
        std::vector<atms::AssumptionId> mine;
        for (std::size_t o = 0; o < chain.objects.size(); ++o) {
            auto it = assumed.find({o, s->motions[o]});
            if (it == assumed.end()) {
                const auto f = bridge::assume_current_motion(e, m, chain.objects[o], s->motions[o]);
                it = assumed.emplace(std::pair{o, s->motions[o]}, *e.assumption(f)).first;
            }
            mine.push_back(it->second);
        }
        motions_.push_back(std::move(mine));
    }
}

std::optional<atms::EnvId> PlaceVectorEngine::run(std::size_t i, Diagnostics& diagnostics) {
    QM_REQUIRE(i < motions_.size(), "no such state in this place vector engine");
    engine::Engine& e = *engine_;
    const std::size_t before = diagnostics.size();
    atms::EnvId out = e.atms().empty_environment();
    if (contexts_) {
        std::vector<atms::AssumptionId> context = forces_;
        context.insert(context.end(), motions_[i].begin(), motions_[i].end());
        out = e.run_in_context(e.atms().environment(context), diagnostics).environment;
    } else {
        e.run(diagnostics);  // premises only: `not` and aggregates are decided generically
    }
    for (std::size_t k = before; k < diagnostics.size(); ++k)
        if (diagnostics.items()[k].severity == Severity::error) return std::nullopt;
    return out;
}

std::optional<StateDynamics> read_dynamics(engine::Engine& e, atms::EnvId environment, const g::Mechanism& m,
                                           std::span<const bridge::PairPlaces> pairs, const Chain& chain, Diagnostics& diagnostics) {
    const FactReader read(e, environment);
    std::map<std::string, std::size_t> pair_index, object_index;
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) pair_index[pairs[chain.pairs[k]].name] = k;
    for (std::size_t k = 0; k < chain.objects.size(); ++k) object_index[m.parts[chain.objects[k]].name] = k;
    auto fail = [&](const std::string& message) {
        diagnostics.error({"<envision>", 1, 1}, message + " (rules/clock/)");
        return std::nullopt;
    };

    StateDynamics out;
    out.net_force.assign(chain.objects.size(), 0);
    read.each(v::net_force, 2, [&](std::span<const engine::ValueId> a) {
        if (const auto it = object_index.find(read.symbol(a[0])); it != object_index.end()) out.net_force[it->second] = read.sign(a[1]);
    });
    std::map<std::string, StepOptions> steps;
    bool bad_step = false;
    read.each(v::step, 3, [&](std::span<const engine::ValueId> a) {
        StepOptions s;
        s.name = read.symbol(a[0]);
        const std::string& d = read.symbol(a[1]);
        const std::string& c = read.symbol(a[2]);
        if ((d != "instant" && d != "interval") || (c != "kinematic" && c != "dynamic")) bad_step = true;
        s.duration = d == "instant" ? Duration::instant : Duration::interval;
        s.cause = c == "kinematic" ? Cause::kinematic : Cause::dynamic;
        s.places.resize(chain.pairs.size());
        s.motions.resize(chain.objects.size());
        steps.emplace(s.name, std::move(s));
    });
    if (bad_step) return fail("a step's duration must be instant or interval and its cause kinematic or dynamic");
    bool bad_how = false;
    read.each(v::place_option, 4, [&](std::span<const engine::ValueId> a) {
        const auto s = steps.find(read.symbol(a[0]));
        const auto p = pair_index.find(read.symbol(a[1]));
        const auto how = how_of(read.symbol(a[3]));
        if (s == steps.end() || p == pair_index.end()) return;
        if (!how) {
            bad_how = true;
            return;
        }
        s->second.places[p->second].push_back({g::PlaceId{static_cast<std::uint32_t>(read.integer(a[2]))}, *how});
    });
    if (bad_how) return fail("a place option's last argument must be stay, move or wrap");
    read.each(v::motion_option, 3, [&](std::span<const engine::ValueId> a) {
        const auto s = steps.find(read.symbol(a[0]));
        const auto o = object_index.find(read.symbol(a[1]));
        if (s == steps.end() || o == object_index.end()) return;
        s->second.motions[o->second].push_back(read.sign(a[2]));
    });
    read.each(v::may_rest, 0, [&](std::span<const engine::ValueId>) { out.may_rest = true; });
    std::vector<std::pair<std::string, std::string>> preempts;
    read.each(v::preempts, 2, [&](std::span<const engine::ValueId> a) { preempts.emplace_back(read.symbol(a[0]), read.symbol(a[1])); });
    for (auto& [name, s] : steps) {
        for (std::size_t k = 0; k < s.places.size(); ++k) {
            if (s.places[k].empty()) return fail("the laws give pair " + pairs[chain.pairs[k]].name + " no place after step " + name);
            std::sort(s.places[k].begin(), s.places[k].end(), [](const PlaceOption& x, const PlaceOption& y) {
                return std::tie(x.place, x.how) < std::tie(y.place, y.how);
            });
        }
        for (std::size_t o = 0; o < s.motions.size(); ++o) {
            if (s.motions[o].empty()) return fail("the laws give part " + m.parts[chain.objects[o]].name + " no motion after step " + name);
            for (const auto x : s.motions[o])
                if (x == ambiguous_sign) return fail("the laws give part " + m.parts[chain.objects[o]].name + " the ambiguous motion (?) after step " + name);
            std::sort(s.motions[o].begin(), s.motions[o].end());
        }
        out.steps.push_back(std::move(s));
    }
    auto index = [&](const std::string& name) -> std::optional<std::size_t> {
        for (std::size_t i = 0; i < out.steps.size(); ++i)
            if (out.steps[i].name == name) return i;
        return std::nullopt;
    };
    for (const auto& [first, then] : preempts) {
        const auto a = index(first), b = index(then);
        if (!a || !b) return fail("(preempts " + first + " " + then + ") names a step the laws did not give");
        if (a == b) return fail("a step cannot preempt itself: " + first);
        out.preempts.emplace_back(*a, *b);
    }
    return out;
}

}  // namespace qm::envision
