// envision/state_space.cpp: states as ATMS interpretations (thesis Def 35, Figure 8.4, 8.2.3).
#include "envision/state_space.hpp"
#include "bridge/clock_vocabulary.hpp"
#include "engine/consistency.hpp"
#include "engine/preferences.hpp"
#include "envision/fact_reader.hpp"
#include "qm/assert.hpp"
#include "qm/limit_reached.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace qm::envision {
namespace g = qm::geometry;
namespace v = qm::bridge::clock;

namespace {

// What one assumption of a choice set stands for.
struct Choice {
    bool is_place = false;
    std::size_t index = 0;  // chain pair or chain object
    std::uint32_t value = 0;  // place id
    std::int8_t motion = 0;
};

struct OrderedSets {
    std::vector<std::vector<atms::AssumptionId>> sets;
    std::vector<std::vector<Choice>> meaning;  // parallel to sets
};

// The choice sets of the laws, recognised by what their assumptions stand for, in the order of
// 8.2.3: each pair's places, then the motions of its parts not chosen yet.
std::optional<OrderedSets> order_choice_sets(engine::Engine& e, const g::Mechanism& m, std::span<const bridge::PairPlaces> pairs,
                                             const Chain& chain, Diagnostics& diagnostics) {
    std::map<std::string, std::size_t> pair_index, object_index;
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) pair_index[pairs[chain.pairs[k]].name] = k;
    for (std::size_t k = 0; k < chain.objects.size(); ++k) object_index[m.parts[chain.objects[k]].name] = k;
    std::vector<std::optional<std::size_t>> place_set(chain.pairs.size()), motion_set(chain.objects.size());
    const FactReader read(e, std::nullopt);
    const auto& sets = e.choice_sets();
    std::vector<std::vector<Choice>> meaning(sets.size());
    for (std::size_t s = 0; s < sets.size(); ++s) {
        for (const atms::AssumptionId a : sets[s]) {
            const auto f = e.fact_of(e.atms().node_of(a));
            if (!f) continue;
            const engine::Fact& fact = e.facts().fact(*f);
            const std::string& predicate = e.values().print(fact.predicate);
            Choice c;
            if (predicate == v::at && fact.args.size() == 2 && pair_index.count(read.symbol(fact.args[0]))) {
                c.is_place = true;
                c.index = pair_index.at(read.symbol(fact.args[0]));
                c.value = static_cast<std::uint32_t>(read.integer(fact.args[1]));
                place_set[c.index] = s;
            } else if (predicate == v::motion && fact.args.size() == 2 && object_index.count(read.symbol(fact.args[0]))) {
                c.index = object_index.at(read.symbol(fact.args[0]));
                c.motion = read.sign(fact.args[1]);
                motion_set[c.index] = s;
            } else {
                break;  // a choice set of some other kind: not the envisioner's
            }
            meaning[s].push_back(c);
        }
    }
    OrderedSets out;
    std::vector<bool> used(sets.size(), false);
    auto take = [&](std::optional<std::size_t> s) {
        if (!s || used[*s]) return;
        used[*s] = true;
        out.sets.push_back(sets[*s]);
        out.meaning.push_back(meaning[*s]);
    };
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) {
        if (!place_set[k]) {
            diagnostics.error({"<envision>", 1, 1}, "the laws give pair " + pairs[chain.pairs[k]].name +
                                                        " no choice of place: expected a choice set of (at P PLACE) assumptions (rules/clock/states.rules)");
            return std::nullopt;
        }
        take(place_set[k]);
        const auto& spec = pairs[chain.pairs[k]].spec;
        for (std::size_t o = 0; o < chain.objects.size(); ++o)
            if (m.same_shaft(chain.objects[o], spec.a) || m.same_shaft(chain.objects[o], spec.b)) take(motion_set[o]);
    }
    for (std::size_t o = 0; o < chain.objects.size(); ++o) {
        if (!motion_set[o]) {
            diagnostics.error({"<envision>", 1, 1}, "the laws give part " + m.parts[chain.objects[o]].name +
                                                        " no choice of motion: expected a choice set of (motion O M) assumptions (rules/clock/states.rules)");
            return std::nullopt;
        }
        take(motion_set[o]);
    }
    return out;
}

void read_tables(engine::Engine& e, std::span<const bridge::PairPlaces> pairs, const Chain& chain, ChainTables& tables) {
    const FactReader read(e, std::nullopt);
    std::map<std::string, std::size_t> pair_index;
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) pair_index[pairs[chain.pairs[k]].name] = k;
    read.each(v::arrival, 5, [&](std::span<const engine::ValueId> a) {
        const auto it = pair_index.find(read.symbol(a[0]));
        const auto how = how_of(read.symbol(a[2]));
        if (it == pair_index.end() || !how) return;
        tables.add_arrival(it->second, g::PlaceId{static_cast<std::uint32_t>(read.integer(a[1]))}, *how, read.direction(a[3]),
                           read.direction(a[4]));
    });
    read.each(v::collision, 4, [&](std::span<const engine::ValueId> a) {
        const auto it = pair_index.find(read.symbol(a[0]));
        if (it == pair_index.end()) return;
        tables.add_collision(it->second, g::PlaceId{static_cast<std::uint32_t>(read.integer(a[1]))}, read.direction(a[2]), read.direction(a[3]));
    });
    read.each(v::place_change, 1, [&](std::span<const engine::ValueId> a) {
        if (const auto how = how_of(read.symbol(a[0]))) tables.add_place_change(*how);
    });
}

// Where the laws make fact f (the rule, or the item, of its first justification), for errors.
SourceLocation where_made(const engine::Engine& e, engine::FactId f) {
    for (const atms::JustId j : e.atms().justifications(e.node(f))) {
        const engine::Firing& firing = e.firing(e.atms().justification(j).informant);
        if (firing.where) return *firing.where;
    }
    return {"<envision>", 1, 1};
}

// Per chain object and motion, the assumption (PREDICATE O H) the laws make (bridge vocabulary);
// a fact of the predicate that is not an assumption, not of two arguments, or not of an object's name
// and a definite sign (H is (+), (0) or (-)), is an error of the laws, located at the rule that
// concludes it. `first`, if given, is set to where the laws make the first such fact.
using PerMotion = std::vector<std::array<std::optional<atms::AssumptionId>, 3>>;
std::optional<PerMotion> per_motion(engine::Engine& e, const std::map<std::string, std::size_t>& object_index, const char* predicate,
                                    std::size_t objects, Diagnostics& diagnostics, std::optional<SourceLocation>* first = nullptr) {
    PerMotion out(objects);
    for (const engine::FactId f : e.facts_of(e.values().symbol(predicate))) {
        const engine::Fact& fact = e.facts().fact(f);
        const auto a = e.assumption(f);
        const auto is_sign = [&](engine::ValueId v) {
            const engine::Value& x = e.values().value(v);
            return x.kind == engine::ValueKind::direction && x.text.size() == 1 && (x.text[0] == '+' || x.text[0] == '0' || x.text[0] == '-');
        };
        if (fact.args.size() != 2 || !a || e.values().value(fact.args[0]).kind != engine::ValueKind::symbol || !is_sign(fact.args[1])) {
            diagnostics.error(where_made(e, f), "the laws conclude " + e.print(f) + ", but the envisioner reads (" + predicate +
                                                    " O H) only as an assumption, one for each object O and motion H of (+), (0), (-)");
            return std::nullopt;
        }
        if (first && !*first) *first = where_made(e, f);
        const engine::Value& h = e.values().value(fact.args[1]);
        const std::size_t at = h.text[0] == '-' ? 0 : h.text[0] == '0' ? 1 : 2;
        const auto it = object_index.find(e.values().value(fact.args[0]).text);
        if (it != object_index.end()) out[it->second][at] = *a;
    }
    return out;
}

std::map<std::string, std::size_t> object_indices(const g::Mechanism& m, const Chain& chain) {
    std::map<std::string, std::size_t> out;
    for (std::size_t k = 0; k < chain.objects.size(); ++k) out[m.parts[chain.objects[k]].name] = k;
    return out;
}

// The laws' preference between hypothesised next states (rules/clock/nearness.rules: a `prefer` on
// the motion choice sets, ranked in the environment of the motions a step allows, each an assumption
// (step-allows O H)): read once per chain as a table by object, allowed motions and motion, so that
// the successor step (successors.hpp) applies it by lookup. A preference the laws cannot rank that
// way is an error at the `prefer` declaration.
bool read_preference(engine::Engine& e, const g::Mechanism& m, const Chain& chain, const OrderedSets& ordered, ChainTables& tables,
                     Diagnostics& diagnostics) {
    const auto references = per_motion(e, object_indices(m, chain), v::step_allows, chain.objects.size(), diagnostics);
    if (!references) return false;
    for (std::size_t k = 0; k < ordered.sets.size(); ++k) {
        const auto& meaning = ordered.meaning[k];
        if (meaning.empty() || meaning.front().is_place) continue;
        const engine::CompiledPreference* p = engine::choosing_preference(e, ordered.sets[k]);
        if (!p) continue;
        tables.preference_where = p->where.file.str() + ":" + std::to_string(p->where.line);
        const std::size_t o = meaning.front().index;
        std::vector<atms::AssumptionId> refs;
        for (const auto& r : (*references)[o]) {
            if (!r) {
                diagnostics.error(p->where, "the laws prefer among the motions of " + m.parts[chain.objects[o]].name +
                                                " but assume no (step-allows O H) for each of its motions: the envisioner ranks a "
                                                "motion in the environment of the motions a step allows (rules/clock/nearness.rules)");
                return false;
            }
            refs.push_back(*r);
        }
        const auto table = engine::choice_set_rank_table(e, ordered.sets[k], refs);
        for (std::size_t mask = 0; mask < table.size(); ++mask)
            for (std::size_t i = 0; i < meaning.size(); ++i)
                tables.set_preference_rank(o, static_cast<std::uint8_t>(mask), meaning[i].motion, table[mask][i]);
    }
    return true;
}

// Which motion each object may have after a step (rules/clock/settling.rules): for every situation
// of the object in a step (the motions the step allows it and those it forbids, its motion now, the
// motions the step's collisions fix, each an assumption of its own, or no collision, whether some state with the step's places gives it a
// motion the step allows) and every motion after, whether that environment of
// assumptions is consistent, and if not the rule refuting it (engine/consistency.hpp); read once per
// chain, looked up by the successor step. An object the laws make none of these assumptions for is
// settled by nothing (every motion allowed); one with only some of them is an error of the laws.
bool read_settling(engine::Engine& e, const g::Mechanism& m, const Chain& chain, ChainTables& tables, Diagnostics& diagnostics) {
    const auto objects = object_indices(m, chain);
    const std::size_t n = chain.objects.size();
    const char* const names[] = {v::step_allows, v::step_forbids, v::motion_now, v::collision_fixes, v::next_motion};
    std::vector<PerMotion> per;
    std::optional<SourceLocation> made;  // where the laws make one of the settling assumptions (for errors)
    for (const char* name : names) {
        auto p = per_motion(e, objects, name, n, diagnostics, name == names[0] ? nullptr : &made);
        if (!p) return false;
        per.push_back(std::move(*p));
    }
    const PerMotion &allows = per[0], &forbids = per[1], &now = per[2], &fixes_of = per[3], &next = per[4];
    // (no-collision O), (step-reachable O), (step-unreachable O)
    using PerObject = std::vector<std::optional<atms::AssumptionId>>;
    auto per_object = [&](const char* predicate) -> std::optional<PerObject> {
        PerObject out(n);
        for (const engine::FactId f : e.facts_of(e.values().symbol(predicate))) {
            const engine::Fact& fact = e.facts().fact(f);
            const auto a = e.assumption(f);
            if (fact.args.size() != 1 || !a || e.values().value(fact.args[0]).kind != engine::ValueKind::symbol) {
                diagnostics.error(where_made(e, f), "the laws conclude " + e.print(f) + ", but the envisioner reads (" +
                                                        std::string(predicate) + " O) only as an assumption, one for each object");
                return std::nullopt;
            }
            if (!made) made = where_made(e, f);
            const auto it = objects.find(e.values().value(fact.args[0]).text);
            if (it != objects.end()) out[it->second] = *a;
        }
        return out;
    };
    const auto none = per_object(v::no_collision), reachable = per_object(v::step_reachable),
               unreachable = per_object(v::step_unreachable);
    if (!none || !reachable || !unreachable) return false;
    for (std::size_t o = 0; o < n; ++o) {
        bool any = none->at(o).has_value(), all = any;
        // Whether a state allows the step's motions is optional, but both of its assumptions or none.
        const bool reach_known = reachable->at(o).has_value();
        all = all && reach_known == unreachable->at(o).has_value();
        for (std::size_t i = 1; i < per.size(); ++i)
            for (const auto& a : per[i][o]) {
                any = any || a.has_value();
                all = all && a.has_value();
            }
        if (!any) continue;
        if (!all) {
            diagnostics.error(made.value_or(SourceLocation{"<envision>", 1, 1}),
                              "the laws settle the motion of " + m.parts[chain.objects[o]].name +
                                  " after a step with only some of the assumptions (step-forbids O H), (motion-now O C), "
                                  "(collision-fixes O F), (no-collision O), (next-motion O M), and (step-reachable O) with "
                                  "(step-unreachable O) or neither: the envisioner needs each, for each motion (rules/clock/settling.rules)");
            return false;
        }
        for (const auto& a : allows[o])
            if (!a) {
                diagnostics.error(made.value_or(SourceLocation{"<envision>", 1, 1}),
                                  "the laws settle the motion of " + m.parts[chain.objects[o]].name +
                                      " after a step but assume no (step-allows O H) for each of its motions (rules/clock/nearness.rules)");
                return false;
            }
        engine::Refutations refutations(e);
        std::vector<atms::AssumptionId> env;
        for (std::uint8_t mask = 0; mask < 8; ++mask)
            for (std::int8_t c = -1; c <= 1; ++c)
                for (std::uint8_t fixes = 0; fixes < 8; ++fixes)  // 0: no collision
                    for (const bool reach : {false, true})
                        for (std::int8_t x = -1; x <= 1; ++x) {
                            env.clear();
                            for (std::size_t h = 0; h < 3; ++h) env.push_back(mask >> h & 1U ? *allows[o][h] : *forbids[o][h]);
                            env.push_back(*now[o][static_cast<std::size_t>(c + 1)]);
                            if (fixes == 0) env.push_back(*(*none)[o]);
                            for (std::size_t h = 0; h < 3; ++h)
                                if (fixes >> h & 1U) env.push_back(*fixes_of[o][h]);
                            if (reach_known) env.push_back(reach ? *(*reachable)[o] : *(*unreachable)[o]);
                            env.push_back(*next[o][static_cast<std::size_t>(x + 1)]);
                            const auto refuted = refutations.of(e.atms().environment(env));
                            std::optional<ChainTables::Refuter> r;
                            if (refuted)
                                r = ChainTables::Refuter{refuted->rule, refuted->where.file.str() + ":" + std::to_string(refuted->where.line)};
                            tables.set_settling(o, mask, c, fixes, reach, x, r);
                        }
    }
    return true;
}

bool state_less(const State& x, const State& y) {
    if (x.places != y.places) return x.places < y.places;
    return x.motions < y.motions;
}

}  // namespace

namespace {

std::unique_ptr<engine::Engine> run_laws(const Laws& laws, const g::Mechanism& m, std::span<const bridge::PairPlaces> pairs,
                                         const Chain& chain, Diagnostics& diagnostics) {
    auto e = laws.state_space_engine();
    bridge::assert_parts(*e, m, chain.objects, /*choices=*/true);
    bridge::assert_linkages(*e, m, chain.objects);
    bridge::PlaceFactOptions all;
    all.choice = true;
    for (const std::size_t k : chain.pairs) bridge::assert_pair(*e, m, pairs[k], all);
    for (std::size_t i = 0; i < chain.pairs.size(); ++i)
        for (std::size_t j = i + 1; j < chain.pairs.size(); ++j) bridge::assert_correlation(*e, m, pairs[chain.pairs[i]], pairs[chain.pairs[j]]);
    const std::size_t before = diagnostics.size();
    e->run(diagnostics);
    for (std::size_t i = before; i < diagnostics.size(); ++i)
        if (diagnostics.items()[i].severity == Severity::error) return nullptr;
    return e;
}

}  // namespace

std::optional<StateSpaceEngine> state_space_engine(const Laws& laws, const g::Mechanism& m, std::span<const bridge::PairPlaces> pairs,
                                                   const Chain& chain, Diagnostics& diagnostics) {
    auto e = run_laws(laws, m, pairs, chain, diagnostics);
    if (!e) return std::nullopt;
    const auto ordered = order_choice_sets(*e, m, pairs, chain, diagnostics);
    if (!ordered) return std::nullopt;
    StateSpaceEngine out{std::move(e), std::vector<std::map<std::uint32_t, atms::AssumptionId>>(chain.pairs.size()),
                         std::vector<std::map<std::int8_t, atms::AssumptionId>>(chain.objects.size())};
    for (std::size_t k = 0; k < ordered->sets.size(); ++k)
        for (std::size_t i = 0; i < ordered->sets[k].size(); ++i) {
            const Choice& c = ordered->meaning[k][i];
            if (c.is_place) out.place[c.index][c.value] = ordered->sets[k][i];
            else out.motion[c.index][c.motion] = ordered->sets[k][i];
        }
    return out;
}

std::optional<StateSpace> enumerate_states(const Laws& laws, const g::Mechanism& m, std::span<const bridge::PairPlaces> pairs,
                                           const Chain& chain, StateLimit limit, const ProgressFn& progress, Diagnostics& diagnostics) {
    Progress report{.phase = Progress::Phase::states, .chain = chain.index + 1};
    if (progress) progress(report);
    auto e = run_laws(laws, m, pairs, chain, diagnostics);
    if (!e) return std::nullopt;
    const auto ordered = order_choice_sets(*e, m, pairs, chain, diagnostics);
    if (!ordered) return std::nullopt;

    StateSpace out;
    bool exceeded = false;
    auto each = [&](const atms::Environment& env) {
        if (limit.found_before + out.states.size() >= limit.max_states) {
            exceeded = true;
            return false;
        }
        State s;
        s.places.assign(chain.pairs.size(), g::PlaceId{0});
        s.motions.assign(chain.objects.size(), 0);
        for (std::size_t k = 0; k < ordered->sets.size(); ++k)
            for (std::size_t i = 0; i < ordered->sets[k].size(); ++i)
                if (env.contains(ordered->sets[k][i])) {
                    const Choice& c = ordered->meaning[k][i];
                    if (c.is_place) s.places[c.index] = g::PlaceId{c.value};
                    else s.motions[c.index] = c.motion;
                    break;
                }
        out.states.push_back(std::move(s));
        if (progress && out.states.size() % 4096 == 0) {
            report.states = out.states.size();
            progress(report);
        }
        return true;
    };
    try {
        e->atms().for_each_interpretation(ordered->sets, e->atms().empty_environment(), each);
    } catch (...) {  // out of memory: the caller still learns how many states were found
        report.states = out.states.size();
        if (progress) progress(report);
        throw;
    }
    report.states = out.states.size();
    if (progress) progress(report);
    if (exceeded) throw LimitReached(LimitReached::Kind::states, limit.max_states);
    std::sort(out.states.begin(), out.states.end(), state_less);
    read_tables(*e, pairs, chain, out.tables);
    if (!read_preference(*e, m, chain, *ordered, out.tables, diagnostics)) return std::nullopt;
    if (!read_settling(*e, m, chain, out.tables, diagnostics)) return std::nullopt;
    out.nogoods = e->atms().minimal_nogoods().size();
    return out;
}

}  // namespace qm::envision
