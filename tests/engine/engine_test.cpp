// tests/engine/engine_test.cpp: the Engine facade on programs built directly in compiled form.
// Labels of derived facts are checked against a brute-force oracle on seeded random programs
// (every environment over the assumptions, a naive fixpoint per environment), small ones and ones
// with many facts per predicate; firings are counted against the number of distinct satisfying
// bindings; negation and aggregates are checked in both modes; a rule with a condition repeated
// 1,000 times gives the answers of the rule written once.
#include "compiled_program_builder.hpp"
#include "run_rule_text.hpp"
#include "../support/golden.hpp"
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include "engine/run_report.hpp"
#include <doctest/doctest.h>
#include <algorithm>
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

// The size of a random program. The default is small (predicates p, q, r of arity 1 and e of arity
// 2 over the domain {0, 1, 2}); a wide one has many facts per predicate, a ternary predicate t,
// three variables (so repeated arguments such as (t ?v0 ?v2 ?v0) and variables in every position)
// and body atoms repeated (verbatim or with one argument changed), to exercise the argument
// indexes and the matcher's plan.
struct Shape {
    int domain = 3;            // constants 0 .. domain - 1
    int premises = 2;
    int assumptions = 4;
    int slots = 2;             // variables ?v0 .. ?v(slots - 1)
    int max_body = 2;          // atoms per rule body
    bool ternary = false;      // the predicate t of arity 3
    int repeat_percent = 0;    // chance that a body atom repeats an earlier one of its rule (or nearly)
};

Shape wide_shape() {
    Shape s;
    s.domain = 5;
    s.premises = 30;
    s.assumptions = 5;
    s.slots = 3;
    s.max_body = 3;
    s.ternary = true;
    s.repeat_percent = 40;
    return s;
}

// A random monotonic program of the given shape.
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
    Shape shape;
    std::vector<GroundFact> premises, assumptions;
    std::vector<Rule> rules;

    static int arity(const std::string& predicate) { return predicate == "e" ? 2 : predicate == "t" ? 3 : 1; }

    explicit RandomProgram(std::uint32_t seed, Shape sh = {}) : shape(sh) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        const char* preds[] = {"p", "q", "r", "e", "t"};
        const int n_preds = shape.ternary ? 5 : 4;
        auto random_fact = [&] {
            GroundFact f{preds[pick(0, n_preds - 1)], {}};
            for (int a = 0; a < arity(f.predicate); ++a) f.args.push_back(pick(0, shape.domain - 1));
            return f;
        };
        for (int i = 0; i < shape.premises; ++i) premises.push_back(random_fact());
        std::set<GroundFact> seen(premises.begin(), premises.end());
        while (assumptions.size() < static_cast<std::size_t>(shape.assumptions)) {
            auto f = random_fact();
            if (seen.insert(f).second) assumptions.push_back(f);
        }
        int n_rules = pick(3, 7);
        for (int i = 0; i < n_rules; ++i) {
            Rule r;
            int n_body = pick(1, shape.max_body);
            std::set<int> bound;
            for (int k = 0; k < n_body; ++k) {
                if (shape.repeat_percent > 0 && k > 0 && pick(0, 99) < shape.repeat_percent) {
                    // A repeat of an earlier atom: verbatim, or (one time in two) with one argument
                    // replaced by a constant or a variable, which must not be taken for a repeat.
                    Body b = r.body[pick(0, k - 1)];
                    if (pick(0, 1) == 0) {
                        int s = pick(0, 1) == 0 ? -1 - pick(0, shape.domain - 1) : pick(0, shape.slots - 1);
                        if (s >= 0) bound.insert(s);
                        b.slots[static_cast<std::size_t>(pick(0, static_cast<int>(b.slots.size()) - 1))] = s;
                    }
                    r.body.push_back(b);
                    continue;
                }
                Body b{preds[pick(0, n_preds - 1)], {}};
                for (int a = 0; a < arity(b.predicate); ++a) {
                    int s = pick(0, 4) == 0 ? -1 - pick(0, shape.domain - 1) : pick(0, shape.slots - 1);
                    if (s >= 0) bound.insert(s);
                    b.slots.push_back(s);
                }
                r.body.push_back(b);
            }
            r.less_test = bound.count(0) && bound.count(1) && pick(0, 2) == 0;
            if (pick(0, 5) > 0) {
                Body h{preds[pick(0, n_preds - 1)], {}};
                std::vector<int> choices(bound.begin(), bound.end());
                for (int a = 0; a < arity(h.predicate); ++a)
                    h.slots.push_back(choices.empty() || pick(0, 4) == 0 ? -1 - pick(0, shape.domain - 1)
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
            p.rules.push_back(rule(name, static_cast<std::uint32_t>(shape.slots), when, then));
        }
        return p;
    }

    // Calls f(values) for every assignment of the variables over the domain.
    template <class F>
    void for_each_assignment(F&& f) const {
        std::vector<int> values(static_cast<std::size_t>(shape.slots), 0);
        for (;;) {
            f(values);
            std::size_t k = 0;
            while (k < values.size() && ++values[k] == shape.domain) values[k++] = 0;
            if (k == values.size()) return;
        }
    }

    // A ground fact as a dense number (predicate, then arguments in base domain), so that the
    // oracle's membership tests are array look-ups (it runs for every environment of every seed).
    [[nodiscard]] std::size_t code(const std::string& predicate, const std::vector<int>& args) const {
        static const std::string names[] = {"p", "q", "r", "e", "t"};
        std::size_t k = static_cast<std::size_t>(std::find(std::begin(names), std::end(names), predicate) - std::begin(names));
        for (int a : args) k = k * static_cast<std::size_t>(shape.domain) + static_cast<std::size_t>(a);
        return k * 4 + args.size();  // the arity keeps codes of different arities apart
    }

    // Naive fixpoint from premises + the assumptions in mask; returns (facts, inconsistent).
    std::pair<std::set<GroundFact>, bool> closure(unsigned mask) const {
        std::set<GroundFact> facts(premises.begin(), premises.end());
        for (std::size_t i = 0; i < assumptions.size(); ++i)
            if (mask & (1u << i)) facts.insert(assumptions[i]);
        // Codes are below 4 * 5 * domain^3 (five predicates of arity at most 3).
        std::vector<char> holds(20 * static_cast<std::size_t>(shape.domain * shape.domain * shape.domain), 0);
        for (const auto& f : facts) holds[code(f.predicate, f.args)] = 1;
        bool inconsistent = false;
        std::vector<int> args;
        for (bool changed = true; changed;) {
            changed = false;
            for (const auto& r : rules)
                for_each_assignment([&](const std::vector<int>& vs) {
                    auto ground_of = [&](const Body& b) {
                        args.clear();
                        for (int s : b.slots) args.push_back(s >= 0 ? vs[static_cast<std::size_t>(s)] : -1 - s);
                        return code(b.predicate, args);
                    };
                    if (r.less_test && !(vs[0] < vs[1])) return;
                    for (const auto& b : r.body)
                        if (!holds[ground_of(b)]) return;
                    if (!r.head) {
                        inconsistent = true;
                        return;
                    }
                    const std::size_t k = ground_of(*r.head);
                    if (holds[k]) return;
                    holds[k] = 1;
                    facts.insert(GroundFact{r.head->predicate, args});
                    changed = true;
                });
        }
        return {facts, inconsistent};
    }
};

}  // namespace

namespace {
// Runs rp and checks every label and the minimal nogoods against the naive closure of every
// environment over its assumptions.
void check_labels(const RandomProgram& rp) {
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
}  // namespace

TEST_CASE("engine/engine: labels and nogoods equal a brute-force evaluation of random programs") {
    for (std::uint32_t seed = 1; seed <= 300; ++seed) {
        CAPTURE(seed);
        check_labels(RandomProgram(seed));
    }
}

TEST_CASE("engine/engine: labels and nogoods equal brute force on programs with many facts per predicate") {
    // 30 premises and 5 assumptions over 5 predicates (one ternary) and the domain 0..4, rules of up
    // to 3 atoms (some repeated verbatim) over 3 variables: joins go through the argument indexes
    // with variables in every position, repeated arguments and constants.
    for (std::uint32_t seed = 1; seed <= 150; ++seed) {
        CAPTURE(seed);
        check_labels(RandomProgram(seed, wide_shape()));
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

namespace {
// The closed-world rules added to a random program in stratum 1: s(x) <- p(x), not q(x); with
// `more`, also u(x, y) <- e(x, y), not e(y, x); w(x) <- q(x), not t(x, ?y, x) (a local variable
// between two bound positions); cnt(x, n) <- p(x), n = the number of e(x, ?y) that hold;
// p2(x) <- s(x) and z(x) <- not q(?x), p2(x): ?x is local to the `not` (no q holds at all), and
// p2's facts arrive while stratum 1 runs, so z is matched from them as seeds, which must not bind
// ?x ahead of the `not`.
void add_closed_world_rules(CompiledProgram& program, ValueTable& v, bool more) {
    program.rules.push_back(rule("s-rule", 1, {match(atom(v, "p", {var(0)})), negation(atom(v, "q", {var(0)}))},
                                 {assert_atom(atom(v, "s", {var(0)}))}, 1));
    if (more) {
        program.rules.push_back(rule("u-rule", 2,
                                     {match(atom(v, "e", {var(0), var(1)})), negation(atom(v, "e", {var(1), var(0)}))},
                                     {assert_atom(atom(v, "u", {var(0), var(1)}))}, 1));
        program.rules.push_back(rule("w-rule", 2,
                                     {match(atom(v, "q", {var(0)})), negation(atom(v, "t", {var(0), var(1), var(0)}))},
                                     {assert_atom(atom(v, "w", {var(0)}))}, 1));
        program.rules.push_back(rule("cnt-rule", 3,
                                     {match(atom(v, "p", {var(0)})),
                                      aggregate(atom(v, "e", {var(0), var(1)}), constant(v.integer(1)),
                                                *default_builtins().find("+"), constant(v.integer(0)), 2)},
                                     {assert_atom(atom(v, "cnt", {var(0), var(2)}))}, 1));
        program.rules.push_back(
            rule("p2-rule", 1, {match(atom(v, "s", {var(0)}))}, {assert_atom(atom(v, "p2", {var(0)}))}, 1));
        program.rules.push_back(rule("z-rule", 1, {negation(atom(v, "q", {var(0)})), match(atom(v, "p2", {var(0)}))},
                                     {assert_atom(atom(v, "z", {var(0)}))}, 1));
    }
    program.stratum_count = 2;
}

// Whether (predicate args...) holds in env.
bool holds(Engine& engine, const std::string& predicate, std::vector<int> args, qm::atms::EnvId env) {
    std::vector<ValueId> values;
    for (int a : args) values.push_back(engine.values().integer(a));
    auto f = engine.find(engine.values().symbol(predicate), values);
    return f && engine.atms().holds_in(engine.node(*f), env);
}

// For every context C (a set of the program's assumptions): each closed-world rule's conclusion
// holds in C + {closed world of C} iff its body holds in the naive closure of premises + C (when
// that closure is consistent), and the closed world of C excludes every assumption outside C.
void check_closed_world(const RandomProgram& rp, bool more) {
    ValueTable v;
    CompiledProgram program = rp.compile(v);
    add_closed_world_rules(program, v, more);
    Engine engine(std::move(program), std::move(v));
    std::vector<qm::atms::AssumptionId> assumption_of;
    for (const auto& a : rp.assumptions) {
        std::vector<ValueId> args;
        for (int x : a.args) args.push_back(engine.values().integer(x));
        assumption_of.push_back(*engine.assumption(*engine.find(engine.values().symbol(a.predicate), args)));
    }
    const int domain = rp.shape.domain;
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
        auto in = [&](const std::string& p, std::vector<int> args) { return facts.count(GroundFact{p, std::move(args)}) > 0; };
        bool no_q = true;
        for (int y = 0; y < domain; ++y) no_q = no_q && !in("q", {y});
        for (int x = 0; x < domain; ++x) {
            CAPTURE(x);
            CHECK(holds(engine, "s", {x}, ctx.environment) == (!inconsistent && in("p", {x}) && !in("q", {x})));
            if (!more) continue;
            bool some_t = false;
            int count = 0;
            for (int y = 0; y < domain; ++y) {
                CAPTURE(y);
                some_t = some_t || in("t", {x, y, x});
                count += in("e", {x, y}) ? 1 : 0;
                CHECK(holds(engine, "u", {x, y}, ctx.environment) == (!inconsistent && in("e", {x, y}) && !in("e", {y, x})));
            }
            CHECK(holds(engine, "w", {x}, ctx.environment) == (!inconsistent && in("q", {x}) && !some_t));
            CHECK(holds(engine, "z", {x}, ctx.environment) == (!inconsistent && in("p", {x}) && no_q));
            for (int c = 0; c <= domain; ++c)
                CHECK(holds(engine, "cnt", {x, c}, ctx.environment) == (!inconsistent && in("p", {x}) && c == count));
        }
        for (std::size_t i = 0; i < rp.assumptions.size(); ++i)
            if (!(mask & (1u << i)))
                CHECK(!engine.atms().is_consistent(engine.atms().environment({ctx.closed_world, assumption_of[i]})));
    }
}
}  // namespace

TEST_CASE("engine/engine: `not` in every context equals a brute-force closed-world evaluation") {
    // Random monotonic stratum 0 as above, plus s(x) <- p(x), not q(x) in stratum 1.
    for (std::uint32_t seed = 1; seed <= 60; ++seed) {
        CAPTURE(seed);
        check_closed_world(RandomProgram(seed), false);
    }
}

TEST_CASE("engine/engine: `not` and aggregates over many facts per predicate equal brute force in every context") {
    // The wide programs, with `not` and an aggregate looked up through the index of all facts by a
    // bound first argument, a bound second, and first and third bound around a local variable.
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        CAPTURE(seed);
        check_closed_world(RandomProgram(seed, wide_shape()), true);
    }
}

namespace {
// The report of a rule program given as text.
RunReport report_of(const std::string& text) { return make_report(*run_rule_text(text, "repeated.rules")); }
std::vector<std::pair<std::string, std::vector<EnvText>>> fact_lines(const RunReport& r) {
    std::vector<std::pair<std::string, std::vector<EnvText>>> out;
    for (const auto& f : r.facts) out.emplace_back(f.fact, f.label);
    return out;
}
}  // namespace

TEST_CASE("engine/engine: a condition repeated 1,000 times gives the answers of the rule written once") {
    const std::string queens6 = qm::test::slurp(std::string(QM_SOURCE_DIR) + "/scenarios/rules/queens6.rules");
    const RunReport once = report_of(queens6);
    REQUIRE(once.interpretations.size() == 4);
    // Each repeated condition in turn: a match of bound variables, a match that binds new
    // variables, and a test.
    const std::string column = "  when (queen ?r1 ?c) (queen ?r2 ?c) (< ?r1 ?r2)\n";
    const std::string diagonal = "  when (queen ?r1 ?c1) (queen ?r2 ?c2) (< ?r1 ?r2)\n";
    REQUIRE(queens6.find(column) != std::string::npos);
    REQUIRE(queens6.find(diagonal) != std::string::npos);
    for (const auto& [line, repeated] : {std::pair{diagonal, std::string("(queen ?r2 ?c2) ")},
                                         std::pair{column, std::string("(queen ?r3 ?c3) ")},
                                         std::pair{diagonal, std::string("(< ?r1 ?r2) ")}}) {
        CAPTURE(repeated);
        std::string many = line.substr(0, line.size() - 1);
        for (int i = 0; i < 1000; ++i) many += " " + repeated;
        std::string program = queens6;
        program.replace(program.find(line), line.size(), many + "\n");
        const RunReport r = report_of(program);
        // (queen ?r3 ?c3) adds no fact: every fact, label, nogood and interpretation is the same.
        CHECK(fact_lines(r) == fact_lines(once));
        CHECK(r.nogoods == once.nogoods);
        CHECK(r.interpretations == once.interpretations);
    }
}
