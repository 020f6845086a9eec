// tests/rules/force_test.cpp: rules/force_distribution.rules (Table 3.3, Defs 8-10, transmission),
// rules/net_force.rules (Def 11, Law 5) and rules/nearness.rules (Def 38, section 6.2).
#include "law_harness.hpp"

using qm::test::Laws;
using S = std::set<std::string>;

namespace {
const std::vector<std::string> force_laws{"directions.rules", "reference_frame.rules", "contact.rules",
                                    "contact_constraint.rules", "uniqueness_of_motion.rules", "force_distribution.rules",
                                    "net_force.rules", "cause_comparison.rules", "nearness.rules", "given_motion.rules"};
}

TEST_CASE("rules/force: a force pushing a lever down off its pivot turns it clockwise (section 6.1)") {
    Laws l(force_laws, "fact (dimensions 2)\nfact (rigid-body lever)\n" + qm::test::pinned("lever") +
                     "fact (external-force lever (0 -) (- -) hand)\n");
    CHECK(l.all("distributed-force").empty());             // every translation is blocked (Table 3.3)
    CHECK(l.all("torque") == S{"(torque lever (-) hand)"});  // Rotate-90((0 -), -) = (- 0) faces (- -)
    CHECK(l.holds("(net-force lever (0 0))"));
    CHECK(l.holds("(net-torque lever (-))"));
    CHECK(l.holds("(rot-nearness lever (-) 0)"));
    CHECK(l.holds("(rot-nearness lever (0) 2)"));
    CHECK(l.holds("(rot-nearness lever (+) 3)"));  // -v: beyond the threshold, all rank 3 (8.3.4)
    CHECK_FALSE(l.holds("(rot-nearness lever (+) 5)"));
    // Beyond the zero threshold a force cannot move it (8.3.4).
    CHECK(l.nogoods().count({"(rot-motion lever (+))"}) == 1);
}

TEST_CASE("rules/force: the distributed force of a free body is its half plane (Table 3.3)") {
    Laws l(force_laws, "fact (dimensions 2)\nfact (rigid-body block)\nfact (external-force block (0 -) (0 0) gravity)\n");
    CHECK(l.all("distributed-force").size() == 3);
    CHECK(l.all("torque").empty());  // acting at the centre
    CHECK(l.holds("(net-force block (0 -))"));
    CHECK(l.holds("(trans-nearness block (0 -) 0)"));
    CHECK(l.holds("(trans-nearness block (+ -) 1)"));
    CHECK(l.holds("(trans-nearness block (0 0) 2)"));
    CHECK(l.holds("(trans-nearness block (+ 0) 3)"));
}

TEST_CASE("rules/force: forces of one cause cancel, of different causes are ambiguous (Law 5)") {
    const std::string body = "fact (dimensions 2)\nfact (rigid-body a)\n";
    Laws same(force_laws, body + "fact (external-force a (0 -) (0 0) push)\nfact (external-force a (+ +) (0 0) push)\n");
    CHECK(same.holds("(net-force a (+ 0))"));
    Laws different(force_laws, body + "fact (external-force a (0 -) (0 0) push)\nfact (external-force a (+ +) (0 0) spring)\n");
    CHECK(different.holds("(net-force a (+ ?))"));
    // The two causes oppose along y: the net force branches on which prevails (cause_comparison.rules),
    // and each resolution is the force's own direction in its branch.
    CHECK(different.holds("(trans-nearness a (+ +) 0)"));
    CHECK(different.holds("(trans-nearness a (+ 0) 0)"));
    CHECK(different.holds("(trans-nearness a (+ -) 0)"));
}

TEST_CASE("rules/force: a free force pushes what it moves the body into (5.3.2)") {
    // A pushed right into b across a vertical face; b gets a force into its face, same cause.
    Laws l(force_laws, "fact (dimensions 2)\nfact (rigid-body a)\nfact (rigid-body b)\n"
                 "fact (surface a ar)\nfact (surface-normal ar (+ 0))\nfact (origin-dir ar (- 0))\n"
                 "fact (surface b bl)\nfact (surface-normal bl (- 0))\nfact (origin-dir bl (+ +))\n"
                 "fact (contact ar bl)\nfact (external-force a (+ 0) (0 0) hand)\n");
    CHECK(l.holds("(force-on b (+ 0) (+ +) hand)"));
    CHECK(l.holds("(torque b (+) hand)"));  // pushed right below-left of its centre: counter-clockwise
    CHECK_FALSE(l.holds("(force-on a (- 0) (- 0) hand)"));  // nothing comes back through the same face
}

TEST_CASE("rules/force: a net torque pushes the object it turns into, one contact on (5.3.2)") {
    // A pinned cam driven counter-clockwise touches a follower above it, right of the cam's centre:
    // turning (+) moves that point up, into the follower, which is held down by its weight.
    const std::string cam = "fact (dimensions 2)\nfact (rigid-body cam)\nfact (rigid-body follower)\n" +
                            qm::test::pinned("cam") +
                            "fact (surface cam top)\nfact (surface-normal top (0 +))\nfact (origin-dir top (- -))\n"
                            "fact (surface follower foot)\nfact (surface-normal foot (0 -))\nfact (origin-dir foot (0 0))\n"
                            "fact (contact top foot)\nfact (external-force follower (0 -) (0 0) weight)\n";
    Laws l(force_laws, cam + "fact (external-force cam (0 +) (- 0) motor)\n");
    CHECK(l.holds("(cause-torque cam motor (+))"));
    CHECK(l.holds("(pushed-force follower (0 +) (0 0) motor)"));
    CHECK(l.holds("(net-force follower (0 ?))"));            // motor against weight: either may win
    CHECK(l.holds("(trans-nearness follower (0 +) 0)"));
    // Two opposite torques of one cause cancel before anything is pushed (Law 5).
    Laws balanced(force_laws, cam + "fact (external-force cam (0 +) (- 0) motor)\nfact (external-force cam (0 -) (- 0) motor)\n");
    CHECK(balanced.holds("(cause-torque cam motor (0))"));
    CHECK(balanced.all("pushed-force").empty());
    CHECK(balanced.holds("(net-force follower (0 -))"));
}

TEST_CASE("rules/given_motion: a current motion persists, and pushes what it moves into (6.2, Table 3.2)") {
    const std::string scene = "fact (dimensions 2)\nfact (rigid-body a)\nfact (rigid-body b)\n"
                              "fact (surface a ar)\nfact (surface-normal ar (+ 0))\nfact (origin-dir ar (- 0))\n"
                              "fact (surface b bl)\nfact (surface-normal bl (- 0))\nfact (origin-dir bl (+ 0))\n"
                              "fact (contact ar bl)\nfact (external-force b (0 -) (0 0) weight)\n";
    Laws l(force_laws, scene + "fact (given-motion a (+ 0) (0))\n");
    CHECK(l.nogoods().count({"(trans-motion a (0 0))"}) == 1);
    CHECK(l.nogoods().count({"(rot-motion a (+))"}) == 1);
    // b is pushed: its weight's nearness threshold does not hold it back (it is not a force on b).
    CHECK(l.holds("(pushed-by-current-motion b)"));
    CHECK(l.all("force-on") == S{"(force-on b (0 -) (0 0) weight)"});
    CHECK(l.nogoods().count({"(trans-motion b (+ 0))"}) == 0);
    // Moving away from b pushes nothing.
    Laws away(force_laws, scene + "fact (given-motion a (- 0) (0))\n");
    CHECK_FALSE(away.holds("(pushed-by-current-motion b)"));
    CHECK(away.nogoods().count({"(trans-motion b (+ 0))"}) == 1);
}
