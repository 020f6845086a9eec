// tests/envision/acceptance_test.cpp: the thesis' own results on the bundled mechanisms of
// scenarios/clock/, each asked as the graph questions of
// envision/behaviour_query.hpp ask it (described behaviours, 9.1.5, 11.2.2):
// - the whole clock has two kinematic chains, the ratchet's apart from the train (9.1.3);
// - a gear pair abstracts to one place, so a train of any length has one place vector (8.1.6);
// - the escapement holds de Carle's cycle (9.1.5): impulse on one pallet, drop, a tooth falling on
//   the other pallet (a collision), recoil, impulse the other way, and back, inside the operating
//   region; the free-spinning cycle of Figure 9.23; the pallets inverted (Figures 9.22, 9.24);
// - the ratchet jams from rest in free space (Figure 9.27) and skips (Figure 9.28);
// - the Scotch yoke's crank keeps turning while the yoke stops and reverses (Figure 9.32);
// - the cam's follower rides up and down with the cam under its return force, and without it is
//   pushed away and the cam turns freely (9.4).
// Place ids named in descriptions are checked against the geometry (kind, side) first, so a change
// of vocabulary fails here with a message rather than silently asking another question.
#include "envision/behaviour_query.hpp"
#include "envision/chain.hpp"
#include "envision_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

using namespace qm;
using namespace qm::envision;
using namespace qm::envision::testing;

namespace {

// Under ASan+UBSan (Debug) the whole clock's eight vocabularies and the full-turn escapement's 1,360
// states take most of a quarter of an hour from a cold cache; there the small mechanisms (gears,
// ratchet, yoke, cams) exercise the same code, and the escapement's and the clock's questions run
// in the Release suite only.
#if defined(QM_SANITIZED_BUILD)
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif
#if defined(NDEBUG)
constexpr bool optimised = true;
#else
constexpr bool optimised = false;
#endif
constexpr bool release_only = sanitized || !optimised;

struct Scene {
    const Envisionment& e;
    const ChainEnvisionment& c;
    const bridge::PairPlaces& pair;  // the chain's first pair
    explicit Scene(const Envisionment& env)
        : e(env), c(env.chains.at(0)), pair(env.pairs.at(env.chains.at(0).chain.pairs.at(0))) {}
};

const geometry::Place& place_of(const Scene& s, StateId id) {
    return s.pair.vocabulary.places[s.c.states[id].places.at(0).value];
}

// The mean of a place's points along axis q1 (the second part's coordinate).
double q1_of(const geometry::Place& p) {
    REQUIRE(!p.points.empty());
    double sum = 0;
    for (const auto& x : p.points) sum += x.y();
    return sum / static_cast<double>(p.points.size());
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

bool touching(const geometry::Place& p) { return !p.normals.empty(); }

std::int8_t motion(const Scene& s, StateId id, std::size_t object) { return s.c.states[id].motions.at(object); }

BehaviourAnswer ask(const Scene& s, const std::string& steps, const std::vector<std::string>& avoid = {}) {
    Diagnostics d;
    auto b = parse_behaviour(s.e, steps, "--path", avoid, d);
    REQUIRE_MESSAGE(b.has_value(), printed(d));
    return find_behaviour(s.e, *b);
}

std::optional<StateId> named(const Scene& s, const std::vector<std::uint32_t>& places, const std::vector<std::int8_t>& motions) {
    State want;
    for (const auto p : places) want.places.push_back(geometry::PlaceId{p});
    want.motions = motions;
    return s.c.states.find(want);
}

}  // namespace

TEST_CASE("envision/acceptance: the whole clock has two kinematic chains, the ratchet apart from the train (9.1.3)" * doctest::skip(release_only)) {
    const auto m = mechanism("scenarios/clock/clock.def");
    const auto pairs = pairs_of(m);
    const auto chains = kinematic_chains(m, pairs);
    REQUIRE(chains.size() == 2);
    std::set<std::string> first, second;
    for (const auto o : chains[0].objects) first.insert(m.parts[o].name);
    for (const auto o : chains[1].objects) second.insert(m.parts[o].name);
    const bool ratchet_first = first.contains("ratchet-wheel");
    const auto& ratchet = ratchet_first ? first : second;
    const auto& train = ratchet_first ? second : first;
    CHECK(ratchet == std::set<std::string>{"ratchet-wheel", "pawl"});
    CHECK(train.contains("scape-wheel"));
    CHECK(train.contains("pallets"));
    CHECK(train.size() > 6);
}

TEST_CASE("envision/acceptance: a gear pair is one place, and a train of any length one place vector (8.1.6)") {
    for (const char* file : {"scenarios/clock/gear_pair.def", "scenarios/clock/gear_train.def"}) {
        CAPTURE(file);
        const auto& e = envisioned_once(file);
        REQUIRE(e.chains.size() == 1);
        for (const auto& p : e.pairs) CHECK(p.vocabulary.places.size() == 1);
        std::set<std::vector<geometry::PlaceId>> vectors;
        for (const auto& s : e.chains[0].states.states()) vectors.insert(s.places);
        CHECK(vectors.size() == 1);
        // Linked and meshing parts turn together: the chain's states are its one place with all
        // parts at rest or all turning, one way or the other (3 states, however long the train).
        CHECK(e.chains[0].states.size() == 3);
    }
}

TEST_CASE("envision/acceptance: the escapement's normal operating cycle, de Carle's description (9.1.5, Figure 9.21)" * doctest::skip(release_only)) {
    const Scene s(envisioned_once("scenarios/clock/escapement.def"));
    const auto& places = s.pair.vocabulary.places;
    const double hanging = std::numbers::pi;  // the pallets' coordinate 0 is inverted (escapement.def)
    // The places the description names: join 4 and CSEG 54 on one pallet (pallets swung below
    // 180 degrees), CSEG 57 on the other (above), all inside the operating region.
    for (const std::uint32_t id : {4u, 54u, 57u}) {
        CAPTURE(id);
        REQUIRE(touching(places[id]));
        CHECK(std::abs(q1_of(places[id]) - hanging) < 23.0 * std::numbers::pi / 180.0);
    }
    CHECK(places[54].kind == geometry::PlaceKind::cseg);
    CHECK(places[57].kind == geometry::PlaceKind::cseg);
    CHECK(q1_of(places[4]) < hanging);
    CHECK(q1_of(places[54]) < hanging);
    CHECK(q1_of(places[57]) > hanging);

    // Impulse on the first pallet (both turning), the tooth drops off and the wheel turns free,
    // a tooth lands on the other pallet and the wheel recoils, impulse there with the pallets
    // swinging back, drop, land on the first pallet, recoil, impulse, and the same state again.
    const std::string P = "scape-wheel/pallets";
    const auto a = ask(s, P + "-4 scape-wheel=- pallets=+ ; " + P + ":free scape-wheel=- ; " + P + "-57 scape-wheel=+ ; " + P +
                              "-57 scape-wheel=- pallets=- ; " + P + ":free scape-wheel=- ; " + P + "-54 scape-wheel=+ ; " + P +
                              "-54 scape-wheel=- pallets=+ ; " + P + ":free scape-wheel=- ; " + P + "-4 scape-wheel=- pallets=+");
    REQUIRE(!a.path.empty());
    CHECK(a.path.front() == a.path.back());
    CHECK(path_follows_transitions(s.c, a.path));
    // The whole cycle stays in the operating region (within about 23 degrees of hanging).
    for (const StateId x : a.path) CHECK(std::abs(q1_of(place_of(s, x)) - hanging) < 23.0 * std::numbers::pi / 180.0);
    // A tooth lands on each pallet by collision (5.3.3), and the wheel recoils after each landing.
    int landings_below = 0, landings_above = 0;
    for (std::size_t k = 1; k < a.path.size(); ++k)
        if (has_transition(s.c, a.path[k - 1], a.path[k], Cause::collision) && !touching(place_of(s, a.path[k - 1]))) {
            (q1_of(place_of(s, a.path[k])) < hanging ? landings_below : landings_above) += 1;
            CHECK(motion(s, a.path[k], 0) == +1);  // the recoil: the wheel driven back
        }
    CHECK(landings_below >= 1);
    CHECK(landings_above >= 1);
    // The cycle is one of the envisionment's behavioural cycles.
    const auto k = cycle_of(s.c, a.path.front());
    REQUIRE(k != SIZE_MAX);
    for (const StateId x : a.path) CHECK(cycle_of(s.c, x) == k);
}

TEST_CASE("envision/acceptance: the escapement spins free with the pallets hanging still (Figure 9.23)" * doctest::skip(release_only)) {
    const Scene s(envisioned_once("scenarios/clock/escapement.def"));
    // A behavioural cycle in which no state touches, the pallets do not move and hang within 3
    // degrees of straight down, and the wheel turns (either way; the spring's way is clockwise).
    bool clockwise = false;
    for (const auto& cycle : s.c.graph.cycles) {
        bool all = true;
        for (const StateId x : cycle) {
            const auto& p = place_of(s, x);
            all = all && !touching(p) && motion(s, x, 1) == 0 && motion(s, x, 0) == -1 &&
                  std::abs(degrees(q1_of(p)) - 180.0) < 3.0;
        }
        clockwise = clockwise || all;
    }
    CHECK(clockwise);
}

TEST_CASE("envision/acceptance: the pallets inverted (Figures 9.22, 9.24)" * doctest::skip(release_only)) {
    const Scene s(envisioned_once("scenarios/clock/escapement.def"));
    // Figure 9.24: upside down the pallets clear the wheel; the wheel spins free while they
    // balance at the top (a cycle at the external division there).
    bool balanced_on_top = false;
    for (const auto& cycle : s.c.graph.cycles) {
        bool all = true;
        for (const StateId x : cycle) {
            const double q = degrees(q1_of(place_of(s, x)));
            all = all && !touching(place_of(s, x)) && motion(s, x, 1) == 0 && motion(s, x, 0) != 0 &&
                  std::min(std::abs(q), std::abs(q - 360.0)) < 1.0;
        }
        balanced_on_top = balanced_on_top || all;
    }
    CHECK(balanced_on_top);
    // Figure 9.22: turned over past the blocked bands (65 to 80 degrees from hanging) the pallets
    // still meet the teeth with the outer sides of their arms, in states that lie on a behavioural
    // cycle with the pallets falling through free space.
    std::size_t over = 0, on_cycle = 0;
    for (std::uint32_t v = 0; v < s.c.states.size(); ++v) {
        const StateId x{v};
        const double from_hanging = std::abs(degrees(q1_of(place_of(s, x))) - 180.0);
        if (!touching(place_of(s, x)) || from_hanging < 65.0 || from_hanging > 80.0) continue;
        ++over;
        on_cycle += cycle_of(s.c, x) != SIZE_MAX ? 1 : 0;
    }
    CHECK(over > 0);
    CHECK(on_cycle > 0);
}

TEST_CASE("envision/acceptance: the ratchet jams from rest in free space (9.2.3, Figure 9.27)") {
    const Scene s(envisioned_once("scenarios/clock/ratchet.def"));
    REQUIRE(!s.c.graph.terminal.empty());
    bool reached = false;
    for (const StateId jam : s.c.graph.terminal) {
        const auto& p = place_of(s, jam);
        // The pawl's tip in the corner of a tooth gap: a concave join, nothing moving.
        CHECK(p.kind == geometry::PlaceKind::join);
        CHECK(p.concave == std::optional<bool>(true));
        CHECK(motion(s, jam, 0) == 0);
        CHECK(motion(s, jam, 1) == 0);
        const auto a = ask(s, "ratchet-wheel/pawl:free ratchet-wheel=0 pawl=0 ; #" + std::to_string(jam.value));
        reached = reached || !a.path.empty();
    }
    CHECK(reached);
}

TEST_CASE("envision/acceptance: the ratchet skips, the pawl bouncing on the turning wheel (Figure 9.28)") {
    const Scene s(envisioned_once("scenarios/clock/ratchet.def"));
    // With the wheel turning counter-clockwise throughout (the spring's way), a tooth strikes the
    // pawl up, the pawl falls back through free space, and the same state comes round again: the
    // wheel's axis is one tooth pitch (8.1.6), so that is the next tooth.
    std::size_t cycles = 0;
    for (std::uint32_t v = 0; v < s.c.states.size(); ++v) {
        const StateId x{v};
        if (!touching(place_of(s, x)) || motion(s, x, 0) != +1 || motion(s, x, 1) != +1) continue;
        const auto a = ask(s, "#" + std::to_string(v) + " ; ratchet-wheel/pawl:free pawl=- ; #" + std::to_string(v),
                           {"ratchet-wheel=0", "ratchet-wheel=-"});
        if (a.path.size() < 3) continue;
        ++cycles;
        CHECK(path_follows_transitions(s.c, a.path));
        for (const StateId y : a.path) CHECK(motion(s, y, 0) == +1);
    }
    CHECK(cycles > 0);
}

TEST_CASE("envision/acceptance: the Scotch yoke's crank keeps turning, the yoke stops and reverses (Figure 9.32)") {
    const Scene s(envisioned_once("scenarios/clock/scotch_yoke.def"));
    const std::vector<std::string> crank_turning{"crank=0", "crank=-"};
    // The slot has play (0.3 wide for a pin of 0.2: scotch_yoke.def), so at each end of the stroke
    // the yoke coasts across it and the pin strikes the slot's other side: the yoke stops and turns
    // back within that collision (5.3.3), while the crank turns on.
    // With the crank turning counter-clockwise (the motor's way) throughout, the yoke pushed one way
    // and then the other, and round again to the same state.
    std::size_t cycles = 0;
    for (std::uint32_t v = 0; v < s.c.states.size() && cycles == 0; ++v) {
        const StateId x{v};
        if (!touching(place_of(s, x)) || motion(s, x, 0) != +1 || motion(s, x, 1) != +1) continue;
        const auto a = ask(s, "#" + std::to_string(v) + " ; crank/yoke:contact yoke=- ; #" + std::to_string(v), crank_turning);
        if (a.path.size() < 3) continue;
        ++cycles;
        CHECK(path_follows_transitions(s.c, a.path));
        // The yoke changes direction only through rest or by a collision (Law 3: continuity;
        // 5.3.3: a collision's motion is the qualitative sum).
        for (std::size_t k = 1; k < a.path.size(); ++k)
            if (motion(s, a.path[k - 1], 1) * motion(s, a.path[k], 1) == -1)
                CHECK(has_transition(s.c, a.path[k - 1], a.path[k], Cause::collision));
    }
    CHECK(cycles == 1);
}

TEST_CASE("envision/acceptance: the cam's follower rides with the cam, and without its return force is pushed away (9.4)") {
    const std::string ride = "cam/follower-5 cam=+ follower=+ ; cam/follower-1 ; cam/follower-6 follower=- ; cam/follower-0 ; "
                             "cam/follower-5 cam=+ follower=+";
    const std::vector<std::string> cam_turning{"cam=0", "cam=-"};
    {
        const Scene s(envisioned_once("scenarios/clock/cam.def"));
        const auto& places = s.pair.vocabulary.places;
        // CSEG 5 rises under the turning cam, join 1 is its top, CSEG 6 falls, join 0 its bottom.
        REQUIRE(places.size() > 6);
        CHECK(places[5].kind == geometry::PlaceKind::cseg);
        CHECK(places[6].kind == geometry::PlaceKind::cseg);
        CHECK(places[1].kind == geometry::PlaceKind::join);
        CHECK(places[0].kind == geometry::PlaceKind::join);
        CHECK(q1_of(places[1]) > q1_of(places[0]));
        const auto a = ask(s, ride, cam_turning);
        REQUIRE(!a.path.empty());
        CHECK(a.path.front() == a.path.back());
        CHECK(path_follows_transitions(s.c, a.path));
    }
    {
        const Scene s(envisioned_once("scenarios/clock/cam_free.def"));
        CHECK(ask(s, ride, cam_turning).path.empty());
        // Pushed up by the cam, the follower never comes down again...
        const auto pushed = named(s, {5}, {+1, +1});
        REQUIRE(pushed.has_value());
        const auto down = ask(s, "#" + std::to_string(pushed->value) + " ; follower=-", cam_turning);
        CHECK(down.path.empty());
        // ...and the cam turns freely under it, the follower held at the top of its stroke.
        bool free_turning = false;
        const auto reach = reachable_from(s.c, *pushed);
        for (const auto& cycle : s.c.graph.cycles) {
            bool all = reach[cycle.front().value];
            for (const StateId x : cycle)
                all = all && place_of(s, x).kind != geometry::PlaceKind::cseg && motion(s, x, 0) == +1 && motion(s, x, 1) == 0;
            free_turning = free_turning || all;
        }
        CHECK(free_turning);
    }
}

namespace qm::envision {
namespace {

using testing::envisioned_once;

TEST_CASE("envision/acceptance: a part held at rest leaves the others to start (3.3)") {
    // #444: the pallets rest on a CSEG of normal (0 +) under gravity, the wheel driven (-): the
    // pallets cannot fall, the wheel turns along the face at once (#442), and nothing stops there.
    const Scene s(envisioned_once("scenarios/clock/escapement.def"));
    const auto& st = s.c.states[StateId{444}];
    REQUIRE(place_of(s, StateId{444}).kind == geometry::PlaceKind::cseg);
    REQUIRE(st.motions == std::vector<std::int8_t>{0, 0});
    CHECK(s.c.states[StateId{442}].places == st.places);
    CHECK(s.c.states[StateId{442}].motions == std::vector<std::int8_t>{-1, 0});
    CHECK(has_transition(s.c, StateId{444}, StateId{442}, Cause::dynamic));
    // Every state where the escapement may stop has every part still; with nothing holding the
    // wheel's spring for good, none is a jam, and the possible rests are where its contacts may
    // balance it.
    CHECK(s.c.graph.terminal.empty());
    for (const StateId r : s.c.graph.possible_rests) {
        CHECK(s.c.states[r].motions == std::vector<std::int8_t>{0, 0});
        CHECK(touching(place_of(s, r)));
    }
    // #10: a corner of the pallets in a notch of the wheel (a concave join), the spring turning the
    // wheel clockwise and gravity the pallets counter-clockwise, each against a flank: the contacts
    // may balance them (a rigid-body simulation comes to rest there for some masses), or the two
    // start clockwise at once.
    const auto& ten = s.c.states[StateId{10}];
    REQUIRE(place_of(s, StateId{10}).kind == geometry::PlaceKind::join);
    REQUIRE(place_of(s, StateId{10}).concave == true);
    REQUIRE(ten.motions == std::vector<std::int8_t>{0, 0});
    CHECK(std::count(s.c.graph.possible_rests.begin(), s.c.graph.possible_rests.end(), StateId{10}) == 1);
    CHECK(has_transition(s.c, StateId{10}, StateId{8}, Cause::dynamic));
}

TEST_CASE("envision/acceptance: without its return force the follower rides no cycle up or down its stroke (9.4)") {
    const Scene s(envisioned_once("scenarios/clock/cam_free.def"));
    // Every behavioural cycle has the follower still somewhere or moving both ways; the laps in
    // which it only ever goes one way are transient, the follower named.
    for (const auto& cycle : s.c.graph.cycles) {
        bool still_or_both = false;
        for (const StateId x : cycle) still_or_both = still_or_both || motion(s, x, 1) != motion(s, cycle.front(), 1) || motion(s, x, 1) == 0;
        CHECK(still_or_both);
    }
    REQUIRE(!s.c.graph.transient.empty());
    for (const auto& t : s.c.graph.transient) {
        CHECK(t.object == 1);
        for (const StateId x : t.states) CHECK(motion(s, x, 1) == t.motion);
    }
}

}  // namespace
}  // namespace qm::envision
