// analysis/analysis.cpp: the Alex driver (thesis chapter 6): scene -> facts -> laws -> freedom,
// motions and stability per situation. Laws come only from the rule files.
#include "analysis/analysis.hpp"
#include "analysis/branches.hpp"
#include "analysis/detail/analysis_state.hpp"
#include "scene/direction_text.hpp"
#include "scene/kinematic_chains.hpp"
#include "engine/preferences.hpp"
#include "engine/rule_folder.hpp"
#include "scene/vocabulary.hpp"
#include "scene/what_if.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <filesystem>

namespace qm::analysis {
namespace v = scene::vocabulary;
using engine::ValueId;

namespace {

// Every *.rules file directly in dir, in name order, checked as laws for a scene of this many dimensions.
std::optional<engine::LoadedProgram> load_rules(const std::filesystem::path& dir, const Scene& scene,
                                                Diagnostics& diagnostics) {
    auto laws = engine::load_rule_folder(dir, diagnostics, law_check_options(scene.translation_arity(), "scene '" + scene.name + "'"));
    if (!laws) return std::nullopt;
    return std::move(laws->compiled);
}

// Law 1's choice sets, by object: which assumption stands for which motion.
std::optional<IdVector<ObjectId, ObjectChoices>> read_choices(const Scene& scene, engine::Engine& e, SceneFacts& facts,
                                                             Diagnostics& diagnostics) {
    IdVector<ObjectId, ObjectChoices> out;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) out.push_back(ObjectChoices{ObjectId{i}, {}, {}, {}, {}});
    const ValueId trans = facts.predicate(v::trans_motion), rot = facts.predicate(v::rot_motion);
    for (const auto& set : e.choice_sets()) {
        for (atms::AssumptionId a : set) {
            auto f = e.fact_of(e.atms().node_of(a));
            if (!f) continue;
            const engine::Fact& fact = e.facts().fact(*f);
            if ((fact.predicate != trans && fact.predicate != rot) || fact.args.size() != 2) continue;
            auto o = facts.object_of(fact.args[0]);
            const engine::Value& d = e.values().value(fact.args[1]);
            if (!o || d.kind != engine::ValueKind::direction) continue;
            ObjectChoices& c = out[*o];
            (fact.predicate == trans ? c.trans : c.rot).push_back(a);
            (fact.predicate == trans ? c.trans_dirs : c.rot_dirs).push_back(scene::from_sign_string(d.text));
        }
    }
    for (const ObjectChoices& c : out)
        if (c.trans.empty() || c.rot.empty()) {
            diagnostics.error(scene.objects[c.object].where,
                              "the laws give object '" + scene.objects[c.object].name + "' no choice of " +
                                  (c.trans.empty() ? "translational" : "rotational") +
                                  " motion: expected a choice set of (" + std::string(c.trans.empty() ? v::trans_motion : v::rot_motion) +
                                  " O D) assumptions (Law 1, rules/uniqueness_of_motion.rules)");
            return std::nullopt;
        }
    return out;
}

}  // namespace

engine::LawCheckOptions law_check_options(std::optional<std::size_t> dimensions, const std::string& what) {
    engine::LawCheckOptions o;
    o.require_citations = true;
    if (!dimensions) return o;
    // Translations have one sign per dimension (Def 1), rotations one in the plane and three in
    // space (Def 4, Table 2.1): scene::Scene::translation_arity()/rotation_arity().
    const std::size_t rotation = *dimensions == 2 ? 1 : 3;
    o.direction_arities = {*dimensions, rotation};
    o.arity_context = what + " is " + std::to_string(*dimensions) + "-D: its translations have " +
                      std::to_string(*dimensions) + " signs and its rotations " + std::to_string(rotation);
    return o;
}

bool Analysis::State::holds(std::string_view predicate, std::span<const ValueId> args, atms::EnvId env) {
    auto f = facts->find(predicate, args);
    return f && engine->atms().holds_in(engine->node(*f), env);
}

MotionRanks Analysis::State::ranks(ObjectId o, atms::EnvId env) const {
    // The laws' preference (`prefer` in rules/nearness.rules: Def 38 up to 8.3.4's threshold).
    return {engine::choice_set_ranks(*engine, choices[o].trans, env), engine::choice_set_ranks(*engine, choices[o].rot, env)};
}

std::vector<atms::NodeId> Analysis::State::rank_nodes(ObjectId o) const {
    std::vector<atms::NodeId> out;
    for (const auto* set : {&choices[o].trans, &choices[o].rot})
        for (atms::AssumptionId a : *set)
            for (engine::FactId f : engine::rank_facts(*engine, a)) out.push_back(engine->node(f));
    return out;
}

std::vector<std::pair<ObjectId, ObjectId>> Analysis::State::pairs(std::size_t s, atms::EnvId env) const {
    std::vector<std::pair<ObjectId, ObjectId>> out;
    const atms::Environment& members = engine->atms().env(env);
    if (facts->granularity() == Granularity::situation) {
        for (const SceneItem* item : facts->items(s))
            if (item->kind == SceneItem::Kind::contact) out.emplace_back(scene.owner(item->first), scene.owner(item->second));
    } else {
        // Every contact the environment holds: the situation's, less a what-if's taken away, plus
        // a what-if's added from other situations.
        for (const SceneItem& item : facts->all_items())
            if (item.kind == SceneItem::Kind::contact && members.contains(*item.assumption))
                out.emplace_back(scene.owner(item.first), scene.owner(item.second));
    }
    for (const Linkage& l : scene.linkages) out.emplace_back(l.first, l.second);
    return out;
}

std::optional<engine::ContextRun> Analysis::State::run(std::size_t s, std::span<const QueryFact> without,
                                                       Diagnostics& diagnostics, std::span<const atms::AssumptionId> added) {
    const std::size_t before = diagnostics.size();
    atms::EnvId context = facts->context(s, without);
    if (!added.empty()) {
        std::vector<atms::AssumptionId> members = engine->atms().env(context).assumptions();
        members.insert(members.end(), added.begin(), added.end());
        context = engine->atms().environment(members);
    }
    engine::ContextRun r = engine->run_in_context(context, diagnostics);
    for (std::size_t i = before; i < diagnostics.size(); ++i)
        if (diagnostics.items()[i].severity == Severity::error) return std::nullopt;
    return r;
}

std::optional<SituationResult> Analysis::State::solve(std::size_t s, std::span<const QueryFact> without,
                                                      Diagnostics& diagnostics) {
    auto r = run(s, without, diagnostics);
    if (!r) return std::nullopt;
    refresh_branches();  // a smaller situation may branch where the whole did not
    SituationResult result = read(s, r->environment);
    add_kinematic(result, s, without);
    return result;
}

void Analysis::State::refresh_branches() {
    std::vector<atms::AssumptionId> motions;
    for (const ObjectChoices& c : choices) {
        motions.insert(motions.end(), c.trans.begin(), c.trans.end());
        motions.insert(motions.end(), c.rot.begin(), c.rot.end());
    }
    branches = branch_sets(engine->choice_sets(), motions);
}

SituationResult Analysis::State::read(std::size_t s, atms::EnvId env,
                                      std::vector<std::vector<std::uint32_t>>* branches_of) {

    SituationResult r;
    r.index = s;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectId o{i};
        Freedom f;
        for (const Direction& d : scene::all_directions(scene.translation_arity()))
            if (holds(v::trans_freedom, std::vector<ValueId>{facts->symbol(o), facts->direction(d)}, env))
                f.translation.push_back(d);
        for (const Direction& d : scene::all_directions(scene.rotation_arity()))
            if (holds(v::rot_freedom, std::vector<ValueId>{facts->symbol(o), facts->direction(d)}, env))
                f.rotation.push_back(d);
        r.freedom.push_back(std::move(f));
    }

    bool stable = true;
    // Kinematic chains (Def 22), grouped where a branching choice set reaches several (docs/ANALYSIS.md).
    const auto chains = scene::kinematic_chains(scene.objects.size(), pairs(s, env));
    std::vector<std::vector<atms::NodeId>> read_nodes(chains.size());
    if (!branches.empty())
        for (std::size_t c = 0; c < chains.size(); ++c)
            for (ObjectId o : chains[c]) {
                auto nodes = rank_nodes(o);
                read_nodes[c].insert(read_nodes[c].end(), nodes.begin(), nodes.end());
            }
    for (const atms::ChoiceSetGroup& group : atms::group_by_shared_nogoods(engine->atms(), branches, env, read_nodes)) {
        std::vector<ObjectChoices> members;
        for (std::size_t c : group.members)
            for (ObjectId o : chains[c]) members.push_back(choices[o]);
        std::sort(members.begin(), members.end(),
                  [](const ObjectChoices& a, const ObjectChoices& b) { return a.object < b.object; });
        std::vector<std::vector<atms::AssumptionId>> sets;
        for (std::uint32_t i : group.sets) sets.push_back(branches.sets[i]);
        ChainOutcome outcome = solve_group(
            engine->atms(), members, sets, env,
            [&](std::size_t i, atms::EnvId where) { return ranks(members[i].object, where); }, options.combination_limit);
        if (outcome.truncated) r.complete = false;
        if (outcome.truncated)
            r.notes.push_back("chain of " + scene.objects[members.front().object].name + ": enumeration stopped after " +
                              std::to_string(options.combination_limit) + " consistent combinations (--limit)");
        if (outcome.motions.combinations.empty()) stable = false;
        for (const auto& combination : outcome.motions.combinations)
            for (const ObjectMotion& m : combination)
                if (!is_zero(m.translation) || !is_zero(m.rotation)) stable = false;
        r.chains.push_back(std::move(outcome.motions));
        if (branches_of) branches_of->push_back(group.sets);
    }
    r.stable = stable;
    return r;
}

std::shared_ptr<const Laws> share_laws(engine::LoadedProgram loaded) {
    return std::make_shared<const Laws>(Laws{engine::share_program(std::move(loaded.program)), std::move(loaded.values),
                                             std::move(loaded.citations)});
}

std::unique_ptr<Analysis::State> build_state(const Scene& scene, const AnalysisOptions& options,
                                             std::shared_ptr<const Laws> laws, Diagnostics& diagnostics) {
    auto state = std::make_unique<Analysis::State>();
    state->scene = scene;
    state->options = options;
    state->engine = std::make_unique<engine::Engine>(laws->program, laws->values);
    state->laws = std::move(laws);
    state->engine->set_limits(options.limits);
    Granularity granularity = Granularity::item;
    if (options.granularity) granularity = *options.granularity;
    else
        for (const Situation& s : scene.situations)
            if (s.contacts.size() + s.forces.size() + s.motions.size() + scene.forces.size() + options.given.size() >
                AnalysisOptions::auto_item_limit)
                granularity = Granularity::situation;
    state->facts = std::make_unique<SceneFacts>(state->scene, *state->engine, options.given, granularity);
    // Run every situation first: the laws declare the choice sets of Law 1 as they fire.
    for (std::size_t s = 1; s <= state->scene.situations.size(); ++s) {
        auto run = state->run(s, options.without, diagnostics);
        if (!run) return nullptr;
        state->runs.push_back(*run);
    }
    auto choices = read_choices(state->scene, *state->engine, *state->facts, diagnostics);
    if (!choices) return nullptr;
    state->choices = std::move(*choices);
    state->refresh_branches();
    for (std::size_t s = 1; s <= state->scene.situations.size(); ++s) {
        state->chain_branches.emplace_back();
        state->results.push_back(state->read(s, state->runs[s - 1].environment, &state->chain_branches.back()));
    }
    // After every situation is read: the kinematic sets run contexts of their own.
    for (std::size_t s = 1; s <= state->scene.situations.size(); ++s)
        state->add_kinematic(state->results[s - 1], s, options.without);
    return state;
}

std::optional<Analysis> analyse(const Scene& scene, const AnalysisOptions& options, Diagnostics& diagnostics) {
    auto loaded = load_rules(options.rules_directory, scene, diagnostics);
    if (!loaded) return std::nullopt;
    const std::shared_ptr<const Laws> laws = share_laws(std::move(*loaded));
    if (scene.situations.empty()) {
        // Nothing to analyse, but the laws are still read and checked against the scene (Law 1's
        // choice sets must exist for every object): one empty situation is that check.
        Scene probe = scene;
        probe.situations.push_back(Situation{{}, {}, {}, scene.where});
        auto state = build_state(probe, options, laws, diagnostics);
        if (!state) return std::nullopt;
        state->scene.situations.clear();
        state->runs.clear();
        state->results.clear();
        state->chain_branches.clear();
        return Analysis(std::move(state));
    }
    auto state = build_state(scene, options, laws, diagnostics);
    if (!state) return std::nullopt;
    return Analysis(std::move(state));
}

Analysis::Analysis(std::unique_ptr<State> state) : state_(std::move(state)) {}
Analysis::Analysis(Analysis&&) noexcept = default;
Analysis& Analysis::operator=(Analysis&&) noexcept = default;
Analysis::~Analysis() = default;

const Scene& Analysis::scene() const noexcept { return state_->scene; }
const std::vector<SituationResult>& Analysis::situations() const noexcept { return state_->results; }

std::optional<SituationResult> Analysis::what_if(std::size_t situation, std::span<const QueryFact> without,
                                                 Diagnostics& diagnostics) {
    QM_REQUIRE(situation >= 1 && situation <= state_->results.size(), "situation index out of range");
    for (const QueryFact& q : without)
        if (!scene::can_take_away(q)) {
            diagnostics.error({"whatif", 1, 1}, "expected 'Contact a b' or 'Force obj' to take away");
            return std::nullopt;
        }
    std::vector<QueryFact> all = state_->options.without;
    all.insert(all.end(), without.begin(), without.end());
    if (state_->facts->granularity() == Granularity::situation) {
        // One assumption stands for the whole situation: analyse the smaller situation afresh.
        auto state = state_->restricted(situation, all, {}, diagnostics);
        if (!state) return std::nullopt;
        SituationResult r = state->results.front();
        r.index = situation;
        r.notes.push_back("what-if: this scene is analysed one assumption per situation, so the smaller situation "
                          "was analysed afresh");
        return r;
    }
    auto r = state_->solve(situation, all, diagnostics);
    if (r)
        r->notes.push_back("what-if: the monotonic laws' labels were reused; the rules with `not` or an aggregate "
                           "(freedom, force distribution, net force, nearness) were run again for the smaller situation");
    return r;
}

std::optional<SituationResult> Analysis::with_given(std::size_t situation, std::span<const Motion> given,
                                                    Diagnostics& diagnostics) {
    QM_REQUIRE(situation >= 1 && situation <= state_->results.size(), "situation index out of range");
    // A given motion is a new assumption, and the closed world of the rules with `not` may not
    // grow once used: analyse the situation afresh with the motion added.
    auto state = state_->restricted(situation, {}, given, diagnostics);
    if (!state) return std::nullopt;
    SituationResult r = state->results.front();
    r.index = situation;
    r.notes.push_back("given motions are new assumptions: the situation was analysed afresh");
    std::vector<Motion> before = state_->scene.situations[situation - 1].motions;
    before.insert(before.end(), state_->options.given.begin(), state_->options.given.end());
    for (const Motion& m : before)
        if (scene::replaced_by(m, given))
            r.notes.push_back("the given motion of " + state_->scene.objects[m.object].name + " replaces Motion (" +
                              state_->scene.objects[m.object].name + " " + thesis_text(m.translation) + " " +
                              thesis_text(m.rotation) + ")");
    return r;
}

std::unique_ptr<Analysis::State> Analysis::State::restricted(std::size_t s, std::span<const QueryFact> without,
                                                             std::span<const Motion> given, Diagnostics& diagnostics,
                                                             std::optional<Granularity> granularity,
                                                             const scene::Additions* added) const {
    Scene changed = scene::what_if_scene(scene, s, without, given);
    if (added) (void)scene::add_to_scene(changed, *added, 1);
    AnalysisOptions o = options;
    std::erase_if(o.given, [&](const Motion& m) { return scene::replaced_by(m, given); });
    o.without.clear();
    o.granularity = granularity;
    return build_state(changed, o, laws, diagnostics);
}

namespace {
std::uint64_t product(const std::vector<ChainMotions>& chains) {
    std::uint64_t total = 1;
    for (const ChainMotions& c : chains) {
        const std::uint64_t n = c.combinations.size();
        if (n == 0) return 0;
        if (total > UINT64_MAX / n) return UINT64_MAX;
        total *= n;
    }
    return total;
}
}  // namespace

std::uint64_t SituationResult::combination_count() const { return product(chains); }
std::uint64_t SituationResult::kinematic_count() const { return product(kinematic); }

void SituationResult::for_each_combination(const std::function<bool(const SceneMotion&)>& f) const {
    analysis::for_each_combination(chains, f);
}

void for_each_combination(const std::vector<ChainMotions>& chains, const std::function<bool(const SceneMotion&)>& f) {
    if (product(chains) == 0) return;
    std::size_t objects = 0;
    for (const ChainMotions& c : chains) objects += c.objects.size();
    SceneMotion motion;
    for (std::size_t i = 0; i < objects; ++i) motion.push_back({});
    std::vector<std::size_t> at(chains.size(), 0);
    for (;;) {
        for (std::size_t c = 0; c < chains.size(); ++c)
            for (std::size_t k = 0; k < chains[c].objects.size(); ++k)
                motion[chains[c].objects[k]] = chains[c].combinations[at[c]][k];
        if (!f(motion)) return;
        // Odometer over the chains, last chain fastest: canonical order of the whole scene when
        // chains are ordered by their first object.
        std::size_t c = chains.size();
        while (c > 0) {
            --c;
            if (++at[c] < chains[c].combinations.size()) break;
            at[c] = 0;
            if (c == 0) return;
        }
        if (chains.empty()) return;
    }
}

}  // namespace qm::analysis
