// engine/engine_run.cpp: the strata loop, semi-naive matching and the agenda.
#include "engine/engine.hpp"
#include "qm/assert.hpp"
#include "qm/limit_reached.hpp"
#include <algorithm>
#include <string>

namespace qm::engine {

void Engine::run(Diagnostics& diagnostics, const RunOptions& options) { run_strata(std::nullopt, diagnostics, options); }

ContextRun Engine::run_in_context(atms::EnvId context, Diagnostics& diagnostics, const RunOptions& options) {
    std::uint32_t index = 0;
    while (index < contexts_.size() && contexts_[index].base != context) ++index;
    if (index == contexts_.size()) {
        atms::NodeId n = atms_.add_assumption(new_datum({Datum::Kind::closed_world, index}));
        auto a = atms_.assumption_of(n);
        QM_ASSERT(a.has_value(), "an assumption node has an assumption");
        std::vector<atms::AssumptionId> members = atms_.env(context).assumptions();
        members.push_back(*a);
        contexts_.push_back(Context{context, n, *a, atms_.environment(members), 0});
        if (is_choice_assumption_.size() <= a->value) is_choice_assumption_.resize(a->value + 1, false);
    }
    run_strata(index, diagnostics, options);
    const Context& c = contexts_[index];
    return ContextRun{index, c.environment, c.assumption};
}

void Engine::run_strata(std::optional<std::uint32_t> context, Diagnostics& diagnostics, const RunOptions& options) {
    options_ = options;
    steps_ = 0;
    stopped_ = false;
    for (std::uint32_t s = 0; s < program_.stratum_count && !stopped_; ++s) {
        // A rule with `not` or an aggregate is matched afresh in every run (its answers depend on
        // the context); a monotonic rule is matched in full once, then only against new facts.
        for (std::size_t i = 0; i < program_.rules.size(); ++i) {
            RuleId r{static_cast<std::uint32_t>(i)};
            const CompiledRule& rule = program_.rules[r];
            if (rule.stratum != s) continue;
            if (rule.non_monotonic || !rule_matched_[r]) {
                // Facts not yet logged are matched later, as fresh facts. No rule runs before
                // every rule of the stratum has been matched, so contradiction rules are in place
                // before anything can derive from a doomed environment.
                rule_fresh_[r].clear();
                rule_matched_[r] = 1;
                match_rule(r, std::nullopt, context, diagnostics);
            }
        }
        drain(s, context, diagnostics);
    }
    close_contexts();
}

// Executes queued instances and matches newly active facts against the rules of strata <= s
// until nothing changes. New facts are matched after every single execution, so that urgent
// instances (contradictions) they trigger run before anything else. Only the rules a new fact can
// wake are visited (log_active() queues it for them), in rule order; rules of later strata keep
// their queued facts until their stratum.
bool Engine::drain(std::uint32_t s, std::optional<std::uint32_t> context, Diagnostics& diagnostics) {
    bool changed = false;
    std::vector<FactId> fresh;
    for (;;) {
        if (stopped_) return changed;
        for (FactId f : pending_activation_)
            if (facts_.activate(f)) log_active(f);
        pending_activation_.clear();
        // Matching queues instances but activates nothing, so woken_ does not change in this loop.
        std::size_t kept = 0;
        for (RuleId r : woken_) {
            if (program_.rules[r].stratum > s || !rule_matched_[r]) {
                woken_[kept++] = r;
                continue;
            }
            fresh.swap(rule_fresh_[r]);
            rule_fresh_[r].clear();
            if (!fresh.empty()) match_fresh(r, fresh, context, diagnostics);
        }
        woken_.resize(kept);
        if (agenda_.empty() && pending_activation_.empty()) return changed;
        if (!agenda_.empty()) {
            RuleInstance instance = agenda_.pop();
            try {
                execute(instance, diagnostics);
            } catch (LimitReached& limit) {
                // The innermost place that knows which rule was at work says so.
                const CompiledRule& rule = program_.rules[instance.rule];
                if (limit.doing.empty()) limit.doing = "firing rule '" + rule.name + "'";
                if (!limit.where) limit.where = rule.where;
                throw;
            }
        }
        changed = true;
    }
}

// Queues a newly active fact for every rule that matches its predicate.
void Engine::log_active(FactId f) {
    auto it = shared_->by_trigger.find(facts_.fact(f).predicate.value);
    if (it == shared_->by_trigger.end()) return;
    for (RuleId r : it->second) {
        auto at = std::lower_bound(woken_.begin(), woken_.end(), r);
        if (at == woken_.end() || *at != r) woken_.insert(at, r);
        rule_fresh_[r].push_back(f);
    }
}

// Matches rule r against the facts that became active since it was last matched (of predicates it
// matches, in activation order): seeded at each `match` condition of the fact's predicate, and,
// for a quantifier's atom, from the bindings the fact unifies with.
void Engine::match_fresh(RuleId r, std::span<const FactId> fresh, std::optional<std::uint32_t> context,
                         Diagnostics& diagnostics) {
    const CompiledRule& rule = program_.rules[r];
    // A new fact of a predicate used inside a quantifier can complete a `for all` or an `exists`
    // only for the bindings of the rule's other variables it unifies with: match the rule again
    // from those (the agenda drops repeated bindings). If it cannot be unified ahead (a function
    // call over the quantified variable), match the whole rule.
    bool full = false;
    std::vector<Binding> prebound;
    Matcher probe(facts_, values_, builtins_, ClosedWorld{}, equals_);
    for (std::size_t k = 0; k < fresh.size() && !full; ++k) {
        FactId f = fresh[k];
        ValueId p = facts_.fact(f).predicate;
        for (const auto& c : rule.conditions) {
            if (c.kind != CompiledCondition::Kind::for_all && c.kind != CompiledCondition::Kind::exists) continue;
            for (const auto& a : c.atoms) {
                if (a.predicate != p) continue;
                bool has_call = std::any_of(a.args.begin(), a.args.end(),
                                            [](const CompiledTerm& t) { return t.kind == CompiledTerm::Kind::call; });
                if (has_call) {
                    full = true;
                    break;
                }
                if (auto b = probe.prebind(rule, a, c.slot, f)) prebound.push_back(std::move(*b));
            }
            if (full) break;
        }
    }
    if (full) return match_rule(r, std::nullopt, context, diagnostics);
    std::sort(prebound.begin(), prebound.end());
    prebound.erase(std::unique(prebound.begin(), prebound.end()), prebound.end());
    for (const Binding& b : prebound) match_rule(r, std::nullopt, context, diagnostics, &b);
    for (FactId f : fresh) {
        ValueId p = facts_.fact(f).predicate;
        for (std::uint32_t c = 0; c < rule.conditions.size(); ++c) {
            const auto& cond = rule.conditions[c];
            // A repeat of an earlier identical condition matches where that one does: its seed
            // finds the same matches, already found through the earlier one's.
            if (cond.kind == CompiledCondition::Kind::match && cond.atom.predicate == p && !shared_->plans[r].repeat_of[c])
                match_rule(r, Seed{c, f}, context, diagnostics);
        }
    }
}

void Engine::match_rule(RuleId r, std::optional<Seed> seed, std::optional<std::uint32_t> context,
                        Diagnostics& diagnostics, const Binding* initial) {
    const CompiledRule& rule = program_.rules[r];
    if (stopped_) return;
    std::optional<std::uint32_t> rule_context = rule.non_monotonic ? context : std::nullopt;
    if (rule.non_monotonic) closed_world_used_ = true;
    ClosedWorld world{[this, rule_context](FactId f) { return status(f, rule_context); },
                      [this, rule_context](FactId f) { return why_undecidable(f, rule_context); }};
    Matcher matcher(facts_, values_, builtins_, world, equals_, match_buffers_);
    if (options_.max_steps) matcher.limit_steps(*options_.max_steps - steps_);
    std::set<std::pair<std::string, std::string>> reported;
    bool urgent = std::any_of(rule.consequents.begin(), rule.consequents.end(),
                              [](const CompiledConsequent& c) { return c.kind == CompiledConsequent::Kind::falsity; });
    // The callbacks capture one pointer each, so that std::function keeps them inline: this runs
    // once per seed fact in every state's engine, and two heap blocks a call showed in the profile.
    struct Sink {
        Engine& engine;
        RuleId r;
        bool urgent;
        std::optional<std::uint32_t> rule_context;
        const CompiledRule& rule;
        std::set<std::pair<std::string, std::string>>& reported;
        Diagnostics& diagnostics;
    } sink{*this, r, urgent, rule_context, rule, reported, diagnostics};
    try {
        matcher.match(
            rule, shared_->plans[r], seed,
            [s = &sink](const Binding& b, std::span<const FactId> ants) {
                s->engine.agenda_.push(s->r, b, ants, s->rule_context, s->urgent);
            },
            [s = &sink](const MatchError& e) {
                std::string where = to_string(e.where);
                if (s->reported.insert({where, e.message}).second)
                    s->diagnostics.error(e.where, "rule '" + s->rule.name + "': " + e.message);
            },
            initial);
    } catch (LimitReached& limit) {  // deciding a `not` in a context may intern environments
        if (limit.doing.empty()) limit.doing = "matching rule '" + rule.name + "'";
        if (!limit.where) limit.where = rule.where;
        throw;
    }
    steps_ += matcher.steps();
    if (matcher.stopped()) stop(rule, rule.where, diagnostics);
}

bool Engine::spend(std::size_t n, const CompiledRule& rule, const SourceLocation& where, Diagnostics& diagnostics) {
    if (stopped_) return false;
    if (options_.max_steps && n > *options_.max_steps - steps_) {
        stop(rule, where, diagnostics);
        return false;
    }
    steps_ += n;
    return true;
}

// A run that stops is not resumed: the firing it was about to make is dropped, so what it found
// is sound but stays incomplete (docs/RULES.md "## Semantics").
void Engine::stop(const CompiledRule& rule, const SourceLocation& where, Diagnostics& diagnostics) {
    if (stopped_) return;
    stopped_ = true;
    diagnostics.error(where, "rule '" + rule.name + "': the run stopped here after " + std::to_string(steps_) +
                                 " steps, the limit set by its options (RunOptions::max_steps); what it found is "
                                 "sound but incomplete");
}

// Records, for every context, the nogoods {closed-world of C, X} for assumptions X outside C and
// outside every choice set: the closed world of C is the world where nothing else is assumed.
void Engine::close_contexts() {
    for (std::size_t i = 0; i < contexts_.size(); ++i) {
        Context& c = contexts_[i];
        std::uint32_t count = static_cast<std::uint32_t>(atms_.assumption_count());
        if (c.assumptions_closed == count) continue;
        const atms::Environment base = atms_.env(c.base);  // a copy: add_nogood may grow the env table
        Firing why{Firing::Kind::closed_world, std::nullopt, {}, static_cast<std::uint32_t>(i), &context_where_};
        std::optional<atms::InformantId> informant;
        for (std::uint32_t k = c.assumptions_closed; k < count; ++k) {
            atms::AssumptionId a{k};
            if (a == c.assumption || base.contains(a)) continue;
            if (a.value < is_choice_assumption_.size() && is_choice_assumption_[a.value]) continue;
            if (!informant) informant = new_firing(why);
            atms_.add_nogood(*informant, {c.node, atms_.node_of(a)});
        }
        c.assumptions_closed = count;
    }
}

}  // namespace qm::engine
