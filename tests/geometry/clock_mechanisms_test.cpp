// tests/geometry/clock_mechanisms_test.cpp: the bundled mechanisms of scenarios/clock/ read, and
// their place vocabularies have the properties their comments promise and the
// envisioner relies on: each gear pair is one place (8.1.6), the escapement's pallets turn all
// the way round with a free-spinning channel (Figure 9.23), inverted regions (9.22, 9.24) and a
// way from one pallet to the other; the ratchet's straight-down division lies in blocked space
// (9.2), it can jam (9.27) and a tooth can throw the pawl up (9.28); the Scotch yoke's pin stays
// in its slot; the cam's follower meets a stop at the top of its stroke; the whole clock has two
// kinematic chains and the same pair vocabularies as the separate files, its ratchet the mirror
// image of ratchet.def's. Each distinct pair is built once (keyed like the place cache).
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_cache.hpp"
#include "place_signature.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <sstream>

using namespace qm::geometry;
using qm::geometry::test::signature;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double degree = pi / 180;

// The six gear pairs at chordal 1e-7 are most of this test's work, and slow under ASan+UBSan
// (Debug): there, the gear train is checked on its first two pairs (a 10/30 and the 10/40 pair,
// each kind of pair but the 12/36 once), the rest in Release.
#if defined(NDEBUG) && !defined(QM_SANITIZED_BUILD)
constexpr std::size_t gear_pairs_checked = 6;
#else
constexpr std::size_t gear_pairs_checked = 2;
#endif

Mechanism load(const std::string& name) {
    qm::Diagnostics d;
    auto m = read_mechanism_file((std::filesystem::path(QM_SOURCE_DIR) / "scenarios/clock" / name).string(), d);
    std::ostringstream os;
    d.print(os);
    INFO(name, ": ", os.str());
    REQUIRE(m);
    return *m;
}

struct Pair {
    std::string a, b;
    std::string material;  // what the place cache keys the vocabulary by
    const PlaceVocabulary* vocabulary = nullptr;
};

// The vocabulary of every modelled pair, each distinct one built once; of gear pairs (both parts
// spur gears) only the first `gear_pairs_checked`.
std::vector<Pair> pairs_of(const Mechanism& m) {
    static std::map<std::string, PlaceVocabulary> built;
    const auto sel = kinematic_pairs(m);
    CHECK(sel.skipped.empty());
    std::vector<Pair> out;
    std::size_t gears = 0;
    for (const auto& spec : sel.modelled) {
        const bool gear_pair = m.parts[spec.a].name.starts_with("gear-") && m.parts[spec.b].name.starts_with("gear-");
        if (gear_pair && ++gears > gear_pairs_checked) continue;
        const auto oracle = pair_oracle(m, spec);
        const auto request = place_request(m, spec);
        Pair p{m.parts[spec.a].name, m.parts[spec.b].name, place_cache_material(*oracle, request), nullptr};
        auto it = built.find(p.material);
        if (it == built.end()) {
            auto r = build_place_vocabulary(*oracle, request);
            REQUIRE(r.status == PlaceStatus::ok);
            it = built.emplace(p.material, std::move(r.vocabulary)).first;
        }
        p.vocabulary = &it->second;
        out.push_back(std::move(p));
    }
    return out;
}

bool contact(const Place& p) { return p.kind == PlaceKind::cseg || (p.kind == PlaceKind::join && p.join_kind != JoinKind::crossing); }

// Is `to` reached from `from` by adjacencies under motion d, through places that `via` allows?
bool reaches(const PlaceVocabulary& v, const std::function<bool(const Place&)>& from, const std::function<bool(const Place&)>& to,
             QualDirection d, const std::function<bool(const Place&)>& via) {
    std::vector<char> seen(v.places.size(), 0);
    std::vector<PlaceId> todo;
    for (const auto& p : v.places)
        if (from(p)) todo.push_back(p.id);
    while (!todo.empty()) {
        const PlaceId x = todo.back();
        todo.pop_back();
        for (const auto& a : v.adjacency) {
            if (a.from != x || a.motion != d || a.constrained || seen[a.to.value]) continue;
            const Place& y = v.at(a.to);
            if (to(y)) return true;
            if (!via(y)) continue;
            seen[a.to.value] = 1;
            todo.push_back(a.to);
        }
    }
    return false;
}

// Is there a cycle under motion d among the places `in` allows (a behaviour that goes round)?
bool cycle(const PlaceVocabulary& v, QualDirection d, const std::function<bool(const Place&)>& in) {
    for (const auto& p : v.places) {
        if (!in(p)) continue;
        const PlaceId start = p.id;
        if (reaches(v, [&](const Place& x) { return x.id == start; }, [&](const Place& x) { return x.id == start; }, d, in)) return true;
    }
    return false;
}

// Every point of the place has its q1 within [lo, hi] (radians, wrapped into [0, 2 pi)).
bool q1_within(const Place& p, double lo, double hi) {
    return std::all_of(p.points.begin(), p.points.end(), [&](const Eigen::Vector2d& x) {
        const double q = std::fmod(std::fmod(x[1], 2 * pi) + 2 * pi, 2 * pi);
        return lo <= hi ? (q >= lo && q <= hi) : (q >= lo || q <= hi);
    });
}

bool constrained(const PlaceVocabulary& v, PlaceId p, QualDirection d) {
    return std::any_of(v.adjacency.begin(), v.adjacency.end(), [&](const Adjacency& a) { return a.from == p && a.motion == d && a.constrained; });
}

// A gear pair abstracted to one place (8.1.6): a gap face where the gears turn together, opposite
// ways, over an interval, and every other motion meets blocked space.
void check_one_gear_place(const Pair& p) {
    INFO(p.a, " / ", p.b);
    const auto& v = *p.vocabulary;
    REQUIRE(v.places.size() == 1);
    CHECK(v.places[0].kind == PlaceKind::face);
    CHECK(v.places[0].gap);
    REQUIRE(v.adjacency.size() == 8);
    for (const auto& a : v.adjacency) {
        const bool together = a.motion.s[0] == -a.motion.s[1];
        CHECK(a.to == a.from);
        CHECK(a.constrained == !together);
        CHECK(!a.instantaneous);
    }
}

constexpr QualDirection dir(int a, int b) { return QualDirection{{static_cast<std::int8_t>(a), static_cast<std::int8_t>(b)}}; }

}  // namespace

TEST_CASE("geometry/clock_mechanisms: a gear pair and the clock's gear train are one place per pair") {
    const auto pair = pairs_of(load("gear_pair.def"));
    REQUIRE(pair.size() == 1);
    check_one_gear_place(pair[0]);
    const auto m = load("gear_train.def");
    CHECK(kinematic_pairs(m).modelled.size() == 6);
    const auto train = pairs_of(m);
    REQUIRE(train.size() == gear_pairs_checked);
    for (const auto& p : train) check_one_gear_place(p);
    CHECK(m.linkages.size() == 4);
}

TEST_CASE("geometry/clock_mechanisms: the escapement's pallets turn all the way round") {
    const auto m = load("escapement.def");
    const auto pairs = pairs_of(m);
    REQUIRE(pairs.size() == 1);
    const auto& v = *pairs[0].vocabulary;
    const auto r = place_request(m, kinematic_pairs(m).modelled[0]);
    CHECK(r.cspace.axes[0].periodic);
    CHECK(r.cspace.axes[0].span() == doctest::Approx(2 * pi / 15));  // one tooth pitch
    CHECK(r.cspace.axes[1].periodic);
    CHECK(r.cspace.axes[1].span() == doctest::Approx(2 * pi));  // the full turn
    // Gravity's divisions: pallets standing up (0) and hanging down (pi), both in free space.
    bool up = false, down = false;
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::external_division) continue;
        CHECK(p.axis == 0);
        up = up || q1_within(p, 2 * pi - 1e-9, 1e-9);
        down = down || q1_within(p, pi - 1e-9, pi + 1e-9);
        CHECK((q1_within(p, 2 * pi - 1e-9, 1e-9) || q1_within(p, pi - 1e-9, pi + 1e-9)));
    }
    CHECK(up);
    CHECK(down);
    // The pallets meet the wheel only within 80 degrees of hanging; beyond the blocked bands
    // (65 to 80 degrees either way) they meet it turned over (our Figure 9.22).
    int over_left = 0, over_right = 0;
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::cseg) continue;
        CHECK(q1_within(p, pi - 81 * degree, pi + 81 * degree));
        over_left += q1_within(p, pi - 81 * degree, pi - 60 * degree);
        over_right += q1_within(p, pi + 60 * degree, pi + 81 * degree);
    }
    CHECK(over_left > 0);
    CHECK(over_right > 0);
    const auto free_place = [](const Place& p) { return !contact(p); };
    // Figure 9.23: hanging within 4 degrees of straight down, the wheel spins free either way
    // with the pallets still (a cycle under (+ 0) and (- 0) through places of no contact).
    auto near_down = [&](const Place& p) { return free_place(p) && q1_within(p, pi - 4 * degree, pi + 4 * degree); };
    CHECK(cycle(v, dir(1, 0), near_down));
    CHECK(cycle(v, dir(-1, 0), near_down));
    // Figure 9.24: inverted, the same.
    auto near_up = [&](const Place& p) { return free_place(p) && q1_within(p, 2 * pi - 30 * degree, 30 * degree); };
    CHECK(cycle(v, dir(1, 0), near_up));
    CHECK(cycle(v, dir(-1, 0), near_up));
    // The normal cycle needs the drop from one pallet onto the other: from a contact on one
    // side of hanging, with the wheel turning clockwise under its spring, through free space
    // to a contact on the other side, and back.
    auto above = [&](const Place& p) { return contact(p) && q1_within(p, pi + 2 * degree, pi + 23.5 * degree); };
    auto below = [&](const Place& p) { return contact(p) && q1_within(p, pi - 23.5 * degree, pi - 2 * degree); };
    CHECK((reaches(v, above, below, dir(-1, -1), free_place) || reaches(v, above, below, dir(-1, 1), free_place)));
    CHECK((reaches(v, below, above, dir(-1, -1), free_place) || reaches(v, below, above, dir(-1, 1), free_place)));
}

TEST_CASE("geometry/clock_mechanisms: the ratchet jams, can throw its pawl up, and ignores its blocked division") {
    const auto pairs = pairs_of(load("ratchet.def"));
    REQUIRE(pairs.size() == 1);
    const auto& v = *pairs[0].vocabulary;
    // 9.2: gravity flips where the pawl points straight down (-30 degrees) and up (150); the
    // first lies in blocked space and is ignored.
    int divisions = 0;
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::external_division) {
            ++divisions;
            CHECK(q1_within(p, 150 * degree - 1e-9, 150 * degree + 1e-9));
        }
    CHECK(divisions > 0);
    // Figure 9.27: a concave corner where the spring (wheel +) and gravity (pawl -) both push
    // into blocked space: jammed.
    const bool jam = std::any_of(v.places.begin(), v.places.end(), [&](const Place& p) {
        return p.kind == PlaceKind::join && p.concave.value_or(false) && constrained(v, p.id, dir(1, 0)) &&
               constrained(v, p.id, dir(0, -1)) && constrained(v, p.id, dir(1, -1));
    });
    CHECK(jam);
    // Figure 9.28: a contact where the wheel turning counter-clockwise pushes the pawl up.
    CHECK(std::any_of(v.places.begin(), v.places.end(),
                      [](const Place& p) { return p.kind == PlaceKind::cseg && p.normals.front() == dir(-1, 1); }));
}

TEST_CASE("geometry/clock_mechanisms: the Scotch yoke's pin stays in its slot; the crank drives the yoke both ways") {
    const auto pairs = pairs_of(load("scotch_yoke.def"));
    REQUIRE(pairs.size() == 1);
    const auto& v = *pairs[0].vocabulary;
    CHECK(v.count(PlaceKind::stop) == 0);  // the channel never reaches the limits
    // Every free sample is a pin in the slot: |pin x - slot centre x| below half the play.
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::face) CHECK(std::abs(0.6 * std::cos(p.points[0][0]) - 0.6 - p.points[0][1]) < 0.05 + 1e-9);
    // Figure 9.32: with the crank turning counter-clockwise the yoke slides along the slot's
    // sides one way on some CSEGs and the other way on others.
    auto slides = [&](QualDirection d) {
        return std::any_of(v.adjacency.begin(), v.adjacency.end(), [&](const Adjacency& a) {
            return a.motion == d && !a.constrained && !a.instantaneous && v.at(a.from).kind == PlaceKind::cseg;
        });
    };
    CHECK(slides(dir(1, 1)));
    CHECK(slides(dir(1, -1)));
}

TEST_CASE("geometry/clock_mechanisms: the cam's follower stops at the top of its stroke, with or without its return force") {
    const auto with = pairs_of(load("cam.def"));
    const auto without = pairs_of(load("cam_free.def"));
    REQUIRE(with.size() == 1);
    REQUIRE(without.size() == 1);
    CHECK(with[0].material == without[0].material);  // the return force divides no place
    const auto& v = *with[0].vocabulary;
    CHECK(v.count(PlaceKind::stop) == 2);
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::stop) {
            CHECK(p.normals.front() == dir(0, -1));
            CHECK(constrained(v, p.id, dir(0, 1)));
        }
    // No face lets the follower move for ever: the stops end its axis (docs/PLACES.md, "Stops").
    for (const auto& a : v.adjacency)
        if (a.from == a.to && v.at(a.from).kind == PlaceKind::face) CHECK(a.motion.s[1] == 0);
    // The follower rides on the cam: its two CSEGs (rising (+ +) and falling (- +) under the
    // follower) meet at the cam's top (convex) and bottom (concave).
    int rising = 0, falling = 0;
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::cseg) (p.normals.front() == dir(1, 1) ? rising : falling) += 1;
    CHECK(rising == 1);
    CHECK(falling == 1);
}

TEST_CASE("geometry/clock_mechanisms: the QRG clock is two kinematic chains of its parts' own vocabularies") {
    const auto m = load("clock.def");
    const auto all = kinematic_pairs(m).modelled;
    REQUIRE(all.size() == 8);
    const auto pairs = pairs_of(m);
    REQUIRE(pairs.size() == 2 + gear_pairs_checked);
    // Kinematic chains (9.1.3): transitive closure of pairs and linkages.
    std::vector<std::size_t> root(m.parts.size());
    std::iota(root.begin(), root.end(), 0);
    std::function<std::size_t(std::size_t)> find = [&](std::size_t x) { return root[x] == x ? x : root[x] = find(root[x]); };
    auto join = [&](const std::string& a, const std::string& b) { root[find(m.find_part(a)->value)] = find(m.find_part(b)->value); };
    for (const auto& p : all) join(m.parts[p.a].name, m.parts[p.b].name);
    for (const auto& l : m.linkages)
        for (const auto& q : l.parts) join(m.parts[l.parts[0]].name, m.parts[q].name);
    std::set<std::size_t> chains;
    for (std::size_t i = 0; i < m.parts.size(); ++i) chains.insert(find(i));
    CHECK(chains.size() == 2);
    CHECK(find(m.find_part("ratchet-wheel")->value) == find(m.find_part("pawl")->value));
    CHECK(find(m.find_part("ratchet-wheel")->value) != find(m.find_part("gear-6")->value));
    // The escapement and the gear pairs are the very pairs of their own files (the same cache
    // key); the ratchet is ratchet.def's mirror image: the configuration space reflected through
    // its origin, every normal and motion negated.
    std::map<std::string, std::string> own;
    for (const auto* file : {"escapement.def", "gear_train.def"})
        for (const auto& p : pairs_of(load(file))) own[p.a + "/" + p.b] = p.material;
    const auto ratchet = pairs_of(load("ratchet.def"));
    for (const auto& p : pairs) {
        INFO(p.a, " / ", p.b);
        if (p.a == "ratchet-wheel") {
            CHECK(signature(*p.vocabulary) == signature(*ratchet[0].vocabulary, true));
            CHECK(signature(*p.vocabulary) != signature(*ratchet[0].vocabulary));
        } else {
            CHECK(p.material == own.at(p.a + "/" + p.b));
        }
    }
}
