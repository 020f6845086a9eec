// tests/envision/verify_test.cpp: the envisionment's invariants (envision/verify.hpp) hold on every
// bundled and test mechanism, and they catch laws that stop a chain where a part could start.
#include "envision/verify.hpp"
#include "envision_fixture.hpp"
#include "invariants.hpp"

#include <fstream>

namespace qm::envision {
namespace {

using testing::bundled;
using testing::mechanism;

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

TEST_CASE("every bundled and test mechanism keeps the invariants: jams are jams, cycles repeat, moving states lead on") {
    for (const auto& scene : bundled()) {
        CAPTURE(scene);
        const auto m = mechanism(scene);
        const auto e = testing::envisioned(m);
        const auto problems = verify(m, e);
        CHECK_MESSAGE(problems.empty(), joined(problems));
        const auto independent = testing::invariant_problems(m, e);
        CHECK_MESSAGE(independent.empty(), joined(independent));
    }
}

TEST_CASE("laws that keep a held part's due start stop the chain, and the invariants say where") {
    // rules/clock/ without the reading of 3.3 in settling.rules: a part that must start and cannot
    // holds up the whole step.
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(QM_BINARY_DIR) / "verify_rules_without_held";
    fs::remove_all(dir);
    fs::copy(testing::rules_folder(), dir);
    std::ifstream in(dir / "settling.rules");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const std::string must = "(no-collision ?o) (step-reachable ?o) (motion-now ?o ?c)";
    const auto at = text.find(must);
    REQUIRE(at != std::string::npos);
    text.replace(at, must.size(), "(no-collision ?o) (motion-now ?o ?c)");
    const auto held = text.find("rule held-stays");
    REQUIRE(held != std::string::npos);
    text.erase(held);
    std::ofstream(dir / "settling.rules") << text;
    const auto m = mechanism("scenarios/clock/escapement.def");
    EnvisionOptions o;
    o.rules = dir;
    const auto e = testing::envisioned(m, o);
    const auto problems = verify(m, e);
    REQUIRE(!problems.empty());
    CHECK(joined(problems).find("state #444 scape-wheel/pallets-62 0 0 is terminal, yet nothing holds the net force - on scape-wheel") !=
          std::string::npos);
    // The independent reading, from the parts' geometry, sees the same.
    CHECK(joined(testing::invariant_problems(m, e)).find("#444 scape-wheel/pallets-62 0 0 is terminal, and nothing in the geometry holds scape-wheel's net force -") !=
          std::string::npos);
}

}  // namespace
}  // namespace qm::envision
