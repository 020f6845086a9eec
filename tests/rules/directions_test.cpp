// tests/rules/directions_test.cpp: rules/directions.rules and rules/uniqueness_of_motion.rules
// (Defs 1 and 4, Law 1), rules/reference_frame.rules (section 6.1) and rules/freedom.rules (Def 24).
#include "law_harness.hpp"

using qm::test::Laws;

TEST_CASE("rules/directions: T and P in two and three dimensions (Defs 1, 4)") {
    Laws two({"directions.rules"}, "fact (dimensions 2)\n");
    CHECK(two.all("translation").size() == 9);
    CHECK(two.all("rotation") == std::set<std::string>{"(rotation (+))", "(rotation (-))", "(rotation (0))"});
    Laws three({"directions.rules"}, "fact (dimensions 3)\n");
    CHECK(three.all("translation").size() == 27);
    CHECK(three.all("rotation").size() == 27);
}

TEST_CASE("rules/uniqueness_of_motion: one translation and one rotation per object (Law 1)") {
    Laws l({"directions.rules", "uniqueness_of_motion.rules"}, "fact (dimensions 2)\nfact (rigid-body a)\nfact (rigid-body b)\n");
    CHECK(l.engine().choice_sets().size() == 4);
    CHECK(l.interpretations().size() == 27 * 27);
}

TEST_CASE("rules/reference_frame: the frame's constraints, never the zero direction (section 6.1)") {
    Laws l({"directions.rules", "reference_frame.rules", "uniqueness_of_motion.rules", "freedom.rules"},
           "fact (dimensions 2)\nfact (rigid-body rack)\n"
           "fact (frame-trans-constraint rack (0 0))\nfact (frame-trans-constraint rack (+ +))\n"
           "fact (frame-trans-constraint rack (0 +))\nfact (frame-rot-constraint rack (0))\n");
    CHECK(l.all("trans-constraint") == std::set<std::string>{"(trans-constraint rack (+ +))", "(trans-constraint rack (0 +))"});
    CHECK(l.all("rot-constraint").empty());
    // Def 24: free is what is not constrained.
    CHECK(l.all("trans-freedom").size() == 7);
    CHECK(l.holds("(trans-freedom rack (0 0))"));
    CHECK_FALSE(l.holds("(trans-freedom rack (+ +))"));
    CHECK(l.all("rot-freedom").size() == 3);
}
