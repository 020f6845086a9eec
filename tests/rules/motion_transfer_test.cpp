// tests/rules/motion_transfer_test.cpp: rules/motion_transfer.rules (Table 3.2) on the gear pair of
// Figure 7.12: exactly the three pairs the guide's worked check names are nogood.
#include "law_harness.hpp"

using qm::test::Laws;
using Sets = std::set<std::set<std::string>>;

namespace {
const std::vector<std::string> transfer_laws{"directions.rules", "reference_frame.rules", "contact.rules",
                                    "contact_constraint.rules", "uniqueness_of_motion.rules", "motion_transfer.rules"};
const std::string gears =
    "fact (dimensions 2)\nfact (rigid-body driver)\nfact (rigid-body follower)\n"
    "fact (surface follower l1)\nfact (surface-normal l1 (- -))\nfact (origin-dir l1 (0 +))\n"
    "fact (surface driver d1)\nfact (surface-normal d1 (+ +))\nfact (origin-dir d1 (0 -))\n" +
    qm::test::pinned("driver") + qm::test::pinned("follower");
}  // namespace

TEST_CASE("rules/motion_transfer: turning into the other gear forces it to turn away (Figure 7.14)") {
    Laws l(transfer_laws, gears + "fact (contact l1 d1)\n");
    const Sets expected{{"(rot-motion driver (-))", "(rot-motion follower (-))", "(trans-motion driver (0 0))"},
                        {"(rot-motion driver (-))", "(rot-motion follower (-))", "(trans-motion follower (0 0))"},
                        {"(rot-motion driver (-))", "(rot-motion follower (0))", "(trans-motion follower (0 0))"},
                        {"(rot-motion driver (0))", "(rot-motion follower (-))", "(trans-motion driver (0 0))"}};
    Sets pushing;
    for (const auto& n : l.law_nogoods())
        if (n.size() > 1) pushing.insert(n);
    CHECK(pushing == expected);
    CHECK(l.interpretations().size() == 6);
}

TEST_CASE("rules/motion_transfer: without contact nothing is pushed") {
    Laws l(transfer_laws, gears);
    for (const auto& n : l.law_nogoods()) CHECK(n.size() == 1);  // only the frame's constraints
    CHECK(l.interpretations().size() == 9);
}

TEST_CASE("rules/motion_transfer: a body pushing a free boulder leaves it the moves of Figure 3.4") {
    // The block moves right into the boulder's left face; the boulder's centre is down-right of the
    // contact. It must translate right-ish or turn clockwise.
    Laws l(transfer_laws,
           "fact (dimensions 2)\nfact (rigid-body block)\nfact (rigid-body boulder)\n"
           "fact (surface block k)\nfact (surface-normal k (+ 0))\nfact (origin-dir k (- 0))\n"
           "fact (surface boulder o)\nfact (surface-normal o (- 0))\nfact (origin-dir o (+ -))\n"
           "fact (contact k o)\n"
           "rule given-block\n  when (trans-motion block ?t) (!= ?t (+ 0))\n  then false\n"
           "rule given-block-rotation\n  when (rot-motion block ?r) (!= ?r (0))\n  then false\n");
    std::set<std::string> boulder;
    for (const auto& i : l.interpretations()) {
        std::string t, r;
        for (const auto& a : i) {
            if (a.rfind("(trans-motion boulder", 0) == 0) t = a;
            if (a.rfind("(rot-motion boulder", 0) == 0) r = a;
        }
        const bool away = t.find("(+ ") != std::string::npos || r.find("(-)") != std::string::npos;
        CHECK(away);
        boulder.insert(t + r);
    }
    // Right-ish with no rotation or clockwise, or any vertical move turning clockwise: 6 + 3. Turning
    // counter-clockwise or moving left would push the contact back into the block (Table 3.2 applied
    // the other way), which cannot give way.
    CHECK(boulder.size() == 9);
    for (const auto& b : boulder) {
        CAPTURE(b);
        CHECK(b.find("(trans-motion boulder (- ") == std::string::npos);
        CHECK(b.find("(rot-motion boulder (+))") == std::string::npos);
    }
}
