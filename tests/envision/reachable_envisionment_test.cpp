// tests/envision/reachable_envisionment_test.cpp: `--from` envisioned on the fly (11.3.4,
// EnvisionOptions::from) against the whole envisionment cut down to what the state leads to
// (restrict_to_reachable, whose reachable set behaviour_query_test checks against a depth-first
// search): the same states shown, transitions, cycles, transient cycles, terminal states and
// possible rests, from seeded random states of one- and two-chain mechanisms; and the states the
// start does not lead to were never given transitions (their net forces were never found). And
// `--next` (from_only): one state's transitions answer it as the whole envisionment does.
#include "envision/state_report.hpp"
#include "envision_fixture.hpp"

#include <random>

namespace qm::envision {
namespace {

// The state as --from names it: `#ID`, or `CHAIN:#ID` where there are several chains.
std::string from_option(const Envisionment& e, std::size_t chain, StateId s) {
    return (e.chains.size() > 1 ? std::to_string(chain + 1) + ":" : std::string()) + "#" + std::to_string(s.value);
}

void same_as_cut_down(const std::string& relative, int starts) {
    const auto m = testing::mechanism(relative);
    const Envisionment& whole = testing::envisioned_once(relative);
    std::mt19937 rng(7);
    for (int n = 0; n < starts; ++n) {
        const std::size_t chain = std::uniform_int_distribution<std::size_t>(0, whole.chains.size() - 1)(rng);
        const auto& all = whole.chains[chain];
        const StateId from{std::uniform_int_distribution<std::uint32_t>(0, static_cast<std::uint32_t>(all.states.size() - 1))(rng)};
        CAPTURE(relative);
        CAPTURE(from_option(whole, chain, from));
        Envisionment expected = whole;
        restrict_to_reachable(expected, chain, from);
        EnvisionOptions o;
        o.from = from_option(whole, chain, from);
        const Envisionment got = testing::envisioned(m, o);
        REQUIRE(got.chains.size() == 1);
        const auto& a = got.chains.front();
        const auto& b = expected.chains.front();
        CHECK(a.chain.index == b.chain.index);
        CHECK(a.states.size() == b.states.size());
        CHECK(a.shown == b.shown);
        REQUIRE(a.transitions.size() == b.transitions.size());
        for (std::size_t t = 0; t < a.transitions.size(); ++t) {
            const auto& x = a.transitions[t];
            const auto& y = b.transitions[t];
            CHECK((x.from == y.from && x.to == y.to && x.duration == y.duration && x.causes == y.causes));
        }
        CHECK(a.graph.cycles == b.graph.cycles);
        CHECK(a.graph.terminal == b.graph.terminal);
        CHECK(a.graph.possible_rests == b.graph.possible_rests);
        CHECK(a.graph.transient.size() == b.graph.transient.size());
        std::size_t untouched = 0;
        for (std::uint32_t i = 0; i < a.states.size(); ++i) {
            const StateId s{i};
            if (a.is_shown(s)) {
                CHECK(a.states[s].net_force == b.states[s].net_force);
                CHECK(a.states[s].may_rest == b.states[s].may_rest);
            } else {
                untouched += a.states[s].net_force.empty() ? 1 : 0;
            }
        }
        CHECK(untouched == a.states.size() - a.shown_count());
    }
}

TEST_CASE("envision/reachable: --from on the fly is the whole envisionment cut down, one chain") {
    same_as_cut_down("scenarios/clock/escapement.def", 6);
    same_as_cut_down("scenarios/clock/ratchet.def", 4);
}

TEST_CASE("envision/reachable: --from on the fly is the whole envisionment cut down, two chains") {
    same_as_cut_down("tests/envision/scenes/two_chains.def", 4);
}

TEST_CASE("envision/reachable: [large] --from on the fly is the whole envisionment cut down, chains of several pairs") {
    same_as_cut_down("scenarios/clock/clock.def", 4);
    same_as_cut_down("scenarios/clock/pawl_ratchet.def", 4);
}

// `--next` with from_only: the one state's transitions, every chain kept; its answer is the one the
// whole envisionment gives, and no other state was given transitions.
void next_as_from_whole(const std::string& relative, int starts) {
    const auto m = testing::mechanism(relative);
    const Envisionment& whole = testing::envisioned_once(relative);
    EnvisionOptions o;
    o.rules = testing::rules_folder();
    std::mt19937 rng(11);
    for (int n = 0; n < starts; ++n) {
        const std::size_t chain = std::uniform_int_distribution<std::size_t>(0, whole.chains.size() - 1)(rng);
        const StateId s{std::uniform_int_distribution<std::uint32_t>(0, static_cast<std::uint32_t>(whole.chains[chain].states.size() - 1))(rng)};
        CAPTURE(relative);
        CAPTURE(from_option(whole, chain, s));
        EnvisionOptions only = o;
        only.from = from_option(whole, chain, s);
        only.from_only = true;
        const Envisionment got = testing::envisioned(m, only);
        REQUIRE(got.chains.size() == whole.chains.size());
        std::ostringstream a, b;
        Diagnostics d;
        REQUIRE(write_next(a, m, got, {chain, s}, o, d));
        REQUIRE(write_next(b, m, whole, {chain, s}, o, d));
        CHECK(a.str() == b.str());
        for (const auto& t : got.chains[chain].transitions) CHECK(t.from == s);
    }
}

TEST_CASE("envision/reachable: --next finds one state's transitions and answers as the whole envisionment does") {
    next_as_from_whole("scenarios/clock/escapement.def", 6);
    next_as_from_whole("tests/envision/scenes/two_chains.def", 4);
}

TEST_CASE("envision/reachable: a --from that names no state is bad input, located in the option") {
    const auto m = testing::mechanism("scenarios/clock/cam.def");
    EnvisionOptions o;
    o.rules = testing::rules_folder();
    o.cache = &testing::test_cache();
    o.from = "#100000";
    Diagnostics d;
    CHECK_FALSE(qm::envision::envision(m, o, d).has_value());
    CHECK(d.has_errors());
    CHECK(testing::printed(d).find("--from:1:") != std::string::npos);
}

}  // namespace
}  // namespace qm::envision
