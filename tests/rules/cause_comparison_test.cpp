// tests/rules/cause_comparison_test.cpp: rules/cause_comparison.rules (section 2.1.3's "method of
// comparison" and section 2.3's branching on opposing forces; Def 11), with net_force.rules and
// nearness.rules reading the resolved net force.
#include "law_harness.hpp"

using qm::test::Laws;
using S = std::set<std::string>;
using SS = std::set<std::set<std::string>>;

namespace {
const std::vector<std::string> laws{"directions.rules",        "reference_frame.rules", "contact.rules",
                                    "contact_constraint.rules", "force_distribution.rules", "net_force.rules",
                                    "cause_comparison.rules",   "nearness.rules"};

// The environments (as assumption texts) of a fact's label.
SS label(Laws& l, const std::string& fact) {
    SS out;
    auto f = l.fact(fact);
    if (!f) return out;
    for (qm::atms::EnvId e : l.engine().label(*f)) {
        std::set<std::string> env;
        for (qm::atms::AssumptionId a : l.engine().atms().env(e).assumptions()) env.insert(l.engine().print(a));
        out.insert(env);
    }
    return out;
}

std::string body(const std::string& forces) { return "fact (dimensions 2)\nfact (rigid-body a)\n" + forces; }
}  // namespace

TEST_CASE("rules/cause_comparison: two causes pushing oppositely branch on which prevails (2.3)") {
    Laws l(laws, body("fact (external-force a (+ 0) (0 0) hand)\nfact (external-force a (- 0) (0 0) wind)\n"));
    CHECK(l.holds("(net-force a (? 0))"));
    REQUIRE(l.engine().choice_sets().size() == 1);
    CHECK(l.interpretations() == SS{{"(cause-comparison hand wind (+))"},
                                    {"(cause-comparison hand wind (0))"},
                                    {"(cause-comparison hand wind (-))"}});
    // The net force in each branch: the prevailing cause's direction, or none when they balance.
    CHECK(label(l, "(resolved-net-force a (+ 0))") == SS{{"(cause-comparison hand wind (+))"}});
    CHECK(label(l, "(resolved-net-force a (0 0))") == SS{{"(cause-comparison hand wind (0))"}});
    CHECK(label(l, "(resolved-net-force a (- 0))") == SS{{"(cause-comparison hand wind (-))"}});
    CHECK_FALSE(l.holds("(resolved-net-force a (? 0))"));
    // Nearness ranks hold in their branch only.
    CHECK(label(l, "(trans-nearness a (+ 0) 0)") == SS{{"(cause-comparison hand wind (+))"}});
    CHECK(label(l, "(trans-nearness a (- 0) 0)") == SS{{"(cause-comparison hand wind (-))"}});
    CHECK(label(l, "(trans-nearness a (0 0) 0)") == SS{{"(cause-comparison hand wind (0))"}});
}

TEST_CASE("rules/cause_comparison: no branch where nothing opposes, or one cause opposes itself (Law 5)") {
    Laws perpendicular(laws, body("fact (external-force a (+ 0) (0 0) hand)\nfact (external-force a (0 -) (0 0) wind)\n"));
    CHECK(perpendicular.engine().choice_sets().empty());
    CHECK(label(perpendicular, "(resolved-net-force a (+ -))") == SS{{}});
    Laws same(laws, body("fact (external-force a (+ 0) (0 0) hand)\nfact (external-force a (- 0) (0 0) hand)\n"));
    CHECK(same.engine().choice_sets().empty());
    CHECK(label(same, "(resolved-net-force a (0 0))") == SS{{}});
    CHECK(same.all("cause-force-along").empty());
}

TEST_CASE("rules/cause_comparison: three causes along one axis keep ? (more information is needed)") {
    Laws l(laws, body("fact (external-force a (+ 0) (0 0) hand)\nfact (external-force a (+ 0) (0 0) spring)\n"
                      "fact (external-force a (- 0) (0 0) wind)\n"));
    CHECK(l.all("force-decided-by").empty());
    CHECK(l.engine().choice_sets().empty());
    CHECK(label(l, "(resolved-net-force a (? 0))") == SS{{}});
    // Def 38 for an ambiguous force, as before: the nearest rank over its resolutions.
    CHECK(l.holds("(trans-nearness a (- 0) 0)"));
    CHECK(l.holds("(trans-nearness a (0 0) 0)"));
}

TEST_CASE("rules/cause_comparison: each axis is decided by its own pair; one question per pair for every object") {
    Laws l(laws, "fact (dimensions 2)\nfact (rigid-body a)\nfact (rigid-body b)\n"
                 "fact (external-force a (+ 0) (0 0) hand)\nfact (external-force a (- 0) (0 0) wind)\n"
                 "fact (external-force a (0 +) (0 0) lift)\nfact (external-force a (0 -) (0 0) weight)\n"
                 "fact (external-force b (- +) (0 0) hand)\nfact (external-force b (+ 0) (0 0) wind)\n");
    CHECK(l.engine().choice_sets().size() == 2);
    CHECK(l.all("force-decided-by") == S{"(force-decided-by a 1 hand wind (+) (-))", "(force-decided-by a 2 lift weight (+) (-))",
                                         "(force-decided-by b 1 hand wind (-) (+))"});
    CHECK(label(l, "(resolved-net-force a (+ -))") ==
          SS{{"(cause-comparison hand wind (+))", "(cause-comparison lift weight (-))"}});
    CHECK(label(l, "(resolved-net-force a (0 +))") ==
          SS{{"(cause-comparison hand wind (0))", "(cause-comparison lift weight (+))"}});
    // The same answer for b: where hand prevails, b goes hand's way along x.
    CHECK(label(l, "(resolved-net-force b (- +))") == SS{{"(cause-comparison hand wind (+))"}});
    CHECK(label(l, "(resolved-net-force b (0 +))") == SS{{"(cause-comparison hand wind (0))"}});
    CHECK(label(l, "(resolved-net-force b (+ +))") == SS{{"(cause-comparison hand wind (-))"}});
    CHECK(l.interpretations().size() == 9);
}

TEST_CASE("rules/cause_comparison: opposing torques of two causes branch too") {
    // A pinned lever pushed down left of its pivot by a hand (origin (+ 0): counter-clockwise, since
    // Rotate-90((0 -), +) = (+ 0) faces the origin) and right of it by a weight (clockwise).
    Laws l(laws, body(qm::test::pinned("a") + "fact (external-force a (0 -) (+ 0) hand)\nfact (external-force a (0 -) (- 0) weight)\n"));
    CHECK(l.holds("(net-torque a (?))"));
    CHECK(l.all("torque-decided-by") == S{"(torque-decided-by a 1 hand weight (+) (-))"});
    CHECK(label(l, "(resolved-net-torque a (+))") == SS{{"(cause-comparison hand weight (+))"}});
    CHECK(label(l, "(resolved-net-torque a (0))") == SS{{"(cause-comparison hand weight (0))"}});
    CHECK(label(l, "(resolved-net-torque a (-))") == SS{{"(cause-comparison hand weight (-))"}});
    CHECK(label(l, "(rot-nearness a (-) 0)") == SS{{"(cause-comparison hand weight (-))"}});
}

TEST_CASE("rules/cause_comparison: comparisons of magnitudes are transitive") {
    // x against y on a, y against z on b, x against z on c: 27 branches, of which the 13 weak orders
    // of three magnitudes are consistent.
    Laws l(laws, "fact (dimensions 2)\nfact (rigid-body a)\nfact (rigid-body b)\nfact (rigid-body c)\n"
                 "fact (external-force a (+ 0) (0 0) x)\nfact (external-force a (- 0) (0 0) y)\n"
                 "fact (external-force b (+ 0) (0 0) y)\nfact (external-force b (- 0) (0 0) z)\n"
                 "fact (external-force c (+ 0) (0 0) x)\nfact (external-force c (- 0) (0 0) z)\n");
    CHECK(l.engine().choice_sets().size() == 3);
    CHECK(l.interpretations().size() == 13);
    const SS ng = l.nogoods();
    CHECK(ng.count({"(cause-comparison x y (+))", "(cause-comparison y z (+))", "(cause-comparison x z (-))"}) == 1);
    CHECK(ng.count({"(cause-comparison x y (0))", "(cause-comparison y z (0))", "(cause-comparison x z (+))"}) == 1);
    CHECK(ng.count({"(cause-comparison x y (+))", "(cause-comparison y z (+))", "(cause-comparison x z (+))"}) == 0);
}
