// tests/envision/random_mechanisms_test.cpp: the envisionment's invariants (envision/verify.hpp, and
// independently tests/envision/invariants.hpp) on
// seeded random mechanisms, as a user might draw them: a random polygon turning on a pivot, against
// a random polygon that slides towards it or swings on a pivot beside it, with or without a motor,
// a spring or gravity. Drawings whose parts never touch, or overlap as drawn, are refused by the
// geometry (exit 2 for a user) and not counted; at least 200 others are envisioned and checked.
#include "envision/verify.hpp"
#include "envision_fixture.hpp"
#include "invariants.hpp"
#include "../support/random_mechanism.hpp"

namespace qm::envision {
namespace {

#if defined(QM_SANITIZED_BUILD) || !defined(NDEBUG)
constexpr int wanted = 24;  // the same code paths, in the time a sanitized build has
#else
constexpr int wanted = 200;
#endif

TEST_CASE("random mechanisms keep the invariants: jams are jams, cycles repeat, moving states lead on") {
    int envisioned = 0, refused = 0;
    for (int seed = 1; envisioned < wanted && seed < 20 * wanted; ++seed) {
        const std::string text = qm::test::random_mechanism_text(seed);
        CAPTURE(text);
        Diagnostics d;
        auto m = geometry::read_mechanism("random-" + std::to_string(seed) + ".def", text, d);
        if (!m) {
            ++refused;
            continue;
        }
        EnvisionOptions o;
        o.rules = testing::rules_folder();
        o.max_states = 50'000;
        o.threads = 1;
        Diagnostics run;
        const auto e = qm::envision::envision(*m, o, run);
        if (!e) {  // parts that never touch, or meet as drawn: the user's drawing is refused
            ++refused;
            continue;
        }
        ++envisioned;
        auto problems = verify(*m, *e);
        for (auto& p : testing::invariant_problems(*m, *e)) problems.push_back("independently: " + p);
        std::string all;
        for (const auto& p : problems) all += p + "\n";
        CHECK_MESSAGE(problems.empty(), all);
    }
    MESSAGE(envisioned << " envisioned, " << refused << " refused");
    CHECK(envisioned == wanted);
}

}  // namespace
}  // namespace qm::envision
