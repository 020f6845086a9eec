// tests/engine/match_plan_test.cpp: plan_matching() (engine/match_plan.hpp). Which conditions
// repeat an earlier one, on hand-made rules; which may be seeded first, against the definition
// checked condition by condition (quadratic) on seeded random rules.
#include "compiled_program_builder.hpp"
#include "engine/match_plan.hpp"
#include <doctest/doctest.h>
#include <random>

using namespace qm::engine;
using namespace qm::engine::test;

namespace {

void slots_of(const CompiledTerm& t, std::vector<bool>& out) {
    if (t.kind == CompiledTerm::Kind::variable) out[t.slot] = true;
    for (const auto& a : t.args) slots_of(a, out);
}

// The definition: seeding condition s first is unsafe iff some `not`, aggregate or quantifier
// written before s uses a variable of s's atom that no condition before it has bound.
bool safe_by_definition(const CompiledRule& rule, std::uint32_t s) {
    std::vector<bool> seed(rule.slot_count(), false);
    for (const auto& t : rule.conditions[s].atom.args) slots_of(t, seed);
    std::vector<bool> bound(rule.slot_count(), false);
    for (std::uint32_t i = 0; i < s; ++i) {
        const CompiledCondition& c = rule.conditions[i];
        std::vector<bool> used(rule.slot_count(), false);
        std::vector<bool> binds(rule.slot_count(), false);
        switch (c.kind) {
            case CompiledCondition::Kind::match:
                for (const auto& t : c.atom.args) slots_of(t, binds);
                break;
            case CompiledCondition::Kind::test:
                for (const auto& t : c.test.args) slots_of(t, binds);
                break;
            case CompiledCondition::Kind::negation:
            case CompiledCondition::Kind::aggregate:
                for (const auto& t : c.atom.args) slots_of(t, used);
                if (c.kind == CompiledCondition::Kind::aggregate) binds[c.slot] = true;
                break;
            case CompiledCondition::Kind::for_all:
            case CompiledCondition::Kind::exists:
                for (const auto& a : c.atoms)
                    for (const auto& t : a.args) slots_of(t, used);
                slots_of(c.set, used);
                for (const auto& t : c.tests)
                    for (const auto& x : t.args) slots_of(x, used);
                if (c.kind == CompiledCondition::Kind::exists) binds[c.slot] = true;
                break;
        }
        for (Slot v = 0; v < rule.slot_count(); ++v)
            if (used[v] && seed[v] && !bound[v]) return false;
        for (Slot v = 0; v < rule.slot_count(); ++v) bound[v] = bound[v] || binds[v];
    }
    return true;
}

CompiledCondition quantifier(CompiledCondition::Kind kind, Slot slot, CompiledTerm set, std::vector<CompiledAtom> atoms) {
    CompiledCondition c;
    c.kind = kind;
    c.slot = slot;
    c.set = std::move(set);
    c.atoms = std::move(atoms);
    return c;
}

}  // namespace

TEST_CASE("engine/match_plan: an identical later `match` or test repeats the first; `not` and aggregates never do") {
    ValueTable v;
    const auto& b = default_builtins();
    auto q = [&](Slot x, Slot y) { return atom(v, "q", {var(x), var(y)}); };
    CompiledRule r = rule("r", 3,
                          {match(q(0, 1)), builtin_test(b, "<", {var(0), var(1)}), match(q(1, 0)), match(q(0, 1)),
                           negation(atom(v, "n", {var(2)})), builtin_test(b, "<", {var(0), var(1)}), match(q(0, 1)),
                           negation(atom(v, "n", {var(2)})), match(atom(v, "q", {var(0), constant(v.integer(1))})),
                           builtin_test(b, "<", {var(1), var(0)})},
                          {falsity()});
    MatchPlan p = plan_matching(r);
    REQUIRE(p.repeat_of.size() == r.conditions.size());
    const std::vector<std::optional<std::uint32_t>> expected{std::nullopt, std::nullopt, std::nullopt, 0u, std::nullopt,
                                                             1u, 0u, std::nullopt, std::nullopt, std::nullopt};
    CHECK(p.repeat_of == expected);
}

TEST_CASE("engine/match_plan: a condition may be seeded first exactly when the definition allows it") {
    ValueTable v;
    const auto& b = default_builtins();
    const CompiledTerm set = call(b, "range", {constant(v.integer(1)), constant(v.integer(3))});
    std::mt19937 rng(11);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    std::size_t safe = 0, unsafe = 0;
    for (int round = 0; round < 2000; ++round) {
        const Slot slots = 4;
        auto term = [&] { return pick(0, 5) == 0 ? constant(v.integer(pick(0, 2))) : var(static_cast<Slot>(pick(0, 3))); };
        auto random_atom = [&] { return atom(v, pick(0, 1) ? "p" : "q", {term(), term()}); };
        std::vector<CompiledCondition> when;
        const int n = pick(1, 6);
        for (int k = 0; k < n; ++k) {
            switch (pick(0, 5)) {
                case 0: when.push_back(negation(random_atom())); break;
                case 1:
                    when.push_back(aggregate(random_atom(), term(), *b.find("+"), constant(v.integer(0)),
                                             static_cast<Slot>(pick(0, 3))));
                    break;
                case 2: when.push_back(builtin_test(b, "=", {term(), term()})); break;
                case 3:
                    when.push_back(quantifier(pick(0, 1) ? CompiledCondition::Kind::for_all : CompiledCondition::Kind::exists,
                                              static_cast<Slot>(pick(0, 3)), set, {random_atom()}));
                    break;
                default: when.push_back(match(random_atom())); break;
            }
        }
        CompiledRule r = rule("r", slots, when, {falsity()});
        MatchPlan p = plan_matching(r);
        REQUIRE(p.seed_first_safe.size() == r.conditions.size());
        for (std::uint32_t s = 0; s < r.conditions.size(); ++s) {
            if (r.conditions[s].kind != CompiledCondition::Kind::match) continue;
            CAPTURE(round);
            CAPTURE(s);
            const bool expected = safe_by_definition(r, s);
            CHECK((p.seed_first_safe[s] != 0) == expected);
            (expected ? safe : unsafe) += 1;
        }
    }
    // Both answers occur often enough to mean something.
    CHECK(safe > 500);
    CHECK(unsafe > 200);
}
