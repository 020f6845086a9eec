// tests/envision/behaviour_query_test.cpp: the graph questions (envision/behaviour_query.hpp) on
// bundled mechanisms: a described behaviour `#a ; #b` is found exactly when b is reachable from a
// (reachability checked by a plain depth-first search here), every path found follows transitions,
// matches its descriptions in order and is shortest (breadth-first: no path with fewer states has
// the endpoints); descriptions by place kind and motion match the states they name; avoided states
// are never on a path; and bad descriptions are located errors.
#include "envision/behaviour_query.hpp"
#include "envision_fixture.hpp"

#include <random>
#include <set>

using namespace qm;
using namespace qm::envision;
using namespace qm::envision::testing;

namespace {

std::vector<bool> dfs(const ChainEnvisionment& c, StateId from) {
    std::vector<bool> seen(c.states.size(), false);
    std::vector<StateId> stack{from};
    while (!stack.empty()) {
        const StateId s = stack.back();
        stack.pop_back();
        if (seen[s.value]) continue;
        seen[s.value] = true;
        for (const auto& t : c.transitions)
            if (t.from == s) stack.push_back(t.to);
    }
    return seen;
}

std::size_t distance(const ChainEnvisionment& c, StateId a, StateId b) {
    std::vector<std::size_t> d(c.states.size(), SIZE_MAX);
    std::vector<StateId> frontier{a};
    d[a.value] = 0;
    for (std::size_t k = 0; !frontier.empty(); ++k) {
        std::vector<StateId> next;
        for (const StateId s : frontier)
            for (const auto& t : c.transitions)
                if (t.from == s && d[t.to.value] == SIZE_MAX) {
                    d[t.to.value] = k + 1;
                    next.push_back(t.to);
                }
        frontier = std::move(next);
    }
    return d[b.value];
}

}  // namespace

TEST_CASE("envision/behaviour_query: a path between two states exists exactly when one reaches the other, and is shortest") {
    std::mt19937 rng(3);
    for (const char* file : {"scenarios/metric/cam.def", "scenarios/clock/ratchet.def"}) {
        CAPTURE(file);
        const auto& e = envisioned_once(file);
        const auto& c = e.chains[0];
        std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(c.states.size() - 1));
        for (int round = 0; round < 40; ++round) {
            const StateId a{pick(rng)}, b{pick(rng)};
            Diagnostics d;
            const auto beh = parse_behaviour(e, "#" + std::to_string(a.value) + " ; #" + std::to_string(b.value), "--path", {}, d);
            REQUIRE(beh.has_value());
            const auto answer = find_behaviour(e, *beh);
            CHECK(reachable_from(c, a) == dfs(c, a));
            const bool reachable = dfs(c, a)[b.value];
            CHECK(!answer.path.empty() == reachable);
            if (answer.path.empty()) continue;
            CHECK(answer.path.front() == a);
            CHECK(answer.path.back() == b);
            for (std::size_t i = 1; i < answer.path.size(); ++i) CHECK(has_transition(c, answer.path[i - 1], answer.path[i]));
            if (a != b) CHECK(answer.path.size() == distance(c, a, b) + 1);
        }
    }
}

TEST_CASE("envision/behaviour_query: descriptions by kind and motion, avoided states, and what cannot be matched") {
    const auto& e = envisioned_once("scenarios/clock/ratchet.def");
    const auto& c = e.chains[0];
    Diagnostics d;
    const auto beh = parse_behaviour(e, "ratchet-wheel/pawl:free ratchet-wheel=0 pawl=0 ; ratchet-wheel=0 pawl=0 ratchet-wheel/pawl:join", "--path",
                                     {"ratchet-wheel/pawl:cseg"}, d);
    REQUIRE_MESSAGE(beh.has_value(), printed(d));
    const auto answer = find_behaviour(e, *beh);
    REQUIRE(!answer.path.empty());
    CHECK(matches(e, c, answer.path.front(), beh->steps[0]));
    CHECK(matches(e, c, answer.path.back(), beh->steps[1]));
    for (const StateId s : answer.path) {
        CHECK(!matches(e, c, s, beh->avoid[0]));
        const auto& place = e.pairs[c.chain.pairs[0]].vocabulary.at(c.states[s].places[0]);
        CHECK(place.kind != geometry::PlaceKind::cseg);
    }
    const auto& first = e.pairs[c.chain.pairs[0]].vocabulary.at(c.states[answer.path.front()].places[0]);
    CHECK(first.normals.empty());  // free: no contact
    CHECK(c.states[answer.path.front()].motions == std::vector<std::int8_t>{0, 0});
    // Nothing follows a terminal state.
    REQUIRE(!c.graph.terminal.empty());
    const auto stuck = parse_behaviour(e, "#" + std::to_string(c.graph.terminal[0].value) + " ; ratchet-wheel=+", "--path", {}, d);
    REQUIRE(stuck.has_value());
    const auto none = find_behaviour(e, *stuck);
    CHECK(none.path.empty());
    CHECK(none.matched == 1);
    CHECK(none.farthest == c.graph.terminal[0]);
    // Errors, located in the option's text.
    for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
             {"wheel=+", "--path:1:1: error: unknown part 'wheel'"},
             {"pawl=x", "--path:1:6: error: expected a motion +, 0 or -, not 'x'"},
             {"ratchet-wheel/pawl:corner", "--path:1:20: error: unknown kind of place 'corner'"},
             {"ratchet-wheel/pawl-999", "--path:1:1: error: pair 'ratchet-wheel/pawl' has no place 999"},
             {"pawl=+ ; ; pawl=-", "--path:1:1: error: expected a state description"},
             {"#99999", "no state 99999"},
             {"bogus", "--path:1:1: error: expected PAIR-PLACE, PAIR:KIND, PART=MOTION, #ID, terminal, rest, cycle or transient, not 'bogus'"}}) {
        Diagnostics bad;
        CHECK(!parse_behaviour(e, text, "--path", {}, bad).has_value());
        CHECK_MESSAGE(printed(bad).find(message) != std::string::npos, printed(bad));
    }
}

TEST_CASE("envision/behaviour_query: terms for where behaviour ends and for cycles match the graph's own lists") {
    const auto& e = envisioned_once("scenarios/clock/cam_free.def");
    const auto& c = e.chains.at(0);
    auto set_of = [&](const std::string& text) {
        Diagnostics d;
        const auto b = parse_behaviour(e, text, "--path", {}, d);
        REQUIRE_MESSAGE(b.has_value(), printed(d));
        std::set<std::uint32_t> out;
        for (std::uint32_t s = 0; s < c.states.size(); ++s)
            if (matches(e, c, StateId{s}, b->steps.at(0))) out.insert(s);
        return out;
    };
    std::set<std::uint32_t> terminal, rest, cycle, transient;
    for (const auto s : c.graph.terminal) terminal.insert(s.value), rest.insert(s.value);
    for (const auto s : c.graph.possible_rests) rest.insert(s.value);
    for (const auto& x : c.graph.cycles)
        for (const auto s : x) cycle.insert(s.value);
    for (const auto& x : c.graph.transient)
        for (const auto s : x.states) transient.insert(s.value);
    REQUIRE(!cycle.empty());
    REQUIRE(!transient.empty());
    CHECK(set_of("terminal") == terminal);
    CHECK(set_of("rest") == rest);
    CHECK(set_of("cycle") == cycle);
    CHECK(set_of("transient") == transient);
    // A conjunction narrows them.
    std::set<std::uint32_t> still;
    for (const auto s : transient)
        if (c.states[StateId{s}].motions[0] == 1) still.insert(s);
    CHECK(set_of("transient cam=+") == still);
    const auto& r = envisioned_once("scenarios/clock/ratchet.def");
    Diagnostics d;
    const auto b = parse_behaviour(r, "ratchet-wheel/pawl:free ratchet-wheel=0 pawl=0 ; terminal", "--path", {}, d);
    REQUIRE(b.has_value());
    const auto a = find_behaviour(r, *b);
    REQUIRE(!a.path.empty());
    CHECK(std::binary_search(r.chains[0].graph.terminal.begin(), r.chains[0].graph.terminal.end(), a.path.back()));
}
