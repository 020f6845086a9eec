// tests/atms/atms_test.cpp: the Atms facade on de Kleer-style worked examples, and one case for
// every precondition (each must be a clear qm::InternalError, never UB).
#include "atms/atms.hpp"
#include "qm/limit_reached.hpp"

#include <doctest/doctest.h>
#include <algorithm>

using namespace qm::atms;

namespace {
struct Abc {
    Atms atms;
    NodeId a = atms.add_assumption(DatumId{10});
    NodeId b = atms.add_assumption(DatumId{11});
    NodeId c = atms.add_assumption(DatumId{12});
    AssumptionId aa = *atms.assumption_of(a), ab = *atms.assumption_of(b), ac = *atms.assumption_of(c);
    EnvId env(std::initializer_list<AssumptionId> as) { return atms.environment(as); }
};
}  // namespace

TEST_CASE("atms/atms: nodes, premises and assumptions start with the right labels") {
    Atms atms;
    CHECK(atms.node_count() == 1);  // the contradiction node
    CHECK(atms.label(atms.contradiction()).empty());
    const NodeId p = atms.add_premise(DatumId{7});
    const NodeId a = atms.add_assumption(DatumId{8});
    const NodeId x = atms.add_node(DatumId{9});
    CHECK(atms.datum(p) == DatumId{7});
    CHECK(atms.is_premise(p));
    CHECK_FALSE(atms.is_premise(a));
    CHECK(atms.label(p) == std::vector<EnvId>{atms.empty_environment()});
    CHECK(atms.is_true(p));
    REQUIRE(atms.assumption_of(a).has_value());
    CHECK(atms.node_of(*atms.assumption_of(a)) == a);
    CHECK_FALSE(atms.assumption_of(x).has_value());
    CHECK(atms.label(a) == std::vector<EnvId>{atms.environment({*atms.assumption_of(a)})});
    CHECK_FALSE(atms.is_true(a));
    CHECK(atms.is_in(a));
    CHECK(atms.label(x).empty());
    CHECK_FALSE(atms.is_in(x));
}

TEST_CASE("atms/atms: the classic A, B, C example with nogood {A,B}") {
    Abc t;
    Atms& atms = t.atms;
    const NodeId x = atms.add_node(DatumId{0}), y = atms.add_node(DatumId{0}), z = atms.add_node(DatumId{0});
    atms.justify(InformantId{1}, {t.a, t.b}, x);  // A ∧ B → x
    atms.justify(InformantId{2}, {t.b, t.c}, y);  // B ∧ C → y
    atms.justify(InformantId{3}, {x}, z);         // x → z
    atms.justify(InformantId{4}, {y}, z);         // y → z
    const EnvId ab = t.env({t.aa, t.ab}), bc = t.env({t.ab, t.ac}), abc = t.env({t.aa, t.ab, t.ac});
    CHECK(atms.label(x) == std::vector<EnvId>{ab});
    auto zl = std::vector<EnvId>{ab, bc};
    std::sort(zl.begin(), zl.end());
    CHECK(atms.label(z) == zl);
    CHECK(atms.holds_in(z, abc));
    CHECK_FALSE(atms.holds_in(z, t.env({t.aa, t.ac})));
    atms.add_nogood(InformantId{5}, {t.a, t.b});
    CHECK(atms.minimal_nogoods() == std::vector<EnvId>{ab});
    CHECK_FALSE(atms.is_consistent(ab));
    CHECK_FALSE(atms.is_consistent(abc));
    CHECK(atms.is_consistent(bc));
    CHECK(atms.label(x).empty());
    CHECK(atms.label(z) == std::vector<EnvId>{bc});
    CHECK_FALSE(atms.holds_in(z, abc));  // derivable there, but abc is inconsistent
    // A smaller nogood retires the larger one.
    atms.add_nogood(InformantId{6}, {t.b});
    CHECK(atms.minimal_nogoods() == std::vector<EnvId>{t.env({t.ab})});
    CHECK(atms.label(z).empty());
    CHECK(atms.label(t.b).empty());
    CHECK(atms.label(t.a) == std::vector<EnvId>{t.env({t.aa})});
}

// de Kleer's worked examples as Forbus and de Kleer run them in Building Problem Solvers
// (atest.lisp: atms-test1..3, and "an example from de Kleer's paper"); the expected labels are
// worked out by hand here from the definitions.
TEST_CASE("atms/atms: de Kleer's A, B, C chain: d <- a b, e <- b c, f <- d e; a simpler d; nogood {A, B}") {
    Abc t;
    Atms& atms = t.atms;
    const NodeId d = atms.add_node(DatumId{0}), e = atms.add_node(DatumId{0}), f = atms.add_node(DatumId{0});
    atms.justify(InformantId{1}, {t.a, t.b}, d);  // J1
    atms.justify(InformantId{2}, {t.b, t.c}, e);  // J2
    atms.justify(InformantId{3}, {d, e}, f);      // J3
    const EnvId A = t.env({t.aa}), AB = t.env({t.aa, t.ab}), BC = t.env({t.ab, t.ac}), ABC = t.env({t.aa, t.ab, t.ac});
    CHECK(atms.label(d) == std::vector<EnvId>{AB});
    CHECK(atms.label(e) == std::vector<EnvId>{BC});
    CHECK(atms.label(f) == std::vector<EnvId>{ABC});
    // f's explanation in {A,B,C}: J1 and J2 (in some order), then J3.
    const Explanation why = atms.explain(f, ABC);
    REQUIRE(why.steps.size() == 3);
    CHECK(atms.justification(why.steps[2]).informant == InformantId{3});
    CHECK(why.assumptions == std::vector<AssumptionId>{t.aa, t.ab, t.ac});
    // atms-test2: a simpler justification of d replaces {A,B} by {A}; f still needs B and C.
    atms.justify(InformantId{4}, {t.a}, d);
    CHECK(atms.label(d) == std::vector<EnvId>{A});
    CHECK(atms.label(f) == std::vector<EnvId>{ABC});
    // atms-test3: {A,B} is nogood, so f (which needs A, B and C) holds nowhere; d and e survive.
    atms.add_nogood(InformantId{5}, {t.a, t.b});
    CHECK(atms.label(d) == std::vector<EnvId>{A});
    CHECK(atms.label(e) == std::vector<EnvId>{BC});
    CHECK(atms.label(f).empty());
    CHECK(atms.minimal_nogoods() == std::vector<EnvId>{AB});
    CHECK_FALSE(atms.is_consistent(ABC));
}

TEST_CASE("atms/atms: de Kleer's x=1, y=x, x=z example, step by step") {
    Abc t;  // A: x=1, B: y=x, C: x=z
    Atms& atms = t.atms;
    const NodeId x1 = atms.add_node(DatumId{1}), yx = atms.add_node(DatumId{2}), xz = atms.add_node(DatumId{3});
    const NodeId y1 = atms.add_node(DatumId{4}), z1 = atms.add_node(DatumId{5});
    atms.justify(InformantId{1}, {t.a}, x1);
    atms.justify(InformantId{2}, {t.b}, yx);
    atms.justify(InformantId{3}, {t.c}, xz);
    const EnvId A = t.env({t.aa}), B = t.env({t.ab}), C = t.env({t.ac});
    const EnvId AB = t.env({t.aa, t.ab}), BC = t.env({t.ab, t.ac});
    CHECK(atms.label(x1) == std::vector<EnvId>{A});
    CHECK(atms.label(yx) == std::vector<EnvId>{B});
    CHECK(atms.label(xz) == std::vector<EnvId>{C});
    atms.add_nogood(InformantId{9}, {t.a, t.b});  // register nogood {A,B}
    CHECK(atms.minimal_nogoods() == std::vector<EnvId>{AB});
    // x=1, y=x => y=1: its only support {A,B} is nogood.
    atms.justify(InformantId{4}, {x1, yx}, y1);
    CHECK(atms.label(y1).empty());
    CHECK_FALSE(atms.is_in(y1));
    // z=1 is given (a justification with no antecedents): it holds in {}.
    atms.justify(InformantId{5}, std::span<const NodeId>{}, z1);
    CHECK(atms.label(z1) == std::vector<EnvId>{atms.empty_environment()});
    CHECK(atms.is_true(z1));
    // z=1, x=z => x=1: now x=1 holds under A or under C, and so y=1 under {B,C}.
    atms.justify(InformantId{6}, {z1, xz}, x1);
    auto x1_label = std::vector<EnvId>{A, C};
    std::sort(x1_label.begin(), x1_label.end());
    CHECK(atms.label(x1) == x1_label);
    CHECK(atms.label(y1) == std::vector<EnvId>{BC});
    CHECK(atms.holds_in(y1, BC));
    CHECK_FALSE(atms.holds_in(y1, B));
    CHECK_FALSE(atms.holds_in(y1, t.env({t.aa, t.ab, t.ac})));  // inconsistent
}

TEST_CASE("atms/atms: a label is kept minimal when a smaller support arrives") {
    Abc t;
    const NodeId x = t.atms.add_node(DatumId{0});
    t.atms.justify(InformantId{0}, {t.a, t.b}, x);
    t.atms.justify(InformantId{0}, {t.a}, x);
    CHECK(t.atms.label(x) == std::vector<EnvId>{t.env({t.aa})});
    const NodeId p = t.atms.add_premise(DatumId{0});
    t.atms.justify(InformantId{0}, {p}, x);
    CHECK(t.atms.label(x) == std::vector<EnvId>{t.atms.empty_environment()});
    CHECK(t.atms.is_true(x));
}

TEST_CASE("atms/atms: justifying an assumption widens its label (de Kleer allows it)") {
    Abc t;
    t.atms.justify(InformantId{0}, {t.b}, t.a);  // B → A
    auto expected = std::vector<EnvId>{t.env({t.aa}), t.env({t.ab})};
    std::sort(expected.begin(), expected.end());
    CHECK(t.atms.label(t.a) == expected);
}

TEST_CASE("atms/atms: nogoods through derived nodes, and chains through justifications") {
    Abc t;
    Atms& atms = t.atms;
    const NodeId x = atms.add_node(DatumId{0}), y = atms.add_node(DatumId{0});
    atms.justify(InformantId{0}, {t.a}, x);
    atms.justify(InformantId{0}, {t.c}, y);
    atms.add_nogood(InformantId{1}, {x, y});  // so {A, C} is nogood
    CHECK(atms.minimal_nogoods() == std::vector<EnvId>{t.env({t.aa, t.ac})});
    const NodeId w = atms.add_node(DatumId{0});
    atms.justify(InformantId{0}, {x, y}, w);  // only in the inconsistent {A, C}
    CHECK(atms.label(w).empty());
    // Justifications added after the nogood see it at once.
    atms.justify(InformantId{0}, {x, t.b}, w);
    CHECK(atms.label(w) == std::vector<EnvId>{t.env({t.aa, t.ab})});
}

TEST_CASE("atms/atms: the empty nogood makes everything inconsistent") {
    Abc t;
    const NodeId p = t.atms.add_premise(DatumId{0});
    t.atms.add_nogood(InformantId{0}, {p});
    CHECK_FALSE(t.atms.is_consistent(t.atms.empty_environment()));
    CHECK(t.atms.label(p).empty());
    CHECK(t.atms.label(t.a).empty());
    CHECK(t.atms.minimal_nogoods() == std::vector<EnvId>{t.atms.empty_environment()});
    const NodeId q = t.atms.add_premise(DatumId{0});
    CHECK(t.atms.label(q).empty());
    CHECK_FALSE(t.atms.is_consistent(t.env({t.ab})));
}

TEST_CASE("atms/atms: justify records the clause, ignoring duplicate antecedents") {
    Abc t;
    const NodeId x = t.atms.add_node(DatumId{0});
    const JustId j = t.atms.justify(InformantId{42}, {t.a, t.b, t.a}, x);
    const Justification& just = t.atms.justification(j);
    CHECK(just.informant == InformantId{42});
    CHECK(just.antecedents == std::vector<NodeId>{t.a, t.b});
    CHECK(just.consequent == x);
    CHECK(t.atms.justifications(x) == std::vector<JustId>{j});
    CHECK(t.atms.justification_count() == 1);
    const JustId empty = t.atms.justify(InformantId{1}, std::span<const NodeId>{}, x);  // x is true
    CHECK(t.atms.is_true(x));
    CHECK(t.atms.justification(empty).antecedents.empty());
}

TEST_CASE("atms/atms: several Atms objects are independent") {
    Atms one, two;
    const NodeId a = one.add_assumption(DatumId{0});
    one.add_nogood(InformantId{0}, {a});
    const NodeId b = two.add_assumption(DatumId{0});
    CHECK(one.label(a).empty());
    CHECK_FALSE(two.label(b).empty());
    CHECK(two.minimal_nogoods().empty());
}

TEST_CASE("atms/atms: every precondition violation is an InternalError") {
    Abc t;
    Atms& atms = t.atms;
    const NodeId p = atms.add_premise(DatumId{0});
    const NodeId bad{999};
    CHECK_THROWS_AS(atms.justify(InformantId{0}, {t.a}, bad), qm::InternalError);              // unknown consequent
    CHECK_THROWS_AS(atms.justify(InformantId{0}, {bad}, t.a), qm::InternalError);              // unknown antecedent
    CHECK_THROWS_AS(atms.justify(InformantId{0}, {t.a}, p), qm::InternalError);                // premise consequent
    CHECK_THROWS_AS(atms.justify(InformantId{0}, {atms.contradiction()}, t.a), qm::InternalError);
    CHECK_THROWS_AS(atms.add_nogood(InformantId{0}, {bad}), qm::InternalError);
    CHECK_THROWS_AS((void)atms.label(bad), qm::InternalError);
    CHECK_THROWS_AS((void)atms.datum(bad), qm::InternalError);
    CHECK_THROWS_AS((void)atms.is_premise(bad), qm::InternalError);
    CHECK_THROWS_AS((void)atms.assumption_of(bad), qm::InternalError);
    CHECK_THROWS_AS((void)atms.node_of(AssumptionId{77}), qm::InternalError);
    CHECK_THROWS_AS((void)atms.justifications(bad), qm::InternalError);
    CHECK_THROWS_AS((void)atms.justification(JustId{5}), qm::InternalError);
    CHECK_THROWS_AS((void)atms.holds_in(t.a, EnvId{12345}), qm::InternalError);
    CHECK_THROWS_AS((void)atms.holds_in(bad, atms.empty_environment()), qm::InternalError);
    CHECK_THROWS_AS((void)atms.is_consistent(EnvId{12345}), qm::InternalError);
    CHECK_THROWS_AS((void)atms.env(EnvId{12345}), qm::InternalError);
    CHECK_THROWS_AS((void)atms.environment({AssumptionId{77}}), qm::InternalError);
    CHECK_THROWS_AS((void)atms.explain(bad, atms.empty_environment()), qm::InternalError);
    // Three misuses say what went wrong.
    CHECK_THROWS_WITH_AS(atms.justify(InformantId{0}, {t.a}, bad), doctest::Contains("unknown node id"), qm::InternalError);
    CHECK_THROWS_WITH_AS(atms.justify(InformantId{0}, {t.a}, p), doctest::Contains("premise"), qm::InternalError);
    const std::vector<std::vector<AssumptionId>> twice{{t.aa, t.ab}, {t.ab, t.ac}};
    CHECK_THROWS_WITH_AS((void)atms.interpretations(twice), doctest::Contains("two choice sets"), qm::InternalError);
    // Nothing was recorded by the failed calls.
    CHECK(atms.justification_count() == 0);
}

TEST_CASE("atms/atms: the environment limit stops interning, also while interpretations are enumerated") {
    // Ten binary choice sets: 1024 interpretations. Counted without a limit first.
    auto build = [](Atms& atms) {
        std::vector<std::vector<AssumptionId>> sets;
        for (std::uint32_t i = 0; i < 10; ++i) {
            const NodeId x = atms.add_assumption(DatumId{2 * i}), y = atms.add_assumption(DatumId{2 * i + 1});
            sets.push_back({*atms.assumption_of(x), *atms.assumption_of(y)});
        }
        return sets;
    };
    Atms free;
    const auto sets = build(free);
    const std::size_t before = free.environment_count();
    CHECK(free.interpretations(sets).size() == 1024);
    const std::size_t needed = free.environment_count();
    CHECK(needed >= before + 1024);
    Atms exact;
    exact.limit_environments(needed);
    const auto exact_sets = build(exact);
    CHECK(exact.interpretations(exact_sets).size() == 1024);
    Atms short_of_one;
    short_of_one.limit_environments(needed - 1);
    const auto short_sets = build(short_of_one);
    try {
        (void)short_of_one.interpretations(short_sets);
        FAIL("the limit was not reached");
    } catch (const qm::LimitReached& l) {
        CHECK(l.kind == qm::LimitReached::Kind::environments);
        CHECK(l.limit == needed - 1);
        CHECK(short_of_one.environment_count() == needed - 1);  // nothing interned past it
    }
    Atms tiny;
    tiny.limit_environments(3);
    CHECK_THROWS_AS((void)build(tiny), qm::LimitReached);
}
