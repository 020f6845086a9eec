// tests/engine/matcher_test.cpp: Matcher (engine/matcher.hpp). A prefix matched in the plan's
// order (match_plan.hpp: bound arguments first) must report the same matches, with the same
// bindings and antecedents and in the same order, as the conditions walked as written, which is
// the oracle here: the same rule matched with every planned order taken away. Seeded random rules
// and facts, every seed and unseeded.
#include "compiled_program_builder.hpp"
#include "engine/builtin_registry.hpp"
#include "engine/fact_store.hpp"
#include "engine/match_plan.hpp"
#include "engine/matcher.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <random>

using namespace qm::engine;
using namespace qm::engine::test;

namespace {

struct Answer {
    Binding binding;
    std::vector<FactId> antecedents;
    bool operator==(const Answer&) const = default;
};

std::vector<Answer> answers(const FactStore& facts, ValueTable& values, const CompiledRule& rule, const MatchPlan& plan,
                            std::optional<Seed> seed) {
    ClosedWorld world{[&](FactId f) { return facts.is_active(f) ? ClosedWorldStatus::holds : ClosedWorldStatus::absent; },
                      [](FactId) { return std::string(); }};
    Matcher m(facts, values, default_builtins(), world);
    std::vector<Answer> out;
    m.match(
        rule, plan, seed,
        [&](const Binding& b, std::span<const FactId> ants) { out.push_back({b, {ants.begin(), ants.end()}}); },
        [](const MatchError& e) { FAIL("unexpected match error: " << e.message); });
    return out;
}

}  // namespace

TEST_CASE("engine/matcher: a prefix matched bound-first finds what the written order finds, in its order") {
    std::mt19937 rng(29);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const auto& b = default_builtins();
    std::size_t reordered = 0, compared = 0;
    for (int round = 0; round < 300; ++round) {
        CAPTURE(round);
        ValueTable v;
        FactStore facts;
        const char* predicates[] = {"p", "q", "r"};
        // Facts over a small domain, activated in an order unlike their creation order.
        std::vector<FactId> made;
        for (int k = 0; k < pick(5, 40); ++k) {
            std::vector<ValueId> args{v.integer(pick(0, 4)), v.integer(pick(0, 4))};
            made.push_back(facts.intern(v.symbol(predicates[pick(0, 2)]), args).first);
        }
        std::shuffle(made.begin(), made.end(), rng);
        for (FactId f : made)
            if (pick(0, 5) != 0) facts.activate(f);

        // A rule: matches over up to four variables, tests on bound ones, `=` binding a fresh one,
        // and sometimes a `not` after the prefix.
        const Slot slots = 5;
        std::vector<std::uint8_t> bound(slots, 0);
        auto term = [&] {
            return pick(0, 4) == 0 ? constant(v.integer(pick(0, 4))) : var(static_cast<Slot>(pick(0, 3)));
        };
        std::vector<CompiledCondition> when;
        const int n = pick(1, 5);
        for (int k = 0; k < n; ++k) {
            std::vector<Slot> ready;
            for (Slot s = 0; s < slots; ++s)
                if (bound[s]) ready.push_back(s);
            const int kind = pick(0, 5);
            if (kind == 0 && ready.size() >= 2) {
                when.push_back(builtin_test(b, "<", {var(ready[0]), var(ready.back())}));
            } else if (kind == 1 && !ready.empty() && !bound[4]) {
                when.push_back(builtin_test(b, "=", {var(4), call(b, "+", {var(ready.front()), constant(v.integer(1))})}));
                bound[4] = 1;
            } else {
                CompiledAtom a = atom(v, predicates[pick(0, 2)], {term(), term()});
                for (const auto& t : a.args)
                    if (t.kind == CompiledTerm::Kind::variable) bound[t.slot] = 1;
                when.push_back(match(std::move(a)));
            }
        }
        if (pick(0, 3) == 0) when.push_back(negation(atom(v, "q", {term(), term()})));
        if (when.front().kind != CompiledCondition::Kind::match) continue;
        CompiledRule r = rule("r", slots, when, {falsity()});
        const MatchPlan plan = plan_matching(r);
        MatchPlan written = plan;
        for (auto& o : written.order) o.clear();

        auto compare = [&](std::optional<Seed> seed) {
            const bool planned = !plan.order[seed ? seed->condition : r.conditions.size()].empty();
            reordered += planned ? 1 : 0;
            ++compared;
            CHECK(answers(facts, v, r, plan, seed) == answers(facts, v, r, written, seed));
        };
        compare(std::nullopt);
        for (std::uint32_t s = 0; s < r.conditions.size(); ++s) {
            if (r.conditions[s].kind != CompiledCondition::Kind::match || plan.repeat_of[s]) continue;
            for (FactId f : facts.active_with_predicate(r.conditions[s].atom.predicate)) compare(Seed{s, f});
        }
    }
    // The planned orders are exercised, and so is the written one.
    CHECK(reordered > 200);
    CHECK(compared - reordered > 200);
}

TEST_CASE("engine/matcher: a join seeded at its last condition looks its other conditions up by bound argument") {
    // (state ?a) (state ?b) (place-of ?a ?p) (place-of ?b ?q) (adjacent ?p ?q), seeded at the
    // adjacency: written order scans every state twice (S squared steps); bound first, a handful.
    ValueTable v;
    FactStore facts;
    const int states = 200;
    auto sym = [&](const std::string& s) { return v.symbol(s); };
    for (int i = 0; i < states; ++i) {
        std::vector<ValueId> s{sym("s" + std::to_string(i))};
        facts.activate(facts.intern(sym("state"), s).first);
        std::vector<ValueId> p{sym("s" + std::to_string(i)), sym("p" + std::to_string(i))};
        facts.activate(facts.intern(sym("place-of"), p).first);
    }
    std::vector<ValueId> adj{sym("p3"), sym("p4")};
    const FactId seed = facts.intern(sym("adjacent"), adj).first;
    facts.activate(seed);
    CompiledRule r = rule("next", 4,
                          {match(atom(v, "state", {var(0)})), match(atom(v, "state", {var(1)})),
                           match(atom(v, "place-of", {var(0), var(2)})), match(atom(v, "place-of", {var(1), var(3)})),
                           match(atom(v, "adjacent", {var(2), var(3)}))},
                          {falsity()});
    const MatchPlan plan = plan_matching(r);
    REQUIRE(!plan.order[4].empty());
    CHECK(plan.order[4].front() == 4);
    ClosedWorld world{[](FactId) { return ClosedWorldStatus::absent; }, [](FactId) { return std::string(); }};
    Matcher m(facts, v, default_builtins(), world);
    std::size_t found = 0;
    m.match(r, plan, Seed{4, seed}, [&](const Binding&, std::span<const FactId>) { ++found; }, [](const MatchError&) {});
    CHECK(found == 1);
    CHECK(m.steps() < 10);
}
