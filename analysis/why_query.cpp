// analysis/why_query.cpp: Analysis::why, "why was this motion ruled out?" read off the ATMS: the minimal
// nogoods that exclude a motion (or the constraint that removes a freedom), each with its
// derivation down to the scene's premises and assumptions, naming the law at every step. This file
// is the driver: it decides which kind of answer a query gets and hands it to the file of that
// concern: derivation trees (why_derivation.cpp), responsible sets (why_responsible.cpp), a
// refutation by case analysis over the chain's choice sets (why_case_analysis.cpp, over the ATMS
// query atms/case_refutation.hpp), nearness ranks (why_nearness.cpp).
#include "analysis/analysis.hpp"
#include "analysis/detail/analysis_state.hpp"
#include "analysis/detail/why_case_analysis.hpp"
#include "analysis/detail/why_derivation.hpp"
#include "analysis/detail/why_motion.hpp"
#include "analysis/detail/why_nearness.hpp"
#include "analysis/detail/why_responsible.hpp"
#include "scene/direction_text.hpp"
#include "scene/vocabulary.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::analysis {
namespace v = scene::vocabulary;
using engine::ValueId;
using namespace detail;

namespace {

// The motion `choice` (direction d of o) in situation s, with its chain's other choice sets: the
// assumptions a nogood may mention besides the situation's. The branches enumerated with the chain
// (docs/ANALYSIS.md "Branches") are choices too. with_choice_id is left for the caller to intern.
WhyMotion chain_scope(Analysis::State& st, std::size_t situation, ObjectId o, bool translational, const Direction& d,
                      atms::AssumptionId a) {
    auto& atms = st.engine->atms();
    WhyMotion m;
    m.situation = situation;
    m.env = st.runs[situation - 1].environment;
    m.result = &st.results[situation - 1];
    m.object = o;
    m.translational = translational;
    m.direction = d;
    m.choice = a;
    const SituationResult& result = *m.result;
    const atms::Environment& base = atms.env(m.env);
    m.with_choice = base.with(a);
    atms::Environment chain_choices;
    for (std::size_t c = 0; c < result.chains.size(); ++c) {
        const ChainMotions& chain = result.chains[c];
        if (std::find(chain.objects.begin(), chain.objects.end(), o) == chain.objects.end()) continue;
        for (ObjectId x : chain.objects) {
            for (const auto* s : {&st.choices[x].trans, &st.choices[x].rot}) {
                for (atms::AssumptionId c2 : *s) chain_choices = chain_choices.with(c2);
                if (std::find(s->begin(), s->end(), a) == s->end()) m.sets.push_back(*s);
            }
        }
        if (situation - 1 < st.chain_branches.size() && c < st.chain_branches[situation - 1].size())
            for (std::uint32_t b : st.chain_branches[situation - 1][c]) {
                for (atms::AssumptionId c2 : st.branches.sets[b]) chain_choices = chain_choices.with(c2);
                m.sets.push_back(st.branches.sets[b]);
                m.branched = true;
            }
    }
    m.scope = join(base, chain_choices);
    for (atms::EnvId ng : atms.minimal_nogoods())
        if (atms.env(ng).subset_of(m.scope)) m.relevant.push_back(ng);
    return m;
}

}  // namespace

std::optional<WhyAnswer> Analysis::why(const QueryFact& query, std::size_t situation, Diagnostics& diagnostics) {
    QM_REQUIRE(situation >= 1 && situation <= state_->results.size(), "situation index out of range");
    if (state_->facts->granularity() == Granularity::situation &&
        state_->facts->items(situation).size() <= AnalysisOptions::auto_item_limit) {
        // The labels name only the situation: explain from an analysis of this situation with
        // one assumption per item, which names the responsible contacts and forces. (Above the
        // limit that analysis is too costly, and the coarse labels answer: see the note below.)
        auto fine = state_->restricted(situation, {}, {}, diagnostics, Granularity::item);
        if (!fine) return std::nullopt;
        Analysis one(std::move(fine));
        auto w = one.why(query, 1, diagnostics);
        if (w) {
            w->situation = situation;
            w->notes.push_back("explained from a per-item analysis of this situation (the scene is analysed one "
                               "assumption per situation)");
        }
        return w;
    }
    State& st = *state_;
    engine::Engine& e = *st.engine;
    auto& atms = e.atms();
    const std::string where = "--why";
    if (query.kind == QueryFact::Kind::contact || query.kind == QueryFact::Kind::force) {
        diagnostics.error({where, 1, 1}, "expected a motion or a freedom to explain (Translational-Motion, "
                                         "Rotational-Motion, Translational-Freedom, Rotational-Freedom), not a contact or force");
        return std::nullopt;
    }
    const ObjectId o = *query.object;
    const bool translational =
        query.kind == QueryFact::Kind::translational_motion || query.kind == QueryFact::Kind::translational_freedom;
    const bool motion =
        query.kind == QueryFact::Kind::translational_motion || query.kind == QueryFact::Kind::rotational_motion;
    const engine::ContextRun& run = st.runs[situation - 1];
    const atms::EnvId env = run.environment;
    const SituationResult& result = st.results[situation - 1];

    WhyAnswer w;
    w.situation = situation;
    w.query = std::string(translational ? "Translational-" : "Rotational-") + (motion ? "Motion" : "Freedom") + " (" +
              st.scene.objects[o].name + " " + thesis_text(query.direction) + ")";
    const std::vector<ValueId> args{st.facts->symbol(o), st.facts->direction(query.direction)};
    // A contact the laws cannot use changes every answer about the objects it joins: say so first.
    for (const Diagnostic& inert : inert_contacts(situation)) w.notes.push_back(located(inert.where) + ": " + inert.message);

    if (!motion) {
        // Def 24: free unless a law constrains it; the constraint's derivation is the answer.
        auto freedom = st.facts->find(translational ? v::trans_freedom : v::rot_freedom, args);
        if (freedom && atms.holds_in(e.node(*freedom), env)) {
            w.status = WhyAnswer::Status::holds;
            w.notes.push_back("no law constrains it in this situation (Definition 24)");
            return w;
        }
        auto constraint = st.facts->find(translational ? v::trans_constraint : v::rot_constraint, args);
        if (!constraint || !atms.holds_in(e.node(*constraint), env)) {
            diagnostics.error({where, 1, 1}, "the laws neither free nor constrain " + w.query +
                                                 ": expected the rules to define freedom (rules/freedom.rules)");
            return std::nullopt;
        }
        w.status = WhyAnswer::Status::ruled_out;
        const atms::NodeId n = e.node(*constraint);
        for (atms::EnvId label_env : atms.label(n)) {
            if (!atms.env(label_env).subset_of(atms.env(env))) continue;
            w.exclusions.push_back(explain_holding(st, n, label_env));
        }
        w.responsible_sets = minimal_sets(w.exclusions);
        coarse_note(st, w);
        return w;
    }

    // A motion: does a selected combination have it?
    std::string example;
    if (predicted(st, result, o, translational, query.direction, &example)) {
        w.status = WhyAnswer::Status::holds;
        w.notes.push_back("consistent, and a predicted motion, e.g. with" + example);
        return w;
    }
    w.status = WhyAnswer::Status::ruled_out;
    const ObjectChoices& mine = st.choices[o];
    const auto& set = translational ? mine.trans : mine.rot;
    const auto& set_dirs = translational ? mine.trans_dirs : mine.rot_dirs;
    auto pos = std::find(set_dirs.begin(), set_dirs.end(), query.direction);
    if (pos == set_dirs.end()) {
        diagnostics.error({where, 1, 1}, "the laws give no such motion: " + w.query);
        return std::nullopt;
    }
    WhyMotion m = chain_scope(st, situation, o, translational, query.direction,
                                    set[static_cast<std::size_t>(pos - set_dirs.begin())]);
    const atms::AssumptionId a = m.choice;

    // 1. Nogoods made of this motion and the situation alone: each one's items suffice (with
    //    the motion they are inconsistent), and together they are every minimal such set.
    std::vector<atms::EnvId> direct;
    for (atms::EnvId ng : m.relevant)
        if (atms.env(ng).contains(a) && atms.env(ng).subset_of(m.with_choice)) direct.push_back(ng);
    if (!direct.empty()) {
        order_by_relevance(st, direct, a);
        for (atms::EnvId ng : direct) w.exclusions.push_back(explain_nogood(st, ng));
        w.responsible_sets = minimal_sets(w.exclusions);
        coarse_note(st, w);
        return w;
    }

    // Is the motion consistent with some choice of the chain's other motions?
    m.with_choice_id = atms.environment(m.with_choice.assumptions());
    const bool consistent =
        atms.for_each_interpretation(m.sets, m.with_choice_id, [](const atms::Environment&) { return false; }) > 0;

    // 2. Inconsistent: a case analysis over the other motions of its chain.
    if (!consistent) {
        explain_by_cases(st, w, m);
        return w;
    }

    if (!result.complete) {
        // Consistent, and not among the combinations listed before the limit: it may be a later one.
        diagnostics.error({where, 1, 1}, "cannot tell whether " + w.query + " is predicted: it is consistent, but the "
                                         "enumeration of its kinematic chain stopped at --limit " +
                                             std::to_string(st.options.combination_limit) + "; expected a larger --limit");
        return std::nullopt;
    }

    // 3. Consistent, but not what the forces produce (section 6.2, Definition 38).
    explain_by_nearness(st, w, m);
    return w;
}

}  // namespace qm::analysis
