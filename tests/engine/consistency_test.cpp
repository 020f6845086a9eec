// tests/engine/consistency_test.cpp: engine/consistency.hpp's Refutations tell whether an environment is
// consistent and, if not, names the rule whose `false` refutes it and where it is written; checked
// against brute force over every subset of a small program's assumptions.
#include "engine/consistency.hpp"
#include "run_rule_text.hpp"
#include <doctest/doctest.h>
#include <memory>

using namespace qm::engine;

namespace {

// Four switches: a and b never together (line 7), nor c and d (line 10), nor c with (lit), which b
// derives (line 13: a nogood through a derived fact).
const char* program = R"(assume (on a)
assume (on b)
assume (on c)
assume (on d)
rule from-b
  when (on b) then (lit)
rule a-excludes-b
  when (on a) (on b)
  then false
rule c-excludes-d
  when (on c) (on d)
  then false
rule lit-excludes-c
  when (lit) (on c)
  then false
)";

TEST_CASE("Refutations: nothing for a consistent environment, else the rule and line of a nogood within it") {
    const auto engine = test::run_rule_text(program, "c.rules");
    Engine& e = *engine;
    Refutations refutations(e);
    std::vector<qm::atms::AssumptionId> on;
    for (const char* s : {"a", "b", "c", "d"}) {
        const ValueId arg[] = {e.values().symbol(s)};
        const auto f = e.find(e.values().symbol("on"), arg);
        REQUIRE(f);
        on.push_back(*e.assumption(*f));
    }
    // Brute force: which rules' conditions a subset satisfies.
    for (unsigned mask = 0; mask < 16; ++mask) {
        CAPTURE(mask);
        std::vector<qm::atms::AssumptionId> env;
        for (unsigned j = 0; j < 4; ++j)
            if (mask >> j & 1U) env.push_back(on[j]);
        const bool a = mask & 1U, b = mask & 2U, c = mask & 4U, d = mask & 8U;
        const bool ab = a && b, cd = c && d, bc = b && c;
        const auto r = refutations.of(e.atms().environment(env));
        CHECK(r.has_value() == (ab || cd || bc));
        if (!r) continue;
        CHECK(r->where.file == "c.rules");
        if (r->rule == "a-excludes-b") CHECK((ab && r->where.line == 7));
        else if (r->rule == "c-excludes-d") CHECK((cd && r->where.line == 10));
        else CHECK((r->rule == "lit-excludes-c" && bc && r->where.line == 13));
    }
}

}  // namespace
