// tests/envision/multi_pair_test.cpp: mechanisms of several interacting kinematic pairs in one
// kinematic chain (scenarios/clock/pawl_ratchet.def, geneva_detent.def, crank_latch.def,
// escapement_train.def), each asked whether it does what the comment at the head of its file
// promises, as the graph questions of envision/behaviour_query.hpp ask it (9.1.5, 11.2.2):
// - the chain is one chain with more than one pair in which the parts touch (non-trivial pairs);
// - the behaviour the file names (the ratchet wheel driven one way by the lever's pawl; the Geneva
//   wheel turned by the pin and held by the detent; the slider striking the latch, which swings
//   and springs back; de Carle's cycle of the escapement with its train turning, 9.1.5);
// - no terminal state with a driven part moving through free space (nothing stops it there);
// - the invariants every envisionment keeps (envision/verify.hpp, tests/envision/invariants.hpp).
#include "envision/behaviour_query.hpp"
#include "envision/verify.hpp"
#include "envision_fixture.hpp"
#include "invariants.hpp"

#include <algorithm>

using namespace qm;
using namespace qm::envision;
using namespace qm::envision::testing;

namespace {

struct PairsScene {
    const Envisionment& e;
    const ChainEnvisionment& c;
    explicit PairsScene(const Envisionment& env) : e(env), c(env.chains.at(0)) {}

    std::size_t pair(const std::string& name) const {  // position of pair "A/B" in the chain
        for (std::size_t k = 0; k < c.chain.pairs.size(); ++k)
            if (e.pairs[c.chain.pairs[k]].name == name) return k;
        FAIL("no pair " << name);
        return 0;
    }
    std::size_t object(const std::string& name) const {  // position of a part among the objects
        for (std::size_t k = 0; k < c.chain.objects.size(); ++k)
            if (e.parts[c.chain.objects[k].value] == name) return k;
        FAIL("no part " << name);
        return 0;
    }
    const geometry::Place& place(StateId s, std::size_t pair) const {
        return e.pairs[c.chain.pairs[pair]].vocabulary.places[c.states[s].places.at(pair).value];
    }
    bool touching(StateId s, std::size_t pair) const { return !place(s, pair).normals.empty(); }
    std::int8_t motion(StateId s, std::size_t object) const { return c.states[s].motions.at(object); }
    std::size_t size() const { return c.states.size(); }
};

BehaviourAnswer ask_pairs(const PairsScene& s, const std::string& steps, const std::vector<std::string>& avoid = {}) {
    Diagnostics d;
    auto b = parse_behaviour(s.e, steps, "--path", avoid, d);
    REQUIRE_MESSAGE(b.has_value(), printed(d));
    return find_behaviour(s.e, *b);
}

// One chain, every declared pair in it, and more than one pair with states in contact.
void one_chain_of_interacting_pairs(const PairsScene& s, std::size_t pairs) {
    REQUIRE(s.e.chains.size() == 1);
    CHECK(s.c.chain.pairs.size() == pairs);
    std::size_t interacting = 0;
    for (std::size_t p = 0; p < s.c.chain.pairs.size(); ++p) {
        bool contact = false, free = false;
        for (std::uint32_t v = 0; v < s.size(); ++v) (s.touching(StateId{v}, p) ? contact : free) = true;
        CAPTURE(s.e.pairs[s.c.chain.pairs[p]].name);
        CHECK(contact);
        interacting += contact && s.e.pairs[s.c.chain.pairs[p]].vocabulary.places.size() > 1 ? 1 : 0;
    }
    CHECK(interacting >= 2);
}

// Terminal states in which a part moves while no pair of it touches: nothing stops it there.
std::vector<StateId> stuck_in_free_space(const PairsScene& s, std::size_t part, const std::vector<std::size_t>& its_pairs) {
    std::vector<StateId> out;
    for (const StateId t : s.c.graph.terminal) {
        bool free = s.motion(t, part) != 0;
        for (const auto p : its_pairs) free = free && !s.touching(t, p);
        if (free) out.push_back(t);
    }
    return out;
}

const std::vector<std::string> turning_forward(const std::string& part, char forward) {
    const std::string other = forward == '+' ? "-" : "+";
    return {part + "=0", part + "=" + other};
}

}  // namespace

TEST_CASE("envision/multi_pair: pawl_ratchet, a crank rocks a lever whose pawl drives the ratchet wheel") {
    const PairsScene s(envisioned_once("scenarios/clock/pawl_ratchet.def"));
    one_chain_of_interacting_pairs(s, 2);
    // The crank turning counter-clockwise throughout: the lever pushes the wheel clockwise on its
    // forward stroke, comes back, and pushes it clockwise again.
    const auto a = ask_pairs(s, "lever/ratchet-wheel:contact lever=+ ratchet-wheel=- ; lever=- ; lever/ratchet-wheel:contact lever=+ ratchet-wheel=-",
                       turning_forward("crank", '+'));
    REQUIRE(!a.path.empty());
    CHECK(path_follows_transitions(s.c, a.path));
}

TEST_CASE("envision/multi_pair: pawl_ratchet, the crank never stops in free space") {
    const PairsScene s(envisioned_once("scenarios/clock/pawl_ratchet.def"));
    CHECK(stuck_in_free_space(s, s.object("crank"), {s.pair("crank/lever")}).empty());
}

TEST_CASE("envision/multi_pair: [large] geneva_detent, the pin turns the wheel a quarter turn, the detent holds it between") {
    const PairsScene s(envisioned_once("scenarios/clock/geneva_detent.def"));
    one_chain_of_interacting_pairs(s, 2);
    const auto pin = s.pair("driver/wheel"), detent = s.pair("wheel/detent");
    const auto wheel = s.object("wheel");
    // The driver turning clockwise throughout: the pin in a slot turns the wheel counter-clockwise,
    // leaves it, the wheel comes to rest with the detent against it, and the pin enters again.
    const auto a = ask_pairs(s, "driver/wheel:contact driver=- wheel=+ ; driver/wheel:free wheel/detent:contact wheel=0 ; driver/wheel:contact driver=- wheel=+",
                       turning_forward("driver", '-'));
    REQUIRE(!a.path.empty());
    CHECK(path_follows_transitions(s.c, a.path));
    // Held: a state with the pin clear, the wheel at rest and the roller in a slot's mouth (a
    // concave join, touching both corners), reached from the pin turning the wheel.
    bool held = false;
    for (std::uint32_t v = 0; v < s.size() && !held; ++v) {
        const StateId x{v};
        held = !s.touching(x, pin) && s.motion(x, wheel) == 0 && s.place(x, detent).kind == geometry::PlaceKind::join &&
               s.place(x, detent).concave == std::optional<bool>(true);
    }
    CHECK(held);
}

TEST_CASE("envision/multi_pair: [large] geneva_detent, the driver never stops in free space") {
    const PairsScene s(envisioned_once("scenarios/clock/geneva_detent.def"));
    CHECK(stuck_in_free_space(s, s.object("driver"), {s.pair("driver/wheel")}).empty());
}

TEST_CASE("envision/multi_pair: crank_latch, the slider strikes the latch, which swings and springs back to its stop") {
    const PairsScene s(envisioned_once("scenarios/clock/crank_latch.def"));
    one_chain_of_interacting_pairs(s, 3);
    // The crank turning counter-clockwise throughout: the latch rests on its stop, the slider
    // strikes it and pushes it aside, the latch swings back and lands on the stop again.
    const auto a = ask_pairs(s, "latch/stop:contact slider/latch:free crank=+ latch=0 ; slider/latch:contact slider=+ latch=+ ; "
                          "slider/latch:free latch=- ; latch/stop:contact latch=0",
                       turning_forward("crank", '+'));
    REQUIRE(!a.path.empty());
    CHECK(path_follows_transitions(s.c, a.path));
    // The latch moves only when the slider has struck it, or springs back (never pushed the other
    // way: its spring and the slider both act along its axis, the spring towards the stop).
    const auto latch = s.object("latch");
    bool pushed = false;
    for (std::uint32_t v = 0; v < s.size(); ++v)
        pushed = pushed || (s.touching(StateId{v}, s.pair("slider/latch")) && s.motion(StateId{v}, latch) == +1);
    CHECK(pushed);
}

TEST_CASE("envision/multi_pair: crank_latch, the crank never stops while turning in free space") {
    const PairsScene s(envisioned_once("scenarios/clock/crank_latch.def"));
    CHECK(stuck_in_free_space(s, s.object("crank"), {s.pair("crank/slider")}).empty());
}

TEST_CASE("envision/multi_pair: [large] escapement_train, de Carle's cycle with the gear train turning through its play (9.1.5)") {
    const PairsScene s(envisioned_once("scenarios/clock/escapement_train.def"));
    one_chain_of_interacting_pairs(s, 3);
    // Each gear pair keeps its play (gap-epsilon 0): the band between two CSEG loops, 3 places.
    for (const auto& name : {"gear-1/gear-2", "gear-3/gear-4"})
        CHECK(s.e.pairs[s.c.chain.pairs[s.pair(name)]].vocabulary.places.size() == 3);
    const std::string P = "scape-wheel/pallets";
    const auto a = ask_pairs(s, P + "-4 scape-wheel=- pallets=+ ; " + P + ":free scape-wheel=- ; " + P + "-57 scape-wheel=+ ; " + P +
                              "-57 scape-wheel=- pallets=- ; " + P + ":free scape-wheel=- ; " + P + "-54 scape-wheel=+ ; " + P +
                              "-54 scape-wheel=- pallets=+ ; " + P + ":free scape-wheel=- ; " + P + "-4 scape-wheel=- pallets=+");
    REQUIRE(!a.path.empty());
    CHECK(path_follows_transitions(s.c, a.path));
    // The pallets rock both ways, the last gear turns the spring's way (clockwise) on the path, and
    // the path after its first state (the train's play taken up) lies on one behavioural cycle.
    const auto pallets = s.object("pallets"), gear4 = s.object("gear-4"), wheel = s.object("scape-wheel");
    bool up = false, down = false, driven = false, recoil = false;
    for (const StateId x : a.path) {
        up = up || s.motion(x, pallets) == +1;
        down = down || s.motion(x, pallets) == -1;
        driven = driven || s.motion(x, gear4) == -1;
        recoil = recoil || s.motion(x, wheel) == +1;
    }
    CHECK(up);
    CHECK(down);
    CHECK(driven);
    CHECK(recoil);
    const auto k = cycle_of(s.c, a.path.back());
    REQUIRE(k != SIZE_MAX);
    for (std::size_t i = 1; i < a.path.size(); ++i) CHECK(cycle_of(s.c, a.path[i]) == k);
    // The linked parts turn as one, and nothing ends the train's motion for good.
    for (std::uint32_t v = 0; v < s.size(); ++v)
        CHECK(s.motion(StateId{v}, wheel) == s.motion(StateId{v}, s.object("gear-1")));
    CHECK(s.c.graph.terminal.empty());
}

static void keeps_the_invariants(const std::string& scene) {
    CAPTURE(scene);
    const auto m = mechanism(scene);
    const auto& e = envisioned_once(scene);
    std::string all;
    for (const auto& p : verify(m, e)) all += p + "\n";
    for (const auto& p : testing::invariant_problems(m, e)) all += "independently: " + p + "\n";
    CHECK_MESSAGE(all.empty(), all);
}

TEST_CASE("envision/multi_pair: the crank and latch keep the invariants") { keeps_the_invariants("scenarios/clock/crank_latch.def"); }

TEST_CASE("envision/multi_pair: [large] the escapement with its train keeps the invariants") {
    keeps_the_invariants("scenarios/clock/escapement_train.def");
}

TEST_CASE("envision/multi_pair: the pawl and ratchet keep the invariants") {
    keeps_the_invariants("scenarios/clock/pawl_ratchet.def");
}

TEST_CASE("envision/multi_pair: [large] the Geneva drive keeps the invariants") {
    keeps_the_invariants("scenarios/clock/geneva_detent.def");
}

TEST_CASE("envision/multi_pair: clock, a gear pair wrapping while the escapement stays in a face is no cycle") {
    keeps_the_invariants("scenarios/clock/clock.def");
    const auto& e = envisioned_once("scenarios/clock/clock.def");
    const auto train = std::find_if(e.chains.begin(), e.chains.end(), [&](const ChainEnvisionment& c) { return c.chain.pairs.size() > 1; });
    REQUIRE(train != e.chains.end());
    const PairsScene s{e};
    REQUIRE(&s.c == &*train);
    const std::size_t wheel = s.object("scape-wheel");
    // A lap that keeps the escapement in one place cannot turn the scape wheel round: the wheel
    // meets a pallet within a tooth's pitch wherever the anchor is not clear of it.
    for (const auto& cycle : s.c.graph.cycles) {
        CAPTURE(cycle.front().value);
        CHECK(!(cycle.size() == 1 && s.motion(cycle.front(), wheel) != 0));
    }
    // Such a lap, where one is found, is transient for the escapement's places, never a cycle.
    for (const auto& t : s.c.graph.transient) {
        CAPTURE(t.states.front().value);
        CHECK(t.pair.has_value());
        if (t.pair) CHECK(s.e.pairs[s.c.chain.pairs[*t.pair]].name == "scape-wheel/pallets");
        for (const auto v : t.states) CHECK(s.motion(v, t.object) == t.motion);
    }
}
