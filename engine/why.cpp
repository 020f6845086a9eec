// engine/why.cpp
#include "engine/why.hpp"
#include "engine/binding.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <set>

namespace qm::engine {
namespace {

std::string node_text(const Engine& e, atms::NodeId n) {
    const auto& atms = e.atms();
    if (n == atms.contradiction()) return "false";
    if (auto a = atms.assumption_of(n)) {
        auto f = e.fact_of(n);
        if (f && e.node(*f) != n) return "assume " + e.print(*a);
        return e.print(*a);
    }
    auto f = e.fact_of(n);
    QM_ASSERT(f.has_value(), "a non-assumption node stands for a fact");
    return e.print(*f);
}

// A term under a firing's binding: its value where it is ground, otherwise as written (a variable
// local to a `not` by its name).
std::string term_text(Engine& e, const CompiledRule& rule, const CompiledTerm& t, const Binding& b) {
    if (is_ground(t, b))
        if (Evaluation v = evaluate(t, b, e.values(), e.builtins()); v.value) return e.values().print(*v.value);
    switch (t.kind) {
        case CompiledTerm::Kind::constant: return e.values().print(t.constant);
        case CompiledTerm::Kind::variable: return rule.slot_names[t.slot];
        case CompiledTerm::Kind::call: {
            std::string out = "(" + e.builtins().get(t.function).name;
            for (const auto& a : t.args) out += " " + term_text(e, rule, a, b);
            return out + ")";
        }
    }
    return {};
}

// The `not` conditions of a firing's rule, under its binding. They are not antecedents (a label
// cannot say "where P does not hold"), so the ATMS does not know them: the rule does.
std::vector<std::string> absent_of(Engine& e, const CompiledRule& rule, const Binding& b) {
    std::vector<std::string> out;
    for (const auto& c : rule.conditions) {
        if (c.kind != CompiledCondition::Kind::negation) continue;
        std::string atom = "(" + e.values().print(c.atom.predicate);
        for (const auto& t : c.atom.args) atom += " " + term_text(e, rule, t, b);
        out.push_back(atom + ")");
    }
    return out;
}

WhyStep step_of(Engine& e, atms::JustId j) {
    const atms::Justification& just = e.atms().justification(j);
    const Firing& firing = e.firing(just.informant);
    WhyStep s;
    std::string at = firing.where->file.str() + ":" + std::to_string(firing.where->line);
    switch (firing.kind) {
        case Firing::Kind::rule: {
            const CompiledRule& rule = e.program().rules[*firing.rule];
            s.informant = "rule " + rule.name + " at " + at;
            for (std::size_t i = 0; i < firing.binding.size(); ++i)
                if (firing.binding[i]) s.binding.push_back(rule.slot_names[i] + " = " + e.values().print(*firing.binding[i]));
            s.absent = absent_of(e, rule, firing.binding);
            break;
        }
        case Firing::Kind::premise: s.informant = "premise at " + at; break;
        case Firing::Kind::assumption: s.informant = "assumption at " + at; break;
        case Firing::Kind::closed_world: s.informant = "closed world of context " + std::to_string(*firing.context); break;
    }
    for (atms::NodeId a : just.antecedents) s.antecedents.push_back(node_text(e, a));
    s.consequent = node_text(e, just.consequent);
    return s;
}

std::vector<WhyStep> steps_of(Engine& e, const atms::Explanation& x) {
    std::vector<WhyStep> out;
    for (atms::JustId j : x.steps) out.push_back(step_of(e, j));
    return out;
}

// The minimal environments that would derive n if nogoods were ignored (depth-first over the
// justifications; a node on the current path contributes nothing, which breaks cycles). Capped so
// that explaining stays cheap; only used to find the nogoods that rule a fact out.
std::vector<atms::Environment> support(const atms::Atms& atms, atms::NodeId n, std::set<atms::NodeId>& path) {
    constexpr std::size_t cap = 64;
    if (auto a = atms.assumption_of(n)) {
        atms::AssumptionId id = *a;
        return {atms::Environment::of(std::span<const atms::AssumptionId>(&id, 1))};
    }
    if (atms.is_premise(n)) return {atms::Environment{}};
    if (!path.insert(n).second) return {};
    std::vector<atms::Environment> out;
    for (atms::JustId j : atms.justifications(n)) {
        std::vector<atms::Environment> partial{atms::Environment{}};
        for (atms::NodeId a : atms.justification(j).antecedents) {
            auto envs = support(atms, a, path);
            std::vector<atms::Environment> next;
            for (const auto& p : partial)
                for (const auto& q : envs)
                    if (next.size() < cap) next.push_back(join(p, q));
            partial = std::move(next);
        }
        for (auto& p : partial)
            if (out.size() < cap) out.push_back(std::move(p));
    }
    path.erase(n);
    return out;
}

}  // namespace

std::vector<std::string> absent_conditions(Engine& engine, const Firing& firing) {
    if (firing.kind != Firing::Kind::rule) return {};
    return absent_of(engine, engine.program().rules[*firing.rule], firing.binding);
}

Why why(Engine& engine, FactId f) {
    Why w;
    w.fact = engine.print(f);
    auto& atms = engine.atms();
    atms::NodeId n = engine.node(f);
    for (atms::EnvId env : atms.label(n)) {
        w.status = Why::Status::holds;
        w.derivations.push_back({env_text(engine, env), steps_of(engine, atms.explain(n, env))});
    }
    if (w.status == Why::Status::holds) return w;
    std::set<atms::NodeId> path;
    auto envs = support(atms, n, path);
    if (envs.empty()) return w;
    w.status = Why::Status::ruled_out;
    // The minimal nogoods inside some supporting environment, in EnvId order (asked per
    // environment: listing every nogood would form every pair of a large choice set).
    std::set<atms::EnvId> excluding;
    for (const atms::Environment& e : envs)
        for (atms::EnvId ng : atms.minimal_nogoods_within(e)) excluding.insert(ng);
    for (atms::EnvId ng : excluding) w.nogoods.push_back({env_text(engine, ng), steps_of(engine, atms.explain_nogood(ng))});
    return w;
}

}  // namespace qm::engine
