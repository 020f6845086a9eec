// tests/envision/behaviour_graph_test.cpp: behavioural cycles, transient ones and the ends of
// behaviour on small graphs built by hand (9.1.5, 9.2.3).
#include "envision/behaviour_graph.hpp"
#include <doctest/doctest.h>

namespace qm::envision {
namespace {

State state(std::vector<std::int8_t> motions, bool may_rest = false) {
    State s;
    s.places = {geometry::PlaceId{0}};
    s.motions = std::move(motions);
    s.may_rest = may_rest;
    return s;
}

Transition edge(std::uint32_t a, std::uint32_t b, Duration d = Duration::interval) { return {StateId{a}, StateId{b}, d, Cause::kinematic}; }

TEST_CASE("a component in which a bounded coordinate moves one way throughout is transient, with that coordinate") {
    // Objects: 0 turns on a periodic axis, 1 slides along a bounded one.
    const std::vector<bool> bounded{false, true};
    const std::vector<State> states{state({+1, -1}), state({-1, -1}), state({+1, 0}), state({+1, +1}), state({0, 0})};
    const std::vector<Transition> one_way{edge(0, 1), edge(1, 0)};
    auto g = behaviour_graph(states, one_way, bounded);
    CHECK(g.cycles.empty());
    REQUIRE(g.transient.size() == 1);
    CHECK(g.transient[0].states == std::vector<StateId>{StateId{0}, StateId{1}});
    CHECK(g.transient[0].object == 1);
    CHECK(g.transient[0].motion == -1);
    // The slider still in one state, or moving both ways: the cycle can repeat.
    for (const auto& t : {std::vector<Transition>{edge(0, 2), edge(2, 0)}, std::vector<Transition>{edge(0, 3), edge(3, 0)}}) {
        g = behaviour_graph(states, t, bounded);
        CHECK(g.transient.empty());
        CHECK(g.cycles.size() == 1);
    }
    // The same lap with the sliding coordinate periodic (a wheel): a cycle.
    g = behaviour_graph(states, one_way, {false, false});
    CHECK(g.cycles.size() == 1);
    CHECK(g.transient.empty());
    // A state leading back to itself over an interval, moving along the bounded axis: transient.
    g = behaviour_graph(states, std::vector<Transition>{edge(1, 1)}, bounded);
    CHECK(g.transient.size() == 1);
    // ...over an instant it is no cycle at all.
    g = behaviour_graph(states, std::vector<Transition>{edge(1, 1, Duration::instant)}, bounded);
    CHECK(g.transient.empty());
    CHECK(g.cycles.empty());
}

TEST_CASE("a wheel turning one way throughout is transient only where a pair's places keep it from coming round") {
    // Objects: 0 and 1 both turn on periodic axes; pair 3 keeps object 0 (and nothing else) confined.
    const std::vector<State> states{state({+1, -1}), state({+1, +1})};
    const std::vector<Transition> lap{edge(0, 1), edge(1, 0)};
    std::vector<std::pair<std::vector<StateId>, std::size_t>> asked;
    const KeptFromComingRound kept = [&](const std::vector<StateId>& members, std::size_t object) -> std::optional<std::size_t> {
        asked.emplace_back(members, object);
        return object == 0 ? std::optional<std::size_t>{3} : std::nullopt;
    };
    auto g = behaviour_graph(states, lap, {false, false}, kept);
    CHECK(g.cycles.empty());
    REQUIRE(g.transient.size() == 1);
    CHECK(g.transient[0].object == 0);
    CHECK(g.transient[0].motion == +1);
    CHECK(g.transient[0].pair == std::optional<std::size_t>{3});
    // Object 1 changes its motion on the lap, so only object 0 is asked about.
    CHECK(asked == std::vector<std::pair<std::vector<StateId>, std::size_t>>{{{StateId{0}, StateId{1}}, 0}});
    // A pair whose places go round: the lap can repeat.
    g = behaviour_graph(states, lap, {false, false}, [](const std::vector<StateId>&, std::size_t) { return std::optional<std::size_t>{}; });
    CHECK(g.cycles.size() == 1);
    CHECK(g.transient.empty());
    // A bounded coordinate is reported as such, before any pair is asked.
    g = behaviour_graph(states, lap, {true, false}, kept);
    REQUIRE(g.transient.size() == 1);
    CHECK(!g.transient[0].pair);
}

TEST_CASE("terminal states have no transition out; possible rests have some and may also stay") {
    const std::vector<State> states{state({0, 0}, true), state({+1, 0}), state({0, 0}, true), state({0, 0})};
    const std::vector<Transition> t{edge(0, 1), edge(1, 2), edge(3, 1)};
    const auto g = behaviour_graph(states, t, {false, false});
    CHECK(g.terminal == std::vector<StateId>{StateId{2}});
    CHECK(g.possible_rests == std::vector<StateId>{StateId{0}});
    CHECK(g.ends() == 2);
}

}  // namespace
}  // namespace qm::envision
