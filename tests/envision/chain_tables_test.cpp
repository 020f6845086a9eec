// tests/envision/chain_tables_test.cpp: the settling table the envisioner reads from the laws
// (rules/clock/settling.rules through engine/consistency.hpp) against the filters it replaces,
// written here as plain C++ from the thesis: a collision fixes its pair's motions (5.3.3), and an
// object whose motion the step does not allow (Table 5.1 with its net force, 8.3.3) takes one of
// the step's options, unless no state with the step's places gives it one (3.3: it cannot move, so
// it keeps its motion); otherwise any motion.
#include "envision_fixture.hpp"

#include <optional>

namespace qm::envision {
namespace {

using testing::bundled;
using testing::envisioned_once;

// The oracle: the successor step's filters written directly in C++, apart from the laws. fixes:
// the motions collisions fix the object to (a mask; 0: none): where some state allows the outcome,
// exactly it; where none does, it or rest (8.3.4's threshold).
bool oracle(std::uint8_t allowed, std::int8_t now, std::uint8_t fixes, bool reachable, std::int8_t next) {
    if (fixes != 0) return fixes == ChainTables::bit(next) || (!reachable && next == 0);
    const bool must = (allowed >> (now + 1) & 1U) == 0;
    if (must && !reachable) return next == now;
    return !must || (allowed >> (next + 1) & 1U) != 0;
}

TEST_CASE("the settling table of every bundled chain is the collision and must-change filters, each cited by its rule") {
    for (const auto& scene : bundled()) {
        CAPTURE(scene);
        for (const auto& c : envisioned_once(scene).chains) {
            for (std::size_t o = 0; o < c.chain.objects.size(); ++o)
                for (std::uint8_t mask = 0; mask < 8; ++mask)
                    for (std::int8_t now = -1; now <= 1; ++now)
                        for (std::uint8_t fixes = 0; fixes < 8; ++fixes)
                            for (const bool reach : {false, true})
                                for (std::int8_t next = -1; next <= 1; ++next) {
                                    CAPTURE(o);
                                    CAPTURE(int(mask));
                                    CAPTURE(int(now));
                                    CAPTURE(int(fixes));
                                    CAPTURE(reach);
                                    CAPTURE(int(next));
                                    const std::uint8_t code = c.tables.settling(o, mask, now, fixes, reach, next);
                                    CHECK((code == 0) == oracle(mask, now, fixes, reach, next));
                                    if (code == 0) continue;
                                    CHECK(c.tables.refuter(code).where.find("rules/clock/settling.rules:") != std::string::npos);
                                    if (fixes != 0) CHECK(c.tables.refuter(code).rule == (reach ? "collision-fixes-motion" : "collision-outcome-or-rest"));
                                    else CHECK(c.tables.refuter(code).rule == (reach ? "must-change" : "held-stays"));
                                }
        }
    }
}

TEST_CASE("where the laws settle nothing, the table allows every motion") {
    const ChainTables empty;
    for (std::int8_t next = -1; next <= 1; ++next) {
        CHECK(empty.settling(0, 0, 1, 0, true, next) == 0);
        CHECK(empty.settling(3, 2, 0, ChainTables::bit(1), false, next) == 0);
    }
}

TEST_CASE("a settling table codes each refuting rule once") {
    ChainTables t;
    const ChainTables::Refuter a{"a", "f.rules:3"}, b{"b", "f.rules:7"};
    t.set_settling(0, 1, 0, 0, true, 1, a);
    t.set_settling(0, 1, 0, 0, true, -1, a);
    t.set_settling(1, 1, 0, ChainTables::bit(0), true, 1, b);
    t.set_settling(1, 1, 0, ChainTables::bit(0), true, 0, std::nullopt);
    CHECK(t.settling(0, 1, 0, 0, true, 1) == t.settling(0, 1, 0, 0, true, -1));
    CHECK(t.refuter(t.settling(0, 1, 0, 0, true, 1)) == a);
    CHECK(t.refuter(t.settling(1, 1, 0, ChainTables::bit(0), true, 1)) == b);
    CHECK(t.settling(1, 1, 0, ChainTables::bit(0), true, 0) == 0);
    CHECK(t.settling(0, 1, 0, 0, true, 0) == 0);   // never set
    CHECK(t.settling(0, 1, 0, 0, false, 1) == 0);  // never set
}

}  // namespace
}  // namespace qm::envision
