// engine/engine_consequents.cpp: executing a rule instance. Each consequent gets one ATMS
// justification from exactly the instance's antecedent fact nodes (plus the closed-world assumption
// of the context, for a rule with `not` or an aggregate run in a context), with the firing as informant.
#include "engine/engine.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <unordered_set>

namespace qm::engine {

std::optional<FactId> Engine::instantiate(const CompiledAtom& atom, const Binding& b, Diagnostics& diagnostics) {
    std::vector<ValueId>& args = scratch_args_;  // interning copies them
    args.clear();
    for (const auto& t : atom.args) {
        Evaluation e = evaluate(t, b, values_, builtins_);
        if (!e.value) {
            diagnostics.error(atom.where, e.error.empty() ? "consequent has an unbound variable" : e.error);
            return std::nullopt;
        }
        args.push_back(*e.value);
    }
    return intern_fact(atom.predicate, args);
}

void Engine::execute(RuleInstance& instance, Diagnostics& diagnostics) {
    const CompiledRule& rule = program_.rules[instance.rule];
    if (!spend(1, rule, rule.where, diagnostics)) return;
    ++rule_firings_;
    atms::InformantId why = new_firing(Firing{Firing::Kind::rule, instance.rule, instance.binding, instance.context, &rule.where});
    // The engine's scratch vector (nothing below executes another instance): no heap block a firing.
    std::vector<atms::NodeId>& ants = scratch_ants_;
    ants.clear();
    for (FactId f : instance.antecedents) ants.push_back(fact_nodes_[f].node);
    if (instance.context) ants.push_back(contexts_[*instance.context].node);

    // The instance's own binding (the firing has its copy): quantifiers bind their slot in it and
    // reset it after.
    Binding& b = instance.binding;
    // A quantified consequent's element gets its own informant, whose binding includes the element,
    // so explanations show which element a justification is for.
    auto element_informant = [&] {
        return new_firing(Firing{Firing::Kind::rule, instance.rule, b, instance.context, &rule.where});
    };
    // The elements of a consequent quantifier's set that pass its tests.
    auto elements = [&](const CompiledConsequent& c) -> std::vector<ValueId> {
        std::vector<ValueId> out;
        Evaluation set = evaluate(c.set, b, values_, builtins_);
        if (!set.value || values_.value(*set.value).kind != ValueKind::set) {
            diagnostics.error(c.where, set.error.empty() ? "quantifier set is not a set" : set.error);
            return out;
        }
        for (ValueId e : values_.value(*set.value).elements) {
            b[c.slot] = e;
            bool pass = true;
            for (const auto& t : c.tests) {
                std::vector<ValueId> args;
                for (const auto& a : t.args) {
                    Evaluation v = evaluate(a, b, values_, builtins_);
                    if (!v.value) {
                        if (!v.error.empty()) diagnostics.error(t.where, v.error);
                        pass = false;
                        break;
                    }
                    args.push_back(*v.value);
                }
                if (!pass) break;
                BuiltinResult r = builtins_.apply(t.test, values_, args);
                if (!r.error.empty()) diagnostics.error(t.where, r.error);
                if (!r.holds) {
                    pass = false;
                    break;
                }
            }
            if (pass) out.push_back(e);
        }
        b[c.slot].reset();
        return out;
    };

    for (const auto& c : rule.consequents) {
        switch (c.kind) {
            case CompiledConsequent::Kind::assert_atom:
                if (auto f = instantiate(c.atom, b, diagnostics)) {
                    atms_.justify(why, ants, fact_nodes_[*f].node);
                    note_if_in(*f);
                }
                break;
            case CompiledConsequent::Kind::falsity: atms_.add_nogood(why, ants); break;
            case CompiledConsequent::Kind::assume_atom:
                if (auto f = instantiate(c.atom, b, diagnostics)) {
                    assume_fact(*f, why, ants);
                    note_if_in(*f);
                }
                break;
            case CompiledConsequent::Kind::for_all_assert: {
                const std::vector<ValueId> es = elements(c);
                if (!spend(es.size(), rule, c.where, diagnostics)) return;
                for (ValueId e : es) {
                    b[c.slot] = e;
                    if (auto f = instantiate(c.atom, b, diagnostics)) {
                        atms_.justify(element_informant(), ants, fact_nodes_[*f].node);
                        note_if_in(*f);
                    }
                }
                b[c.slot].reset();
                break;
            }
            case CompiledConsequent::Kind::exactly_one: {
                // One step per element and one per pair of elements, before anything is assumed: a
                // choice set is declared whole or not at all. (The pairs are one ATMS constraint
                // now, but a bounded run still counts them, so RunOptions::max_steps means what it
                // meant.)
                const std::vector<ValueId> es = elements(c);
                if (!spend(es.size() + es.size() * (es.size() - (es.empty() ? 0 : 1)) / 2, rule, c.where, diagnostics))
                    return;
                std::vector<atms::AssumptionId> set;
                std::unordered_set<atms::AssumptionId> members;  // an element repeated adds nothing
                for (ValueId e : es) {
                    b[c.slot] = e;
                    if (auto f = instantiate(c.atom, b, diagnostics)) {
                        assume_fact(*f, element_informant(), ants);
                        note_if_in(*f);
                        const atms::AssumptionId a = *atms_.assumption_of(*fact_nodes_[*f].assumption);
                        if (members.insert(a).second) set.push_back(a);
                    }
                }
                b[c.slot].reset();
                declare_choice_set(c, rule, why, ants, std::move(set), diagnostics);
                break;
            }
        }
    }
}

// Law 1 style uniqueness: each element an assumption, no two together (one at-most-one constraint of
// the ATMS, which stands for a nogood for every pair), one choice set. The interpretations pick one
// assumption from every choice set, which the ATMS can only do for disjoint sets: a set sharing an
// assumption with another (not identical) set is refused, located.
// "Exactly one of nothing" is false: an empty set makes the firing's antecedents a nogood, so the
// environments where it fired are inconsistent, and `--why` names the rule that made them so. (An
// empty choice set registered as such would instead leave no interpretation at all, with no
// nogood to say why, even where the firing's antecedents do not hold.)
void Engine::declare_choice_set(const CompiledConsequent& c, const CompiledRule& rule, atms::InformantId why,
                                std::span<const atms::NodeId> antecedents, std::vector<atms::AssumptionId> set,
                                Diagnostics& diagnostics) {
    if (set.empty()) {
        atms_.add_nogood(why, antecedents);
        return;
    }
    std::vector<atms::AssumptionId> key = set;
    std::sort(key.begin(), key.end());
    // The same set declared again (another binding, another rule) adds nothing; a refused one was
    // reported when first seen.
    if (!choice_set_keys_.insert(key).second) return;
    for (atms::AssumptionId a : set) {
        auto owner = choice_set_of_.find(a);
        if (owner == choice_set_of_.end()) continue;
        const std::vector<atms::AssumptionId>& other = choice_sets_[owner->second];
        std::string members;
        for (atms::AssumptionId m : other) members += (members.empty() ? "" : ", ") + print(m);
        const SourceLocation& at = choice_set_where_[owner->second];
        diagnostics.error(c.where, "rule '" + rule.name + "': `exactly one` would put " + print(a) +
                                       " in a second choice set: it is already in the choice set {" + members +
                                       "} declared at " + to_string(at) + "; choice sets must be disjoint or identical");
        return;
    }
    choice_set_constraints_.push_back(atms_.add_at_most_one(why, set));
    const auto index = static_cast<std::uint32_t>(choice_sets_.size());
    for (atms::AssumptionId a : set) {
        is_choice_assumption_[a.value] = true;
        choice_set_of_.emplace(a, index);
    }
    choice_sets_.push_back(std::move(set));
    choice_set_where_.push_back(c.where);
}

}  // namespace qm::engine
