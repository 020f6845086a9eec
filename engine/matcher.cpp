// engine/matcher.cpp: depth-first evaluation of a rule's conditions in written order.
#include "engine/matcher.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <array>
#include <limits>

namespace qm::engine {

// The state of one match() call: the binding, a trail of slots bound (for undo) and the
// antecedents gathered so far.
struct Matcher::Run {
    Matcher& m;
    const CompiledRule& rule;
    const MatchPlan* plan;  // null only for prebind(), which never steps through conditions
    std::optional<Seed> seed;
    const OnMatch& on_match;
    const OnError& on_error;
    // In a MatchBuffers (the caller's, or one of match()'s own):
    Binding& binding;
    std::vector<Slot>& trail;
    std::vector<FactId>& antecedents;
    std::vector<ValueId>& scratch;  // arguments of a `for all` atom being looked up
    std::vector<FactId>& matched_at;  // per condition: the fact its `match` matched on the current path
                                      // (kept only when the plan has repeats, which read it)

    void bind(Slot s, ValueId v) {
        binding[s] = v;
        trail.push_back(s);
    }
    void undo(std::size_t mark) {
        while (trail.size() > mark) {
            binding[trail.back()].reset();
            trail.pop_back();
        }
    }
    void error(const SourceLocation& where, std::string message) { on_error(MatchError{where, std::move(message)}); }

    // Takes one step; false once the matcher's limit is reached (then every loop ends at once).
    bool tick() {
        if (m.stopped_) return false;
        if (m.step_limit_ && m.steps_ >= *m.step_limit_) {
            m.stopped_ = true;
            return false;
        }
        ++m.steps_;
        return true;
    }

    // Evaluates a ground term; reports builtin errors. Empty when not ground or on error.
    std::optional<ValueId> value_of(const CompiledTerm& t, const SourceLocation& where) {
        Evaluation e = evaluate(t, binding, m.values_, m.builtins_);
        if (!e.error.empty()) error(where, e.error);
        return e.value;
    }

    // Unifies atom with fact f, binding unbound variables. Leaves bindings on the trail.
    bool unify(const CompiledAtom& atom, FactId f) {
        const Fact& fact = m.facts_.fact(f);
        if (fact.predicate != atom.predicate || fact.args.size() != atom.args.size()) return false;
        for (std::size_t i = 0; i < atom.args.size(); ++i) {
            const CompiledTerm& t = atom.args[i];
            if (t.kind == CompiledTerm::Kind::variable && !binding[t.slot]) {
                bind(t.slot, fact.args[i]);
                continue;
            }
            if (!is_ground(t, binding)) return false;  // a call over unbound variables cannot match
            auto v = value_of(t, atom.where);
            if (!v || *v != fact.args[i]) return false;
        }
        return true;
    }

    // The facts that may unify with atom under the current binding (only the active ones, or all
    // of them for the closed world): the shortest of the predicate's list and the lists of the
    // atom's ground arguments (constants and bound variables). Each list is a subsequence of the
    // predicate's, in the same order, so narrowing skips facts that cannot unify and never changes
    // the order of those that do: a join costs what it matches, not what the predicate holds.
    std::span<const FactId> candidates(const CompiledAtom& atom, bool active_only) {
        std::span<const FactId> best = active_only ? m.facts_.active_with_predicate(atom.predicate)
                                                   : m.facts_.with_predicate(atom.predicate);
        for (std::uint32_t i = 0; i < atom.args.size() && !best.empty(); ++i) {
            const CompiledTerm& t = atom.args[i];
            if (t.kind == CompiledTerm::Kind::call || !is_ground(t, binding)) continue;
            ValueId v = t.kind == CompiledTerm::Kind::constant ? t.constant : *binding[t.slot];
            auto s = active_only ? m.facts_.active_with_argument(atom.predicate, i, v)
                                 : m.facts_.with_argument(atom.predicate, i, v);
            if (s.size() < best.size()) best = s;
        }
        return best;
    }

    // Matches atoms[k..] against active facts, then calls next().
    void match_atoms(std::span<const CompiledAtom> atoms, const std::function<void()>& next) {
        if (atoms.empty()) return next();
        const CompiledAtom& atom = atoms.front();
        for (FactId f : candidates(atom, true)) {
            if (!tick()) return;
            std::size_t mark = trail.size();
            if (unify(atom, f)) {
                antecedents.push_back(f);
                match_atoms(atoms.subspan(1), next);
                antecedents.pop_back();
            }
            undo(mark);
        }
    }

    bool tests_hold(std::span<const CompiledTest> tests) {
        for (const auto& t : tests)
            if (!test_holds(t)) return false;
        return true;
    }

    bool test_holds(const CompiledTest& t) {
        // Tests take few arguments: evaluate them into a buffer on the stack when they fit.
        std::array<ValueId, 4> small{};
        std::vector<ValueId> large;
        if (t.args.size() > small.size()) large.resize(t.args.size());
        std::span<ValueId> args = large.empty() ? std::span<ValueId>(small.data(), t.args.size()) : std::span<ValueId>(large);
        for (std::size_t k = 0; k < t.args.size(); ++k) {
            auto v = value_of(t.args[k], t.where);
            if (!v) {
                if (is_ground(t.args[k], binding)) return false;  // builtin error, already reported
                error(t.where, "builtin test '" + m.builtins_.get(t.test).name + "' uses an unbound variable");
                return false;
            }
            args[k] = *v;
        }
        BuiltinResult r = m.builtins_.apply(t.test, m.values_, args);
        if (!r.error.empty()) {
            error(t.where, r.error);
            return false;
        }
        return r.holds;
    }

    // The elements of a quantifier's set, or empty after reporting an error.
    std::optional<std::vector<ValueId>> elements(const CompiledTerm& set, const SourceLocation& where) {
        auto v = value_of(set, where);
        if (!v) return std::nullopt;
        const Value& value = m.values_.value(*v);
        if (value.kind != ValueKind::set) {
            error(where, "'" + m.values_.print(*v) + "' is not a set");
            return std::nullopt;
        }
        return value.elements;
    }

    // Calls each(f, status) for every fact unifying with atom (any activity), leaving no bindings.
    // Returns false if some fact was undecidable (reported).
    template <class Each>
    bool closed_world_scan(const CompiledAtom& atom, Each&& each) {
        bool decidable = true;
        for (FactId f : candidates(atom, false)) {
            if (!tick()) return decidable;
            std::size_t mark = trail.size();
            if (unify(atom, f)) {
                ClosedWorldStatus s = m.closed_world_.status(f);
                if (s == ClosedWorldStatus::undecidable) {
                    error(atom.where, m.closed_world_.why_undecidable(f));
                    decidable = false;
                } else if (s == ClosedWorldStatus::holds) {
                    each(f);
                }
            }
            undo(mark);
        }
        return decidable;
    }

    // A prefix matched in the plan's order (match_plan.hpp): each match is kept with its facts in
    // written order and its activation ranks, the key of the written order's depth-first walk
    // (every candidate list is in activation order), then walked on from the end of the prefix in
    // that order, so that answers come out as the written order would give them.
    struct Found {
        std::vector<std::uint32_t> key;
        std::vector<FactId> facts;
        Binding binding;
    };

    void planned(std::span<const std::uint32_t> order, std::vector<Found>& found) {
        if (m.stopped_) return;
        if (order.empty()) {
            Found f{{}, {}, binding};
            for (std::uint32_t i = 0; i < plan->prefix; ++i)
                if (rule.conditions[i].kind == CompiledCondition::Kind::match) {
                    f.key.push_back(m.facts_.activation_rank(matched_at[i]));
                    f.facts.push_back(matched_at[i]);
                }
            found.push_back(std::move(f));
            return;
        }
        const std::uint32_t i = order.front();
        const CompiledCondition& c = rule.conditions[i];
        auto rest = order.subspan(1);
        if (c.kind == CompiledCondition::Kind::test) {
            if (plan->repeat_of[i]) return planned(rest, found);
            return test_then(c.test, [&] { planned(rest, found); });
        }
        auto take = [&](FactId f) {
            std::size_t mark = trail.size();
            if (unify(c.atom, f)) {
                matched_at[i] = f;
                planned(rest, found);
            }
            undo(mark);
        };
        if (seed && seed->condition == i) return take(seed->fact);
        if (const auto& first = plan->repeat_of[i]) return take(matched_at[*first]);
        for (FactId f : candidates(c.atom, true)) {
            if (!tick()) return;
            take(f);
        }
    }

    void step_planned(std::span<const std::uint32_t> order) {
        matched_at.resize(rule.conditions.size());
        std::vector<Found> found;
        planned(order, found);
        std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.key < b.key; });
        for (const Found& f : found) {
            if (m.stopped_) return;
            binding.assign(f.binding.begin(), f.binding.end());
            trail.clear();
            antecedents.assign(f.facts.begin(), f.facts.end());
            std::size_t k = 0;
            for (std::uint32_t i = 0; i < plan->prefix; ++i)
                if (rule.conditions[i].kind == CompiledCondition::Kind::match) matched_at[i] = f.facts[k++];
            step(plan->prefix);
        }
    }

    void step(std::size_t i) {
        if (m.stopped_) return;
        if (i == rule.conditions.size()) return on_match(binding, antecedents);
        const CompiledCondition& c = rule.conditions[i];
        switch (c.kind) {
            case CompiledCondition::Kind::match: return step_match(i, c);
            case CompiledCondition::Kind::test: return step_test(i, c);
            case CompiledCondition::Kind::negation: return step_negation(i, c);
            case CompiledCondition::Kind::for_all: return step_for_all(i, c);
            case CompiledCondition::Kind::exists: return step_exists(i, c);
            case CompiledCondition::Kind::aggregate: return step_aggregate(i, c);
        }
    }

    void step_match(std::size_t i, const CompiledCondition& c) {
        auto matched = [&](FactId f) {
            antecedents.push_back(f);
            if (!matched_at.empty()) matched_at[i] = f;
            step(i + 1);
            antecedents.pop_back();
        };
        if (seed && seed->condition == i) {
            std::size_t mark = trail.size();
            if (unify(c.atom, seed->fact)) matched(seed->fact);
            undo(mark);
            return;
        }
        // An identical earlier `match` has bound every variable of this atom to the fact it
        // matched, which is the only fact this one can match: take it without looking it up.
        if (const auto& first = plan->repeat_of[i]) return matched(matched_at[*first]);
        match_atoms(std::span<const CompiledAtom>(&c.atom, 1), [&] {
            if (!matched_at.empty()) matched_at[i] = antecedents.back();
            step(i + 1);
        });
    }

    void step_test(std::size_t i, const CompiledCondition& c) {
        // An identical earlier test held on this path (with the same arguments: they were ground
        // there, or its `=` bound them), so this one holds too.
        if (plan->repeat_of[i]) return step(i + 1);
        test_then(c.test, [&] { step(i + 1); });
    }

    // Goes on (next()) if test t holds, or with its variable bound by `(= ?x TERM)`.
    template <class Next>
    void test_then(const CompiledTest& t, Next&& next) {
        // `(= ?x TERM)` with ?x unbound binds ?x (the checker guarantees TERM is ground here).
        if (m.equals_ && t.test == *m.equals_ && t.args.size() == 2 &&
            t.args[0].kind == CompiledTerm::Kind::variable && !binding[t.args[0].slot]) {
            auto v = value_of(t.args[1], t.where);
            if (!v) {
                if (!is_ground(t.args[1], binding)) error(t.where, "'=' has unbound variables on both sides");
                return;
            }
            std::size_t mark = trail.size();
            bind(t.args[0].slot, *v);
            next();
            undo(mark);
            return;
        }
        if (test_holds(t)) next();
    }

    void step_negation(std::size_t i, const CompiledCondition& c) {
        bool some_holds = false;
        bool decidable = closed_world_scan(c.atom, [&](FactId) { some_holds = true; });
        if (decidable && !some_holds) step(i + 1);
    }

    void step_for_all(std::size_t i, const CompiledCondition& c) {
        auto elements_of = elements(c.set, c.where);
        if (!elements_of) return;
        std::size_t pushed = 0;
        bool all = true;
        for (ValueId e : *elements_of) {
            if (!tick()) {
                all = false;
                break;
            }
            std::size_t mark = trail.size();
            bind(c.slot, e);
            if (tests_hold(c.tests)) {
                for (const auto& atom : c.atoms) {
                    scratch.clear();
                    for (const auto& a : atom.args) {
                        auto v = value_of(a, atom.where);
                        if (!v) break;
                        scratch.push_back(*v);
                    }
                    std::optional<FactId> f;
                    if (scratch.size() == atom.args.size()) f = m.facts_.find(atom.predicate, scratch);
                    if (!f || !m.facts_.is_active(*f)) {
                        all = false;
                        break;
                    }
                    antecedents.push_back(*f);
                    ++pushed;
                }
            }
            undo(mark);
            if (!all) break;
        }
        if (all) step(i + 1);
        antecedents.resize(antecedents.size() - pushed);
    }

    void step_exists(std::size_t i, const CompiledCondition& c) {
        auto elements_of = elements(c.set, c.where);
        if (!elements_of) return;
        for (ValueId e : *elements_of) {
            if (!tick()) return;
            std::size_t mark = trail.size();
            if (binding[c.slot] && *binding[c.slot] != e) continue;
            if (!binding[c.slot]) bind(c.slot, e);
            if (tests_hold(c.tests)) match_atoms(c.atoms, [&] { step(i + 1); });
            undo(mark);
        }
    }

    void step_aggregate(std::size_t i, const CompiledCondition& c) {
        auto start = value_of(c.start, c.where);
        if (!start) return;
        ValueId total = *start;
        std::vector<FactId> folded;
        bool ok = true;
        bool decidable = closed_world_scan(c.atom, [&](FactId f) {
            if (!ok) return;
            auto v = value_of(c.value, c.where);
            if (!v) {
                ok = false;
                return;
            }
            BuiltinResult r = m.builtins_.apply(c.function, m.values_, std::array<ValueId, 2>{total, *v});
            if (!r.error.empty() || !r.value) {
                error(c.where, r.error.empty() ? "aggregate function returned no value" : r.error);
                ok = false;
                return;
            }
            total = *r.value;
            folded.push_back(f);
        });
        if (!decidable || !ok) return;
        std::size_t mark = trail.size();
        if (binding[c.slot] && *binding[c.slot] != total) return;
        if (!binding[c.slot]) bind(c.slot, total);
        antecedents.insert(antecedents.end(), folded.begin(), folded.end());
        step(i + 1);
        antecedents.resize(antecedents.size() - folded.size());
        undo(mark);
    }
};

Matcher::Matcher(const FactStore& facts, ValueTable& values, const BuiltinRegistry& builtins,
                 const ClosedWorld& closed_world)
    : Matcher(facts, values, builtins, closed_world, builtins.find("=")) {}

Matcher::Matcher(const FactStore& facts, ValueTable& values, const BuiltinRegistry& builtins,
                 const ClosedWorld& closed_world, std::optional<BuiltinId> equals)
    : facts_(facts), values_(values), builtins_(builtins), closed_world_(closed_world), equals_(equals) {}

Matcher::Matcher(const FactStore& facts, ValueTable& values, const BuiltinRegistry& builtins,
                 const ClosedWorld& closed_world, std::optional<BuiltinId> equals, MatchBuffers& buffers)
    : Matcher(facts, values, builtins, closed_world, equals) {
    buffers_ = &buffers;
}

void Matcher::match(const CompiledRule& rule, const MatchPlan& plan, std::optional<Seed> seed, const OnMatch& on_match,
                    const OnError& on_error, const Binding* initial) {
    QM_REQUIRE(plan.repeat_of.size() == rule.conditions.size() && plan.seed_first_safe.size() == rule.conditions.size(),
               "the plan is the rule's");
    if (seed) {
        QM_REQUIRE(seed->condition < rule.conditions.size() &&
                       rule.conditions[seed->condition].kind == CompiledCondition::Kind::match,
                   "a seed names a match condition");
    }
    QM_REQUIRE(!initial || initial->size() == rule.slot_count(), "an initial binding has one entry per slot");
    MatchBuffers own;
    MatchBuffers& b = buffers_ ? *buffers_ : own;
    if (initial) b.binding.assign(initial->begin(), initial->end());
    else b.binding.assign(rule.slot_count(), std::nullopt);
    b.trail.clear();
    b.antecedents.clear();
    b.scratch.clear();
    b.matched_at.clear();
    Run run{*this, rule, &plan, seed, on_match, on_error, b.binding, b.trail, b.antecedents, b.scratch, b.matched_at};
    if (plan.has_repeat) run.matched_at.resize(rule.conditions.size());
    // Semi-naive matching: bind the seed fact's variables first, so that the conditions written
    // before it are looked up through the argument index instead of scanned. This gives the same
    // matches in the same order unless an earlier `not`, aggregate or quantifier would see one of
    // those variables unbound (then local to it): such rules are matched as written.
    // A prefix whose written order would scan a predicate while another condition could be looked
    // up through a bound argument is matched in the plan's order instead (match_plan.hpp).
    if (!initial && (!seed || seed->condition < plan.prefix)) {
        const auto& order = plan.order[seed ? seed->condition : rule.conditions.size()];
        if (!order.empty()) return run.step_planned(order);
    }
    if (seed && plan.seed_first_safe[seed->condition]) {
        if (!run.unify(rule.conditions[seed->condition].atom, seed->fact)) return;
        run.trail.clear();
    }
    run.step(0);
}

std::optional<Binding> Matcher::prebind(const CompiledRule& rule, const CompiledAtom& atom, Slot local, FactId f) {
    const OnMatch none = [](const Binding&, std::span<const FactId>) {};
    bool failed = false;
    const OnError note = [&](const MatchError&) { failed = true; };
    MatchBuffers own;
    own.binding.assign(rule.slot_count(), std::nullopt);
    Run run{*this, rule, nullptr, std::nullopt, none, note, own.binding, own.trail, own.antecedents, own.scratch, own.matched_at};
    // Only plain variables and constants can be unified before the quantified variable is known.
    for (const CompiledTerm& t : atom.args)
        if (t.kind == CompiledTerm::Kind::call) return std::nullopt;
    if (!run.unify(atom, f) || failed) return std::nullopt;
    run.binding[local].reset();
    return run.binding;
}

}  // namespace qm::engine
