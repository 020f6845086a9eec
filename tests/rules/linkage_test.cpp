// tests/rules/linkage_test.cpp: rules/linkage.rules (Def 21).
#include "law_harness.hpp"

using qm::test::Laws;

TEST_CASE("rules/linkage: linked objects move together and share their forces (Def 21)") {
    Laws l({"directions.rules", "uniqueness_of_motion.rules", "linkage.rules", "force_distribution.rules",
            "reference_frame.rules"},
           "fact (dimensions 2)\nfact (rigid-body a)\nfact (rigid-body b)\nfact (linkage a b)\n"
           "fact (external-force a (0 -) (0 0) g)\n");
    // Every interpretation gives a and b the same motions: 9 x 3 of them, not (9 x 3)^2.
    CHECK(l.interpretations().size() == 27);
    CHECK(l.holds("(force-on b (0 -) (0 0) g)"));
    Laws unlinked({"directions.rules", "uniqueness_of_motion.rules", "linkage.rules"},
                  "fact (dimensions 2)\nfact (rigid-body a)\nfact (rigid-body b)\n");
    CHECK(unlinked.interpretations().size() == 27 * 27);
}
