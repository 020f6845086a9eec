// alex/why_query.cpp: Analysis::why, "why was this motion ruled out?" read off the ATMS: the minimal
// nogoods that exclude a motion (or the constraint that removes a freedom), each with its
// derivation down to the scene's premises and assumptions, naming the law at every step.
#include "alex/analysis.hpp"
#include "alex/detail/analysis_state.hpp"
#include "alex/direction_text.hpp"
#include "alex/vocabulary.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace qm::alex {
namespace v = vocabulary;
using engine::ValueId;

namespace {

// Fact text in the thesis' notation where it has one (section 2, Defs 7, 19, 23, 24), else in the
// rule language's.
std::string fact_text(const Analysis::State& st, engine::FactId f) {
    const engine::Engine& e = *st.engine;
    const engine::Fact& fact = e.facts().fact(f);
    const std::string pred = e.values().print(fact.predicate);
    static const std::map<std::string, std::string> thesis{
        {std::string(v::trans_motion), "Translational-Motion"},     {std::string(v::rot_motion), "Rotational-Motion"},
        {std::string(v::trans_freedom), "Translational-Freedom"},   {std::string(v::rot_freedom), "Rotational-Freedom"},
        {std::string(v::trans_constraint), "TransConstraint"},      {std::string(v::rot_constraint), "RotConstraint"}};
    if (auto it = thesis.find(pred); it != thesis.end() && fact.args.size() == 2)
        return it->second + " (" + e.values().print(fact.args[0]) + " " + e.values().print(fact.args[1]) + ")";
    if (auto a = e.assumption(f))
        if (const SceneItem* item = st.facts->item(*a)) return item->text;
    return e.print(f);
}

std::string node_text(const Analysis::State& st, atms::NodeId n) {
    const engine::Engine& e = *st.engine;
    if (n == e.atms().contradiction()) return "false";
    if (auto f = e.fact_of(n)) return fact_text(st, *f);
    if (auto a = e.atms().assumption_of(n)) return e.print(*a);
    return "?";
}

std::string located(const SourceLocation& w) { return w.file + ":" + std::to_string(w.line); }

// Turns an ATMS explanation (justifications in derivation order) into a tree rooted at `root`;
// a node met twice is shown once and referred to afterwards.
class TreeBuilder {
public:
    TreeBuilder(const Analysis::State& st, const atms::Explanation& x) : st_(st) {
        for (atms::JustId j : x.steps) by_consequent_.try_emplace(st.engine->atms().justification(j).consequent, j);
    }
    Derivation build(atms::NodeId n) {
        const engine::Engine& e = *st_.engine;
        const auto& atms = e.atms();
        Derivation d;
        d.fact = node_text(st_, n);
        // A scene item is a leaf, however it is held (its own assumption, or its situation's).
        if (auto f = e.fact_of(n))
            if (const SceneItem* item = st_.facts->item(*f)) {
                d.fact = item->text;
                d.source = located(item->where);
                items_used_.insert(item->text);
                return d;
            }
        auto it = by_consequent_.find(n);
        if (it == by_consequent_.end()) {  // a leaf: a premise or an assumption
            leaf(n, d);
            return d;
        }
        if (!shown_.insert(n).second) {
            d.shown_above = true;
            return d;
        }
        const atms::Justification& just = atms.justification(it->second);
        const engine::Firing& firing = e.firing(just.informant);
        if (firing.kind == engine::Firing::Kind::rule) {
            const engine::CompiledRule& rule = e.program().rules[*firing.rule];
            d.law = rule.name;
            d.source = located(firing.where);
            for (std::size_t i = 0; i < firing.binding.size(); ++i)
                if (firing.binding[i]) d.bindings.push_back(rule.slot_names[i] + " = " + e.values().print(*firing.binding[i]));
        } else if (firing.kind == engine::Firing::Kind::closed_world) {
            d.law = "closed world";
            d.source = "the situation";
        } else {
            d.source = located(firing.where);
        }
        for (atms::NodeId a : just.antecedents) {
            // The assumption node behind a scene item reads as the item itself: skip the step
            // "item <- assume item".
            d.from.push_back(build(a));
        }
        collapse_assumption_step(d);
        return d;
    }

    // The scene items the trees built so far rest on.
    [[nodiscard]] std::vector<std::string> items_used() const { return {items_used_.begin(), items_used_.end()}; }

private:
    void leaf(atms::NodeId n, Derivation& d) {
        const engine::Engine& e = *st_.engine;
        const auto& atms = e.atms();
        if (auto a = atms.assumption_of(n)) {
            if (const SceneItem* item = st_.facts->item(*a)) {
                d.fact = item->text;
                d.source = located(item->where);
            } else if (!e.fact_of(n)) {
                d.fact = "the closed world of the situation (what it does not say is false)";
            } else {
                d.fact = "assumed: " + d.fact;  // a choice (Law 1) or an assumption the laws made
            }
            return;
        }
        const auto& justs = atms.justifications(n);
        if (!justs.empty()) d.source = located(e.firing(atms.justification(justs.front()).informant).where);
    }
    // A fact justified only by its own assumption node is a leaf: drop the indirection.
    static void collapse_assumption_step(Derivation& d) {
        if (d.law.empty() && d.from.size() == 1 && d.from.front().fact == d.fact) {
            Derivation inner = std::move(d.from.front());
            d = std::move(inner);
        }
    }

    const Analysis::State& st_;
    std::map<atms::NodeId, atms::JustId> by_consequent_;
    std::set<atms::NodeId> shown_;
    std::set<std::string> items_used_;
};

// The items of an environment. With one assumption per situation an environment names only the
// situation: then the items the derivation used stand for it (a sufficient set, maybe not minimal).
std::vector<std::string> item_texts(const Analysis::State& st, const atms::Environment& env,
                                    const TreeBuilder* used = nullptr) {
    if (used && st.facts->granularity() == Granularity::situation) return used->items_used();
    std::vector<std::string> out;
    for (atms::AssumptionId a : env.assumptions())
        if (const SceneItem* item = st.facts->item(a)) out.push_back(item->text);
    return out;
}

Exclusion explain_nogood(const Analysis::State& st, atms::EnvId nogood) {
    const atms::Explanation x = st.engine->atms().explain_nogood(nogood);
    TreeBuilder b(st, x);
    Derivation d = b.build(st.engine->atms().contradiction());
    return {item_texts(st, st.engine->atms().env(nogood), &b), std::move(d)};
}

void coarse_note(const Analysis::State& st, WhyAnswer& w) {
    if (st.facts->granularity() == Granularity::situation)
        w.notes.push_back("this large scene is analysed one assumption per situation: each reason's contacts and "
                          "forces are those its derivation uses, a sufficient set that may not be minimal");
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
            TreeBuilder b(st, atms.explain(n, label_env));
            Derivation d = b.build(n);
            w.exclusions.push_back({item_texts(st, atms.env(label_env), &b), std::move(d)});
            w.responsible_sets.push_back(w.exclusions.back().responsible);
        }
        coarse_note(st, w);
        return w;
    }

    // A motion: does a selected combination have it?
    for (const ChainMotions& chain : result.chains)
        for (std::size_t k = 0; k < chain.objects.size(); ++k)
            if (chain.objects[k] == o)
                for (const auto& combination : chain.combinations) {
                    const Direction& d = translational ? combination[k].translation : combination[k].rotation;
                    if (d != query.direction) continue;
                    w.status = WhyAnswer::Status::holds;
                    std::string text = "consistent, and a predicted motion, e.g. with";
                    for (std::size_t j = 0; j < chain.objects.size(); ++j)
                        text += " " + st.scene.objects[chain.objects[j]].name + " " +
                                thesis_text(combination[j].translation) + " " + thesis_text(combination[j].rotation);
                    w.notes.push_back(text);
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
    const atms::AssumptionId a = set[static_cast<std::size_t>(pos - set_dirs.begin())];
    const atms::Environment& base = atms.env(env);
    const atms::Environment with_a = base.with(a);

    // The chain's other choices: the assumptions a nogood may mention besides the situation's. The
    // branches enumerated with the chain (docs/ANALYSIS.md "Branches") are choices too.
    std::vector<std::vector<atms::AssumptionId>> sets;
    atms::Environment chain_choices;
    bool branched = false;
    for (std::size_t c = 0; c < result.chains.size(); ++c) {
        const ChainMotions& chain = result.chains[c];
        if (std::find(chain.objects.begin(), chain.objects.end(), o) == chain.objects.end()) continue;
        for (ObjectId x : chain.objects) {
            for (const auto* s : {&st.choices[x].trans, &st.choices[x].rot}) {
                for (atms::AssumptionId c2 : *s) chain_choices = chain_choices.with(c2);
                if (std::find(s->begin(), s->end(), a) == s->end()) sets.push_back(*s);
            }
        }
        if (situation - 1 < st.chain_branches.size() && c < st.chain_branches[situation - 1].size())
            for (std::uint32_t b : st.chain_branches[situation - 1][c]) {
                for (atms::AssumptionId c2 : st.branches.sets[b]) chain_choices = chain_choices.with(c2);
                sets.push_back(st.branches.sets[b]);
                branched = true;
            }
    }
    const atms::Environment scope = join(base, chain_choices);
    std::vector<atms::EnvId> relevant;
    for (atms::EnvId ng : atms.minimal_nogoods())
        if (atms.env(ng).subset_of(scope)) relevant.push_back(ng);

    // 1. Nogoods made of this motion and the situation alone.
    for (atms::EnvId ng : relevant)
        if (atms.env(ng).contains(a) && atms.env(ng).subset_of(with_a)) {
            w.exclusions.push_back(explain_nogood(st, ng));
            w.responsible_sets.push_back(w.exclusions.back().responsible);
        }
    if (!w.exclusions.empty()) {
        coarse_note(st, w);
        return w;
    }

    // 2. Case analysis: every way of choosing the other objects' motions meets a nogood.
    std::set<std::uint32_t> used;
    bool consistent_somewhere = false;
    const std::size_t dead_end_cap = 64;
    std::function<void(std::size_t, const atms::Environment&)> search = [&](std::size_t k, const atms::Environment& partial) {
        if (consistent_somewhere || used.size() >= dead_end_cap) return;
        if (k == sets.size()) {
            consistent_somewhere = true;
            return;
        }
        for (atms::AssumptionId c : sets[k]) {
            const atms::Environment next = partial.with(c);
            auto hit = std::find_if(relevant.begin(), relevant.end(), [&](atms::EnvId ng) { return atms.env(ng).subset_of(next); });
            if (hit != relevant.end()) used.insert(hit->value);
            else search(k + 1, next);
            if (consistent_somewhere) return;
        }
    };
    search(0, with_a);
    if (!consistent_somewhere) {
        std::set<std::string> responsible;
        for (std::uint32_t ng : used) {
            w.exclusions.push_back(explain_nogood(st, atms::EnvId{ng}));
            for (auto& t : w.exclusions.back().responsible) responsible.insert(t);
        }
        w.responsible_sets.push_back({responsible.begin(), responsible.end()});
        w.notes.push_back(std::string("excluded by case analysis: every choice of the other objects' motions in its "
                                      "kinematic chain") +
                          (branched ? ", in every branch of the laws (docs/ANALYSIS.md, Branches)," : "") +
                          " meets one of these nogoods");
        coarse_note(st, w);
        return w;
    }

    // 3. Consistent, but not what the forces produce (section 6.2, Definition 38): its rank, in the
    // situation or, where the forces branch, in each branch.
    const std::string_view rank_pred = translational ? v::trans_nearness : v::rot_nearness;
    for (engine::FactId f : e.facts_of(st.facts->predicate(rank_pred))) {
        const engine::Fact& fact = e.facts().fact(f);
        if (fact.args.size() != 3 || fact.args[0] != args[0] || fact.args[1] != args[1]) continue;
        const atms::NodeId n = e.node(f);
        for (atms::EnvId label_env : atms.label(n)) {
            if (!atms.env(label_env).subset_of(scope)) continue;
            TreeBuilder b(st, atms.explain(n, label_env));
            Derivation d = b.build(n);
            w.exclusions.push_back({item_texts(st, atms.env(label_env), &b), std::move(d)});
            w.responsible_sets.push_back(w.exclusions.back().responsible);
            break;
        }
    }
    w.notes.push_back("consistent, but not produced by the forces: other consistent combinations are nearer to every "
                      "net force (section 6.2, Definition 38), e.g. the predicted motions of this situation");
    return w;
}

}  // namespace qm::alex
