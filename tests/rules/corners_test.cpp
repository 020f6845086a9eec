// tests/rules/corners_test.cpp: rules/corners.rules (section 3.1.1, Defs 18, 25, 26; Figure 3.3).
#include "law_harness.hpp"

using qm::test::Laws;
using S = std::set<std::string>;

namespace {
const std::vector<std::string> corner_laws{"directions.rules", "reference_frame.rules", "contact.rules", "corners.rules",
                                    "contact_constraint.rules", "uniqueness_of_motion.rules"};
// The upper triangle's lowest corner, between its faces c (normal (+ -)) and e (normal (- -)).
// Its blocked space is (+ +), (0 +), (- +): a face with normal (- +) (A) can touch it, one with
// normal (- -) (B) cannot (Figure 3.3).
const std::string triangle =
    "fact (dimensions 2)\nfact (rigid-body upper)\nfact (rigid-body lower)\n"
    "fact (surface upper c)\nfact (surface-normal c (+ -))\nfact (origin-dir c (- +))\n"
    "fact (surface upper e)\nfact (surface-normal e (- -))\nfact (origin-dir e (+ +))\n"
    "fact (surface upper tip)\nfact (corner upper tip c e)\nfact (origin-dir tip (0 +))\n"
    "fact (surface lower a)\nfact (surface-normal a (- +))\nfact (origin-dir a (+ -))\n"
    "fact (surface lower b)\nfact (surface-normal b (- -))\nfact (origin-dir b (+ +))\n";
}  // namespace

TEST_CASE("rules/corners: which surfaces can touch a corner (Def 25, Figure 3.3)") {
    Laws l(corner_laws, triangle);
    CHECK(l.holds("(can-contact tip a)"));
    CHECK_FALSE(l.holds("(can-contact tip b)"));
}

TEST_CASE("rules/corners: a corner on a surface takes the reverse of its normal (3.1.1)") {
    Laws l(corner_laws, triangle + qm::test::fixed("lower") + "fact (contact tip a)\n");
    CHECK(l.holds("(touch tip a {(+ -)})"));
    CHECK(l.holds("(touch a tip {(- +)})"));
    // The fixed lower block then blocks the triangle's corner from moving into a.
    CHECK(l.holds("(trans-constraint upper (+ -))"));
    CHECK_FALSE(l.holds("(trans-constraint upper (0 +))"));
}

TEST_CASE("rules/corners: a corner against a surface it cannot touch imposes nothing") {
    Laws l(corner_laws, triangle + qm::test::fixed("lower") + "fact (contact tip b)\n");
    CHECK(l.all("touch").empty());
    CHECK(l.all("trans-constraint").size() == 8);  // only the lower block's own frame constraints
}

TEST_CASE("rules/corners: two corners constrain only where every potential contact does (Def 26)") {
    // A second corner on the lower block, between a (- +) and its top face t (0 +).
    const std::string two = triangle + qm::test::fixed("lower") +
                            "fact (surface lower t)\nfact (surface-normal t (0 +))\nfact (origin-dir t (0 -))\n"
                            "fact (surface lower ridge)\nfact (corner lower ridge a t)\nfact (origin-dir ridge (0 -))\n"
                            "fact (contact tip ridge)\n";
    Laws l(corner_laws, two);
    // Each corner may touch both sides of the other (an ambiguous dot product counts as "may"):
    // tip against a and t, the ridge against c and e.
    CHECK(l.holds("(can-contact tip a)"));
    CHECK(l.holds("(can-contact tip t)"));
    CHECK(l.holds("(can-contact ridge c)"));
    CHECK(l.holds("(can-contact ridge e)"));
    CHECK(l.holds("(touch tip ridge {(+ -) (0 -) (- -)})"));
    // Blocked only where every potential contact blocks: the point resting on the ridge can slide
    // off either side, only straight down is blocked.
    CHECK(l.holds("(trans-constraint upper (0 -))"));
    CHECK_FALSE(l.holds("(trans-constraint upper (+ -))"));
    CHECK_FALSE(l.holds("(trans-constraint upper (- -))"));
    CHECK_FALSE(l.holds("(trans-constraint upper (+ 0))"));
}
