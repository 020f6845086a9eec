// tests/engine/engine_test.cpp: the Engine facade on programs built directly in compiled form.
// Labels of derived facts are checked against a brute-force oracle on seeded random programs
// (every environment over the assumptions, a naive fixpoint per environment); firings are counted
// against the number of distinct satisfying bindings; negation is checked in both modes.
#include "compiled_program_builder.hpp"
#include "engine/engine.hpp"
#include <doctest/doctest.h>
#include <map>
#include <random>
#include <set>

using namespace qm::engine;
using namespace qm::engine::test;
using EnvSet = std::set<std::set<std::string>>;

namespace {

EnvSet label_text(const Engine& e, const std::vector<qm::atms::EnvId>& envs) {
    EnvSet out;
    for (auto env : envs) {
        std::set<std::string> s;
        for (auto a : e.atms().env(env).assumptions()) s.insert(e.print(a));
        out.insert(s);
    }
    return out;
}

EnvSet minimal(const std::vector<std::set<std::string>>& sets) {
    EnvSet out;
    for (const auto& s : sets) {
        bool dominated = false;
        for (const auto& t : sets)
            if (t != s && std::includes(s.begin(), s.end(), t.begin(), t.end())) dominated = true;
        if (!dominated) out.insert(s);
    }
    return out;
}

struct GroundFact {
    std::string predicate;
    std::vector<int> args;
    bool operator<(const GroundFact& o) const { return std::tie(predicate, args) < std::tie(o.predicate, o.args); }
    std::string text() const {
        // Appends only: GCC 12 -O3 reports a false -Wrestrict on `" " + std::to_string(a)`.
        std::string s = "(";
        s += predicate;
        for (int a : args) {
            s += ' ';
            s += std::to_string(a);
        }
        s += ')';
        return s;
    }
};

// A random monotonic program over predicates p, q, r (arity 1) and e (arity 2), domain {0, 1, 2}.
struct RandomProgram {
    struct Body {
        std::string predicate;
        std::vector<int> slots;  // -1 - k means the constant k
    };
    struct Rule {
        std::vector<Body> body;
        bool less_test = false;  // (< ?v0 ?v1)
        std::optional<Body> head;  // empty: false
    };
    std::vector<GroundFact> premises, assumptions;
    std::vector<Rule> rules;

    explicit RandomProgram(std::uint32_t seed) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        const char* preds[] = {"p", "q", "r", "e"};
        auto random_fact = [&] {
            GroundFact f{preds[pick(0, 3)], {}};
            f.args.push_back(pick(0, 2));
            if (f.predicate == "e") f.args.push_back(pick(0, 2));
            return f;
        };
        for (int i = 0; i < 2; ++i) premises.push_back(random_fact());
        std::set<GroundFact> seen(premises.begin(), premises.end());
        while (assumptions.size() < 4) {
            auto f = random_fact();
            if (seen.insert(f).second) assumptions.push_back(f);
        }
        int n_rules = pick(3, 7);
        for (int i = 0; i < n_rules; ++i) {
            Rule r;
            int n_body = pick(1, 2);
            std::set<int> bound;
            for (int k = 0; k < n_body; ++k) {
                Body b{preds[pick(0, 3)], {}};
                int arity = b.predicate == "e" ? 2 : 1;
                for (int a = 0; a < arity; ++a) {
                    int s = pick(0, 4) == 0 ? -1 - pick(0, 2) : pick(0, 1);
                    if (s >= 0) bound.insert(s);
                    b.slots.push_back(s);
                }
                r.body.push_back(b);
            }
            r.less_test = bound.count(0) && bound.count(1) && pick(0, 2) == 0;
            if (pick(0, 5) > 0) {
                Body h{preds[pick(0, 3)], {}};
                int arity = h.predicate == "e" ? 2 : 1;
                std::vector<int> choices(bound.begin(), bound.end());
                for (int a = 0; a < arity; ++a)
                    h.slots.push_back(choices.empty() || pick(0, 4) == 0 ? -1 - pick(0, 2)
                                                                         : choices[pick(0, (int)choices.size() - 1)]);
                r.head = h;
            }
            rules.push_back(r);
        }
    }

    CompiledProgram compile(ValueTable& v) const {
        CompiledProgram p;
        auto ints = [&](const std::vector<int>& xs) {
            std::vector<ValueId> out;
            for (int x : xs) out.push_back(v.integer(x));
            return out;
        };
        auto term = [&](int s) { return s >= 0 ? var(static_cast<Slot>(s)) : constant(v.integer(-1 - s)); };
        auto to_atom = [&](const Body& b) {
            std::vector<CompiledTerm> args;
            for (int s : b.slots) args.push_back(term(s));
            return atom(v, b.predicate, args);
        };
        for (const auto& f : premises) p.premises.push_back(ground(v, f.predicate, ints(f.args)));
        for (const auto& f : assumptions) p.assumptions.push_back(ground(v, f.predicate, ints(f.args)));
        for (std::size_t i = 0; i < rules.size(); ++i) {
            const Rule& r = rules[i];
            std::vector<CompiledCondition> when;
            for (const auto& b : r.body) when.push_back(match(to_atom(b)));
            if (r.less_test) when.push_back(builtin_test(default_builtins(), "<", {var(0), var(1)}));
            std::vector<CompiledConsequent> then;
            then.push_back(r.head ? assert_atom(to_atom(*r.head)) : falsity());
            std::string name = "r";
            name += std::to_string(i);
            p.rules.push_back(rule(name, 2, when, then));
        }
        return p;
    }

    // Naive fixpoint from premises + the assumptions in mask; returns (facts, inconsistent).
    std::pair<std::set<GroundFact>, bool> closure(unsigned mask) const {
        std::set<GroundFact> facts(premises.begin(), premises.end());
        for (std::size_t i = 0; i < assumptions.size(); ++i)
            if (mask & (1u << i)) facts.insert(assumptions[i]);
        bool inconsistent = false;
        for (bool changed = true; changed;) {
            changed = false;
            for (const auto& r : rules)
                for (int v0 = 0; v0 < 3; ++v0)
                    for (int v1 = 0; v1 < 3; ++v1) {
                        auto val = [&](int s) { return s >= 0 ? (s == 0 ? v0 : v1) : -1 - s; };
                        auto ground_of = [&](const Body& b) {
                            GroundFact g{b.predicate, {}};
                            for (int s : b.slots) g.args.push_back(val(s));
                            return g;
                        };
                        bool ok = !r.less_test || v0 < v1;
                        for (const auto& b : r.body) ok = ok && facts.count(ground_of(b));
                        if (!ok) continue;
                        if (!r.head) inconsistent = true;
                        else if (facts.insert(ground_of(*r.head)).second) changed = true;
                    }
        }
        return {facts, inconsistent};
    }
};

}  // namespace

TEST_CASE("engine/engine: labels and nogoods equal a brute-force evaluation of random programs") {
    for (std::uint32_t seed = 1; seed <= 300; ++seed) {
        CAPTURE(seed);
        RandomProgram rp(seed);
        ValueTable v;
        CompiledProgram program = rp.compile(v);
        Engine engine(std::move(program), std::move(v));
        qm::Diagnostics d;
        engine.run(d);
        REQUIRE(!d.has_errors());

        unsigned n = 1u << rp.assumptions.size();
        std::vector<std::set<std::string>> nogood_sets;
        std::map<std::string, std::vector<std::set<std::string>>> holds_in;
        std::vector<std::pair<std::set<GroundFact>, bool>> closures;
        for (unsigned mask = 0; mask < n; ++mask) closures.push_back(rp.closure(mask));
        for (unsigned mask = 0; mask < n; ++mask) {
            std::set<std::string> env;
            for (std::size_t i = 0; i < rp.assumptions.size(); ++i)
                if (mask & (1u << i)) env.insert(rp.assumptions[i].text());
            if (closures[mask].second) {
                nogood_sets.push_back(env);
                continue;
            }
            for (const auto& f : closures[mask].first) holds_in[f.text()].push_back(env);
        }
        EnvSet expected_nogoods = minimal(nogood_sets);
        CHECK(label_text(engine, engine.atms().minimal_nogoods()) == expected_nogoods);

        // Every fact the engine knows has the oracle's label, and every fact the oracle derives is known.
        std::set<std::string> known;
        for (std::uint32_t i = 0; i < engine.facts().size(); ++i) {
            FactId f{i};
            std::string text = engine.print(f);
            known.insert(text);
            auto it = holds_in.find(text);
            EnvSet expected = it == holds_in.end() ? EnvSet{} : minimal(it->second);
            CAPTURE(text);
            CHECK(label_text(engine, engine.label(f)) == expected);
        }
        for (const auto& [text, envs] : holds_in) CHECK(known.count(text) == 1);
    }
}

TEST_CASE("engine/engine: a rule fires exactly once per satisfying binding") {
    // path(x, z) <- edge(x, y), path(y, z); path(x, y) <- edge(x, y), on a random graph whose
    // edges are assumptions: firings must equal the number of distinct satisfying bindings in the
    // final fact set (every edge and path fact is consistent here, so all become active).
    std::mt19937 rng(7);
    ValueTable v;
    CompiledProgram p;
    std::set<std::pair<int, int>> edges;
    for (int i = 0; i < 14; ++i) edges.insert({int(rng() % 6), int(rng() % 6)});
    for (auto [a, b] : edges) p.assumptions.push_back(ground(v, "edge", {v.integer(a), v.integer(b)}));
    p.rules.push_back(rule("base", 2, {match(atom(v, "edge", {var(0), var(1)}))},
                           {assert_atom(atom(v, "path", {var(0), var(1)}))}));
    p.rules.push_back(rule("step", 3,
                           {match(atom(v, "edge", {var(0), var(1)})), match(atom(v, "path", {var(1), var(2)}))},
                           {assert_atom(atom(v, "path", {var(0), var(2)}))}));
    Engine engine(std::move(p), std::move(v));
    qm::Diagnostics d;
    engine.run(d);
    engine.run(d);  // a second run finds nothing new
    REQUIRE(!d.has_errors());
    std::set<std::pair<int, int>> path(edges.begin(), edges.end());
    for (bool changed = true; changed;) {
        changed = false;
        for (auto [a, b] : edges)
            for (int c = 0; c < 6; ++c)
                if (path.count({b, c}) && path.insert({a, c}).second) changed = true;
    }
    std::size_t bindings = edges.size();
    for (auto [a, b] : edges)
        for (int c = 0; c < 6; ++c) bindings += path.count({b, c});
    CHECK(engine.rule_firings() == bindings);
    CHECK(engine.facts_of(engine.values().symbol("path")).size() == path.size());
}

TEST_CASE("engine/engine: `not` in every context equals a brute-force closed-world evaluation") {
    // Random monotonic stratum 0 as above, plus s(x) <- p(x), not q(x) in stratum 1. For every
    // context C (a set of the program's assumptions): s(x) holds in C + {closed world of C} iff
    // p(x) and not q(x) in the naive closure of premises + C (when that closure is consistent).
    for (std::uint32_t seed = 1; seed <= 60; ++seed) {
        CAPTURE(seed);
        RandomProgram rp(seed);
        ValueTable v;
        CompiledProgram program = rp.compile(v);
        program.rules.push_back(rule("s-rule", 1,
                                     {match(atom(v, "p", {var(0)})), negation(atom(v, "q", {var(0)}))},
                                     {assert_atom(atom(v, "s", {var(0)}))}, 1));
        program.stratum_count = 2;
        Engine engine(std::move(program), std::move(v));
        std::vector<qm::atms::AssumptionId> assumption_of;
        for (const auto& a : rp.assumptions) {
            std::vector<ValueId> args;
            for (int x : a.args) args.push_back(engine.values().integer(x));
            assumption_of.push_back(*engine.assumption(*engine.find(engine.values().symbol(a.predicate), args)));
        }
        unsigned n = 1u << rp.assumptions.size();
        for (unsigned mask = 0; mask < n; ++mask) {
            CAPTURE(mask);
            std::vector<qm::atms::AssumptionId> members;
            for (std::size_t i = 0; i < rp.assumptions.size(); ++i)
                if (mask & (1u << i)) members.push_back(assumption_of[i]);
            qm::Diagnostics d;
            ContextRun ctx = engine.run_in_context(engine.atms().environment(members), d);
            REQUIRE(!d.has_errors());
            auto [facts, inconsistent] = rp.closure(mask);
            for (int x = 0; x < 3; ++x) {
                bool expected = !inconsistent && facts.count(GroundFact{"p", {x}}) && !facts.count(GroundFact{"q", {x}});
                ValueId arg = engine.values().integer(x);
                auto s = engine.find(engine.values().symbol("s"), std::span<const ValueId>(&arg, 1));
                bool holds = s && engine.atms().holds_in(engine.node(*s), ctx.environment);
                CAPTURE(x);
                CHECK(holds == expected);
            }
            // The closed world of C excludes every assumption outside C.
            for (std::size_t i = 0; i < rp.assumptions.size(); ++i)
                if (!(mask & (1u << i)))
                    CHECK(!engine.atms().is_consistent(engine.atms().environment({ctx.closed_world, assumption_of[i]})));
        }
    }
}
