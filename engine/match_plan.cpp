// engine/match_plan.cpp: the facts-independent analysis of a rule's conditions (match_plan.hpp).
#include "engine/match_plan.hpp"
#include <algorithm>
#include <map>
#include <span>

namespace qm::engine {
namespace {

// Every variable slot in t.
template <class F>
void for_each_slot(const CompiledTerm& t, F&& f) {
    if (t.kind == CompiledTerm::Kind::variable) f(t.slot);
    for (const auto& a : t.args) for_each_slot(a, f);
}

// A key equal for two terms exactly when they are the same term (same constants, slots, calls).
void append_key(const CompiledTerm& t, std::vector<std::uint32_t>& key) {
    key.push_back(static_cast<std::uint32_t>(t.kind));
    switch (t.kind) {
        case CompiledTerm::Kind::constant: key.push_back(t.constant.value); break;
        case CompiledTerm::Kind::variable: key.push_back(t.slot); break;
        case CompiledTerm::Kind::call:
            key.push_back(t.function.value);
            key.push_back(static_cast<std::uint32_t>(t.args.size()));
            for (const auto& a : t.args) append_key(a, key);
            break;
    }
}

// The key of a condition that can repeat an identical earlier one: a `match` or a builtin test.
// (A `not`, an aggregate or a quantifier may see variables bound between the two that were local
// at the first, so an identical text need not give the same answer: those are never repeats.)
std::optional<std::vector<std::uint32_t>> repeat_key(const CompiledCondition& c) {
    std::vector<std::uint32_t> key{static_cast<std::uint32_t>(c.kind)};
    const std::vector<CompiledTerm>* args = nullptr;
    if (c.kind == CompiledCondition::Kind::match) {
        key.push_back(c.atom.predicate.value);
        args = &c.atom.args;
    } else if (c.kind == CompiledCondition::Kind::test) {
        key.push_back(c.test.test.value);
        args = &c.test.args;
    } else {
        return std::nullopt;
    }
    key.push_back(static_cast<std::uint32_t>(args->size()));
    for (const auto& t : *args) append_key(t, key);
    return key;
}

// Seeding condition s first is safe unless a `not`, aggregate or quantifier written before s uses
// one of s's variables while it is still unbound there (local to it): binding it ahead would change
// that condition's answer. Which variables are bound before a condition does not depend on s, so
// one pass finds, for every slot, the first condition that uses it unbound (`local_at`); s is safe
// iff every variable of its atom is first used unbound at or after s.
std::vector<std::uint8_t> seed_first_safety(const CompiledRule& rule) {
    const std::uint32_t none = static_cast<std::uint32_t>(rule.conditions.size());
    std::vector<std::uint8_t> bound(rule.slot_count(), 0);
    std::vector<std::uint32_t> local_at(rule.slot_count(), none);
    for (std::uint32_t i = 0; i < rule.conditions.size(); ++i) {
        const CompiledCondition& c = rule.conditions[i];
        auto mark_bound = [&](Slot s) { bound[s] = 1; };
        auto note_local = [&](Slot s) {
            if (!bound[s] && local_at[s] == none) local_at[s] = i;
        };
        switch (c.kind) {
            case CompiledCondition::Kind::match:
                for (const auto& t : c.atom.args) for_each_slot(t, mark_bound);
                break;
            case CompiledCondition::Kind::test:
                // `(= ?x TERM)` binds ?x when it is unbound; a seed-bound ?x makes it a comparison,
                // which is what it would find anyway.
                for (const auto& t : c.test.args) for_each_slot(t, mark_bound);
                break;
            case CompiledCondition::Kind::negation:
            case CompiledCondition::Kind::aggregate:
                for (const auto& t : c.atom.args) for_each_slot(t, note_local);
                if (c.kind == CompiledCondition::Kind::aggregate) bound[c.slot] = 1;
                break;
            case CompiledCondition::Kind::for_all:
            case CompiledCondition::Kind::exists:
                for (const auto& a : c.atoms)
                    for (const auto& t : a.args) for_each_slot(t, note_local);
                for_each_slot(c.set, note_local);
                for (const auto& t : c.tests)
                    for (const auto& x : t.args) for_each_slot(x, note_local);
                if (c.kind == CompiledCondition::Kind::exists) bound[c.slot] = 1;
                break;
        }
    }
    std::vector<std::uint8_t> safe(rule.conditions.size(), 0);
    for (std::uint32_t s = 0; s < rule.conditions.size(); ++s) {
        const CompiledCondition& c = rule.conditions[s];
        if (c.kind != CompiledCondition::Kind::match) continue;
        bool ok = true;
        for (const auto& t : c.atom.args) for_each_slot(t, [&](Slot v) { ok = ok && local_at[v] >= s; });
        safe[s] = ok ? 1 : 0;
    }
    return safe;
}

std::vector<Slot> slots_of(std::span<const CompiledTerm> terms, bool calls_only) {
    std::vector<Slot> out;
    for (const auto& t : terms) {
        if (calls_only && t.kind != CompiledTerm::Kind::call) continue;
        for_each_slot(t, [&](Slot s) { out.push_back(s); });
    }
    return out;
}

// The order of the prefix's conditions, seeded at `seed` (or unseeded): at each step the first
// test (in written order) whose arguments are bound, else the first `match` with a ground argument
// (a constant or a bound variable: an index lookup), else the first `match` whose function calls
// can be evaluated. A repeat follows the condition it repeats. A test that binds (`=` with its left
// variable unbound where it is written) may do so wherever its right side is bound. Empty if the
// order is the written one (for a seed, apart from where the seed stands: it matches one fact).
std::vector<std::uint32_t> plan_order(const CompiledRule& rule, const MatchPlan& plan, std::optional<std::uint32_t> seed,
                                      const std::vector<std::uint8_t>& binds_left) {
    const std::uint32_t n = plan.prefix;
    std::vector<std::uint8_t> bound(rule.slot_count(), 0), placed(n, 0);
    std::vector<std::uint32_t> order;
    auto all_bound = [&](const std::vector<Slot>& slots) {
        return std::all_of(slots.begin(), slots.end(), [&](Slot s) { return bound[s] != 0; });
    };
    auto place = [&](std::uint32_t i) {
        const CompiledCondition& c = rule.conditions[i];
        const auto& args = c.kind == CompiledCondition::Kind::match ? c.atom.args : c.test.args;
        for (Slot s : slots_of(args, false)) bound[s] = 1;
        placed[i] = 1;
        order.push_back(i);
        for (std::uint32_t j = i + 1; j < n; ++j)
            if (plan.repeat_of[j] == i) {
                placed[j] = 1;
                order.push_back(j);
            }
    };
    if (seed) place(*seed);
    while (order.size() < n) {
        std::optional<std::uint32_t> ready_test, indexed, evaluable;
        for (std::uint32_t i = 0; i < n && !ready_test; ++i) {
            if (placed[i]) continue;
            const CompiledCondition& c = rule.conditions[i];
            if (c.kind == CompiledCondition::Kind::test) {
                std::span<const CompiledTerm> args = c.test.args;
                if (binds_left[i]) args = args.subspan(1);
                if (all_bound(slots_of(args, false))) ready_test = i;
                continue;
            }
            if (!all_bound(slots_of(c.atom.args, true))) continue;
            if (!evaluable) evaluable = i;
            bool ground = std::any_of(c.atom.args.begin(), c.atom.args.end(), [&](const CompiledTerm& t) {
                return t.kind == CompiledTerm::Kind::constant || (t.kind == CompiledTerm::Kind::variable && bound[t.slot]);
            });
            if (ground && !indexed) indexed = i;
        }
        auto next = ready_test ? ready_test : indexed ? indexed : evaluable;
        if (!next) return {};  // cannot happen for a checked rule; match as written
        place(*next);
    }
    std::vector<std::uint32_t> written;
    for (std::uint32_t i = 0; i < n; ++i) written.push_back(i);
    std::vector<std::uint32_t> without_seed = order;
    if (seed) {
        std::erase(without_seed, *seed);
        std::erase(written, *seed);
    }
    return without_seed == written ? std::vector<std::uint32_t>{} : order;
}

// Per test condition: 1 if it is `(= ?x TERM)`-shaped with ?x not bound by the conditions written
// before it, so that it binds ?x there (the checker lets only `=` do that).
std::vector<std::uint8_t> binding_tests(const CompiledRule& rule, std::uint32_t prefix) {
    std::vector<std::uint8_t> bound(rule.slot_count(), 0), binds(prefix, 0);
    for (std::uint32_t i = 0; i < prefix; ++i) {
        const CompiledCondition& c = rule.conditions[i];
        const auto& args = c.kind == CompiledCondition::Kind::match ? c.atom.args : c.test.args;
        if (c.kind == CompiledCondition::Kind::test && args.size() == 2 && args[0].kind == CompiledTerm::Kind::variable &&
            !bound[args[0].slot])
            binds[i] = 1;
        for (Slot s : slots_of(args, false)) bound[s] = 1;
    }
    return binds;
}

}  // namespace

MatchPlan plan_matching(const CompiledRule& rule) {
    MatchPlan plan;
    plan.seed_first_safe = seed_first_safety(rule);
    plan.repeat_of.resize(rule.conditions.size());
    std::map<std::vector<std::uint32_t>, std::uint32_t> first;
    for (std::uint32_t i = 0; i < rule.conditions.size(); ++i) {
        auto key = repeat_key(rule.conditions[i]);
        if (!key) continue;
        auto [it, fresh] = first.emplace(std::move(*key), i);
        if (!fresh) {
            plan.repeat_of[i] = it->second;
            plan.has_repeat = true;
        }
    }
    const auto n = static_cast<std::uint32_t>(rule.conditions.size());
    while (plan.prefix < n && (rule.conditions[plan.prefix].kind == CompiledCondition::Kind::match ||
                               rule.conditions[plan.prefix].kind == CompiledCondition::Kind::test))
        ++plan.prefix;
    const auto binds_left = binding_tests(rule, plan.prefix);
    plan.order.resize(n + 1);
    for (std::uint32_t s = 0; s < plan.prefix; ++s)
        if (rule.conditions[s].kind == CompiledCondition::Kind::match && !plan.repeat_of[s])
            plan.order[s] = plan_order(rule, plan, s, binds_left);
    plan.order[n] = plan_order(rule, plan, std::nullopt, binds_left);
    return plan;
}

}  // namespace qm::engine
