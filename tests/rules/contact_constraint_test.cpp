// tests/rules/contact_constraint_test.cpp: rules/contact_constraint.rules (Table 3.1, Def 23) with
// directions, reference_frame, contact and uniqueness_of_motion.
#include "law_harness.hpp"

using qm::test::Laws;
using S = std::set<std::string>;

namespace {
const std::vector<std::string> contact_laws{"directions.rules", "reference_frame.rules", "contact.rules",
                                    "contact_constraint.rules", "uniqueness_of_motion.rules"};
const std::string block_and_table =
    "fact (dimensions 2)\nfact (rigid-body block)\nfact (rigid-body table)\n"
    "fact (surface table tb)\nfact (surface-normal tb (0 +))\nfact (origin-dir tb (0 0))\n"
    "fact (surface block bl)\nfact (surface-normal bl (0 -))\nfact (origin-dir bl (+ +))\n"
    "fact (surface block bm)\nfact (surface-normal bm (0 -))\nfact (origin-dir bm (0 +))\n"
    "fact (surface block br)\nfact (surface-normal br (0 -))\nfact (origin-dir br (- +))\n" +
    qm::test::fixed("table");
}  // namespace

TEST_CASE("rules/contact_constraint: a fixed table blocks the downward half plane (Figure 7.5)") {
    Laws l(contact_laws, block_and_table + "fact (contact tb bl)\nfact (contact tb bm)\nfact (contact tb br)\n");
    CHECK(l.all("trans-constraint") >= S{"(trans-constraint block (+ -))", "(trans-constraint block (0 -))",
                                         "(trans-constraint block (- -))"});
    CHECK_FALSE(l.holds("(trans-constraint block (+ 0))"));
    CHECK_FALSE(l.holds("(trans-constraint block (0 +))"));
    // The left end turns counter-clockwise into the table, the right end clockwise.
    CHECK(l.holds("(rot-constraint block (+))"));
    CHECK(l.holds("(rot-constraint block (-))"));
    // Def 23: a constrained motion is impossible.
    CHECK(l.nogoods().count({"(trans-motion block (0 -))"}) == 1);
    CHECK(l.nogoods().count({"(rot-motion block (+))"}) == 1);
}

TEST_CASE("rules/contact_constraint: the middle of the bottom alone does not stop rotation") {
    Laws l(contact_laws, block_and_table + "fact (contact tb bm)\n");
    CHECK(l.holds("(trans-constraint block (0 -))"));
    CHECK_FALSE(l.holds("(rot-constraint block (+))"));
    CHECK_FALSE(l.holds("(rot-constraint block (-))"));
}

TEST_CASE("rules/contact_constraint: constraints flow up a stack, not from a free obstacle") {
    const std::string upper =
        "fact (rigid-body top)\n"
        "fact (surface block tm)\nfact (surface-normal tm (0 +))\nfact (origin-dir tm (0 -))\n"
        "fact (surface top um)\nfact (surface-normal um (0 -))\nfact (origin-dir um (0 +))\nfact (contact tm um)\n";
    {
        Laws l(contact_laws, block_and_table + upper + "fact (contact tb bm)\n");
        CHECK(l.holds("(trans-constraint top (0 -))"));  // through the block, which the table holds
    }
    {
        Laws l(contact_laws, block_and_table + upper);           // the block floats: it blocks nothing
        CHECK_FALSE(l.holds("(trans-constraint top (0 -))"));
        CHECK_FALSE(l.holds("(trans-constraint block (0 -))"));
    }
}

TEST_CASE("rules/contact_constraint: an obstacle free to yield sideways does not block (Figure 3.2)") {
    // A wedge with a sloped underside on a fixed ramp sloping down to the right: the wedge can
    // still slide (+ -), so the block on its level top is not blocked downwards.
    Laws l(contact_laws,
           "fact (dimensions 2)\nfact (rigid-body block)\nfact (rigid-body wedge)\nfact (rigid-body ramp)\n" +
               qm::test::fixed("ramp") +
               "fact (surface ramp r)\nfact (surface-normal r (+ +))\nfact (origin-dir r (0 0))\n"
               "fact (surface wedge wb)\nfact (surface-normal wb (- -))\nfact (origin-dir wb (0 +))\n"
               "fact (surface wedge wt)\nfact (surface-normal wt (0 +))\nfact (origin-dir wt (0 -))\n"
               "fact (surface block b)\nfact (surface-normal b (0 -))\nfact (origin-dir b (0 +))\n"
               "fact (contact r wb)\nfact (contact wt b)\n");
    CHECK(l.holds("(trans-constraint wedge (- -))"));
    CHECK_FALSE(l.holds("(trans-constraint wedge (+ -))"));
    CHECK_FALSE(l.holds("(trans-constraint block (0 -))"));
}
