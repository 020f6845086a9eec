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

// The oracle: the successor step's filters written directly in C++, apart from the laws.
bool oracle(std::uint8_t allowed, std::int8_t now, std::optional<std::int8_t> fix, bool reachable, std::int8_t next) {
    if (fix) return next == *fix;
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
                        for (const bool reach : {false, true})
                            for (std::int8_t next = -1; next <= 1; ++next) {
                                CAPTURE(o);
                                CAPTURE(int(mask));
                                CAPTURE(int(now));
                                CAPTURE(reach);
                                CAPTURE(int(next));
                                std::optional<std::int8_t> none;
                                const std::uint8_t free = c.tables.settling(o, mask, now, none, reach, next);
                                CHECK((free == 0) == oracle(mask, now, none, reach, next));
                                if (free != 0) {
                                    CHECK(c.tables.refuter(free).rule == (reach ? "must-change" : "held-stays"));
                                    CHECK(c.tables.refuter(free).where.find("rules/clock/settling.rules:") != std::string::npos);
                                }
                                for (std::int8_t f = -1; f <= 1; ++f) {
                                    const std::uint8_t code = c.tables.settling(o, mask, now, f, reach, next);
                                    CHECK((code == 0) == oracle(mask, now, f, reach, next));
                                    if (code != 0) CHECK(c.tables.refuter(code).rule == "collision-fixes-motion");
                                    // Two collisions fixing one object: the successor step requires both
                                    // (5.3.3: they never happen at once, so disagreeing ones leave nothing).
                                    for (std::int8_t g = -1; g <= 1; ++g) {
                                        const bool both = code == 0 && c.tables.settling(o, mask, now, g, reach, next) == 0;
                                        CHECK(both == (f == g && next == f));
                                    }
                                }
                            }
        }
    }
}

TEST_CASE("where the laws settle nothing, the table allows every motion") {
    const ChainTables empty;
    for (std::int8_t next = -1; next <= 1; ++next) {
        CHECK(empty.settling(0, 0, 1, std::nullopt, true, next) == 0);
        CHECK(empty.settling(3, 2, 0, std::int8_t{1}, false, next) == 0);
    }
}

TEST_CASE("a settling table codes each refuting rule once") {
    ChainTables t;
    const ChainTables::Refuter a{"a", "f.rules:3"}, b{"b", "f.rules:7"};
    t.set_settling(0, 1, 0, std::nullopt, true, 1, a);
    t.set_settling(0, 1, 0, std::nullopt, true, -1, a);
    t.set_settling(1, 1, 0, std::int8_t{0}, true, 1, b);
    t.set_settling(1, 1, 0, std::int8_t{0}, true, 0, std::nullopt);
    CHECK(t.settling(0, 1, 0, std::nullopt, true, 1) == t.settling(0, 1, 0, std::nullopt, true, -1));
    CHECK(t.refuter(t.settling(0, 1, 0, std::nullopt, true, 1)) == a);
    CHECK(t.refuter(t.settling(1, 1, 0, std::int8_t{0}, true, 1)) == b);
    CHECK(t.settling(1, 1, 0, std::int8_t{0}, true, 0) == 0);
    CHECK(t.settling(0, 1, 0, std::nullopt, true, 0) == 0);   // never set
    CHECK(t.settling(0, 1, 0, std::nullopt, false, 1) == 0);  // never set
}

}  // namespace
}  // namespace qm::envision
