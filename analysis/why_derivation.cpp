// analysis/why_derivation.cpp: derivation trees of --why's reasons (analysis/detail/why_derivation.hpp):
// an ATMS explanation (justifications in derivation order) becomes a tree of facts in the thesis'
// notation, each step naming its law.
#include "analysis/detail/why_derivation.hpp"
#include "engine/why.hpp"
#include "scene/vocabulary.hpp"
#include <filesystem>
#include <map>
#include <set>
#include <tuple>
#include <algorithm>

namespace qm::analysis::detail {
namespace v = scene::vocabulary;

std::string located(const SourceLocation& w) { return w.file.str() + ":" + std::to_string(w.line); }

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
            d.source = law_location(*firing.where);
            if (auto c = st_.laws->citations.find(firing.where->file.str()); c != st_.laws->citations.end()) d.citation = c->second;
            for (std::size_t i = 0; i < firing.binding.size(); ++i)
                if (firing.binding[i]) d.bindings.push_back(rule.slot_names[i] + " = " + e.values().print(*firing.binding[i]));
            d.absent = engine::absent_conditions(*st_.engine, firing);
        } else if (firing.kind == engine::Firing::Kind::closed_world) {
            d.law = "closed world";
            d.source = "the situation";
        } else {
            d.source = located(*firing.where);
        }
        for (atms::NodeId a : just.antecedents) {
            // The assumption node behind a scene item reads as the item itself: skip the step
            // "item <- assume item".
            d.from.push_back(build(a));
        }
        // The closed world is one assumption for every `not` of the situation: say which facts'
        // absence this step used.
        if (!d.absent.empty())
            for (Derivation& f : d.from)
                if (f.fact == closed_world_text) {
                    f.fact = "the situation holds no ";
                    for (std::size_t i = 0; i < d.absent.size(); ++i) f.fact += (i ? ", no " : "") + d.absent[i];
                    f.fact += " (closed world: what it does not say is false)";
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
                d.fact = closed_world_text;
            } else {
                d.fact = "assumed: " + d.fact;  // a choice (Law 1) or an assumption the laws made
            }
            return;
        }
        const auto& justs = atms.justifications(n);
        if (!justs.empty()) d.source = located(*e.firing(atms.justification(justs.front()).informant).where);
    }
    // A fact justified only by its own assumption node is a leaf: drop the indirection.
    static void collapse_assumption_step(Derivation& d) {
        if (d.law.empty() && d.from.size() == 1 && d.from.front().fact == d.fact) {
            Derivation inner = std::move(d.from.front());
            d = std::move(inner);
        }
    }

    // A law's file:line relative to the rules folder, when it is in it (else as loaded).
    [[nodiscard]] std::string law_location(const SourceLocation& w) const {
        const std::filesystem::path rel = std::filesystem::path(w.file.str()).lexically_relative(st_.options.rules_directory);
        const bool inside = !rel.empty() && *rel.begin() != "..";
        return (inside ? rel.generic_string() : w.file.str()) + ":" + std::to_string(w.line);
    }
    static constexpr const char* closed_world_text = "the closed world of the situation (what it does not say is false)";

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

}  // namespace

Exclusion explain_nogood(const Analysis::State& st, atms::EnvId nogood) {
    const atms::Explanation x = st.engine->atms().explain_nogood(nogood);
    TreeBuilder b(st, x);
    Derivation d = b.build(st.engine->atms().contradiction());
    return {item_texts(st, st.engine->atms().env(nogood), &b), std::move(d)};
}

Exclusion explain_holding(const Analysis::State& st, atms::NodeId n, atms::EnvId label_env) {
    const auto& atms = st.engine->atms();
    TreeBuilder b(st, atms.explain(n, label_env));
    Derivation d = b.build(n);
    return {item_texts(st, atms.env(label_env), &b), std::move(d)};
}

void order_by_relevance(const Analysis::State& st, std::vector<atms::EnvId>& nogoods, atms::AssumptionId a) {
    const auto& atms = st.engine->atms();
    auto key = [&](atms::EnvId ng) {
        const atms::Environment& x = atms.env(ng);
        std::size_t items = 0;
        for (atms::AssumptionId b : x.assumptions())
            if (st.facts->item(b)) ++items;
        return std::tuple(x.contains(a) ? 0 : 1, items > 0 ? 0 : 1, x.size());
    };
    std::stable_sort(nogoods.begin(), nogoods.end(), [&](atms::EnvId x, atms::EnvId y) { return key(x) < key(y); });
}

}  // namespace qm::analysis::detail
